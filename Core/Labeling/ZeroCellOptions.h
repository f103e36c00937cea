// How the zero cell (label 0 for every shape) is chosen: the options the labeling and one-step
// filters hold (ZeroCellMode, ZeroCellPoint) and the labeling stage takes whole.
#ifndef boolsurf_ZeroCellOptions_h
#define boolsurf_ZeroCellOptions_h

#include <array>

namespace boolsurf
{

/// The values of the filters' ZeroCellMode property.
enum class ZeroCellMode : int
{
  /// Beyond each component's longest boundary loop; on a closed component, labels shifted to a
  /// minimum of 0 (LabelingInput::ZeroCells).
  Automatic = 0,
  /// The cell containing Point, in its component (LabelingInput::SetZeroCell).
  Point = 1,
};

struct ZeroCellOptions
{
  ZeroCellMode Mode = ZeroCellMode::Automatic;
  /// A point on or near the surface, read in Point mode.
  std::array<double, 3> Point{ 0, 0, 0 };
};

} // namespace boolsurf

#endif

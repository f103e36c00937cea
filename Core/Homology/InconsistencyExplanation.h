// Why a shape is inconsistent, in homology: each curve's class in the surface's generators
// (how many times, with sign, it winds around each handle), the generators a shape has in
// excess (the sum over its curves), and the explanation a user reads, with the fixes.
// Computed from the curves and the homology basis alone; the filters write and read these as
// field data (Filters/Private/vtkBoolSurfHomologyOutput).
#ifndef boolsurf_InconsistencyExplanation_h
#define boolsurf_InconsistencyExplanation_h

#include "Geodesic/TracedCurve.h"
#include "Labeling/CellLabeling.h"

#include <string>
#include <vector>

namespace boolsurf
{

class HomologyBasis;

/// Closed loops on the surface (the generators, or their shortened versions).
struct HomologyLoops
{
  std::vector<int> Ids;          ///< generator id of each loop
  std::vector<int> Offsets;      ///< loops + 1 offsets into the points
  std::vector<double> Positions; ///< xyz per point
  std::vector<SurfacePoint> Points;
};

/// The homology of a set of curves: each curve's class in the surface's generators (and, read
/// back from an arrangement's field data, the generators themselves).
struct HomologyFields
{
  bool Present = false;
  int NumberOfGenerators = 0;
  std::vector<int> CurveIds, CurveShapeIds;
  std::vector<std::vector<int>> CurveClasses; ///< per row
  HomologyLoops Generators;
  HomologyLoops ShortGenerators; ///< locally shortest loops, for the generators that have one
};

/// The curve rows of HomologyFields (classes, ids, shapes) computed in memory, without the
/// generators' points: what the one-step filter needs to explain inconsistent shapes.
bool ComputeCurveClasses(const HomologyBasis& basis,
  const std::vector<TracedCurve>& curves,
  HomologyFields& out,
  std::string& error);

/// Per shape index (of `shapeIds`, sorted), the sum of its curves' classes.
std::vector<std::vector<int>> ShapeExcess(const HomologyFields& h,
  const std::vector<int>& shapeIds);

/// For every inconsistent shape of `labels`: the curves that wind around generators (with
/// sign and multiplicity), the generators in excess and the three fixes, in words. Empty when
/// every shape is consistent.
std::string ExplainInconsistency(const LabelingResult& labels, const HomologyFields& h);

/// "+1 x G0, -2 x G3" for a class vector ("no generator" when zero).
std::string DescribeClass(const std::vector<int>& homology);

} // namespace boolsurf

#endif

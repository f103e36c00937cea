// Boundary of a selected region of arrangement cells, as oriented loops (BoolSurf step 7).
//
// The boundary is made of the patches (curve pieces between intersection points) that have
// a selected cell on one side and an unselected cell on the other. Each is oriented so the
// selected region is on its left, then pieces are chained end to start into polylines:
// closed loops where the region is bounded, open chains only where a patch ends without a
// continuation (which a valid arrangement of closed curves does not produce).
#ifndef boolsurf_RegionBoundary_h
#define boolsurf_RegionBoundary_h

#include <vector>

namespace boolsurf
{

struct BoundaryPatch
{
  std::vector<int> Points; ///< point ids along the patch, in curve direction
  int LeftCell = -1;
  int RightCell = -1;
};

struct BoundaryPolyline
{
  std::vector<int> Points;    ///< a closed loop does not repeat its first point
  std::vector<int> Patches;   ///< patch ids in order
  std::vector<char> Reversed; ///< whether each patch was walked against its direction
  bool Closed = false;
};

/// Loops bounding the cells with selected[cell] != 0. Patch is BoundaryPatch or the
/// arrangement's ArrangementPatch (any type with Points, LeftCell and RightCell).
template <class Patch>
std::vector<BoundaryPolyline> ExtractRegionBoundary(const std::vector<Patch>& patches,
  const std::vector<char>& selected);

} // namespace boolsurf

#endif

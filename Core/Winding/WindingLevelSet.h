// The level set {w = threshold} of a field given per corner of the refined surface, as closed
// loops of surface points: the "completed curves" of the winding-number stage
// (Winding/SurfaceWinding.h), which chain into BoolSurf as control curves.
//
// The field is linear in each refined triangle (its three corner values) and continuous across
// every refined edge except where a curve runs: there the two sides' corner values differ (the
// jump). The level set is made of
//  - iso segments inside refined triangles, where the corner values straddle the threshold
//    (a corner at or above the threshold counts as above, so no iso point falls on a corner
//    whose value equals it exactly);
//  - jump segments along refined edges, the part of the edge where one side is above and the
//    other below (a closed curve that bounds its region exactly is its own level set);
//  - boundary segments along the open boundary of the surface, where the side that exists is
//    above, so that a region reaching the boundary is closed by it.
// Every loop is oriented with the region {w >= threshold} on its left (positive winding inside,
// as the labels of Labeling/CellLabeling.h count it).
#ifndef boolsurf_WindingLevelSet_h
#define boolsurf_WindingLevelSet_h

#include "Arrangement/Arrangement.h"
#include "Mesh/SurfacePoint.h"

#include <functional>
#include <string>
#include <vector>

namespace boolsurf
{

/// One loop of the level set, in order, not repeating its first point. Consecutive points lie
/// in one mesh triangle (the segment between them is straight in it), and there is a point
/// wherever the loop crosses a mesh edge, so Points form a valid TracedCurve.
struct LevelSetLoop
{
  std::vector<CanonicalPoint> Points;
  /// The same points as triangle + barycentric on the mesh (WriteSurfacePoint, preferring the
  /// triangle shared with the next point), ready for control-point arrays.
  std::vector<SurfacePoint> SurfacePoints;
  double Length = 0;
};

struct LevelSetInput
{
  double Threshold = 0.5;
  /// Field value at corner k (0, 1, 2, in the order of GetTriangle) of refined triangle r.
  std::function<double(int r, int k)> CornerValue;
  /// Refined triangles where the field may jump across an edge (those touching a curve point):
  /// everywhere else the corner values of neighbours agree, so only triangles whose corners
  /// straddle the threshold, these, and triangles on the boundary need to be looked at. Both
  /// triangles of an edge where the values jump must be listed (a jump to an unlisted
  /// neighbour is not seen, and its segments do not close); order does not matter. Null: the
  /// field is continuous everywhere.
  const std::vector<int>* JumpTriangles = nullptr;
};

/// The loops of the level set of `input` on the refined surface of `arr` (computed on `mesh`),
/// in the order of the lowest refined triangle each comes from. Corner values are read in one
/// pass over the refined surface, and again for the triangles the level set meets. Where several
/// loops meet at one point (regions touching at a corner) they are paired in a fixed order, so the
/// result is deterministic. Values exactly at the threshold can give regions of no width: their
/// spikes (a point the loop leaves and comes straight back to) are removed, and a loop that
/// collapses to fewer than three points (a region reduced to a point or a segment) is left out.
/// False with a message naming the refined triangle when a corner value is not finite, or when
/// the segments do not close into loops (values that jump across an edge not listed in
/// JumpTriangles).
bool ExtractLevelSet(const TriangleMesh& mesh,
  const Arrangement& arr,
  const LevelSetInput& input,
  std::vector<LevelSetLoop>& loops,
  std::string& error);

} // namespace boolsurf

#endif

// Arrangement stage 3, general path: the constrained triangulation of one crossed mesh
// triangle, built by a plane sweep in O(k log k) for k points and curve pieces.
//
// Input: stage 2's local subdivision of the triangle (SegmentIntersection.h): the boundary
// polygon, the interior points (curve points and exact crossings) and the chains, whose
// consecutive points bound pieces that cross no other piece and hold no point inside.
//
// The sweep visits the points in lexicographic (x, y) order, exactly (crossings included,
// ExactCrossings.h). Its status is the ordered set of pieces and boundary edges that cross the
// sweep line (a balanced tree: O(log k) per point). Between two consecutive status edges lies
// a region whose part left of the sweep line is not yet triangulated; that part is bounded by
// a polyline of visited points, rising lexicographically to its rightmost point and falling
// after it, with every inner vertex reflex. A new point sees that rightmost point, fans
// triangles towards both ends while they are strictly counter-clockwise and takes its place;
// its pieces to the right then split the region (as in Hertel and Mehlhorn's sweep
// triangulation of polygons, generalised here to holes, dangling pieces and isolated points).
// Each triangle is made once, so after sorting the work is linear apart from the status.
//
// Points with equal exact coordinates become one (Alias). Every decision is an exact
// orientation or comparison: no point is created or moved and no step budget exists. An input
// that breaks the guarantee above (two pieces crossing, a point inside a piece: possible only
// after stage 2 merged near points) is detected, by the sweep or by the final check that the
// triangles tile the triangle exactly once with every piece as an edge, and reported.
#ifndef boolsurf_SweepTriangulation_h
#define boolsurf_SweepTriangulation_h

#include "Arrangement/SegmentIntersection.h"

namespace boolsurf
{

/// Fills arrangement.Triangles (counter-clockwise local ids) and .Alias, and rewrites
/// .Chains into paths of surviving point ids (pieces along the triangle's boundary go
/// through the boundary points on them). Sets arrangement.Error and returns false when the
/// input is not a consistent planar subdivision of the triangle.
bool SweepTriangulate(LocalArrangement& arrangement);

} // namespace boolsurf

#endif

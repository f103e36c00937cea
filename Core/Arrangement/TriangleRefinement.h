// Arrangement stage 3: replace each crossed triangle by a triangulation of itself that embeds
// its curve segments.
//
// The input is the triangle's local planar subdivision from stage 2: boundary points (corners
// and the shared edge points, so that neighbours conform), interior points (curve points and
// crossings) and the split segments ("chains"). Two paths:
//  * Fast path, no interior point (the usual case: one or a few curves crossing from edge to
//    edge without meeting): every chain is a chord of the convex boundary polygon; chords
//    split convex polygons into convex polygons, which are then triangulated by ear clipping.
//  * General path: triangulate the boundary polygon, insert the interior points (splitting the
//    triangle or edge they fall in), then insert each chain piece as a constrained edge by
//    removing the triangles it crosses and re-triangulating the two cavity polygons.
// All decisions use the exact Orient2d on the coordinates fixed in stage 2. A rounded
// crossing that lands exactly on another piece is merged or made a vertex of it, and if
// rounding makes two pieces cross after all, they are split at a new point on both, so the
// output is always a valid triangulation whose paths follow the curves.
#ifndef boolsurf_TriangleRefinement_h
#define boolsurf_TriangleRefinement_h

#include "Arrangement/SegmentIntersection.h"

namespace boolsurf
{

/// Fills arrangement.Triangles, .Blocked, .Alias, .NumberOfNewPoints and rewrites
/// .Chains into the final paths (local ids of points every piece goes through). Sets
/// arrangement.Error and returns false when the triangle cannot be triangulated.
bool RefineTriangle(LocalArrangement& arrangement);

} // namespace boolsurf

#endif

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
// All decisions are exact orientations: on the double coordinates of explicit points, and on
// the defining segments of stage 2's crossings (ExactCrossings.h). Because stage 2 found every
// crossing exactly and put it on every segment through it, no piece crosses another piece or
// passes over a point it was not cut at: a constraint's insertion walks through the triangles
// it crosses, through the vertices on it, and ends. No point is created here, nothing is
// snapped, and no step budget is needed.
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

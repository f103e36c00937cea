// Arrangement stage 3: replace each crossed triangle by a triangulation of itself that embeds
// its curve segments.
//
// The input is the triangle's local planar subdivision from stage 2: boundary points (corners
// and the shared edge points, so that neighbours conform), interior points (curve points and
// crossings) and the split segments ("chains"). Two paths:
//  * Fast path, no interior point (the usual case: one or a few curves crossing from edge to
//    edge without meeting): every chain is a chord of the convex boundary polygon; chords
//    split convex polygons into convex polygons, which are then triangulated by ear clipping.
//  * General path: a plane sweep builds the constrained triangulation in O(k log k) for k
//    points and pieces (SweepTriangulation.h), with exact predicates on explicit points and on
//    stage 2's crossings (ExactCrossings.h). Because stage 2 found every crossing exactly and
//    put it on every segment through it, no piece crosses another piece or passes over a point
//    it was not cut at; the sweep creates no point, snaps nothing and needs no step budget.
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

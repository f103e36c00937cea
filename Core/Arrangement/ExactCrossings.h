// Exact predicates on a triangle's local points, some of which are crossings of two curve
// segments.
//
// A crossing is not rounded to a point: it is kept as the two segments that define it (an
// implicit point, as in Cherchi, Livesu, Scateni and Attene, "Fast and robust mesh
// arrangements using floating-point arithmetic", 2020), and every predicate that involves it
// (orientation, coordinate order) is evaluated exactly on the segments' double end points.
// So a crossing lies exactly on both of its segments, two crossings at the same place are
// recognised as equal, and the pieces between consecutive points of a segment never cross
// each other: the constrained triangulation of stage 3 never meets a crossing it was not
// given, and needs no snapping, detour or step budget.
//
// Evaluation: in homogeneous coordinates (x, y, w) with w = the segments' cross product, the
// orientation of three points is a polynomial of degree up to 9 in the end points'
// coordinates. It is decided by the first of these that can:
//  1. doubles with a running bound on their rounding error (a floating-point filter; the
//     crossing's own coordinates and bounds are computed once, MakeSegmentCrossing);
//  2. exact zeros by construction: three points on one line of the drawing, two crossings of
//     the same two lines (orientations of explicit points only);
//  3. double-double numbers (about 106 bits) with the same bound: near-degenerate cases, such
//     as three curves nearly through one point, whose values are about 1e-16 of their terms;
//  4. GMP integers: every double of the predicate scaled by one power of two to an integer,
//     which keeps every sign and needs no fraction reduction.
// Generic configurations never leave step 1.
#ifndef boolsurf_ExactCrossings_h
#define boolsurf_ExactCrossings_h

#include "Mesh/Vec3.h"

namespace boolsurf
{

/// The point where the line through P0 and P1 meets the line through Q0 and Q1 (the lines
/// must not be parallel).
struct SegmentCrossing
{
  Vec2 P0, P1, Q0, Q1;
  /// The first filter's homogeneous coordinates (x, y, w) and their error bounds, computed
  /// once by MakeSegmentCrossing (every predicate on the crossing starts from them); without
  /// Cached they are computed per predicate.
  double H[3] = { 0.0, 0.0, 0.0 }, E[3] = { 0.0, 0.0, 0.0 };
  bool Cached = false;
  /// With Cached: the crossing lies within Radius of Center on each axis (a certified box),
  /// which settles most comparisons of coordinates without arithmetic.
  Vec2 Center{ 0.0, 0.0 };
  double Radius = 0.0;
};

/// The crossing of the lines (p0, p1) and (q0, q1), with its filter's coordinates cached.
SegmentCrossing MakeSegmentCrossing(Vec2 p0, Vec2 p1, Vec2 q0, Vec2 q1);

/// A point as the exact predicates see it: explicit coordinates P, or, when Crossing is set,
/// that crossing (P is then only its rounded position and is not used).
struct ExactPoint
{
  Vec2 P;
  const SegmentCrossing* Crossing = nullptr;
};

/// Exact sign of the orientation of (a, b, c): +1 counter-clockwise, -1 clockwise, 0 collinear.
int ExactOrient(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c);

/// Exact sign of a's coordinate minus b's on `axis` (0: x, 1: y).
int ExactCompare(const ExactPoint& a, const ExactPoint& b, int axis);

/// The crossing's coordinates, rounded (a few ulps from the exact point).
Vec2 RoundedCrossing(const SegmentCrossing& c);

/// Number of predicate evaluations the floating-point filter could not decide (exact
/// fallbacks), since the process started; for tests and benchmarks.
long long ExactFallbackCount();

} // namespace boolsurf

#endif

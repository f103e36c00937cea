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
// orientation of three points is a polynomial of degree 9 in the end points' coordinates.
// It is computed first in doubles with a running bound on its rounding error (a floating-point
// filter); only when the bound does not settle the sign is it recomputed exactly in GMP's
// rationals, which hold every double exactly. Generic configurations never leave the filter.
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
};

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

/// For q on the line through a and b (orientation zero), whether it lies strictly between
/// them; exact.
bool ExactStrictlyBetween(const ExactPoint& a, const ExactPoint& b, const ExactPoint& q);

/// Number of predicate evaluations the floating-point filter could not decide (exact
/// fallbacks), since the process started; for tests and benchmarks.
long long ExactFallbackCount();

} // namespace boolsurf

#endif

// Robust geometric predicates in the plane (after Shewchuk, "Adaptive Precision
// Floating-Point Arithmetic and Fast Robust Geometric Predicates", 1997).
//
// The arrangement decides topology (which segments cross, on which side a point lies) with
// these predicates, so their sign must be exact for the double inputs given: a rounded sign
// can make two decisions about the same configuration disagree and the local planar
// subdivision inconsistent. Orient2d evaluates in doubles first and, only when the result is
// within the forward error bound of zero, recomputes exactly with floating-point expansions.
#ifndef boolsurf_Predicates_h
#define boolsurf_Predicates_h

#include "Mesh/Vec3.h"

#include <cmath>

namespace boolsurf
{

/// Twice the signed area of triangle (a, b, c): positive when a, b, c turn counter-clockwise,
/// negative when clockwise, zero when collinear. The SIGN is exact; the magnitude is an
/// approximation (exact when the filter succeeds up to rounding).
double Orient2d(Vec2 a, Vec2 b, Vec2 c);

/// Exact sign of Orient2d: +1, -1 or 0.
int Orient2dSign(Vec2 a, Vec2 b, Vec2 c);

/// Orient2d always computed with expansions (no filter); for tests of the filter.
double Orient2dExact(Vec2 a, Vec2 b, Vec2 c);

/// Exact sign of (a + b - 1) for doubles a, b: tells whether the barycentric point (a, b) lies
/// below, on or above the hypotenuse u + v = 1 of the unit triangle.
int SumMinusOneSign(double a, double b);

/// For q on the line through a and b (Orient2d zero): whether q lies strictly between them,
/// decided exactly on one coordinate (x unless the segment is vertical).
inline bool StrictlyBetween(Vec2 a, Vec2 b, Vec2 q)
{
  if (a.x != b.x)
  {
    return (a.x < q.x && q.x < b.x) || (b.x < q.x && q.x < a.x);
  }
  return (a.y < q.y && q.y < b.y) || (b.y < q.y && q.y < a.y);
}

/// Whether q lies strictly inside the segment (a, b) (of some length); exact.
inline bool StrictlyInsideSegment(Vec2 a, Vec2 b, Vec2 q)
{
  return Orient2dSign(a, b, q) == 0 && StrictlyBetween(a, b, q);
}

} // namespace boolsurf

#endif

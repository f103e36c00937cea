// Cubic geodesic Bezier curves by recursive de Casteljau subdivision (b/Surf: Mancinelli,
// Nazzaro, Pellacini, Puppo 2022).
//
// On a surface there is no affine combination of points, but there are geodesic midpoints:
// the point halfway along the shortest path between two points. One subdivision step replaces
// the control polygon (p0, p1, p2, p3) by (p0, q0, r0, s) and (s, r1, q2, p3) where q, r, s
// are midpoints of midpoints exactly as in the planar algorithm; s lies on the curve at the
// middle of the parameter range. After `levels` steps the refined control polygon (3 * 2^L
// legs) is close to the curve and is traced as a geodesic polygon. On a flat mesh every
// midpoint is the planar midpoint, so the anchors of the refined polygon are exactly the
// planar Bezier curve at parameters k / 2^L.
#ifndef boolsurf_GeodesicBezier_h
#define boolsurf_GeodesicBezier_h

#include "Geodesic/GeodesicPath.h"

#include <array>
#include <vector>

namespace boolsurf
{

/// Geodesic midpoint of a and b (the point at half the length of their shortest path).
bool GeodesicMidpoint(GeodesicPathSolver& solver,
  const CanonicalPoint& a,
  const CanonicalPoint& b,
  CanonicalPoint& mid,
  std::string& error);

/// The point at fraction t of the shortest path from a to b (the geodesic lerp).
bool GeodesicLerp(GeodesicPathSolver& solver,
  const CanonicalPoint& a,
  const CanonicalPoint& b,
  double t,
  CanonicalPoint& out,
  std::string& error);

/// One de Casteljau step at parameter t in (0, 1) with geodesic lerps (b/Surf's point
/// insertion): the segment becomes `left` = (p0, q0, r0, s) and `right` = (s, r1, q2, p3), two
/// cubic segments whose union is the curve, s on it at t. On a flat mesh this is the planar
/// split, exactly.
bool SplitGeodesicBezier(GeodesicPathSolver& solver,
  const std::array<CanonicalPoint, 4>& segment,
  double t,
  std::array<CanonicalPoint, 4>& left,
  std::array<CanonicalPoint, 4>& right,
  std::string& error);

/// Refined control polygon of one cubic segment after `levels` de Casteljau subdivisions:
/// 3 * 2^levels + 1 points; point 3k is on the curve at parameter t = k / 2^levels, the two
/// points between consecutive anchors are handles. levels = 0 returns the segment itself.
bool SubdivideGeodesicBezier(GeodesicPathSolver& solver,
  const std::array<CanonicalPoint, 4>& segment,
  int levels,
  std::vector<CanonicalPoint>& polygon,
  std::string& error);

} // namespace boolsurf

#endif

#include "Geodesic/GeodesicBezier.h"

namespace boolsurf
{

//------------------------------------------------------------------------------
bool GeodesicMidpoint(GeodesicPathSolver& solver,
  const CanonicalPoint& a,
  const CanonicalPoint& b,
  CanonicalPoint& mid,
  std::string& error)
{
  // One path per thread reused: midpoints are computed thousands of times per spline.
  thread_local GeodesicPath path;
  if (!solver.Compute(a, b, path, error))
  {
    return false;
  }
  mid = PointAlongPath(solver.GetMesh(), path, 0.5);
  return true;
}

//------------------------------------------------------------------------------
bool GeodesicLerp(GeodesicPathSolver& solver,
  const CanonicalPoint& a,
  const CanonicalPoint& b,
  double t,
  CanonicalPoint& out,
  std::string& error)
{
  if (t <= 0 || a == b)
  {
    out = a;
    return true;
  }
  if (t >= 1)
  {
    out = b;
    return true;
  }
  thread_local GeodesicPath path;
  if (!solver.Compute(a, b, path, error))
  {
    return false;
  }
  out = PointAlongPath(solver.GetMesh(), path, t);
  return true;
}

//------------------------------------------------------------------------------
bool SplitGeodesicBezier(GeodesicPathSolver& solver,
  const std::array<CanonicalPoint, 4>& p,
  double t,
  std::array<CanonicalPoint, 4>& left,
  std::array<CanonicalPoint, 4>& right,
  std::string& error)
{
  CanonicalPoint q0, q1, q2, r0, r1, s;
  if (!GeodesicLerp(solver, p[0], p[1], t, q0, error) ||
    !GeodesicLerp(solver, p[1], p[2], t, q1, error) ||
    !GeodesicLerp(solver, p[2], p[3], t, q2, error) ||
    !GeodesicLerp(solver, q0, q1, t, r0, error) || !GeodesicLerp(solver, q1, q2, t, r1, error) ||
    !GeodesicLerp(solver, r0, r1, t, s, error))
  {
    return false;
  }
  left = { p[0], q0, r0, s };
  right = { s, r1, q2, p[3] };
  return true;
}

//------------------------------------------------------------------------------
bool SubdivideGeodesicBezier(GeodesicPathSolver& solver,
  const std::array<CanonicalPoint, 4>& segment,
  int levels,
  std::vector<CanonicalPoint>& polygon,
  std::string& error)
{
  polygon.assign(segment.begin(), segment.end());
  std::vector<CanonicalPoint> refined;
  for (int level = 0; level < levels; ++level)
  {
    const size_t pieces = (polygon.size() - 1) / 3;
    refined.clear();
    refined.reserve(6 * pieces + 1);
    refined.push_back(polygon[0]);
    for (size_t k = 0; k < pieces; ++k)
    {
      const CanonicalPoint* p = &polygon[3 * k];
      CanonicalPoint q0, q1, q2, r0, r1, s;
      if (!GeodesicMidpoint(solver, p[0], p[1], q0, error) ||
        !GeodesicMidpoint(solver, p[1], p[2], q1, error) ||
        !GeodesicMidpoint(solver, p[2], p[3], q2, error) ||
        !GeodesicMidpoint(solver, q0, q1, r0, error) ||
        !GeodesicMidpoint(solver, q1, q2, r1, error) || !GeodesicMidpoint(solver, r0, r1, s, error))
      {
        return false;
      }
      refined.insert(refined.end(), { q0, r0, s, r1, q2, p[3] });
    }
    polygon.swap(refined);
  }
  return true;
}

} // namespace boolsurf

#include "Geodesic/GeodesicBezier.h"

namespace boolsurf
{

//------------------------------------------------------------------------------
TraceStatus GeodesicMidpoint(GeodesicPathSolver& solver,
  const CanonicalPoint& a,
  const CanonicalPoint& b,
  CanonicalPoint& mid)
{
  // One path per thread reused: midpoints are computed thousands of times per spline.
  thread_local GeodesicPath path;
  TraceStatus status = solver.Compute(a, b, path);
  if (!status)
  {
    return status;
  }
  mid = PointAlongPath(solver.GetMesh(), path, 0.5);
  return status;
}

//------------------------------------------------------------------------------
TraceStatus GeodesicLerp(GeodesicPathSolver& solver,
  const CanonicalPoint& a,
  const CanonicalPoint& b,
  double t,
  CanonicalPoint& out)
{
  if (t <= 0 || a == b)
  {
    out = a;
    return TraceStatus::Success();
  }
  if (t >= 1)
  {
    out = b;
    return TraceStatus::Success();
  }
  thread_local GeodesicPath path;
  TraceStatus status = solver.Compute(a, b, path);
  if (status)
  {
    out = PointAlongPath(solver.GetMesh(), path, t);
  }
  return status;
}

//------------------------------------------------------------------------------
TraceStatus SplitGeodesicBezier(GeodesicPathSolver& solver,
  const std::array<CanonicalPoint, 4>& p,
  double t,
  std::array<CanonicalPoint, 4>& left,
  std::array<CanonicalPoint, 4>& right)
{
  CanonicalPoint q0, q1, q2, r0, r1, s;
  TraceStatus status;
  if (!(status = GeodesicLerp(solver, p[0], p[1], t, q0)) ||
    !(status = GeodesicLerp(solver, p[1], p[2], t, q1)) ||
    !(status = GeodesicLerp(solver, p[2], p[3], t, q2)) ||
    !(status = GeodesicLerp(solver, q0, q1, t, r0)) ||
    !(status = GeodesicLerp(solver, q1, q2, t, r1)) ||
    !(status = GeodesicLerp(solver, r0, r1, t, s)))
  {
    return status;
  }
  left = { p[0], q0, r0, s };
  right = { s, r1, q2, p[3] };
  return TraceStatus::Success();
}

//------------------------------------------------------------------------------
TraceStatus SubdivideGeodesicBezier(GeodesicPathSolver& solver,
  const std::array<CanonicalPoint, 4>& segment,
  int levels,
  std::vector<CanonicalPoint>& polygon)
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
      TraceStatus status;
      if (!(status = GeodesicMidpoint(solver, p[0], p[1], q0)) ||
        !(status = GeodesicMidpoint(solver, p[1], p[2], q1)) ||
        !(status = GeodesicMidpoint(solver, p[2], p[3], q2)) ||
        !(status = GeodesicMidpoint(solver, q0, q1, r0)) ||
        !(status = GeodesicMidpoint(solver, q1, q2, r1)) ||
        !(status = GeodesicMidpoint(solver, r0, r1, s)))
      {
        return status;
      }
      refined.insert(refined.end(), { q0, r0, s, r1, q2, p[3] });
    }
    polygon.swap(refined);
  }
  return TraceStatus::Success();
}

} // namespace boolsurf

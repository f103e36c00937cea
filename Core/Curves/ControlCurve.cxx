#include "Curves/ControlCurve.h"

#include <algorithm>

namespace boolsurf
{

//------------------------------------------------------------------------------
std::string WhatCurveNeeds(bool bezier, bool closed, int size)
{
  if (!bezier)
  {
    return size >= 2 ? std::string()
                     : "a geodesic polygon needs 2 control points; it has " + std::to_string(size);
  }
  const int missing = MissingControlPoints(bezier, closed, size);
  if (missing == 0)
  {
    return std::string();
  }
  return std::string(closed ? "a closed" : "an open") + " cubic Bezier spline needs " +
    (closed ? "3n" : "3n+1") + " control points (anchor, handle, handle, anchor, ...); it has " +
    std::to_string(size) + ": " + std::to_string(missing) + " more complete" +
    (missing == 1 ? "s" : "") + " it";
}

//------------------------------------------------------------------------------
namespace
{
bool SamePoint(const SurfacePoint& a, const SurfacePoint& b)
{
  return a.Triangle == b.Triangle && a.U == b.U && a.V == b.V;
}
} // namespace

//------------------------------------------------------------------------------
bool HasDistinctPoints(const ControlCurve& curve)
{
  const std::vector<SurfacePoint>& p = curve.Points;
  for (std::size_t i = 1; i < p.size(); ++i)
  {
    if (!SamePoint(p[0], p[i]))
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
bool CloseWhereEndsMeet(ControlCurve& curve)
{
  if (curve.Closed || curve.Points.size() < 3 ||
    !SamePoint(curve.Points.front(), curve.Points.back()))
  {
    return false;
  }
  curve.Points.pop_back();
  curve.Closed = true;
  return true;
}

//------------------------------------------------------------------------------
bool CheckControlCurve(const TriangleMesh& mesh, const ControlCurve& curve, std::string& problem)
{
  for (std::size_t i = 0; i < curve.Points.size(); ++i)
  {
    std::string why;
    if (!CheckSurfacePoint(mesh, curve.Points[i], why))
    {
      problem = "control point " + std::to_string(i) + ": " + why;
      return false;
    }
  }
  if (!HasDistinctPoints(curve))
  {
    problem = "it has " + std::to_string(curve.Points.size()) + " control point(s)" +
      (curve.Points.size() >= 2 ? ", all at the same surface point" : "") +
      ": a curve needs two distinct points";
    return false;
  }
  problem = WhatCurveNeeds(
    curve.Type == CurveType::CubicBezier, curve.Closed, static_cast<int>(curve.Points.size()));
  return problem.empty();
}

} // namespace boolsurf

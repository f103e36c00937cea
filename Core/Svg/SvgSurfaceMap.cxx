#include "Svg/SvgSurfaceMap.h"

#include "Geodesic/StraightestGeodesic.h"
#include "Mesh/ParallelRange.h"

#include <algorithm>
#include <cmath>

namespace boolsurf
{
namespace
{

/// Drawings with fewer control points map on the calling thread (waking another costs more
/// than their walks); larger ones in blocks of WalkGrain points.
constexpr std::size_t ParallelWalks = 64;
constexpr int WalkGrain = 16;

/// Twice the signed area of the control polygon of a spline (a good sign of its orientation).
double SignedArea2(const std::vector<Vec2>& p)
{
  double a = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
  {
    const Vec2& q = p[i];
    const Vec2& r = p[(i + 1) % p.size()];
    a += q.x * r.y - r.x * q.y;
  }
  return a;
}

/// The same spline walked the other way (a closed one keeps its first anchor first).
template <class T>
void Reverse(std::vector<T>& points, bool closed)
{
  if (closed && !points.empty())
  {
    std::reverse(points.begin() + 1, points.end());
  }
  else
  {
    std::reverse(points.begin(), points.end());
  }
}

} // namespace

//------------------------------------------------------------------------------
bool MapSvgOntoSurface(const TriangleMesh& mesh,
  const SvgDrawing& drawing,
  const SvgMapOptions& options,
  std::vector<MappedSvgCurve>& out,
  std::vector<std::string>& warnings,
  std::string& error)
{
  out.clear();
  const int t = options.Center.Triangle;
  if (t < 0 || t >= mesh.GetNumberOfTriangles() || !mesh.IsUsable(t))
  {
    error = "the center's triangle " + std::to_string(t) + " is not a triangle of the surface";
    return false;
  }
  if (!(options.Scale > 0) || !std::isfinite(options.Scale))
  {
    error = "the scale must be positive";
    return false;
  }
  // The center triangle's frame: its first edge, then the normal times it.
  const Vec3 n = TriangleNormal(mesh, t);
  Vec3 e1 = mesh.GetCornerPosition(t, 1) - mesh.GetCornerPosition(t, 0);
  e1 = (1.0 / std::sqrt(Dot(e1, e1))) * e1;
  const Vec3 e2 = Cross(n, e1);
  const double angle = options.Rotation * std::acos(-1.0) / 180.0;
  const double c = std::cos(angle), s = std::sin(angle);
  const double cx = 0.5 * (drawing.Min[0] + drawing.Max[0]);
  const double cy = 0.5 * (drawing.Min[1] + drawing.Max[1]);
  // Each control point's walk from the center depends on that point alone: the directions are
  // listed in drawing order, walked in parallel (each into its own slot: the same points on any
  // number of threads), then gathered into the curves in that order.
  struct Walk
  {
    Vec3 Direction;
    double Length = 0; ///< 0: the center itself, no walk
    StraightestWalk Result;
  };
  std::vector<Walk> walks;
  for (const SvgPath& path : drawing.Paths)
  {
    for (const SvgSubpath& sub : path.Subpaths)
    {
      for (const Vec2& p : sub.Points)
      {
        const double x = (p.x - cx) * options.Scale, y = -(p.y - cy) * options.Scale;
        const double qx = c * x - s * y, qy = s * x + c * y;
        walks.push_back({ qx * e1 + qy * e2, std::sqrt(qx * qx + qy * qy), {} });
      }
    }
  }
  ParallelRange(
    options.Threads,
    walks.size() >= ParallelWalks,
    static_cast<int>(walks.size()),
    [&](int i)
    {
      Walk& w = walks[i];
      if (w.Length != 0)
      {
        w.Result = WalkStraightest(mesh, options.Center, w.Direction, w.Length);
      }
    },
    WalkGrain);
  int boundaryHits = 0;
  std::size_t next = 0;
  for (const SvgPath& path : drawing.Paths)
  {
    // Upright drawing coordinates (SVG's y grows downwards): orientation from their areas.
    double area = 0;
    for (const SvgSubpath& sub : path.Subpaths)
    {
      std::vector<Vec2> upright;
      for (const Vec2& p : sub.Points)
      {
        upright.push_back({ p.x, -p.y });
      }
      area += sub.Closed ? SignedArea2(upright) : 0.0;
    }
    for (const SvgSubpath& sub : path.Subpaths)
    {
      MappedSvgCurve curve;
      curve.Type = CurveType::CubicBezier;
      curve.Closed = sub.Closed;
      curve.ShapeId = path.Element;
      curve.EvenOdd = path.EvenOdd;
      for (std::size_t k = 0; k < sub.Points.size(); ++k, ++next)
      {
        const Walk& w = walks[next];
        if (w.Length == 0)
        {
          curve.Points.push_back(options.Center);
          continue;
        }
        boundaryHits += w.Result.HitBoundary ? 1 : 0;
        curve.Points.push_back(w.Result.End);
      }
      if (area < 0)
      {
        Reverse(curve.Points, curve.Closed);
      }
      out.push_back(std::move(curve));
    }
  }
  if (boundaryHits > 0)
  {
    warnings.push_back(std::to_string(boundaryHits) +
      " control point(s) lie beyond an open boundary of the surface: they were stopped at it");
  }
  return true;
}

} // namespace boolsurf

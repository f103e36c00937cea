#include "Geodesic/StraightestGeodesic.h"

#include <algorithm>
#include <cmath>

namespace boolsurf
{
namespace
{

Vec3 Normalized(Vec3 v)
{
  const double n = std::sqrt(Dot(v, v));
  return n > 0 ? (1.0 / n) * v : v;
}

} // namespace

//------------------------------------------------------------------------------
Vec3 TriangleNormal(const TriangleMesh& mesh, int t)
{
  const Vec3 a = mesh.GetCornerPosition(t, 0);
  return Normalized(Cross(mesh.GetCornerPosition(t, 1) - a, mesh.GetCornerPosition(t, 2) - a));
}

//------------------------------------------------------------------------------
StraightestWalk WalkStraightest(const TriangleMesh& mesh,
  const SurfacePoint& start,
  Vec3 direction,
  double length)
{
  StraightestWalk walk;
  int t = start.Triangle;
  Vec3 n = TriangleNormal(mesh, t);
  Vec3 x = mesh.Evaluate(t, start.U, start.V);
  Vec3 d = Normalized(direction - Dot(direction, n) * n);
  double remaining = length;
  // Each step crosses one triangle; the bound only guards against a walk that cannot end.
  for (long long step = 0; remaining > 0 && step < 4LL * mesh.GetNumberOfTriangles() + 16; ++step)
  {
    int exitEdge = -1;
    double exitS = 0, exitW = 0;
    for (int k = 0; k < 3; ++k)
    {
      const Vec3 p = mesh.GetCornerPosition(t, k);
      const Vec3 e = mesh.GetCornerPosition(t, (k + 1) % 3) - p;
      const double denominator = Dot(Cross(d, e), n);
      if (denominator <= 0)
      {
        continue; // moving along or away from this edge's line: not where the walk leaves
      }
      const double s = Dot(Cross(p - x, e), n) / denominator;
      const double w = Dot(Cross(p - x, d), n) / denominator;
      if (s >= 0 && (exitEdge < 0 || s < exitS))
      {
        exitEdge = k;
        exitS = s;
        exitW = w;
      }
    }
    if (exitEdge < 0 || exitS >= remaining)
    {
      x = x + remaining * d;
      walk.Length += remaining;
      remaining = 0;
      break;
    }
    const Vec3 p = mesh.GetCornerPosition(t, exitEdge);
    const Vec3 e = mesh.GetCornerPosition(t, (exitEdge + 1) % 3) - p;
    x = p + std::min(std::max(exitW, 1e-9), 1 - 1e-9) * e;
    walk.Length += exitS;
    remaining -= exitS;
    const int next = mesh.GetNeighbor(t, exitEdge);
    if (next < 0 || !mesh.IsUsable(next))
    {
      walk.HitBoundary = true;
      break;
    }
    // Unfold: keep the component along the edge, carry the one across it into the next plane.
    const Vec3 along = Normalized(e);
    const Vec3 nextNormal = TriangleNormal(mesh, next);
    const Vec3 inward = Normalized(Cross(n, along));              // into t, across the edge
    const Vec3 inwardNext = Normalized(Cross(along, nextNormal)); // into next
    d = Normalized(Dot(d, along) * along + (-Dot(d, inward)) * inwardNext);
    t = next;
    n = nextNormal;
  }
  walk.End = PointInTriangle(mesh, t, x);
  return walk;
}

} // namespace boolsurf

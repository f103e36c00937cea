#include "Arrangement/SegmentIntersection.h"

#include "Arrangement/Predicates.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace boolsurf
{
namespace
{

bool StrictlyInsideUnitTriangle(Vec2 p)
{
  return p.x > 0.0 && p.y > 0.0 && SumMinusOneSign(p.x, p.y) < 0;
}

// A computed crossing may round onto or just outside the triangle's boundary when it is within
// an ulp of it; pull it toward the centroid until it is strictly inside.
Vec2 ClampInside(Vec2 p)
{
  const Vec2 c{ 1.0 / 3.0, 1.0 / 3.0 };
  double eps = 1e-15;
  while (!StrictlyInsideUnitTriangle(p) && eps < 1.0)
  {
    p = c + (1.0 - eps) * (p - c);
    eps *= 4.0;
  }
  return p;
}

// In unit-triangle coordinates: far above rounding noise (~1e-16), far below any curve
// feature a user can draw.
const double CrossingMergeDistance = 1e-13;

struct Hit
{
  double Parameter;
  int Point;
};

/// Scratch of IntersectTriangleSegments, per thread.
struct Scratch
{
  std::vector<int> EndA, EndB, Order;
  std::vector<std::vector<Hit>> Hits;
  std::map<std::pair<double, double>, int> InteriorIds;
};

/// Empties `a` for the next triangle of its slot, keeping its buffers' capacity (the slot's
/// LocalArrangement lives on in the arrangement's work buffers from edit to edit).
void ClearForReuse(LocalArrangement& a)
{
  a.Triangle = -1;
  a.Points.clear();
  a.Boundary.clear();
  for (std::vector<int>& chain : a.Chains)
  {
    chain.clear();
  }
  a.ChainClosed.clear();
  a.Triangles.clear();
  a.Blocked.clear();
  a.Alias.clear();
  a.NumberOfNewPoints = 0;
  a.Error.clear();
}

} // namespace

//------------------------------------------------------------------------------
int BoundaryPointId(const TriangleMesh& mesh,
  const TriangleSegmentMap& map,
  const CanonicalPoint& p)
{
  if (p.Location == PointLocation::Vertex)
  {
    return p.Id;
  }
  if (p.Location != PointLocation::Edge)
  {
    return -1;
  }
  const std::pair<int, int> range = map.FindEdgePoints(p.Id);
  auto first = map.EdgePoints.begin() + range.first;
  auto last = map.EdgePoints.begin() + range.second;
  auto at =
    std::lower_bound(first, last, p.T, [](const EdgePoint& e, double t) { return e.T < t; });
  if (at == last || at->T != p.T)
  {
    return -1;
  }
  return mesh.GetNumberOfVertices() + static_cast<int>(at - map.EdgePoints.begin());
}

//------------------------------------------------------------------------------
void SplitEdgeSegment(const TriangleMesh& mesh,
  const TriangleSegmentMap& map,
  int index,
  std::vector<int>& globalIds)
{
  const EdgeSegment& s = map.EdgeSegments[index];
  globalIds.clear();
  globalIds.push_back(BoundaryPointId(mesh, map, s.A));
  const std::pair<int, int> range = map.FindEdgePoints(s.Edge);
  if (range.first != range.second)
  {
    const int nv = mesh.GetNumberOfVertices();
    const double lo = std::min(s.T0, s.T1), hi = std::max(s.T0, s.T1);
    const size_t before = globalIds.size();
    for (int i = range.first; i < range.second; ++i)
    {
      const double t = map.EdgePoints[i].T;
      if (lo < t && t < hi)
      {
        globalIds.push_back(nv + i);
      }
    }
    if (s.T1 < s.T0)
    {
      std::reverse(globalIds.begin() + before, globalIds.end());
    }
  }
  globalIds.push_back(BoundaryPointId(mesh, map, s.B));
}

//------------------------------------------------------------------------------
void IntersectTriangleSegments(const TriangleMesh& mesh,
  const TriangleSegmentMap& map,
  const std::vector<TracedCurve>& curves,
  int slot,
  LocalArrangement& out)
{
  const int t = map.Triangles[slot];
  const Triangle& tri = mesh.GetTriangle(t);
  const int nv = mesh.GetNumberOfVertices();
  ClearForReuse(out);
  out.Triangle = t;

  // Boundary points: corners, then each edge's points in the edge's order.
  const Vec2 corners[3] = { { 0.0, 0.0 }, { 1.0, 0.0 }, { 0.0, 1.0 } };
  for (int k = 0; k < 3; ++k)
  {
    out.Points.push_back({ corners[k], tri[k], 3 + k });
  }
  std::vector<int> edgePoints;
  for (int k = 0; k < 3; ++k)
  {
    out.Boundary.push_back(k);
    map.GetEdgePointsOnLocalEdge(mesh, t, k, edgePoints);
    const bool forward = mesh.GetEdgeVertices(mesh.GetEdgeId(t, k))[0] == tri[k];
    Vec2 previous = corners[k];
    for (int i : edgePoints)
    {
      const Vec2 p = EdgePointCoordinates(k, map.EdgePoints[i].T, forward);
      if (p.x == previous.x && p.y == previous.y)
      {
        out.Error = "triangle " + std::to_string(t) + ": two points of edge " +
          std::to_string(mesh.GetEdgeId(t, k)) + " are closer than the coordinate precision";
        return;
      }
      previous = p;
      out.Boundary.push_back(static_cast<int>(out.Points.size()));
      out.Points.push_back({ p, nv + i, k });
    }
  }

  // Local ids of the segments' endpoints: boundary points by refined id, face points by their
  // exact coordinates (two curves through the same face point share it).
  auto localOfBoundary = [&](int global) -> int
  {
    for (int b : out.Boundary)
    {
      if (out.Points[b].Global == global)
      {
        return b;
      }
    }
    return -1;
  };
  const int firstInterior = static_cast<int>(out.Points.size());
  const int first = map.SegmentOffset[slot];
  const int count = map.SegmentOffset[slot + 1] - first;
  // Per-call scratch, kept per thread: a few thousand crossed triangles per edit each
  // allocated these anew.
  thread_local Scratch scratch;
  // Curve points inside the triangle, found again by their exact coordinates: by scanning the
  // few of an ordinary triangle, through a map in a crowded one (thousands of curve points).
  const bool mapInterior = count > 64;
  std::map<std::pair<double, double>, int>& interiorIds = scratch.InteriorIds;
  interiorIds.clear();
  auto localOf = [&](const CanonicalPoint& p, Vec2 p2) -> int
  {
    if (p.Location != PointLocation::Face)
    {
      return localOfBoundary(BoundaryPointId(mesh, map, p));
    }
    const int next = static_cast<int>(out.Points.size());
    if (mapInterior)
    {
      const auto found = interiorIds.emplace(std::make_pair(p2.x, p2.y), next);
      if (!found.second)
      {
        return found.first->second;
      }
    }
    else
    {
      for (int i = firstInterior; i < next; ++i)
      {
        if (out.Points[i].P.x == p2.x && out.Points[i].P.y == p2.y)
        {
          return i;
        }
      }
    }
    out.Points.push_back({ p2, -1, -1 });
    return next;
  };

  std::vector<int>& endA = scratch.EndA;
  std::vector<int>& endB = scratch.EndB;
  endA.assign(count, 0);
  endB.assign(count, 0);
  std::vector<std::vector<Hit>>& hits = scratch.Hits;
  if (hits.size() < static_cast<std::size_t>(count))
  {
    hits.resize(count);
  }
  for (int i = 0; i < count; ++i)
  {
    hits[i].clear();
  }
  out.ChainClosed.resize(count);
  for (int i = 0; i < count; ++i)
  {
    const TriangleSegment& s = map.Segments[first + i];
    endA[i] = localOf(s.A, s.A2);
    endB[i] = localOf(s.B, s.B2);
    if (endA[i] < 0 || endB[i] < 0)
    {
      out.Error = "triangle " + std::to_string(t) + ": a segment endpoint of curve " +
        std::to_string(s.Curve) + " is missing from the edge point set";
      return;
    }
    out.ChainClosed[i] = curves[s.Curve].Closed ? 1 : 0;
  }

  // Sweep over x: only segments whose x-ranges overlap are tested.
  std::vector<int>& order = scratch.Order;
  order.resize(count);
  for (int i = 0; i < count; ++i)
  {
    order[i] = i;
  }
  auto xmin = [&](int i) { return std::min(out.Points[endA[i]].P.x, out.Points[endB[i]].P.x); };
  auto xmax = [&](int i) { return std::max(out.Points[endA[i]].P.x, out.Points[endB[i]].P.x); };
  std::sort(order.begin(),
    order.end(),
    [&](int i, int j) { return xmin(i) != xmin(j) ? xmin(i) < xmin(j) : i < j; });

  auto addHit = [&](int segment, int point)
  {
    const Vec2 a = out.Points[endA[segment]].P, b = out.Points[endB[segment]].P;
    hits[segment].push_back({ ParameterAlong(a, b, out.Points[point].P), point });
  };

  for (int oi = 0; oi < count; ++oi)
  {
    const int i = order[oi];
    const double reach = xmax(i);
    for (int oj = oi + 1; oj < count && xmin(order[oj]) <= reach; ++oj)
    {
      const int j = order[oj];
      const int a0 = endA[i], a1 = endB[i], b0 = endA[j], b1 = endB[j];
      const Vec2 p0 = out.Points[a0].P, p1 = out.Points[a1].P;
      const Vec2 q0 = out.Points[b0].P, q1 = out.Points[b1].P;
      const double o1 = Orient2d(p0, p1, q0), o2 = Orient2d(p0, p1, q1);
      if (o1 == 0.0 && o2 == 0.0)
      {
        // Collinear: each segment is cut at the other's endpoints that fall inside it.
        if (b0 != a0 && b0 != a1 && StrictlyBetween(p0, p1, q0))
          addHit(i, b0);
        if (b1 != a0 && b1 != a1 && StrictlyBetween(p0, p1, q1))
          addHit(i, b1);
        if (a0 != b0 && a0 != b1 && StrictlyBetween(q0, q1, p0))
          addHit(j, a0);
        if (a1 != b0 && a1 != b1 && StrictlyBetween(q0, q1, p1))
          addHit(j, a1);
        continue;
      }
      if (a0 == b0 || a0 == b1 || a1 == b0 || a1 == b1)
      {
        continue; // two non-collinear segments with a common endpoint meet only there
      }
      const double o3 = Orient2d(q0, q1, p0), o4 = Orient2d(q0, q1, p1);
      if ((o1 > 0.0 && o2 > 0.0) || (o1 < 0.0 && o2 < 0.0) || (o3 > 0.0 && o4 > 0.0) ||
        (o3 < 0.0 && o4 < 0.0))
      {
        continue; // disjoint
      }
      // T-junctions: an endpoint exactly on the other segment (its interior, since endpoints
      // are distinct and the segments are not collinear).
      if (o1 == 0.0)
      {
        addHit(i, b0);
      }
      else if (o2 == 0.0)
      {
        addHit(i, b1);
      }
      else if (o3 == 0.0)
      {
        addHit(j, a0);
      }
      else if (o4 == 0.0)
      {
        addHit(j, a1);
      }
      else
      {
        // Proper crossing: a new point, shared by both segments.
        const double beta = o1 / (o1 - o2);
        const Vec2 x = ClampInside(q0 + beta * (q1 - q0));
        // Three or more curves through one point: each pair's rounded crossing lands a few
        // ulps from the others, which would leave slivers of cells. Reuse an interior point
        // already on either segment when it is that close.
        int id = -1;
        for (const std::vector<Hit>* h : { &hits[i], &hits[j] })
        {
          for (const Hit& e : *h)
          {
            const Vec2 d = out.Points[e.Point].P - x;
            if (id < 0 && out.Points[e.Point].Where < 0 &&
              std::fabs(d.x) + std::fabs(d.y) < CrossingMergeDistance)
            {
              id = e.Point;
            }
          }
        }
        if (id < 0)
        {
          id = static_cast<int>(out.Points.size());
          out.Points.push_back({ x, -1, -1 });
        }
        addHit(i, id);
        addHit(j, id);
      }
    }
  }

  out.Chains.resize(count); // cleared by ClearForReuse, capacity kept
  for (int i = 0; i < count; ++i)
  {
    std::vector<Hit>& h = hits[i];
    std::sort(h.begin(),
      h.end(),
      [](const Hit& x, const Hit& y)
      { return x.Parameter != y.Parameter ? x.Parameter < y.Parameter : x.Point < y.Point; });
    std::vector<int>& chain = out.Chains[i];
    chain.push_back(endA[i]);
    for (const Hit& x : h)
    {
      if (x.Point != chain.back())
      {
        chain.push_back(x.Point);
      }
    }
    if (chain.back() != endB[i])
    {
      chain.push_back(endB[i]);
    }
  }
}

} // namespace boolsurf

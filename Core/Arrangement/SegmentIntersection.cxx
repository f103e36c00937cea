#include "Arrangement/SegmentIntersection.h"

#include "Arrangement/CrowdedCuts.h"
#include "Arrangement/Predicates.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <unordered_map>
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

/// Scratch of IntersectTriangleSegments, per thread.
struct Scratch
{
  std::map<std::pair<double, double>, int> InteriorIds;
};

/// Scratch of CutSegmentsAtIntersections, per thread.
struct CutScratch
{
  std::vector<int> EndA, EndB, Order, Parent;
  std::vector<char> Bent;
  std::vector<std::vector<int>> Hits;
};

/// Empties `a` for the next triangle of its slot, keeping its buffers' capacity (the slot's
/// LocalArrangement lives on in the arrangement's work buffers from edit to edit).
void ClearForReuse(LocalArrangement& a)
{
  a.Triangle = -1;
  a.Points.clear();
  a.Crossings.clear();
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

/// Stage 2's cuts in an ordinary triangle: every pair of segments whose x-ranges overlap
/// (a sweep over x), tested with exact orientations of their explicit end points.
void CutSegmentPairs(LocalArrangement& out,
  const std::vector<int>& endA,
  const std::vector<int>& endB,
  std::vector<std::vector<int>>& hits,
  std::vector<int>& order)
{
  const int count = static_cast<int>(endA.size());
  order.resize(count);
  for (int i = 0; i < count; ++i)
  {
    order[i] = i;
  }
  const auto xmin = [&](int i)
  { return std::min(out.Points[endA[i]].P.x, out.Points[endB[i]].P.x); };
  const auto xmax = [&](int i)
  { return std::max(out.Points[endA[i]].P.x, out.Points[endB[i]].P.x); };
  // A segment of no length is a point: it cuts the other segment where it lies strictly
  // inside it (every orientation with it is zero, so the collinear case below would not do).
  const auto pointCut = [&](int point, Vec2 q0, Vec2 q1, int b0, int b1, int other)
  {
    if (point != b0 && point != b1 && StrictlyInsideSegment(q0, q1, out.Points[point].P))
    {
      hits[other].push_back(point);
    }
  };
  ForEachXOverlappingPair(order,
    xmin,
    xmax,
    [&](int i, int j)
    {
      const int a0 = endA[i], a1 = endB[i], b0 = endA[j], b1 = endB[j];
      const Vec2 p0 = out.Points[a0].P, p1 = out.Points[a1].P;
      const Vec2 q0 = out.Points[b0].P, q1 = out.Points[b1].P;
      const bool iPoint = p0.x == p1.x && p0.y == p1.y, jPoint = q0.x == q1.x && q0.y == q1.y;
      if (iPoint || jPoint)
      {
        if (iPoint && !jPoint)
        {
          pointCut(a0, q0, q1, b0, b1, j);
        }
        else if (jPoint && !iPoint)
        {
          pointCut(b0, p0, p1, a0, a1, i);
        }
        return;
      }
      const double o1 = Orient2d(p0, p1, q0), o2 = Orient2d(p0, p1, q1);
      if (o1 == 0.0 && o2 == 0.0)
      {
        // Collinear: each segment is cut at the other's endpoints that fall inside it.
        if (b0 != a0 && b0 != a1 && StrictlyBetween(p0, p1, q0))
          hits[i].push_back(b0);
        if (b1 != a0 && b1 != a1 && StrictlyBetween(p0, p1, q1))
          hits[i].push_back(b1);
        if (a0 != b0 && a0 != b1 && StrictlyBetween(q0, q1, p0))
          hits[j].push_back(a0);
        if (a1 != b0 && a1 != b1 && StrictlyBetween(q0, q1, p1))
          hits[j].push_back(a1);
        return;
      }
      if (a0 == b0 || a0 == b1 || a1 == b0 || a1 == b1)
      {
        return; // two non-collinear segments with a common endpoint meet only there
      }
      const double o3 = Orient2d(q0, q1, p0), o4 = Orient2d(q0, q1, p1);
      if ((o1 > 0.0 && o2 > 0.0) || (o1 < 0.0 && o2 < 0.0) || (o3 > 0.0 && o4 > 0.0) ||
        (o3 < 0.0 && o4 < 0.0))
      {
        return; // disjoint
      }
      // T-junctions: an endpoint exactly on the other segment (its interior, since endpoints
      // are distinct and the segments are not collinear).
      if (o1 == 0.0)
      {
        hits[i].push_back(b0);
      }
      else if (o2 == 0.0)
      {
        hits[i].push_back(b1);
      }
      else if (o3 == 0.0)
      {
        hits[j].push_back(a0);
      }
      else if (o4 == 0.0)
      {
        hits[j].push_back(a1);
      }
      else
      {
        // Proper crossing: a new point of both segments, kept as the pair of them. Points at
        // the same place are merged below, once they are ordered along the segments.
        const int id = AddCrossingPoint(out, p0, p1, q0, q1);
        hits[i].push_back(id);
        hits[j].push_back(id);
      }
    });
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
  LocalArrangement& out,
  double mergeDistance)
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

  out.Chains.resize(count); // cleared by ClearForReuse, capacity kept
  out.ChainClosed.resize(count);
  for (int i = 0; i < count; ++i)
  {
    const TriangleSegment& s = map.Segments[first + i];
    const int a = localOf(s.A, s.A2), b = localOf(s.B, s.B2);
    if (a < 0 || b < 0)
    {
      out.Error = "triangle " + std::to_string(t) + ": a segment endpoint of curve " +
        std::to_string(s.Curve) + " is missing from the edge point set";
      return;
    }
    out.Chains[i].push_back(a);
    out.Chains[i].push_back(b);
    out.ChainClosed[i] = curves[s.Curve].Closed ? 1 : 0;
  }
  CutSegmentsAtIntersections(out, mergeDistance);
}

//------------------------------------------------------------------------------
int AddCrossingPoint(LocalArrangement& out, Vec2 p0, Vec2 p1, Vec2 q0, Vec2 q1)
{
  const SegmentCrossing crossing = MakeSegmentCrossing(p0, p1, q0, q1);
  const int id = static_cast<int>(out.Points.size());
  out.Points.push_back(
    { ClampInside(RoundedCrossing(crossing)), -1, -1, static_cast<int>(out.Crossings.size()) });
  out.Crossings.push_back(crossing);
  return id;
}

//------------------------------------------------------------------------------
void CutSegmentsAtIntersections(LocalArrangement& out, double mergeDistance)
{
  thread_local CutScratch scratch;
  const int count = static_cast<int>(out.Chains.size());
  std::vector<int>& endA = scratch.EndA;
  std::vector<int>& endB = scratch.EndB;
  endA.resize(count);
  endB.resize(count);
  for (int i = 0; i < count; ++i)
  {
    endA[i] = out.Chains[i].front();
    endB[i] = out.Chains[i].back();
  }
  std::vector<std::vector<int>>& hits = scratch.Hits;
  if (hits.size() < static_cast<std::size_t>(count))
  {
    hits.resize(count);
  }
  for (int i = 0; i < count; ++i)
  {
    hits[i].clear();
  }

  const int firstCrossing = static_cast<int>(out.Points.size());
  if (count > 64)
  {
    // A crowded triangle: cuts per pair of lines (CrowdedCuts.h).
    CutCrowdedSegments(out, endA, endB, hits);
  }
  else
  {
    CutSegmentPairs(out, endA, endB, hits, scratch.Order);
  }

  // Order each segment's points exactly along it; equal neighbours are one point (three or
  // more curves through a point, a crossing on another curve's point), and so are near
  // interior neighbours unless merging is off. The point kept is an explicit one when there
  // is one, else the first crossing made.
  const auto near = [&out, mergeDistance](int x, int y)
  {
    const LocalPoint &a = out.Points[x], &b = out.Points[y];
    return a.Where < 0 && b.Where < 0 && (a.Crossing >= 0 || b.Crossing >= 0) &&
      std::fabs(a.P.x - b.P.x) + std::fabs(a.P.y - b.P.y) < mergeDistance;
  };
  std::vector<int>& parent = scratch.Parent;
  parent.resize(out.Points.size());
  std::vector<char>& bent = scratch.Bent;
  bent.assign(out.Points.size(), 0);
  for (std::size_t p = 0; p < parent.size(); ++p)
  {
    parent[p] = static_cast<int>(p);
  }
  const auto find = [&parent](int x) { return FindRoot(parent, x); };
  auto kept = [&out](int x, int y)
  {
    const bool ex = out.Points[x].Crossing < 0, ey = out.Points[y].Crossing < 0;
    return ex != ey ? (ex ? x : y) : std::min(x, y);
  };
  for (int i = 0; i < count; ++i)
  {
    std::vector<int>& h = hits[i];
    if (h.empty())
    {
      continue;
    }
    const Vec2 a = out.Points[endA[i]].P, b = out.Points[endB[i]].P;
    const int axis = std::fabs(b.x - a.x) >= std::fabs(b.y - a.y) ? 0 : 1;
    const int direction = (axis == 0 ? b.x > a.x : b.y > a.y) ? 1 : -1;
    if (mergeDistance > 0.0)
    {
      // Merging: by the coordinates along the axis (exact for explicit points, rounded for
      // crossings), which spares the exact comparison of equal crossings. Neighbours in the
      // wrong order are a rounding apart, so they are near and merged; a crossing rounded far
      // off (nearly parallel segments) can only make pieces cross, which stage 3 reports and
      // the exact second pass repairs.
      const auto key = [&](int x) { return axis == 0 ? out.Points[x].P.x : out.Points[x].P.y; };
      std::sort(h.begin(),
        h.end(),
        [&](int x, int y)
        {
          const double kx = direction * key(x), ky = direction * key(y);
          return kx != ky ? kx < ky : x < y;
        });
    }
    else
    {
      std::sort(h.begin(),
        h.end(),
        [&](int x, int y)
        {
          const int c = direction * ExactCompare(ExactPointOf(out, x), ExactPointOf(out, y), axis);
          return c != 0 ? c < 0 : x < y;
        });
    }
    // `isNear`: merged for being near, not equal, so the point kept stands for points it is
    // not exactly equal to.
    const auto unite = [&](int x, int y, bool isNear)
    {
      const int rx = find(x), ry = find(y);
      if (rx != ry)
      {
        const int keep = kept(rx, ry);
        parent[rx == keep ? ry : rx] = keep;
        bent[keep] = static_cast<char>(bent[keep] || bent[rx == keep ? ry : rx] || isNear);
      }
    };
    for (std::size_t k = 1; k < h.size(); ++k)
    {
      if (h[k] == h[k - 1])
      {
        continue;
      }
      if (near(h[k - 1], h[k]))
      {
        unite(h[k - 1], h[k], true);
      }
      else if (ExactCompare(ExactPointOf(out, h[k - 1]), ExactPointOf(out, h[k]), axis) == 0)
      {
        unite(h[k - 1], h[k], false);
      }
    }
    // A crossing a rounding away from the segment's own end (a curve point where several
    // curves meet, which this segment misses by a rounding) is that end. Never equal to it:
    // crossings are strictly inside their segments.
    if (near(endA[i], h.front()))
    {
      unite(endA[i], h.front(), true);
    }
    if (near(h.back(), endB[i]))
    {
      unite(h.back(), endB[i], true);
    }
  }

  // Crossings merged into another point are dropped; the others are renumbered in order. A
  // crossing kept for near points is only near them, so its exact definition no longer says
  // where the pieces through it run: it becomes an explicit point at its rounded position
  // (plain orientations from then on; near-degenerate ones, which these clusters are full
  // of, cost twenty times more on exact crossings).
  std::vector<int>& renumber = scratch.Order; // the sweep order is no longer needed
  const int total = static_cast<int>(out.Points.size());
  renumber.assign(total, -1);
  int next = firstCrossing, nextCrossing = 0;
  for (int p = 0; p < total; ++p)
  {
    if (p < firstCrossing)
    {
      renumber[p] = p;
    }
    else if (find(p) == p)
    {
      out.Points[next] = out.Points[p];
      if (bent[p])
      {
        out.Points[next].Crossing = -1;
      }
      else
      {
        out.Crossings[nextCrossing] = out.Crossings[out.Points[p].Crossing];
        out.Points[next].Crossing = nextCrossing++;
      }
      renumber[p] = next++;
    }
  }
  out.Points.resize(next);
  out.Crossings.resize(nextCrossing);

  for (int i = 0; i < count; ++i)
  {
    std::vector<int>& chain = out.Chains[i];
    chain.clear();
    chain.push_back(endA[i]);
    for (const int x : hits[i])
    {
      const int p = renumber[find(x)];
      if (p != chain.back())
      {
        chain.push_back(p);
      }
    }
    if (chain.back() != endB[i])
    {
      chain.push_back(endB[i]);
    }
  }
}

} // namespace boolsurf

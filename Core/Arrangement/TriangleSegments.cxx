#include "Arrangement/TriangleSegments.h"

#include "Arrangement/Predicates.h"
#include "Arrangement/SortedIds.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace boolsurf
{
namespace
{

std::string PointName(const TracedCurve& curve, int curveIndex, int point)
{
  std::ostringstream s;
  s << "curve " << curveIndex << " (CurveId " << curve.CurveId << ", ShapeId " << curve.ShapeId
    << ") point " << point;
  return s.str();
}

// Canonical form of the point at weights (w0, w1, w2) of triangle t, given the EXACT signs of
// the weights (a weight <= 0 counts as zero; the point is clamped into the triangle).
CanonicalPoint FromClampedWeights(const TriangleMesh& mesh, int t, double w[3], const bool zero[3])
{
  const Triangle& tri = mesh.GetTriangle(t);
  const int zeros = zero[0] + zero[1] + zero[2];
  CanonicalPoint c;
  if (zeros >= 2)
  {
    int k = 0;
    for (int i = 0; i < 3; ++i)
    {
      if (!zero[i] && (zero[k] || w[i] > w[k]))
      {
        k = i;
      }
    }
    c.Location = PointLocation::Vertex;
    c.Id = tri[k];
    return c;
  }
  // Weight k zero: the point is on local edge k+1, from corner k+1 to corner k+2.
  int k = zero[0] ? 0 : (zero[1] ? 1 : 2);
  const int local = (k + 1) % 3;
  const double wa = w[local], wb = w[(local + 1) % 3];
  const double s = wb / (wa + wb);
  if (!(s > 0.0) || !(s < 1.0))
  {
    c.Location = PointLocation::Vertex;
    c.Id = tri[s >= 1.0 ? (local + 1) % 3 : local];
    return c;
  }
  const int e = mesh.GetEdgeId(t, local);
  c.Location = PointLocation::Edge;
  c.Id = e;
  c.T = mesh.GetEdgeVertices(e)[0] == tri[local] ? s : 1.0 - s;
  return c;
}

// Checks a point and brings it to the strict canonical form every later stage assumes: face
// points strictly inside (exactly), edge points with T strictly inside (0, 1).
bool NormalizePoint(const TriangleMesh& mesh, CanonicalPoint& p, std::string& why)
{
  switch (p.Location)
  {
    case PointLocation::Face:
    {
      if (p.Id < 0 || p.Id >= mesh.GetNumberOfTriangles() || !mesh.IsUsable(p.Id))
      {
        why = "triangle id " + std::to_string(p.Id) + " out of range or unusable";
        return false;
      }
      if (!std::isfinite(p.U) || !std::isfinite(p.V))
      {
        why = "non-finite barycentric coordinates";
        return false;
      }
      const int above = SumMinusOneSign(p.U, p.V);
      if (p.U > 0.0 && p.V > 0.0 && above < 0)
      {
        return true;
      }
      double w[3] = { above < 0 ? 1.0 - p.U - p.V : 0.0, std::max(p.U, 0.0), std::max(p.V, 0.0) };
      const bool zero[3] = { above >= 0, p.U <= 0.0, p.V <= 0.0 };
      p = FromClampedWeights(mesh, p.Id, w, zero);
      return true;
    }
    case PointLocation::Edge:
    {
      if (p.Id < 0 || p.Id >= mesh.GetNumberOfEdges())
      {
        why = "edge id " + std::to_string(p.Id) + " out of range";
        return false;
      }
      if (!std::isfinite(p.T))
      {
        why = "non-finite edge parameter";
        return false;
      }
      if (p.T <= 0.0 || p.T >= 1.0)
      {
        const int v = mesh.GetEdgeVertices(p.Id)[p.T <= 0.0 ? 0 : 1];
        p = CanonicalPoint();
        p.Location = PointLocation::Vertex;
        p.Id = v;
      }
      return true;
    }
    case PointLocation::Vertex:
      if (p.Id < 0 || p.Id >= mesh.GetNumberOfVertices() || mesh.GetVertexCorners(p.Id).size() == 0)
      {
        why = "vertex id " + std::to_string(p.Id) + " out of range or in no triangle";
        return false;
      }
      return true;
  }
  why = "unknown location";
  return false;
}

// Edge id joining vertices a and b, or -1.
int EdgeBetween(const TriangleMesh& mesh, int a, int b)
{
  for (int c : mesh.GetVertexCorners(a))
  {
    const int t = c / 3, k = c % 3;
    const Triangle& tri = mesh.GetTriangle(t);
    if (tri[(k + 1) % 3] == b)
    {
      return mesh.GetEdgeId(t, k);
    }
    if (tri[(k + 2) % 3] == b)
    {
      return mesh.GetEdgeId(t, (k + 2) % 3);
    }
  }
  return -1;
}

// Parameter along edge e (canonical direction) of a point known to lie on it.
double ParameterOnEdge(const TriangleMesh& mesh, const CanonicalPoint& p, int e)
{
  if (p.Location == PointLocation::Edge)
  {
    return p.T;
  }
  return mesh.GetEdgeVertices(e)[0] == p.Id ? 0.0 : 1.0;
}

// The mesh edge containing both points, or -1.
int CommonEdge(const TriangleMesh& mesh, const CanonicalPoint& a, const CanonicalPoint& b)
{
  using L = PointLocation;
  if (a.Location == L::Edge && b.Location == L::Edge)
  {
    return a.Id == b.Id ? a.Id : -1;
  }
  if (a.Location == L::Edge && b.Location == L::Vertex)
  {
    const std::array<int, 2> ev = mesh.GetEdgeVertices(a.Id);
    return ev[0] == b.Id || ev[1] == b.Id ? a.Id : -1;
  }
  if (a.Location == L::Vertex && b.Location == L::Edge)
  {
    return CommonEdge(mesh, b, a);
  }
  if (a.Location == L::Vertex && b.Location == L::Vertex)
  {
    return EdgeBetween(mesh, a.Id, b.Id);
  }
  return -1;
}

bool TriangleContains(const TriangleMesh& mesh, int t, const CanonicalPoint& p)
{
  const Triangle& tri = mesh.GetTriangle(t);
  switch (p.Location)
  {
    case PointLocation::Face:
      return p.Id == t;
    case PointLocation::Vertex:
      return tri[0] == p.Id || tri[1] == p.Id || tri[2] == p.Id;
    case PointLocation::Edge:
      return mesh.GetEdgeId(t, 0) == p.Id || mesh.GetEdgeId(t, 1) == p.Id ||
        mesh.GetEdgeId(t, 2) == p.Id;
  }
  return false;
}

// Every triangle having edge e (two on a manifold interior edge).
void TrianglesOfEdge(const TriangleMesh& mesh, int e, std::vector<int>& out)
{
  const int h = mesh.GetEdgeHalfEdge(e);
  const int twin = mesh.GetTwin(h);
  if (twin >= 0)
  {
    out.push_back(h / 3);
    out.push_back(twin / 3);
    return;
  }
  // Boundary or non-manifold edge: every triangle at its first vertex that also has the second.
  const std::array<int, 2> ev = mesh.GetEdgeVertices(e);
  for (int c : mesh.GetVertexCorners(ev[0]))
  {
    const Triangle& tri = mesh.GetTriangle(c / 3);
    if (tri[(c % 3 + 1) % 3] == ev[1] || tri[(c % 3 + 2) % 3] == ev[1])
    {
      out.push_back(c / 3);
    }
  }
}

// Lowest-id triangle containing both points, or -1.
int CommonTriangle(const TriangleMesh& mesh, const CanonicalPoint& a, const CanonicalPoint& b)
{
  int best = -1;
  auto consider = [&](int t)
  {
    if (t >= 0 && (best < 0 || t < best) && TriangleContains(mesh, t, b))
    {
      best = t;
    }
  };
  switch (a.Location)
  {
    case PointLocation::Face:
      consider(a.Id);
      break;
    case PointLocation::Edge:
    {
      const int h = mesh.GetEdgeHalfEdge(a.Id);
      const int twin = mesh.GetTwin(h);
      consider(h / 3);
      if (twin >= 0)
      {
        consider(twin / 3);
      }
      else
      {
        thread_local std::vector<int> ts;
        ts.clear();
        TrianglesOfEdge(mesh, a.Id, ts);
        for (int t : ts)
        {
          consider(t);
        }
      }
      break;
    }
    case PointLocation::Vertex:
      for (int c : mesh.GetVertexCorners(a.Id))
      {
        consider(c / 3);
      }
      break;
  }
  return best;
}

} // namespace

//------------------------------------------------------------------------------
Vec2 EdgePointCoordinates(int k, double T, bool forward)
{
  // Weights of corners k and k+1.
  const double wk = forward ? 1.0 - T : T;
  const double wk1 = forward ? T : 1.0 - T;
  switch (k)
  {
    case 0:
      return { wk1, 0.0 };
    case 2:
      return { 0.0, wk };
    default:
    {
      // (w1, w2) with w1 + w2 == 1 exactly: keep the weight >= 1/2 and derive the other from
      // it (Sterbenz: 1 - x is exact for x in [1/2, 1]).
      if (wk >= 0.5)
      {
        return { wk, 1.0 - wk };
      }
      return { 1.0 - wk1, wk1 };
    }
  }
}

//------------------------------------------------------------------------------
Vec2 LocalCoordinates(const TriangleMesh& mesh, const CanonicalPoint& p, int t)
{
  const Triangle& tri = mesh.GetTriangle(t);
  switch (p.Location)
  {
    case PointLocation::Face:
      return { p.U, p.V };
    case PointLocation::Vertex:
      if (tri[1] == p.Id)
      {
        return { 1.0, 0.0 };
      }
      if (tri[2] == p.Id)
      {
        return { 0.0, 1.0 };
      }
      return { 0.0, 0.0 };
    case PointLocation::Edge:
      for (int k = 0; k < 3; ++k)
      {
        if (mesh.GetEdgeId(t, k) == p.Id)
        {
          const bool forward = mesh.GetEdgeVertices(p.Id)[0] == tri[k];
          return EdgePointCoordinates(k, p.T, forward);
        }
      }
      break;
  }
  return { 0.0, 0.0 };
}

//------------------------------------------------------------------------------
void TriangleSegmentMap::GetEdgePointsOnLocalEdge(const TriangleMesh& mesh,
  int t,
  int k,
  std::vector<int>& out) const
{
  out.clear();
  const int e = mesh.GetEdgeId(t, k);
  const std::pair<int, int> range = this->FindEdgePoints(e);
  if (range.first == range.second)
  {
    return;
  }
  const bool forward = mesh.GetEdgeVertices(e)[0] == mesh.GetTriangle(t)[k];
  for (int i = range.first; i < range.second; ++i)
  {
    out.push_back(i);
  }
  if (!forward)
  {
    std::reverse(out.begin(), out.end());
  }
}

//------------------------------------------------------------------------------
std::pair<int, int> TriangleSegmentMap::FindEdgePoints(int e) const
{
  const auto at = std::lower_bound(this->PointEdges.begin(), this->PointEdges.end(), e);
  if (at == this->PointEdges.end() || *at != e)
  {
    return { 0, 0 };
  }
  const std::size_t i = static_cast<std::size_t>(at - this->PointEdges.begin());
  return { this->PointEdgeStart[i], this->PointEdgeStart[i + 1] };
}

//------------------------------------------------------------------------------
int TriangleSegmentMap::FindSlot(int t) const
{
  const auto at = std::lower_bound(this->Triangles.begin(), this->Triangles.end(), t);
  return at != this->Triangles.end() && *at == t ? static_cast<int>(at - this->Triangles.begin())
                                                 : -1;
}

namespace
{

// Steps 1 and 3 run per curve in parallel (each curve's lookups are cache misses in the mesh:
// about 0.3 us a segment) into per-curve lists, joined in curve order, so the result does not
// depend on scheduling. A refusal names the first failing curve, as a sequential pass would.
template <class Body>
void ParallelOverCurves(int numberOfCurves, const Body& body)
{
  tbb::parallel_for(0, numberOfCurves, [&](int ci) { body(ci); });
}

class CurveRefusals
{
public:
  explicit CurveRefusals(std::size_t curves)
    : Refusals(curves)
  {
  }
  struct Refusal
  {
    std::string Error;
    int Point = -1;
  };
  /// body(curve index, that curve's refusal), curves in parallel.
  template <class Body>
  void ForEachCurve(const Body& body)
  {
    ParallelOverCurves(
      static_cast<int>(this->Refusals.size()), [&](int ci) { body(ci, this->Refusals[ci]); });
  }
  /// The first curve's refusal into `error` and `failed`; false when no curve refused.
  bool RefuseFirst(std::string& error, CurvePointRef* failed) const
  {
    for (int ci = 0; ci < static_cast<int>(this->Refusals.size()); ++ci)
    {
      if (!this->Refusals[ci].Error.empty())
      {
        error = this->Refusals[ci].Error;
        if (failed)
        {
          *failed = CurvePointRef{ ci, this->Refusals[ci].Point };
        }
        return true;
      }
    }
    return false;
  }

private:
  std::vector<Refusal> Refusals;
};
using Refusal = CurveRefusals::Refusal;

struct RawEdgePoint
{
  int Edge;
  double T;
  int Curve, Index;
};

struct Pending
{
  int Triangle;
  TriangleSegment Segment;
};

//------------------------------------------------------------------------------
// Cleared, not reallocated: an edit needs about as much as the last one.
void ClearMap(std::size_t numberOfCurves, TriangleSegmentMap& map)
{
  map.Triangles.clear();
  map.SegmentOffset.clear();
  map.Segments.clear();
  map.EdgeSegments.clear();
  map.EdgePoints.clear();
  map.PointEdges.clear();
  map.PointEdgeStart.clear();
  for (std::vector<SegmentLocation>& segments : map.CurveSegments)
  {
    segments.clear();
  }
  map.CurveSegments.resize(numberOfCurves);
}

//------------------------------------------------------------------------------
// 1. Every point in canonical form (`normalized`); the points on edges collected, with where
// they came from (`raw`, in curve order).
void NormalizeCurvePoints(const TriangleMesh& mesh,
  const std::vector<TracedCurve>& curves,
  CurveRefusals& refusals,
  std::vector<std::vector<CanonicalPoint>>& normalized,
  std::vector<RawEdgePoint>& raw)
{
  std::vector<std::vector<RawEdgePoint>> rawOfCurve(curves.size());
  refusals.ForEachCurve(
    [&](int ci, Refusal& refusal)
    {
      const TracedCurve& curve = curves[ci];
      if (curve.ShapeId < 0)
      {
        refusal.Error = "curve " + std::to_string(ci) + " has a negative ShapeId";
        return;
      }
      const int n = static_cast<int>(curve.Points.size());
      if (n < 2)
      {
        refusal.Error = PointName(curve, ci, 0) + ": a curve needs at least two points";
        return;
      }
      std::vector<CanonicalPoint>& points = normalized[ci];
      points = curve.Points;
      for (int i = 0; i < n; ++i)
      {
        std::string why;
        if (!NormalizePoint(mesh, points[i], why))
        {
          refusal.Error = PointName(curve, ci, i) + ": " + why;
          refusal.Point = i;
          return;
        }
        if (points[i].Location == PointLocation::Edge)
        {
          rawOfCurve[ci].push_back({ points[i].Id, points[i].T, ci, i });
        }
      }
    });
  for (const std::vector<RawEdgePoint>& r : rawOfCurve)
  {
    raw.insert(raw.end(), r.begin(), r.end());
  }
}

//------------------------------------------------------------------------------
// 2. Points of one edge closer than EdgePointMergeDistance (in edge parameter) are one point:
// the same crossing traced twice with different rounding (two curves sharing a leg, a curve
// and its reverse), or a curve point on another curve. Kept apart, they would be distinct
// points a few ulps apart, which the triangles on both sides of the edge cannot tell apart
// in their own coordinates. Decided once per edge, so both triangles agree.
void MergeEdgePoints(std::vector<RawEdgePoint>& raw,
  std::vector<std::vector<CanonicalPoint>>& normalized,
  TriangleSegmentMap& map)
{
  std::sort(raw.begin(),
    raw.end(),
    [](const RawEdgePoint& x, const RawEdgePoint& y)
    { return x.Edge != y.Edge ? x.Edge < y.Edge : x.T < y.T; });
  map.EdgePoints.reserve(raw.size());
  for (size_t i = 0; i < raw.size(); ++i)
  {
    const bool joins =
      i > 0 && raw[i].Edge == raw[i - 1].Edge && raw[i].T - raw[i - 1].T <= EdgePointMergeDistance;
    const double t = joins ? map.EdgePoints.back().T : raw[i].T;
    if (!joins)
    {
      map.EdgePoints.push_back({ raw[i].Edge, t });
    }
    normalized[raw[i].Curve][raw[i].Index].T = t;
  }
}

//------------------------------------------------------------------------------
// 3. Segments, by triangle or along an edge, per curve: SegmentLocation indices are first
// into the curve's own lists (offset when the lists are joined, JoinCurveSegments).
void SplitCurvesIntoSegments(const TriangleMesh& mesh,
  const std::vector<TracedCurve>& curves,
  const std::vector<std::vector<CanonicalPoint>>& normalized,
  CurveRefusals& refusals,
  TriangleSegmentMap& map,
  std::vector<std::vector<Pending>>& pendingOfCurve,
  std::vector<std::vector<EdgeSegment>>& edgeSegmentsOfCurve)
{
  refusals.ForEachCurve(
    [&](int ci, Refusal& refusal)
    {
      const TracedCurve& curve = curves[ci];
      const std::vector<CanonicalPoint>& points = normalized[ci];
      std::vector<SegmentLocation>& order = map.CurveSegments[ci];
      std::vector<Pending>& pending = pendingOfCurve[ci];
      std::vector<EdgeSegment>& edgeSegments = edgeSegmentsOfCurve[ci];
      const int n = static_cast<int>(points.size());
      const int segments = curve.Closed ? n : n - 1;
      for (int i = 0; i < segments; ++i)
      {
        const CanonicalPoint& a = points[i];
        const CanonicalPoint& b = points[(i + 1) % n];
        if (a == b)
        {
          continue; // zero-length segment: nothing to arrange
        }
        const int e = CommonEdge(mesh, a, b);
        if (e >= 0)
        {
          EdgeSegment s;
          s.Curve = ci;
          s.Segment = i;
          s.Edge = e;
          s.T0 = ParameterOnEdge(mesh, a, e);
          s.T1 = ParameterOnEdge(mesh, b, e);
          s.A = a;
          s.B = b;
          order.push_back({ true, static_cast<int>(edgeSegments.size()) });
          edgeSegments.push_back(s);
          continue;
        }
        const int t = CommonTriangle(mesh, a, b);
        if (t < 0)
        {
          refusal.Error = PointName(curve, ci, i) + " and point " + std::to_string((i + 1) % n) +
            " share no triangle";
          refusal.Point = i;
          return;
        }
        Pending p;
        p.Triangle = t;
        p.Segment.Curve = ci;
        p.Segment.Segment = i;
        p.Segment.A = a;
        p.Segment.B = b;
        p.Segment.A2 = LocalCoordinates(mesh, a, t);
        p.Segment.B2 = LocalCoordinates(mesh, b, t);
        order.push_back({ false, static_cast<int>(pending.size()) });
        pending.push_back(p);
      }
    });
}

//------------------------------------------------------------------------------
// The per-curve lists joined in curve order: edge segments appended to the map, and each
// curve's SegmentLocation indices offset. pendingBase[c]: index of curve c's first pending
// triangle segment; the last entry is their count.
void JoinCurveSegments(int numberOfCurves,
  const std::vector<std::vector<Pending>>& pendingOfCurve,
  const std::vector<std::vector<EdgeSegment>>& edgeSegmentsOfCurve,
  TriangleSegmentMap& map,
  std::vector<int>& pendingBase)
{
  pendingBase.assign(static_cast<std::size_t>(numberOfCurves) + 1, 0);
  for (int ci = 0; ci < numberOfCurves; ++ci)
  {
    pendingBase[ci + 1] = pendingBase[ci] + static_cast<int>(pendingOfCurve[ci].size());
    const int edgeBase = static_cast<int>(map.EdgeSegments.size());
    map.EdgeSegments.insert(
      map.EdgeSegments.end(), edgeSegmentsOfCurve[ci].begin(), edgeSegmentsOfCurve[ci].end());
    for (SegmentLocation& loc : map.CurveSegments[ci])
    {
      loc.Index += loc.AlongEdge ? edgeBase : pendingBase[ci];
    }
  }
}

//------------------------------------------------------------------------------
// Edge points are sorted and unique (step 2): each has one id for both triangles of its edge.
void IndexEdgePoints(TriangleSegmentMap& map)
{
  for (int i = 0; i < static_cast<int>(map.EdgePoints.size());)
  {
    int j = i;
    while (j < static_cast<int>(map.EdgePoints.size()) &&
      map.EdgePoints[j].Edge == map.EdgePoints[i].Edge)
    {
      ++j;
    }
    map.PointEdges.push_back(map.EdgePoints[i].Edge);
    map.PointEdgeStart.push_back(i);
    i = j;
  }
  map.PointEdgeStart.push_back(static_cast<int>(map.EdgePoints.size()));
}

//------------------------------------------------------------------------------
// Triangles to refine (map.Triangles): crossed ones, and both sides of every edge holding a
// point (looked up in parallel, like the segments).
void CollectTrianglesToRefine(const TriangleMesh& mesh,
  const std::vector<std::vector<Pending>>& pendingOfCurve,
  int pendingCount,
  TriangleSegmentMap& map)
{
  const int pointEdges = static_cast<int>(map.PointEdges.size());
  std::vector<std::vector<int>> sidesOfEdge(static_cast<std::size_t>(pointEdges));
  tbb::parallel_for(tbb::blocked_range<int>(0, pointEdges, 256),
    [&](const tbb::blocked_range<int>& range)
    {
      for (int i = range.begin(); i != range.end(); ++i)
      {
        TrianglesOfEdge(mesh, map.PointEdges[i], sidesOfEdge[i]);
      }
    });
  std::vector<int> touched;
  touched.reserve(static_cast<std::size_t>(pendingCount) + 2 * map.PointEdges.size());
  for (const std::vector<Pending>& pending : pendingOfCurve)
  {
    for (const Pending& p : pending)
    {
      touched.push_back(p.Triangle);
    }
  }
  for (const std::vector<int>& sides : sidesOfEdge)
  {
    touched.insert(touched.end(), sides.begin(), sides.end());
  }
  SortUniqueIds(touched);
  map.Triangles = touched;
}

//------------------------------------------------------------------------------
// Segments grouped by slot (stable: curve order inside a triangle), and the curves'
// SegmentLocation indices pointed at their places.
void GroupSegmentsBySlot(int numberOfCurves,
  const std::vector<std::vector<Pending>>& pendingOfCurve,
  const std::vector<int>& pendingBase,
  TriangleSegmentMap& map)
{
  const std::vector<int>& touched = map.Triangles;
  const int pendingCount = pendingBase[numberOfCurves];
  std::vector<std::vector<int>> slotOfPending(static_cast<std::size_t>(numberOfCurves));
  ParallelOverCurves(numberOfCurves,
    [&](int ci)
    {
      slotOfPending[ci].resize(pendingOfCurve[ci].size());
      for (size_t i = 0; i < pendingOfCurve[ci].size(); ++i)
      {
        slotOfPending[ci][i] = map.FindSlot(pendingOfCurve[ci][i].Triangle);
      }
    });
  map.SegmentOffset.assign(touched.size() + 1, 0);
  for (const std::vector<int>& slots : slotOfPending)
  {
    for (int slot : slots)
    {
      ++map.SegmentOffset[slot + 1];
    }
  }
  for (size_t s = 0; s < touched.size(); ++s)
  {
    map.SegmentOffset[s + 1] += map.SegmentOffset[s];
  }
  std::vector<int> fill(map.SegmentOffset.begin(), map.SegmentOffset.end() - 1);
  std::vector<int> sortedIndex(static_cast<std::size_t>(pendingCount));
  map.Segments.resize(static_cast<std::size_t>(pendingCount));
  for (int ci = 0; ci < numberOfCurves; ++ci)
  {
    for (size_t i = 0; i < pendingOfCurve[ci].size(); ++i)
    {
      const int at = fill[slotOfPending[ci][i]]++;
      sortedIndex[pendingBase[ci] + i] = at;
      map.Segments[at] = pendingOfCurve[ci][i].Segment;
    }
  }
  ParallelOverCurves(numberOfCurves,
    [&](int ci)
    {
      for (SegmentLocation& loc : map.CurveSegments[ci])
      {
        if (!loc.AlongEdge)
        {
          loc.Index = sortedIndex[loc.Index];
        }
      }
    });
}

} // namespace

//------------------------------------------------------------------------------
bool BuildTriangleSegmentMap(const TriangleMesh& mesh,
  const std::vector<TracedCurve>& curves,
  TriangleSegmentMap& map,
  std::string& error,
  CurvePointRef* failed)
{
  const int numberOfCurves = static_cast<int>(curves.size());
  ClearMap(curves.size(), map);
  CurveRefusals refusals(curves.size());
  std::vector<std::vector<CanonicalPoint>> normalized(curves.size());
  std::vector<RawEdgePoint> raw;
  NormalizeCurvePoints(mesh, curves, refusals, normalized, raw);
  if (refusals.RefuseFirst(error, failed))
  {
    return false;
  }
  MergeEdgePoints(raw, normalized, map);
  std::vector<std::vector<Pending>> pendingOfCurve(curves.size());
  std::vector<std::vector<EdgeSegment>> edgeSegmentsOfCurve(curves.size());
  SplitCurvesIntoSegments(
    mesh, curves, normalized, refusals, map, pendingOfCurve, edgeSegmentsOfCurve);
  if (refusals.RefuseFirst(error, failed))
  {
    return false;
  }
  std::vector<int> pendingBase;
  JoinCurveSegments(numberOfCurves, pendingOfCurve, edgeSegmentsOfCurve, map, pendingBase);
  IndexEdgePoints(map);
  CollectTrianglesToRefine(mesh, pendingOfCurve, pendingBase[numberOfCurves], map);
  GroupSegmentsBySlot(numberOfCurves, pendingOfCurve, pendingBase, map);
  return true;
}

} // namespace boolsurf

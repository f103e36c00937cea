#include "Geodesic/StripStraightening.h"

#include <algorithm>
#include <cmath>

namespace boolsurf
{
namespace
{
constexpr double Pi = 3.14159265358979323846;

// A crossing this close (in edge parameter) to an edge end is the vertex itself: the funnel
// decides collinear cases by the sign of rounded cross products, so a path running through a
// vertex may come out as a crossing at t = 1e-17. Reporting the vertex keeps paths along
// edges and through vertices exact for the arrangement.
constexpr double VertexSnap = 1e-12;

// Vertices whose outside angle is this much below pi get the strip rerouted around them;
// smaller deficits are rounding noise of a straight pass.
constexpr double AngleTolerance = 1e-11;

constexpr int StartId = -2;
constexpr int EndId = -3;

double AngleBetween(const Vec3& a, const Vec3& b)
{
  return std::atan2(Length(Cross(a, b)), Dot(a, b));
}
} // namespace

//------------------------------------------------------------------------------
bool StripStraightener::Straighten(const CanonicalPoint& start,
  const CanonicalPoint& end,
  std::vector<int>& strip,
  int maximumRounds,
  int& rounds)
{
  for (;;)
  {
    this->TrimStrip(start, end, strip);
    if (this->Recorder)
    {
      this->Recorder->insert(this->Recorder->end(), strip.begin(), strip.end());
    }
    if (!this->UnfoldStrip(start, end, strip))
    {
      return false;
    }
    this->RunFunnel();
    this->CollectPathPoints(start, end);
    ++rounds;
    if (rounds >= maximumRounds || !this->RerouteAroundVertices(strip))
    {
      return true;
    }
  }
}

//------------------------------------------------------------------------------
// The strip must begin at the last triangle holding the start and end at the first one after
// it holding the end: triangles beyond would make the start or end lie on a portal, which the
// funnel cannot handle, and a strip that comes back to an end point's fan is simply cut short.
void StripStraightener::TrimStrip(const CanonicalPoint& start,
  const CanonicalPoint& end,
  std::vector<int>& strip)
{
  const TriangleMesh& mesh = this->Mesh;
  const int n = static_cast<int>(strip.size());
  int first = 0;
  for (int i = 0; i < n; ++i)
  {
    if (TriangleContains(mesh, start, strip[i]))
    {
      first = i;
    }
  }
  int last = n - 1;
  for (int i = first; i < n; ++i)
  {
    if (TriangleContains(mesh, end, strip[i]))
    {
      last = i;
      break;
    }
  }
  strip.erase(strip.begin() + last + 1, strip.end());
  strip.erase(strip.begin(), strip.begin() + first);

  // A strip that comes back to a triangle it already crossed holds a loop (rerouting a
  // vertex next to earlier reroutes can sweep all the way round it). The path can always take
  // the short cut, so cut the loop out. Positions in a hash map of the strip's size: a
  // mesh-sized stamped array per solver touched pages all over the mesh (scattered triangle
  // ids), megabytes on a large mesh for a few hundred triangles per strip.
  EdgeIndex& position = this->StripPosition;
  position.Reset(strip.size());
  size_t kept = 0;
  for (size_t i = 0; i < strip.size(); ++i)
  {
    const int t = strip[i];
    const int seen = position.Find(static_cast<EdgeIndex::Key>(t));
    if (seen >= 0 && seen < static_cast<int>(kept) && strip[seen] == t)
    {
      kept = seen + 1;
      continue;
    }
    position.Set(static_cast<EdgeIndex::Key>(t), static_cast<int>(kept));
    strip[kept++] = t;
  }
  strip.resize(kept);
}

//------------------------------------------------------------------------------
// Each triangle is laid flat next to the previous one across their common edge. Positions of
// the shared vertices are copied, never recomputed, so a vertex has exactly one position per
// strip triangle and portal endpoints agree bit for bit with their triangles' corners.
bool StripStraightener::UnfoldStrip(const CanonicalPoint& start,
  const CanonicalPoint& end,
  const std::vector<int>& strip)
{
  const TriangleMesh& mesh = this->Mesh;
  const int n = static_cast<int>(strip.size());
  // Unfolded[i] and Portals[i - 1] depend on Strip[0..i] only: keep what the last unfolding
  // of this path computed for the common prefix (a straightening round changes the strip only
  // from its first reroute on), bit for bit the same as unfolding again.
  const int old = static_cast<int>(this->UnfoldedStrip.size());
  int common = 0;
  while (common < n && common < old && strip[common] == this->UnfoldedStrip[common])
  {
    ++common;
  }
  this->UnfoldedStrip.clear(); // valid again only if this unfolding succeeds
  this->Unfolded.resize(n);
  this->Portals.resize(n - 1);
  if (common == 0)
  {
    const int t = strip[0];
    const Vec3 p0 = mesh.GetCornerPosition(t, 0);
    const Vec3 e1 = mesh.GetCornerPosition(t, 1) - p0;
    const Vec3 e2 = mesh.GetCornerPosition(t, 2) - p0;
    const double l1 = Length(e1);
    this->Unfolded[0] = {
      Vec2{ 0.0, 0.0 }, Vec2{ l1, 0.0 }, Vec2{ Dot(e2, e1) / l1, Length(Cross(e1, e2)) / l1 }
    };
  }
  for (int i = std::max(common - 1, 0); i + 1 < n; ++i)
  {
    const int t = strip[i];
    const int next = strip[i + 1];
    int k = 0;
    while (k < 3 && mesh.GetNeighbor(t, k) != next)
    {
      ++k;
    }
    if (k == 3)
    {
      return false;
    }
    const Triangle& tri = mesh.GetTriangle(t);
    const int a = tri[k], b = tri[(k + 1) % 3];
    const Vec2 a2 = this->Unfolded[i][k], b2 = this->Unfolded[i][(k + 1) % 3];
    const Vec2 o2 = this->Unfolded[i][(k + 2) % 3];
    const bool oppositeOnLeft = Cross(b2 - a2, o2 - a2) > 0.0;

    // Third vertex from the 3D triangle: foot along a->b and height, on the side of the
    // shared edge away from the previous triangle.
    const Triangle& nextTri = mesh.GetTriangle(next);
    int c = 0;
    while (nextTri[c] == a || nextTri[c] == b)
    {
      ++c;
    }
    const Vec3 a3 = mesh.GetPosition(a);
    const Vec3 ab3 = mesh.GetPosition(b) - a3;
    const Vec3 ac3 = mesh.GetPosition(nextTri[c]) - a3;
    const double lab = Length(ab3);
    const double along = Dot(ac3, ab3) / lab;
    const double height = Length(Cross(ab3, ac3)) / lab;
    const Vec2 ab2 = b2 - a2;
    const double l2 = Length(ab2);
    const Vec2 dir = (1.0 / l2) * ab2;
    Vec2 normal{ -dir.y, dir.x };
    if (oppositeOnLeft)
    {
      normal = -1.0 * normal;
    }
    const Vec2 c2 = a2 + along * dir + height * normal;
    for (int j = 0; j < 3; ++j)
    {
      this->Unfolded[i + 1][j] = nextTri[j] == a ? a2 : (nextTri[j] == b ? b2 : c2);
    }

    // Walking away from the previous triangle's third vertex, the vertex on the left is b
    // when that vertex lies left of a->b.
    Portal& portal = this->Portals[i];
    portal.Edge = mesh.GetEdgeId(t, k);
    if (oppositeOnLeft)
    {
      portal.Left = b;
      portal.LeftPosition = b2;
      portal.Right = a;
      portal.RightPosition = a2;
    }
    else
    {
      portal.Left = a;
      portal.LeftPosition = a2;
      portal.Right = b;
      portal.RightPosition = b2;
    }
  }
  auto place = [&](const CanonicalPoint& p, int i)
  {
    const std::array<double, 3> w = WeightsInTriangle(mesh, p, strip[i]);
    const std::array<Vec2, 3>& u = this->Unfolded[i];
    return w[0] * u[0] + w[1] * u[1] + w[2] * u[2];
  };
  this->StartPosition = place(start, 0);
  this->EndPosition = place(end, n - 1);
  this->UnfoldedStrip = strip;
  return true;
}

//------------------------------------------------------------------------------
// Funnel algorithm (the "simple stupid" formulation by M. Mononen of Lee-Preparata): the apex
// and the two funnel sides advance portal by portal; when one side crosses the other, the
// crossed side's point becomes a path corner and the scan restarts from it. Funnel portal 0
// is the start, portals 1..n-1 are the strip portals, portal n is the end.
void StripStraightener::RunFunnel()
{
  const int count = static_cast<int>(this->Portals.size()) + 2;
  auto portalAt = [&](int i, Vec2& left, int& leftId, Vec2& right, int& rightId)
  {
    if (i == 0)
    {
      left = right = this->StartPosition;
      leftId = rightId = StartId;
    }
    else if (i == count - 1)
    {
      left = right = this->EndPosition;
      leftId = rightId = EndId;
    }
    else
    {
      const Portal& p = this->Portals[i - 1];
      left = p.LeftPosition;
      leftId = p.Left;
      right = p.RightPosition;
      rightId = p.Right;
    }
  };

  this->Corners.clear();
  Vec2 apex = this->StartPosition, left = apex, right = apex;
  int apexId = StartId, leftId = StartId, rightId = StartId;
  int apexIndex = 0, leftIndex = 0, rightIndex = 0;
  this->Corners.push_back({ apex, StartId, 0 });
  for (int i = 1; i < count; ++i)
  {
    Vec2 l, r;
    int lId, rId;
    portalAt(i, l, lId, r, rId);

    // A portal holding the apex vertex is crossed at the apex itself and constrains nothing;
    // skipping it walks the fan of triangles around a corner. After a restart both sides sit
    // on the apex and the first portal beyond the fan opens the funnel again. A side moving
    // onto the other side's point (the end, or a shared vertex) closes the funnel on that
    // point without crossing it.
    if (lId == apexId || rId == apexId)
    {
      continue;
    }
    if (Cross(right - apex, r - apex) >= 0.0)
    {
      if (rightId == apexId || rId == leftId || Cross(r - apex, left - apex) > 0.0)
      {
        right = r;
        rightId = rId;
        rightIndex = i;
      }
      else
      {
        apex = left;
        apexId = leftId;
        apexIndex = leftIndex;
        this->Corners.push_back({ apex, apexId, apexIndex });
        right = left = apex;
        rightId = leftId = apexId;
        rightIndex = leftIndex = apexIndex;
        i = apexIndex;
        continue;
      }
    }
    if (Cross(l - apex, left - apex) >= 0.0)
    {
      if (leftId == apexId || lId == rightId || Cross(right - apex, l - apex) > 0.0)
      {
        left = l;
        leftId = lId;
        leftIndex = i;
      }
      else
      {
        apex = right;
        apexId = rightId;
        apexIndex = rightIndex;
        this->Corners.push_back({ apex, apexId, apexIndex });
        right = left = apex;
        rightId = leftId = apexId;
        rightIndex = leftIndex = apexIndex;
        i = apexIndex;
        continue;
      }
    }
  }
  this->Corners.push_back({ this->EndPosition, EndId, count - 1 });
}

//------------------------------------------------------------------------------
void StripStraightener::EmitVertex(int vertex, int portal)
{
  PathPoint& back = this->Points.back();
  if (back.Point.Location == PointLocation::Vertex && back.Point.Id == vertex)
  {
    if (back.FirstPortal >= 0)
    {
      back.FirstPortal = std::min(back.FirstPortal, portal);
      back.LastPortal = std::max(back.LastPortal, portal);
    }
    return;
  }
  auto holds = [&](int i)
  { return this->Portals[i].Left == vertex || this->Portals[i].Right == vertex; };
  const int n = static_cast<int>(this->Portals.size());
  int first = portal, last = portal;
  while (first > 0 && holds(first - 1))
  {
    --first;
  }
  while (last + 1 < n && holds(last + 1))
  {
    ++last;
  }
  PathPoint p;
  p.Point.Location = PointLocation::Vertex;
  p.Point.Id = vertex;
  p.FirstPortal = first;
  p.LastPortal = last;
  this->Points.push_back(p);
}

//------------------------------------------------------------------------------
// Walks the strip portals in order: portals around a corner vertex are crossed at that vertex;
// any other portal is crossed where the straight segment between the surrounding corners
// meets it.
void StripStraightener::CollectPathPoints(const CanonicalPoint& start, const CanonicalPoint& end)
{
  const TriangleMesh& mesh = this->Mesh;
  const int m = static_cast<int>(this->Portals.size());
  const int nc = static_cast<int>(this->Corners.size());
  this->Points.clear();
  this->Points.push_back({ start, -1, -1 });

  // Portal ranges of the interior corners (the run of portals holding the corner vertex).
  thread_local std::vector<std::array<int, 2>> ranges;
  thread_local std::vector<char> emitted;
  ranges.assign(nc, { 0, -1 });
  emitted.assign(nc, 0);
  for (int c = 1; c + 1 < nc; ++c)
  {
    const int v = this->Corners[c].Vertex;
    int first = this->Corners[c].Portal - 1, last = first;
    auto holds = [&](int i) { return this->Portals[i].Left == v || this->Portals[i].Right == v; };
    while (first > 0 && holds(first - 1))
    {
      --first;
    }
    while (last + 1 < m && holds(last + 1))
    {
      ++last;
    }
    ranges[c] = { first, last };
  }

  int j = 0; // current segment: corner j -> corner j + 1
  for (int i = 0; i < m; ++i)
  {
    while (j + 1 < nc - 1 && i > ranges[j + 1][1])
    {
      if (!emitted[j + 1])
      {
        this->EmitVertex(this->Corners[j + 1].Vertex, ranges[j + 1][1]);
      }
      ++j;
    }
    if (j + 1 < nc - 1 && i >= ranges[j + 1][0])
    {
      this->EmitVertex(this->Corners[j + 1].Vertex, i);
      emitted[j + 1] = 1;
      continue;
    }
    const Portal& portal = this->Portals[i];
    const Vec2 a = this->Corners[j].Position;
    const Vec2 d = this->Corners[j + 1].Position - a;
    const Vec2 span = portal.RightPosition - portal.LeftPosition;
    const double denominator = Cross(span, d);
    double t = denominator != 0.0 ? Cross(a - portal.LeftPosition, d) / denominator : 0.0;
    if (!(t > VertexSnap)) // also catches NaN from a degenerate segment
    {
      this->EmitVertex(portal.Left, i);
    }
    else if (t >= 1.0 - VertexSnap)
    {
      this->EmitVertex(portal.Right, i);
    }
    else
    {
      PathPoint p;
      p.Point.Location = PointLocation::Edge;
      p.Point.Id = portal.Edge;
      p.Point.T = mesh.GetEdgeVertices(portal.Edge)[0] == portal.Left ? t : 1.0 - t;
      this->Points.push_back(p);
    }
  }
  for (int c = j + 1; c + 1 < nc; ++c)
  {
    if (!emitted[c])
    {
      this->EmitVertex(this->Corners[c].Vertex, ranges[c][1]);
    }
  }
  if (!(this->Points.back().Point == end))
  {
    this->Points.push_back({ end, -1, -1 });
  }
}

//------------------------------------------------------------------------------
double StripStraightener::OutsideAngle(int v,
  const Vec3& before,
  const Vec3& after,
  int first,
  int second,
  int last,
  std::vector<int>& swept) const
{
  const TriangleMesh& mesh = this->Mesh;
  swept.clear();
  const Vec3 center = mesh.GetPosition(v);
  const Vec3 in = before - center;
  const Vec3 out = after - center;
  const Triangle& firstTri = mesh.GetTriangle(first);
  const int kv = CornerOf(firstTri, v);
  if (kv < 0)
  {
    return -1.0;
  }
  // The two edges of `first` at v are local edges kv (v -> next) and kv + 2 (previous -> v);
  // leave through the one that does not lead back into the strip.
  int edge = mesh.GetNeighbor(first, kv) == second ? (kv + 2) % 3 : kv;
  int other = edge == kv ? firstTri[(kv + 1) % 3] : firstTri[(kv + 2) % 3];
  double angle = AngleBetween(in, mesh.GetPosition(other) - center);
  int current = first;
  const int limit = mesh.GetVertexCorners(v).size();
  for (int steps = 0; steps <= limit; ++steps)
  {
    const int next = mesh.GetNeighbor(current, edge);
    if (next < 0)
    {
      return -1.0; // boundary (or non-manifold edge): the outside is not surface
    }
    if (next == last)
    {
      return angle + AngleBetween(mesh.GetPosition(other) - center, out);
    }
    const int entry = mesh.GetNeighborEdge(current, edge);
    const Triangle& tri = mesh.GetTriangle(next);
    const int kn = CornerOf(tri, v);
    if (kn < 0)
    {
      return -1.0;
    }
    const int exit = entry == kn ? (kn + 2) % 3 : kn;
    const int nextOther = exit == kn ? tri[(kn + 1) % 3] : tri[(kn + 2) % 3];
    angle += AngleBetween(mesh.GetPosition(other) - center, mesh.GetPosition(nextOther) - center);
    swept.push_back(next);
    other = nextOther;
    current = next;
    edge = exit;
  }
  return -1.0;
}

//------------------------------------------------------------------------------
bool StripStraightener::RerouteAroundVertices(std::vector<int>& strip)
{
  const TriangleMesh& mesh = this->Mesh;
  this->NewStrip.clear();
  int copied = 0; // Strip[0, copied) is already in NewStrip
  bool changed = false;
  const int np = static_cast<int>(this->Points.size());
  for (int k = 1; k + 1 < np; ++k)
  {
    const PathPoint& p = this->Points[k];
    if (p.Point.Location != PointLocation::Vertex || p.FirstPortal < copied)
    {
      continue;
    }
    const int a = p.FirstPortal, b = p.LastPortal;
    const double angle = this->OutsideAngle(p.Point.Id,
      PositionOf(mesh, this->Points[k - 1].Point),
      PositionOf(mesh, this->Points[k + 1].Point),
      strip[a],
      strip[a + 1],
      strip[b + 1],
      this->Swept);
    if (angle < 0.0 || angle >= Pi - AngleTolerance)
    {
      continue;
    }
    this->NewStrip.insert(this->NewStrip.end(), strip.begin() + copied, strip.begin() + a + 1);
    this->NewStrip.insert(this->NewStrip.end(), this->Swept.begin(), this->Swept.end());
    copied = b + 1;
    changed = true;
  }
  if (!changed)
  {
    return false;
  }
  this->NewStrip.insert(this->NewStrip.end(), strip.begin() + copied, strip.end());
  // Two rerouted vertices joined by an edge both sweep across that edge, leaving a spur
  // x, y, x in the strip (a step into y and straight back). Spurs hold no path: drop them.
  strip.clear();
  for (int t : this->NewStrip)
  {
    const size_t n = strip.size();
    if (n >= 2 && strip[n - 2] == t)
    {
      strip.pop_back();
    }
    else if (n == 0 || strip[n - 1] != t)
    {
      strip.push_back(t);
    }
  }
  return true;
}

} // namespace boolsurf

#include "Support/SyntheticCurves.h"

#include "Arrangement/Predicates.h"

#include <algorithm>
#include <cmath>

namespace boolsurf
{
namespace
{

inline Vec2 Planar(const Vec3& p)
{
  return { p.x, p.y };
}

void PointTriangles(const TriangleMesh& mesh, const CanonicalPoint& c, std::vector<int>& out)
{
  out.clear();
  if (c.Location == PointLocation::Face)
  {
    out.push_back(c.Id);
  }
  else if (c.Location == PointLocation::Vertex)
  {
    for (int corner : mesh.GetVertexCorners(c.Id))
      out.push_back(corner / 3);
  }
  else
  {
    const int h = mesh.GetEdgeHalfEdge(c.Id);
    out.push_back(h / 3);
    if (mesh.GetTwin(h) >= 0)
      out.push_back(mesh.GetTwin(h) / 3);
  }
}

bool ShareTriangle(const TriangleMesh& mesh, const CanonicalPoint& a, const CanonicalPoint& b)
{
  thread_local std::vector<int> ta, tb;
  PointTriangles(mesh, a, ta);
  PointTriangles(mesh, b, tb);
  for (int x : ta)
    for (int y : tb)
      if (x == y)
        return true;
  return false;
}

} // namespace

// Edges and triangles bucketed by their bounding boxes on a uniform grid.
struct FlatPolygonTracer::Grid
{
  double X0 = 0, Y0 = 0, Cell = 1;
  int N = 1;
  std::vector<std::vector<int>> Edges, Triangles;

  int Clamp(double x, double x0) const
  {
    const int i = static_cast<int>(std::floor((x - x0) / this->Cell));
    return std::min(std::max(i, 0), this->N - 1);
  }
  template <class Visit>
  void ForBox(double xa, double ya, double xb, double yb, const Visit& visit) const
  {
    for (int j = this->Clamp(ya, this->Y0); j <= this->Clamp(yb, this->Y0); ++j)
      for (int i = this->Clamp(xa, this->X0); i <= this->Clamp(xb, this->X0); ++i)
        visit(j * this->N + i);
  }
};

//------------------------------------------------------------------------------
FlatPolygonTracer::FlatPolygonTracer(const TriangleMesh& mesh)
  : Mesh(mesh)
  , Buckets(new Grid)
{
  Grid& g = *this->Buckets;
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const Vec3& p : mesh.GetPositions())
  {
    x0 = std::min(x0, p.x);
    y0 = std::min(y0, p.y);
    x1 = std::max(x1, p.x);
    y1 = std::max(y1, p.y);
  }
  g.N = std::max(1, static_cast<int>(std::sqrt(mesh.GetNumberOfTriangles() / 8.0)));
  g.X0 = x0;
  g.Y0 = y0;
  g.Cell = std::max(x1 - x0, y1 - y0) / g.N * (1.0 + 1e-9) + 1e-300;
  g.Edges.resize(static_cast<size_t>(g.N) * g.N);
  g.Triangles.resize(static_cast<size_t>(g.N) * g.N);
  for (int e = 0; e < mesh.GetNumberOfEdges(); ++e)
  {
    const std::array<int, 2> v = mesh.GetEdgeVertices(e);
    const Vec3 &a = mesh.GetPosition(v[0]), &b = mesh.GetPosition(v[1]);
    g.ForBox(std::min(a.x, b.x),
      std::min(a.y, b.y),
      std::max(a.x, b.x),
      std::max(a.y, b.y),
      [&](int c) { g.Edges[c].push_back(e); });
  }
  for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    if (!mesh.IsUsable(t))
      continue;
    double xa = 1e300, ya = 1e300, xb = -1e300, yb = -1e300;
    for (int k = 0; k < 3; ++k)
    {
      const Vec3& p = mesh.GetCornerPosition(t, k);
      xa = std::min(xa, p.x);
      ya = std::min(ya, p.y);
      xb = std::max(xb, p.x);
      yb = std::max(yb, p.y);
    }
    g.ForBox(xa, ya, xb, yb, [&](int c) { g.Triangles[c].push_back(t); });
  }
}

FlatPolygonTracer::~FlatPolygonTracer() = default;

//------------------------------------------------------------------------------
bool FlatPolygonTracer::Locate(Vec2 p, CanonicalPoint& out) const
{
  const Grid& g = *this->Buckets;
  const std::vector<int>& candidates = g.Triangles[g.Clamp(p.y, g.Y0) * g.N + g.Clamp(p.x, g.X0)];
  for (int t : candidates)
  {
    const Vec2 c[3] = { Planar(this->Mesh.GetCornerPosition(t, 0)),
      Planar(this->Mesh.GetCornerPosition(t, 1)),
      Planar(this->Mesh.GetCornerPosition(t, 2)) };
    // w[k]: weight of corner k, from the exact-sign area opposite to it.
    double w[3];
    bool inside = true;
    for (int k = 0; k < 3; ++k)
    {
      w[k] = Orient2d(c[(k + 1) % 3], c[(k + 2) % 3], p);
      inside = inside && w[k] >= 0.0;
    }
    if (!inside)
      continue;
    const double sum = w[0] + w[1] + w[2];
    const Triangle& tri = this->Mesh.GetTriangle(t);
    const int zeros = (w[0] == 0.0) + (w[1] == 0.0) + (w[2] == 0.0);
    out = CanonicalPoint();
    if (zeros >= 2)
    {
      out.Location = PointLocation::Vertex;
      out.Id = tri[w[0] != 0.0 ? 0 : (w[1] != 0.0 ? 1 : 2)];
    }
    else if (zeros == 1)
    {
      const int k = w[0] == 0.0 ? 0 : (w[1] == 0.0 ? 1 : 2);
      const int local = (k + 1) % 3, next = (k + 2) % 3;
      const double s = w[next] / (w[local] + w[next]);
      const int e = this->Mesh.GetEdgeId(t, local);
      out.Location = PointLocation::Edge;
      out.Id = e;
      out.T = this->Mesh.GetEdgeVertices(e)[0] == tri[local] ? s : 1.0 - s;
    }
    else
    {
      out.Location = PointLocation::Face;
      out.Id = t;
      out.U = w[1] / sum;
      out.V = w[2] / sum;
    }
    return true;
  }
  return false;
}

//------------------------------------------------------------------------------
bool FlatPolygonTracer::Trace(const std::vector<Vec2>& polygon,
  bool closed,
  int shapeId,
  int curveId,
  TracedCurve& out) const
{
  out = TracedCurve();
  out.Closed = closed;
  out.ShapeId = shapeId;
  out.CurveId = curveId;
  const Grid& g = *this->Buckets;
  const int n = static_cast<int>(polygon.size());
  const int sides = closed ? n : n - 1;
  struct Hit
  {
    double S;
    CanonicalPoint P;
  };
  std::vector<Hit> hits;
  std::vector<int> edges;
  for (int i = 0; i < sides; ++i)
  {
    const Vec2 a = polygon[i], b = polygon[(i + 1) % n];
    CanonicalPoint pa;
    if (!this->Locate(a, pa))
      return false;
    hits.clear();
    // Candidate edges: buckets along the side (a small box around each step).
    edges.clear();
    const double length = std::sqrt(Dot(b - a, b - a));
    const int steps = 2 + static_cast<int>(2.0 * length / g.Cell);
    for (int k = 0; k <= steps; ++k)
    {
      const Vec2 p = a + (static_cast<double>(k) / steps) * (b - a);
      g.ForBox(p.x - g.Cell,
        p.y - g.Cell,
        p.x + g.Cell,
        p.y + g.Cell,
        [&](int c) { edges.insert(edges.end(), g.Edges[c].begin(), g.Edges[c].end()); });
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    const double dx = b.x - a.x, dy = b.y - a.y;
    auto along = [&](Vec2 q)
    { return std::fabs(dx) >= std::fabs(dy) ? (q.x - a.x) / dx : (q.y - a.y) / dy; };
    auto vertexHit = [&](int v)
    {
      const double s = along(Planar(this->Mesh.GetPosition(v)));
      if (s > 0.0 && s < 1.0)
      {
        CanonicalPoint c;
        c.Location = PointLocation::Vertex;
        c.Id = v;
        hits.push_back({ s, c });
      }
    };
    for (int e : edges)
    {
      const std::array<int, 2> v = this->Mesh.GetEdgeVertices(e);
      const Vec2 p0 = Planar(this->Mesh.GetPosition(v[0]));
      const Vec2 p1 = Planar(this->Mesh.GetPosition(v[1]));
      const double o0 = Orient2d(a, b, p0), o1 = Orient2d(a, b, p1);
      if (o0 == 0.0)
        vertexHit(v[0]);
      if (o1 == 0.0)
        vertexHit(v[1]);
      if ((o0 > 0.0 && o1 < 0.0) || (o0 < 0.0 && o1 > 0.0))
      {
        const double oa = Orient2d(p0, p1, a), ob = Orient2d(p0, p1, b);
        if ((oa > 0.0 && ob < 0.0) || (oa < 0.0 && ob > 0.0))
        {
          CanonicalPoint c;
          c.Location = PointLocation::Edge;
          c.Id = e;
          c.T = std::min(std::max(o0 / (o0 - o1), 0x1p-52), 1.0 - 0x1p-53);
          hits.push_back({ oa / (oa - ob), c });
        }
      }
    }
    std::sort(hits.begin(), hits.end(), [](const Hit& x, const Hit& y) { return x.S < y.S; });
    if (out.Points.empty() || !(out.Points.back() == pa))
      out.Points.push_back(pa);
    // Hits a few ulps apart (a side passing next to a vertex) may come out of the sort in
    // the wrong order; the right one is the next that shares a triangle with the last point.
    for (size_t k = 0; k < hits.size(); ++k)
    {
      for (size_t m = k; m < hits.size() && m < k + 16; ++m)
      {
        if (ShareTriangle(this->Mesh, out.Points.back(), hits[m].P))
        {
          std::swap(hits[k], hits[m]);
          break;
        }
      }
      if (!(out.Points.back() == hits[k].P))
        out.Points.push_back(hits[k].P);
    }
    if (!closed && i == sides - 1)
    {
      CanonicalPoint pb;
      if (!this->Locate(b, pb))
        return false;
      if (!(out.Points.back() == pb))
        out.Points.push_back(pb);
    }
  }
  if (closed && out.Points.size() > 1 && out.Points.front() == out.Points.back())
    out.Points.pop_back();
  return true;
}

//------------------------------------------------------------------------------
std::vector<TracedCurve> PlaneSectionCurves(const TriangleMesh& mesh,
  Vec3 normal,
  double offset,
  int shapeId,
  int firstCurveId)
{
  const int nv = mesh.GetNumberOfVertices();
  std::vector<double> f(nv);
  for (int v = 0; v < nv; ++v)
    f[v] = Dot(normal, mesh.GetPosition(v)) - offset;
  auto positive = [&](int v) { return f[v] >= 0.0; };
  auto crossed = [&](int e)
  {
    const std::array<int, 2> v = mesh.GetEdgeVertices(e);
    return positive(v[0]) != positive(v[1]);
  };
  auto pointOn = [&](int e)
  {
    const std::array<int, 2> v = mesh.GetEdgeVertices(e);
    CanonicalPoint c;
    c.Location = PointLocation::Edge;
    c.Id = e;
    c.T = std::min(std::max(f[v[0]] / (f[v[0]] - f[v[1]]), 0x1p-52), 1.0 - 0x1p-53);
    return c;
  };
  std::vector<char> visited(mesh.GetNumberOfEdges(), 0);
  // From edge e into triangle t, follow the section until it closes or leaves the mesh.
  auto walk = [&](int e0, int t, std::vector<int>& chain) -> bool
  {
    int e = e0;
    while (t >= 0)
    {
      int next = -1, local = -1;
      for (int k = 0; k < 3; ++k)
      {
        const int ek = mesh.GetEdgeId(t, k);
        if (ek != e && crossed(ek))
        {
          next = ek;
          local = k;
        }
      }
      if (next < 0 || next == e0)
        return next == e0;
      visited[next] = 1;
      chain.push_back(next);
      e = next;
      t = mesh.GetNeighbor(t, local);
    }
    return false;
  };
  std::vector<TracedCurve> curves;
  for (int e0 = 0; e0 < mesh.GetNumberOfEdges(); ++e0)
  {
    if (visited[e0] || !crossed(e0))
      continue;
    visited[e0] = 1;
    const int h = mesh.GetEdgeHalfEdge(e0);
    std::vector<int> forward, backward;
    const bool closed = walk(e0, h / 3, forward);
    if (!closed)
      walk(e0, mesh.GetNeighbor(h / 3, h % 3), backward);
    TracedCurve curve;
    curve.Closed = closed;
    curve.ShapeId = shapeId;
    curve.CurveId = firstCurveId + static_cast<int>(curves.size());
    for (auto it = backward.rbegin(); it != backward.rend(); ++it)
      curve.Points.push_back(pointOn(*it));
    curve.Points.push_back(pointOn(e0));
    for (int e : forward)
      curve.Points.push_back(pointOn(e));
    curves.push_back(std::move(curve));
  }
  return curves;
}

} // namespace boolsurf

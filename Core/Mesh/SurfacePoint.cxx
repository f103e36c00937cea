#include "Mesh/SurfacePoint.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace boolsurf
{

//------------------------------------------------------------------------------
SurfacePoint PointInTriangle(const TriangleMesh& mesh, int t, const Vec3& x)
{
  SurfacePoint p{ t, 0.0, 0.0 };
  BarycentricInTriangle(mesh.GetCornerPosition(t, 0),
    mesh.GetCornerPosition(t, 1),
    mesh.GetCornerPosition(t, 2),
    x,
    p.U,
    p.V);
  return p;
}

//------------------------------------------------------------------------------
void BarycentricInTriangle(const Vec3& a,
  const Vec3& b,
  const Vec3& c,
  const Vec3& x,
  double& u,
  double& v)
{
  const std::array<double, 3> w = TrianglePlaneWeights(a, b, c)(x);
  u = w[1];
  v = w[2];
  ClampBarycentric(u, v);
}

//------------------------------------------------------------------------------
CanonicalPoint Canonicalize(const TriangleMesh& mesh, SurfacePoint p, double snap)
{
  double w[3] = { 1.0 - p.U - p.V, p.U, p.V };
  // Corner 0's weight is implicit: a point on the opposite edge written as (u, 1 - u) gives
  // 1 - u - v a few ulps away from zero. Within that rounding it is zero, so the point lands
  // on the edge it was written from (u and v themselves are compared exactly).
  if (std::abs(w[0]) <= 4.0 * std::numeric_limits<double>::epsilon())
  {
    w[0] = 0.0;
  }
  const bool exactZero[3] = { w[0] == 0.0, w[1] == 0.0, w[2] == 0.0 };
  int zeros = 0;
  for (double& x : w)
  {
    if (x <= snap)
    {
      x = 0.0;
      ++zeros;
    }
  }
  CanonicalPoint c;
  const Triangle& tri = mesh.GetTriangle(p.Triangle);
  if (zeros >= 2)
  {
    // The largest weight marks the vertex (also when all three were clamped, which only a
    // point far outside the triangle produces).
    const int k = static_cast<int>(std::max_element(w, w + 3) - w);
    c.Location = PointLocation::Vertex;
    c.Id = tri[k];
    return c;
  }
  if (zeros == 1)
  {
    // The zero weight is opposite the edge: weight k zero -> edge (k+1) -> (k+2), local k+1.
    int k = 0;
    while (w[k] != 0.0)
    {
      ++k;
    }
    const int localEdge = (k + 1) % 3;
    const int a = tri[localEdge];
    const double wa = w[localEdge], wb = w[(localEdge + 1) % 3];
    const double s = wb / (wa + wb);
    const int e = mesh.GetEdgeId(p.Triangle, localEdge);
    c.Location = PointLocation::Edge;
    c.Id = e;
    const bool forward = mesh.GetEdgeVertices(e)[0] == a;
    c.T = forward ? s : 1.0 - s;
    // Written exactly on the edge with the second vertex's weight explicit (u or v): that
    // weight is the parameter, bit for bit, rather than a renormalized copy an ulp away.
    const int second = forward ? (localEdge + 1) % 3 : localEdge;
    if (exactZero[k] && second != 0)
    {
      c.T = w[second];
    }
    return c;
  }
  c.Location = PointLocation::Face;
  c.Id = p.Triangle;
  if (w[1] == p.U && w[2] == p.V)
  {
    // Nothing was clamped: keep the user's numbers bit for bit (a renormalization by a sum
    // that rounds to 1 - 1 ulp would move them).
    c.U = p.U;
    c.V = p.V;
    return c;
  }
  const double sum = w[0] + w[1] + w[2];
  c.U = w[1] / sum;
  c.V = w[2] / sum;
  return c;
}

//------------------------------------------------------------------------------
std::array<double, 3> WeightsInTriangle(const TriangleMesh& mesh, const CanonicalPoint& c, int t)
{
  std::array<double, 3> w{ 0.0, 0.0, 0.0 };
  const Triangle& tri = mesh.GetTriangle(t);
  switch (c.Location)
  {
    case PointLocation::Face:
      w = { 1.0 - c.U - c.V, c.U, c.V };
      break;
    case PointLocation::Vertex:
      for (int k = 0; k < 3; ++k)
      {
        w[k] = tri[k] == c.Id ? 1.0 : 0.0;
      }
      break;
    case PointLocation::Edge:
    {
      const std::array<int, 2> ev = mesh.GetEdgeVertices(c.Id);
      for (int k = 0; k < 3; ++k)
      {
        w[k] = tri[k] == ev[0] ? 1.0 - c.T : (tri[k] == ev[1] ? c.T : 0.0);
      }
      break;
    }
  }
  return w;
}

//------------------------------------------------------------------------------
int AnyTriangleOf(const TriangleMesh& mesh, const CanonicalPoint& c)
{
  switch (c.Location)
  {
    case PointLocation::Face:
      return c.Id;
    case PointLocation::Edge:
      return mesh.GetEdgeHalfEdge(c.Id) / 3;
    case PointLocation::Vertex:
    {
      IntRange corners = mesh.GetVertexCorners(c.Id);
      return corners.size() > 0 ? corners[0] / 3 : -1;
    }
  }
  return -1;
}

//------------------------------------------------------------------------------
Vec3 PositionOf(const TriangleMesh& mesh, const CanonicalPoint& c)
{
  switch (c.Location)
  {
    case PointLocation::Vertex:
      return mesh.GetPosition(c.Id);
    case PointLocation::Edge:
    {
      const std::array<int, 2> ev = mesh.GetEdgeVertices(c.Id);
      return (1.0 - c.T) * mesh.GetPosition(ev[0]) + c.T * mesh.GetPosition(ev[1]);
    }
    case PointLocation::Face:
    default:
      return mesh.Evaluate(c.Id, c.U, c.V);
  }
}

//------------------------------------------------------------------------------
bool TriangleContains(const TriangleMesh& mesh, const CanonicalPoint& c, int t)
{
  if (t < 0 || t >= mesh.GetNumberOfTriangles() || !mesh.IsUsable(t))
  {
    return false;
  }
  const Triangle& tri = mesh.GetTriangle(t);
  switch (c.Location)
  {
    case PointLocation::Face:
      return c.Id == t;
    case PointLocation::Vertex:
      return tri[0] == c.Id || tri[1] == c.Id || tri[2] == c.Id;
    case PointLocation::Edge:
      return mesh.GetEdgeId(t, 0) == c.Id || mesh.GetEdgeId(t, 1) == c.Id ||
        mesh.GetEdgeId(t, 2) == c.Id;
  }
  return false;
}

//------------------------------------------------------------------------------
namespace
{
// Calls visit(t) for every triangle that contains c, in TrianglesOf's order (a face's own
// triangle if usable; an edge's half-edge triangle, then its twin's; a vertex's fan), until
// visit returns true; whether it did. No list is built: tracing asks this for every point it
// writes.
template <class Visit>
bool VisitTrianglesOf(const TriangleMesh& mesh, const CanonicalPoint& c, Visit&& visit)
{
  switch (c.Location)
  {
    case PointLocation::Face:
      return c.Id >= 0 && c.Id < mesh.GetNumberOfTriangles() && mesh.IsUsable(c.Id) && visit(c.Id);
    case PointLocation::Edge:
    {
      if (c.Id < 0 || c.Id >= mesh.GetNumberOfEdges())
      {
        return false;
      }
      const int h = mesh.GetEdgeHalfEdge(c.Id);
      const int twin = mesh.GetTwin(h);
      return visit(h / 3) || (twin >= 0 && visit(twin / 3));
    }
    case PointLocation::Vertex:
      if (c.Id < 0 || c.Id >= mesh.GetNumberOfVertices())
      {
        return false;
      }
      for (int corner : mesh.GetVertexCorners(c.Id))
      {
        if (visit(corner / 3))
        {
          return true;
        }
      }
      return false;
  }
  return false;
}
} // namespace

void TrianglesOf(const TriangleMesh& mesh, const CanonicalPoint& c, std::vector<int>& out)
{
  out.clear();
  VisitTrianglesOf(mesh,
    c,
    [&out](int t)
    {
      out.push_back(t);
      return false;
    });
}

//------------------------------------------------------------------------------
int SharedTriangle(const TriangleMesh& mesh, const CanonicalPoint& a, const CanonicalPoint& b)
{
  int best = -1;
  VisitTrianglesOf(mesh,
    a,
    [&](int t)
    {
      if (TriangleContains(mesh, b, t) && (best < 0 || t < best))
      {
        best = t;
      }
      return false;
    });
  return best;
}

//------------------------------------------------------------------------------
SurfacePoint ToSurfacePoint(const TriangleMesh& mesh, const CanonicalPoint& c)
{
  SurfacePoint p;
  p.Triangle = AnyTriangleOf(mesh, c);
  if (p.Triangle >= 0)
  {
    const std::array<double, 3> w = WeightsInTriangle(mesh, c, p.Triangle);
    p.U = w[1];
    p.V = w[2];
  }
  return p;
}

//------------------------------------------------------------------------------
SurfacePoint SnapWeights(SurfacePoint p)
{
  double w[3] = { 1.0 - p.U - p.V, p.U, p.V };
  if (std::abs(w[0]) <= 4.0 * std::numeric_limits<double>::epsilon())
  {
    w[0] = 0.0;
  }
  bool zero[3];
  int zeros = 0;
  for (int k = 0; k < 3; ++k)
  {
    zero[k] = w[k] <= SurfacePointSnap;
    zeros += zero[k];
  }
  if (zeros >= 2)
  {
    const int k = static_cast<int>(std::max_element(w, w + 3) - w);
    p.U = k == 1 ? 1.0 : 0.0;
    p.V = k == 2 ? 1.0 : 0.0;
  }
  else if (zero[0])
  {
    const double s = p.U + p.V;
    p.U = p.U / s;
    p.V = 1.0 - p.U;
  }
  else if (zero[1])
  {
    p.U = 0.0;
  }
  else if (zero[2])
  {
    p.V = 0.0;
  }
  return p;
}

//------------------------------------------------------------------------------
namespace
{
SurfacePoint FormIn(const TriangleMesh& mesh, const CanonicalPoint& c, int t)
{
  const std::array<double, 3> w = WeightsInTriangle(mesh, c, t);
  return SurfacePoint{ t, w[1], w[2] };
}

// Whether edge point c written in triangle t (FormIn) reads back as c without reading it: when
// the edge's second vertex is corner 1 or 2 of t, the parameter T is written as u or v and
// Canonicalize takes it from there bit for bit, with the weight opposite the edge an exact 0
// (or, opposite corner 0, within the few ulps it reads as 0); the margin keeps both weights of
// the edge clear of the snap that would make the point a vertex. Tracing writes a few thousand
// such points per edit, and this saves reading each one back.
bool EdgeFormReadsBack(const TriangleMesh& mesh, const CanonicalPoint& c, int t)
{
  constexpr double margin = 2.0 * SurfacePointSnap;
  return c.T > margin && c.T < 1.0 - margin &&
    mesh.GetTriangle(t)[0] != mesh.GetEdgeVertices(c.Id)[1];
}
} // namespace

SurfacePoint WriteSurfacePoint(const TriangleMesh& mesh, const CanonicalPoint& c, int preferred)
{
  if (c.Location == PointLocation::Face)
  {
    return SurfacePoint{ c.Id, c.U, c.V };
  }
  const auto readsBack = [&](const SurfacePoint& sp)
  {
    return (c.Location == PointLocation::Edge && EdgeFormReadsBack(mesh, c, sp.Triangle)) ||
      LocateSurfacePoint(mesh, sp) == c;
  };
  if (preferred >= 0 && TriangleContains(mesh, c, preferred))
  {
    const SurfacePoint sp = FormIn(mesh, c, preferred);
    if (readsBack(sp))
    {
      return sp;
    }
  }
  SurfacePoint found;
  if (VisitTrianglesOf(mesh,
        c,
        [&](int t)
        {
          found = FormIn(mesh, c, t);
          return readsBack(found);
        }))
  {
    return found;
  }
  return ToSurfacePoint(mesh, c);
}

//------------------------------------------------------------------------------
bool CheckSurfacePoint(const TriangleMesh& mesh, const SurfacePoint& p, std::string& problem)
{
  const int nt = mesh.GetNumberOfTriangles();
  if (p.Triangle < 0 || p.Triangle >= nt)
  {
    problem = "triangle id " + std::to_string(p.Triangle) + " is out of range [0, " +
      std::to_string(nt) + ")";
    return false;
  }
  if (!mesh.IsUsable(p.Triangle))
  {
    problem =
      "triangle " + std::to_string(p.Triangle) + " has out-of-range or repeated vertex indices";
    return false;
  }
  if (!std::isfinite(p.U) || !std::isfinite(p.V))
  {
    problem = "barycentric coordinates (" + std::to_string(p.U) + ", " + std::to_string(p.V) +
      ") in triangle " + std::to_string(p.Triangle) + " are not finite";
    return false;
  }
  if (!IsInsideTriangle(p.U, p.V))
  {
    char text[128];
    std::snprintf(text, sizeof(text), "barycentric coordinates (%.17g, %.17g)", p.U, p.V);
    problem = std::string(text) + " lie outside triangle " + std::to_string(p.Triangle) +
      " (u, v >= 0 and u + v <= 1 are needed)";
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool CheckCanonicalPoint(const TriangleMesh& mesh, const CanonicalPoint& c, std::string& problem)
{
  switch (c.Location)
  {
    case PointLocation::Face:
      return CheckSurfacePoint(mesh, SurfacePoint{ c.Id, c.U, c.V }, problem);
    case PointLocation::Edge:
      if (c.Id < 0 || c.Id >= mesh.GetNumberOfEdges())
      {
        problem = "edge id " + std::to_string(c.Id) + " is out of range [0, " +
          std::to_string(mesh.GetNumberOfEdges()) + ")";
        return false;
      }
      if (!std::isfinite(c.T))
      {
        problem = "edge parameter of edge " + std::to_string(c.Id) + " is not finite";
        return false;
      }
      return true;
    case PointLocation::Vertex:
      if (c.Id < 0 || c.Id >= mesh.GetNumberOfVertices())
      {
        problem = "vertex id " + std::to_string(c.Id) + " is out of range [0, " +
          std::to_string(mesh.GetNumberOfVertices()) + ")";
        return false;
      }
      if (mesh.GetVertexCorners(c.Id).size() == 0)
      {
        problem = "vertex " + std::to_string(c.Id) + " belongs to no usable triangle";
        return false;
      }
      return true;
  }
  problem = "unknown point location";
  return false;
}

//------------------------------------------------------------------------------
std::string Describe(const CanonicalPoint& c)
{
  char buffer[96];
  switch (c.Location)
  {
    case PointLocation::Vertex:
      std::snprintf(buffer, sizeof(buffer), "vertex %d", c.Id);
      break;
    case PointLocation::Edge:
      std::snprintf(buffer, sizeof(buffer), "edge %d (t=%.6g)", c.Id, c.T);
      break;
    case PointLocation::Face:
    default:
      std::snprintf(buffer, sizeof(buffer), "triangle %d (u=%.6g, v=%.6g)", c.Id, c.U, c.V);
      break;
  }
  return buffer;
}

} // namespace boolsurf

#include "SurfacePoint.h"

#include <algorithm>
#include <cmath>

namespace boolsurf
{

//------------------------------------------------------------------------------
CanonicalPoint Canonicalize(const TriangleMesh& mesh, SurfacePoint p, double snap)
{
  double w[3] = { 1.0 - p.U - p.V, p.U, p.V };
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
    c.T = mesh.GetEdgeVertices(e)[0] == a ? s : 1.0 - s;
    return c;
  }
  const double sum = w[0] + w[1] + w[2];
  c.Location = PointLocation::Face;
  c.Id = p.Triangle;
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

} // namespace boolsurf

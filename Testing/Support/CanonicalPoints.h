// Canonical surface points written by hand in tests: a vertex, an edge parameter or a face's
// barycentrics, as a regression case records them (Describe's "vertex 7", "edge 12 (t=0.3)",
// "triangle 5 (u=0.2, v=0.1)").
#ifndef boolsurf_testing_CanonicalPoints_h
#define boolsurf_testing_CanonicalPoints_h

#include "Mesh/SurfacePoint.h"

namespace boolsurf
{
namespace testing
{

inline CanonicalPoint VertexPoint(int v)
{
  CanonicalPoint c;
  c.Location = PointLocation::Vertex;
  c.Id = v;
  return c;
}

inline CanonicalPoint EdgePoint(int e, double t)
{
  CanonicalPoint c;
  c.Location = PointLocation::Edge;
  c.Id = e;
  c.T = t;
  return c;
}

inline CanonicalPoint FacePoint(int t, double u, double v)
{
  CanonicalPoint c;
  c.Location = PointLocation::Face;
  c.Id = t;
  c.U = u;
  c.V = v;
  return c;
}

} // namespace testing
} // namespace boolsurf

#endif

// Points on a triangle-mesh surface.
//
// A SurfacePoint is a triangle id plus barycentric (u, v): the weights of the triangle's
// corners 1 and 2 (corner 0 has 1 - u - v). That is the form users give and get
// (`TriangleId` + `Barycentric` arrays).
//
// A point on a mesh edge or vertex lies in several triangles, and their barycentric forms do
// not agree bit for bit. The arrangement must decide exactly which points lie on an edge
// and in which order, so every stage works with the CanonicalPoint form: a vertex id, or an
// edge id plus a parameter along the edge's canonical direction
// (TriangleMesh::GetEdgeVertices), or a triangle with (u, v) strictly inside it.
#ifndef boolsurf_SurfacePoint_h
#define boolsurf_SurfacePoint_h

#include "Mesh/TriangleMesh.h"

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace boolsurf
{

struct SurfacePoint
{
  int Triangle = -1;
  double U = 0, V = 0;
};

/// The point of triangle t nearest to x, for an x in (or next to) the triangle's plane, such as
/// a closest-point query returns: barycentric (u, v) by least squares in the plane, clamped
/// into the triangle (ClampBarycentric). A degenerate triangle gives its corner 0.
SurfacePoint PointInTriangle(const TriangleMesh& mesh, int t, const Vec3& x);

/// Barycentric weights (w0, w1, w2) of the points of the plane of triangle a, b, c, not clamped
/// (points outside the triangle get negative weights); all zero for a degenerate triangle.
class TrianglePlaneWeights
{
public:
  TrianglePlaneWeights(const Vec3& a, const Vec3& b, const Vec3& c)
    : A(a)
    , E1(b - a)
    , E2(c - a)
    , D11(Dot(E1, E1))
    , D12(Dot(E1, E2))
    , D22(Dot(E2, E2))
    , Det(D11 * D22 - D12 * D12)
  {
  }
  bool IsDegenerate() const { return !(this->Det > 0.0); }
  std::array<double, 3> operator()(const Vec3& x) const
  {
    if (this->IsDegenerate())
    {
      return { 0.0, 0.0, 0.0 };
    }
    const double b1 = Dot(x - this->A, this->E1), b2 = Dot(x - this->A, this->E2);
    const double u = (this->D22 * b1 - this->D12 * b2) / this->Det;
    const double v = (this->D11 * b2 - this->D12 * b1) / this->Det;
    return { 1.0 - u - v, u, v };
  }

private:
  Vec3 A, E1, E2;
  double D11, D12, D22, Det;
};

/// The same for a triangle given by its corners a, b, c (in 3D, any orientation): the weights
/// (u, v) of b and c.
void BarycentricInTriangle(const Vec3& a,
  const Vec3& b,
  const Vec3& c,
  const Vec3& x,
  double& u,
  double& v);

/// (u, v) moved into the triangle: negative weights to 0, then scaled so u + v <= 1. For values a
/// rounding error outside it (callers decide how far outside is an error).
inline void ClampBarycentric(double& u, double& v)
{
  u = u > 0 ? u : 0.0;
  v = v > 0 ? v : 0.0;
  if (u + v > 1)
  {
    const double s = u + v;
    u /= s;
    v /= s;
  }
}

enum class PointLocation : unsigned char
{
  Face,   ///< strictly inside Triangle: Id = triangle, (U, V)
  Edge,   ///< strictly inside an edge: Id = edge id, T in (0,1) from vertex 0 to vertex 1
  Vertex, ///< on a mesh vertex: Id = vertex id
};

struct CanonicalPoint
{
  PointLocation Location = PointLocation::Face;
  int Id = -1;
  double U = 0, V = 0; ///< Face only
  double T = 0;        ///< Edge only

  bool operator==(const CanonicalPoint& o) const
  {
    return this->Location == o.Location && this->Id == o.Id && this->U == o.U && this->V == o.V &&
      this->T == o.T;
  }
};

/// The one tolerance that decides where a given surface point lies: a barycentric weight at
/// most this is zero, so a point written a rounding error (1e-16 .. 1e-12) off an edge or a
/// vertex, in either triangle, is on it, and gives the answer of the exact point. Every stage
/// that reads surface points (tracing, arrangement, homology, resolution, control-point
/// recovery, subdivision, scene files) locates them with LocateSurfacePoint, so two readers of
/// one curve never disagree. It is far below any distance a user means: weights are fractions
/// of the triangle (1e-11 of a 1 m triangle is 10 picometres).
constexpr double SurfacePointSnap = 1e-11;

/// Canonical form of p. A barycentric weight whose absolute value is at most `snap` counts
/// as zero, so a point given as (t, 1e-17, 0.3) lands on the edge; pass 0 for an exact test.
/// Weights are clamped into the triangle first. An edge point's parameter is the weight of the
/// edge's second vertex as written when that weight is one of (u, v), so a point written by
/// ToSurfacePoint reads back bit for bit.
CanonicalPoint Canonicalize(const TriangleMesh& mesh, SurfacePoint p, double snap = 0.0);

/// Where p lies, with the one tolerance of every reader: Canonicalize(mesh, p, SurfacePointSnap).
inline CanonicalPoint LocateSurfacePoint(const TriangleMesh& mesh, const SurfacePoint& p)
{
  return Canonicalize(mesh, p, SurfacePointSnap);
}

/// Barycentric weights (w0, w1, w2) of c in triangle t, which must contain c (t itself for a
/// face point, a triangle of the edge or vertex otherwise). Edge points put the two canonical
/// numbers (1 - T, T) at the corners of the edge's vertices, so both triangles of an edge see
/// the same two numbers.
std::array<double, 3> WeightsInTriangle(const TriangleMesh& mesh, const CanonicalPoint& c, int t);

/// Some triangle that contains c (the lowest id).
int AnyTriangleOf(const TriangleMesh& mesh, const CanonicalPoint& c);

/// 3D position of c.
Vec3 PositionOf(const TriangleMesh& mesh, const CanonicalPoint& c);

/// True when triangle t contains c (t itself for a face point, a triangle having the edge or
/// the vertex otherwise). Purely combinatorial: no tolerance.
bool TriangleContains(const TriangleMesh& mesh, const CanonicalPoint& c, int t);

/// Every usable triangle that contains c, appended to `out` after clearing it.
void TrianglesOf(const TriangleMesh& mesh, const CanonicalPoint& c, std::vector<int>& out);

/// A triangle containing both a and b (the lowest id), or -1.
int SharedTriangle(const TriangleMesh& mesh, const CanonicalPoint& a, const CanonicalPoint& b);

/// p in its own triangle with every weight LocateSurfacePoint reads as zero set to exactly 0
/// (a point on a vertex becomes (1, 0, 0) in some order): for stages that carry a given point
/// into another triangulation (subdivision) without a TriangleMesh, so rounding off an edge is
/// not magnified into a distance.
SurfacePoint SnapWeights(SurfacePoint p);

/// Triangle + barycentric form of c (in AnyTriangleOf(c)), for output arrays: the weights of
/// c's location are written exactly (an edge point has an exact 0 opposite its edge, a vertex
/// is (1, 0, 0) in some order).
SurfacePoint ToSurfacePoint(const TriangleMesh& mesh, const CanonicalPoint& c);

/// ToSurfacePoint of vertex v, bit for bit (its lowest corner's triangle, weight 1 at that
/// corner; triangle -1 for an unreferenced vertex), read from the vertex's corner list alone:
/// outputs derive it per point instead of storing 24 bytes per mesh vertex.
inline SurfacePoint VertexSurfacePoint(const TriangleMesh& mesh, int v)
{
  SurfacePoint p;
  const IntRange corners = mesh.GetVertexCorners(v);
  if (corners.size() > 0)
  {
    const int corner = corners[0];
    p.Triangle = corner / 3;
    p.U = corner % 3 == 1 ? 1.0 : 0.0;
    p.V = corner % 3 == 2 ? 1.0 : 0.0;
  }
  return p;
}

/// The canonical form of c as written in an output array: in `preferred` when that triangle
/// contains c (so a curve point is written in a triangle it shares with its neighbours), else
/// in AnyTriangleOf(c). When that form would not read back (LocateSurfacePoint) to c bit for
/// bit, which can happen for an edge point whose parameter sits on the implicit corner, the
/// other triangles of c are tried, and finally the deterministic AnyTriangleOf form, so one
/// point is written the same way by every curve through it.
SurfacePoint WriteSurfacePoint(const TriangleMesh& mesh, const CanonicalPoint& c, int preferred);

/// The one tolerance for "a given point lies inside its triangle": barycentric weights down to
/// -InsideTriangleTolerance, with u + v up to 1 + InsideTriangleTolerance, are inside (a
/// point rounded off an edge when it was written, as scene files of the original BoolSurf
/// code have them); readers then clamp them in (ClampBarycentric, Canonicalize). Every reader
/// of given surface points (control curves, Surface Curves' properties, the SVG mapper's
/// center, scene files read and written, subdivision) refuses a point only beyond it.
constexpr double InsideTriangleTolerance = 1e-6;

/// Whether (u, v) are finite and inside the triangle up to InsideTriangleTolerance.
inline bool IsInsideTriangle(double u, double v)
{
  return std::isfinite(u) && std::isfinite(v) && u >= -InsideTriangleTolerance &&
    v >= -InsideTriangleTolerance && u + v <= 1 + InsideTriangleTolerance;
}

/// False, with a sentence naming the problem, when p cannot be used: triangle id out of
/// range, a triangle with invalid or repeated vertex indices, non-finite barycentrics or ones
/// outside the triangle (IsInsideTriangle).
bool CheckSurfacePoint(const TriangleMesh& mesh, const SurfacePoint& p, std::string& problem);

/// Same for a canonical point (id out of range, non-finite parameters, an isolated vertex).
bool CheckCanonicalPoint(const TriangleMesh& mesh, const CanonicalPoint& c, std::string& problem);

/// Short human-readable form for messages: "vertex 12", "edge 5 (t=0.25)", "triangle 3
/// (u=0.2, v=0.3)".
std::string Describe(const CanonicalPoint& c);

} // namespace boolsurf

#endif

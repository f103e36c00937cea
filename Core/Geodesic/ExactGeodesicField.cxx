// Distance field mode of ExactGeodesicSearch (see the header): many sources at distance 0, no
// target, and the windows kept per edge so the field can be read anywhere afterwards.
#include "Geodesic/ExactGeodesicSearch.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace boolsurf
{
namespace
{
constexpr double Infinity = std::numeric_limits<double>::infinity();
} // namespace

//------------------------------------------------------------------------------
void ExactGeodesicSearch::PrepareField()
{
  const TriangleMesh& mesh = this->Mesh;
  if (this->ForcedMark.size() != static_cast<size_t>(mesh.GetNumberOfVertices()))
  {
    this->ForcedMark.assign(mesh.GetNumberOfVertices(), 0u);
    this->EdgeHead.assign(mesh.GetNumberOfEdges(), -1);
    this->EdgeStamp.assign(mesh.GetNumberOfEdges(), 0u);
    this->FaceSourceHead.assign(mesh.GetNumberOfTriangles(), -1);
    this->FaceStamp.assign(mesh.GetNumberOfTriangles(), 0u);
  }
  if (this->CurrentStamp == 1)
  {
    // ResetMarks wrapped around (or this is the first search): older stamps may repeat.
    std::fill(this->ForcedMark.begin(), this->ForcedMark.end(), 0u);
    std::fill(this->EdgeStamp.begin(), this->EdgeStamp.end(), 0u);
    std::fill(this->FaceStamp.begin(), this->FaceStamp.end(), 0u);
  }
}

//------------------------------------------------------------------------------
void ExactGeodesicSearch::LinkToEdge(int id)
{
  const int edge = this->Windows[id].Edge;
  if (this->WindowNext.size() <= static_cast<size_t>(id))
  {
    this->WindowNext.resize(2 * static_cast<size_t>(id) + 16);
  }
  if (this->EdgeStamp[edge] != this->CurrentStamp)
  {
    this->EdgeStamp[edge] = this->CurrentStamp;
    this->EdgeHead[edge] = -1;
  }
  this->WindowNext[id] = this->EdgeHead[edge];
  this->EdgeHead[edge] = id;
}

//------------------------------------------------------------------------------
void ExactGeodesicSearch::AddFaceSource(int face, const Vec3& a, const Vec3& b)
{
  if (this->FaceStamp[face] != this->CurrentStamp)
  {
    this->FaceStamp[face] = this->CurrentStamp;
    this->FaceSourceHead[face] = -1;
  }
  // One link per (source, triangle): the links live in FaceSourceNext, in pairs.
  const int link = static_cast<int>(this->FaceSourceNext.size());
  this->FaceSourceNext.push_back(this->FaceSourceHead[face]);
  this->FaceSourceNext.push_back(static_cast<int>(this->FieldSources.size()));
  this->FieldSources.push_back({ a, b });
  this->FaceSourceHead[face] = link;
}

//------------------------------------------------------------------------------
// The straight piece a-b as a line source in each triangle holding it: the rays normal to it
// leave the triangle through its other edges as windows from a far point behind the piece.
void ExactGeodesicSearch::AddLineSource(const CanonicalPoint& a, const CanonicalPoint& b)
{
  const TriangleMesh& mesh = this->Mesh;
  const Vec3 pa = PositionOf(mesh, a), pb = PositionOf(mesh, b);
  const double pieceLength = ::boolsurf::Distance(pa, pb);
  if (!(pieceLength > 0.0))
  {
    return;
  }
  const Vec3 u = (1.0 / pieceLength) * (pb - pa);
  const Vec3 middle = 0.5 * (pa + pb);
  const double far = 1e7 * pieceLength;
  std::vector<int> triangles;
  TrianglesOf(mesh, a, triangles);
  for (int t : triangles)
  {
    if (!TriangleContains(mesh, b, t))
    {
      continue;
    }
    this->AddFaceSource(t, pa, pb);
    const Triangle& tri = mesh.GetTriangle(t);
    const Vec3 q[3] = {
      mesh.GetPosition(tri[0]), mesh.GetPosition(tri[1]), mesh.GetPosition(tri[2])
    };
    const Vec3 normal = Cross(q[1] - q[0], q[2] - q[0]);
    const Vec3 side0 = Cross(normal, u);
    if (!(Length(side0) > 0.0))
    {
      continue;
    }
    const Vec3 n = (1.0 / Length(side0)) * side0; // in the triangle's plane, normal to the piece
    // Corners whose foot on the piece's line falls on the piece: their distance is exact.
    for (int k = 0; k < 3; ++k)
    {
      const double along = Dot(q[k] - pa, u);
      if (along > 0.0 && along < pieceLength)
      {
        this->Relax(tri[k], std::abs(Dot(q[k] - pa, n)), FromSource, -1, t);
      }
    }
    const std::array<double, 3> wa = WeightsInTriangle(mesh, a, t);
    const std::array<double, 3> wb = WeightsInTriangle(mesh, b, t);
    for (int k = 0; k < 3; ++k)
    {
      const int edge = mesh.GetEdgeId(t, k);
      const std::array<int, 2> ev = mesh.GetEdgeVertices(edge);
      const Vec3 p0 = mesh.GetPosition(ev[0]), p1 = mesh.GetPosition(ev[1]);
      const double length = ::boolsurf::Distance(p0, p1);
      const Vec3 ex = (1.0 / length) * (p1 - p0);
      if (wa[(k + 2) % 3] <= 0.0 && wb[(k + 2) % 3] <= 0.0)
      {
        // The piece lies on this edge: distance 0 along it, read but never propagated (its
        // rays into each triangle of the edge are that triangle's other edges' windows).
        const double ba = Dot(pa - p0, ex), bb = Dot(pb - p0, ex);
        Window w;
        w.Edge = edge;
        w.Face = w.Origin = w.Parent = -1;
        w.Kind = FromSource;
        w.Sigma = -far;
        w.Sx = 0.5 * (ba + bb);
        w.Sy = -far;
        w.B0 = std::min(ba, bb);
        w.B1 = std::max(ba, bb);
        this->Windows.push_back(w);
        this->LinkToEdge(static_cast<int>(this->Windows.size()) - 1);
        continue;
      }
      const int next = mesh.GetNeighbor(t, k);
      if (next < 0)
      {
        continue;
      }
      // Along the edge (parameter s in [0, 1]): the foot on the piece's line and the side.
      const double along0 = Dot(p0 - pa, u), along1 = Dot(p1 - pa, u);
      const double side0v = Dot(p0 - pa, n), side1v = Dot(p1 - pa, n);
      // An edge normal to the piece through one of its ends (the piece's end is where the
      // curve crosses an edge straight, or a lattice point of a regular grid) lies on the
      // border of the piece's strip: its ends' along values are the piece's end to within
      // rounding, whose signs then cut the edge at a meaningless point, and the next piece's
      // strip may miss the rest (a gap the width of the edge). Values within rounding of the
      // border count as on it, inside: the edge is then in both strips, read at its distance
      // to the line, which is its distance to the piece to within rounding squared.
      const double border = 1e-12 * std::max({ pieceLength, Length(p0 - pa), Length(p1 - pa) });
      for (double sign : { 1.0, -1.0 })
      {
        double lo = 0.0, hi = 1.0;
        // Keep s where f(s) = f0 + s (f1 - f0) >= 0.
        auto keep = [&lo, &hi, border](double f0, double f1)
        {
          if ((f0 >= 0.0 && f1 >= 0.0) || (std::abs(f0) <= border && std::abs(f1) <= border))
          {
            return;
          }
          if (f0 < 0.0 && f1 < 0.0)
          {
            hi = -1.0;
            return;
          }
          const double root = f0 / (f0 - f1);
          if (f0 < 0.0)
          {
            lo = std::max(lo, root);
          }
          else
          {
            hi = std::min(hi, root);
          }
        };
        keep(along0, along1);
        keep(pieceLength - along0, pieceLength - along1);
        keep(sign * side0v, sign * side1v);
        if (!(hi - lo > 0.0))
        {
          continue;
        }
        // The far point behind the piece, on the triangle's side of the edge; distance -far, so
        // a point beyond the edge is reached at its distance to the piece's line.
        Window w =
          this->WholeEdgeWindow(edge, next, t, middle - (sign * far) * n, -far, FromSource, t);
        w.B0 = lo * length;
        w.B1 = hi * length;
        this->AddWindow(w);
      }
    }
  }
}

//------------------------------------------------------------------------------
// Point i of the curve lies on a mesh edge that the curve crosses without turning: its pieces
// lie in the edge's two triangles and make the same angle with the edge (straight once the
// triangles are unfolded), as a traced geodesic does at every edge it crosses.
bool ExactGeodesicSearch::StraightCrossing(const std::vector<CanonicalPoint>& curve,
  size_t i,
  bool closed) const
{
  const TriangleMesh& mesh = this->Mesh;
  const size_t n = curve.size();
  const CanonicalPoint& p = curve[i];
  if (p.Location != PointLocation::Edge || n < 3 || (!closed && (i == 0 || i + 1 == n)))
  {
    return false;
  }
  const CanonicalPoint& before = curve[(i + n - 1) % n];
  const CanonicalPoint& after = curve[(i + 1) % n];
  const int t1 = SharedTriangle(mesh, before, p), t2 = SharedTriangle(mesh, p, after);
  if (t1 < 0 || t2 < 0 || t1 == t2 || TriangleContains(mesh, after, t1) ||
    TriangleContains(mesh, before, t2))
  {
    return false;
  }
  const Vec3 x = PositionOf(mesh, p), a = PositionOf(mesh, before), b = PositionOf(mesh, after);
  const std::array<int, 2> ev = mesh.GetEdgeVertices(p.Id);
  const Vec3 edge = mesh.GetPosition(ev[1]) - mesh.GetPosition(ev[0]);
  const double la = Length(x - a), lb = Length(b - x), le = Length(edge);
  if (!(la > 0.0 && lb > 0.0 && le > 0.0))
  {
    return false;
  }
  return std::abs(Dot(x - a, edge) / (la * le) - Dot(b - x, edge) / (lb * le)) <= 1e-9;
}

//------------------------------------------------------------------------------
bool ExactGeodesicSearch::ComputeDistanceField(
  const std::vector<std::vector<CanonicalPoint>>& curves,
  const std::vector<char>& closed,
  double radius)
{
  const TriangleMesh& mesh = this->Mesh;
  this->Prepare();
  this->ResetMarks();
  this->PrepareField();
  this->FieldMode = true;
  this->Windows.clear();
  this->Heap.clear();
  this->FieldVertices.clear();
  this->FieldSources.clear();
  this->FaceSourceNext.clear();
  this->Best = radius;
  this->BestKind = this->BestId = -1;
  this->ForcedVertex = -1;
  this->LastVertexCount = 0;
  this->BudgetExceeded = false;
  std::vector<int> triangles;
  for (size_t c = 0; c < curves.size(); ++c)
  {
    const std::vector<CanonicalPoint>& curve = curves[c];
    const bool isClosed = c < closed.size() && closed[c];
    for (size_t i = 0; i < curve.size(); ++i)
    {
      const CanonicalPoint& source = curve[i];
      if (this->StraightCrossing(curve, i, isClosed))
      {
        continue; // the two pieces' line sources meet on its normal: nothing is nearer to it
      }
      TrianglesOf(mesh, source, triangles);
      if (triangles.empty())
      {
        continue;
      }
      const Vec3 position = PositionOf(mesh, source);
      for (int t : triangles)
      {
        this->AddFaceSource(t, position, position);
      }
      if (source.Location == PointLocation::Edge)
      {
        // The edge the source lies on gets no window from it: record the straight distance
        // along the edge as a window of zero height, read but never propagated.
        const std::array<int, 2> ev = mesh.GetEdgeVertices(source.Id);
        const double length =
          ::boolsurf::Distance(mesh.GetPosition(ev[0]), mesh.GetPosition(ev[1]));
        Window w;
        w.Edge = source.Id;
        w.Face = w.Origin = w.Parent = -1;
        w.Kind = FromSource;
        w.Sigma = 0.0;
        w.Sx = source.T * length;
        w.Sy = 0.0;
        w.B0 = 0.0;
        w.B1 = length;
        this->Windows.push_back(w);
        this->LinkToEdge(static_cast<int>(this->Windows.size()) - 1);
      }
      this->SeedFromPoint(source, triangles);
    }
    const size_t n = curve.size();
    const size_t pieces = n < 2 ? 0 : (isClosed ? n : n - 1);
    for (size_t i = 0; i < pieces; ++i)
    {
      this->AddLineSource(curve[i], curve[(i + 1) % n]);
    }
  }
  const std::vector<int> noTarget;
  return this->Run(noTarget);
}

//------------------------------------------------------------------------------
double ExactGeodesicSearch::GetFieldDistanceAtVertex(int v) const
{
  return this->Labels[v].Stamp == this->CurrentStamp ? this->Labels[v].Distance : Infinity;
}

//------------------------------------------------------------------------------
double ExactGeodesicSearch::WindowDistanceAt(const Window& w, double b) const
{
  const double dx = w.Sx - b;
  return w.Sigma + std::sqrt(dx * dx + w.Sy * w.Sy);
}

//------------------------------------------------------------------------------
double ExactGeodesicSearch::GetFieldDistanceOnEdge(int edge, double t) const
{
  const TriangleMesh& mesh = this->Mesh;
  const std::array<int, 2> ev = mesh.GetEdgeVertices(edge);
  const double length = ::boolsurf::Distance(mesh.GetPosition(ev[0]), mesh.GetPosition(ev[1]));
  const double b = t * length;
  double best = std::min(this->GetFieldDistanceAtVertex(ev[0]) + b,
    this->GetFieldDistanceAtVertex(ev[1]) + (length - b));
  const int h = mesh.GetEdgeHalfEdge(edge);
  if (mesh.GetTwin(h) < 0)
  {
    // A boundary edge gets no windows (none crosses it): read it from its triangle's, which
    // light it from the triangle's other edges.
    std::array<double, 3> w{ 0.0, 0.0, 0.0 };
    w[h % 3] = 1.0 - t;
    w[(h % 3 + 1) % 3] = t;
    best = std::min(best, this->GetFieldDistanceInTriangle(h / 3, w));
  }
  if (this->EdgeStamp[edge] != this->CurrentStamp)
  {
    return best;
  }
  // Each window: straight through it, or around its nearer end and along the edge (a real
  // path). Where the windows on both sides of a ray through a vertex end on it, rounding may
  // leave a gap between them on the ray, and this reads it from either to within rounding.
  for (int id = this->EdgeHead[edge]; id >= 0; id = this->WindowNext[id])
  {
    const Window& w = this->Windows[id];
    const double end = std::min(w.B1, std::max(w.B0, b));
    best = std::min(best, this->WindowDistanceAt(w, end) + std::abs(b - end));
  }
  return best;
}

//------------------------------------------------------------------------------
double ExactGeodesicSearch::GetFieldDistanceInTriangle(int face,
  const std::array<double, 3>& weights) const
{
  const TriangleMesh& mesh = this->Mesh;
  const Triangle& tri = mesh.GetTriangle(face);
  const Vec3 p[3] = {
    mesh.GetPosition(tri[0]), mesh.GetPosition(tri[1]), mesh.GetPosition(tri[2])
  };
  const Vec3 x = weights[0] * p[0] + weights[1] * p[1] + weights[2] * p[2];
  double best = Infinity;
  for (int k = 0; k < 3; ++k)
  {
    best = std::min(best, this->GetFieldDistanceAtVertex(tri[k]) + ::boolsurf::Distance(p[k], x));
  }
  if (this->FaceStamp[face] == this->CurrentStamp)
  {
    for (int link = this->FaceSourceHead[face]; link >= 0; link = this->FaceSourceNext[link])
    {
      const std::array<Vec3, 2>& piece = this->FieldSources[this->FaceSourceNext[link + 1]];
      best = std::min(best, SegmentPointDistance(piece[0], piece[1], x));
    }
  }
  // Windows on the triangle's edges that light it: x in the edge's frame (vertex 0 at the
  // origin, the triangle on y > 0), reached straight through the window when the ray from the
  // window's source crosses the lit interval.
  for (int k = 0; k < 3; ++k)
  {
    const int edge = mesh.GetEdgeId(face, k);
    if (this->EdgeStamp[edge] != this->CurrentStamp)
    {
      continue;
    }
    const std::array<int, 2> ev = mesh.GetEdgeVertices(edge);
    const Vec3 p0 = mesh.GetPosition(ev[0]);
    const Vec3 axis = mesh.GetPosition(ev[1]) - p0;
    const double length = Length(axis);
    if (!(length > 0.0))
    {
      continue;
    }
    const Vec3 ex = (1.0 / length) * axis;
    const double xx = Dot(x - p0, ex);
    const double xy = Length(x - p0 - xx * ex);
    for (int id = this->EdgeHead[edge]; id >= 0; id = this->WindowNext[id])
    {
      const Window& w = this->Windows[id];
      if (w.Face != face)
      {
        continue;
      }
      const double den = xy - w.Sy;
      const double cross = den > 0.0 ? w.Sx + (xx - w.Sx) * (-w.Sy) / den : xx;
      if (cross >= w.B0 && cross <= w.B1)
      {
        best = std::min(best, w.Sigma + std::hypot(xx - w.Sx, xy - w.Sy));
      }
      else
      {
        // Around the window's nearer end (see GetFieldDistanceOnEdge).
        const double end = cross < w.B0 ? w.B0 : w.B1;
        best = std::min(best, this->WindowDistanceAt(w, end) + std::hypot(xx - end, xy));
      }
    }
  }
  return best;
}

} // namespace boolsurf

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
bool ExactGeodesicSearch::ComputeDistanceField(const std::vector<CanonicalPoint>& sources,
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
  for (const CanonicalPoint& source : sources)
  {
    TrianglesOf(mesh, source, triangles);
    if (triangles.empty())
    {
      continue;
    }
    const int index = static_cast<int>(this->FieldSources.size());
    this->FieldSources.push_back(PositionOf(mesh, source));
    for (int t : triangles)
    {
      if (this->FaceStamp[t] != this->CurrentStamp)
      {
        this->FaceStamp[t] = this->CurrentStamp;
        this->FaceSourceHead[t] = -1;
      }
      // One link per (source, triangle): the links live in FaceSourceNext, in pairs.
      const int link = static_cast<int>(this->FaceSourceNext.size());
      this->FaceSourceNext.push_back(this->FaceSourceHead[t]);
      this->FaceSourceNext.push_back(index);
      this->FaceSourceHead[t] = link;
    }
    if (source.Location == PointLocation::Edge)
    {
      // The edge the source lies on gets no window from it: record the straight distance
      // along the edge as a window of zero height, read but never propagated.
      const std::array<int, 2> ev = mesh.GetEdgeVertices(source.Id);
      const double length = ::boolsurf::Distance(mesh.GetPosition(ev[0]), mesh.GetPosition(ev[1]));
      Window w;
      w.Edge = source.Id;
      w.Face = -1;
      w.Origin = -1;
      w.Parent = -1;
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
  const std::vector<int> noTarget;
  return this->Run(noTarget);
}

//------------------------------------------------------------------------------
double ExactGeodesicSearch::GetFieldDistanceAtVertex(int v) const
{
  return this->Stamp[v] == this->CurrentStamp ? this->Distance[v] : Infinity;
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
  if (this->EdgeStamp[edge] != this->CurrentStamp)
  {
    return best;
  }
  for (int id = this->EdgeHead[edge]; id >= 0; id = this->WindowNext[id])
  {
    const Window& w = this->Windows[id];
    if (b >= w.B0 && b <= w.B1)
    {
      best = std::min(best, this->WindowDistanceAt(w, b));
    }
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
      best =
        std::min(best, ::boolsurf::Distance(this->FieldSources[this->FaceSourceNext[link + 1]], x));
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
    }
  }
  return best;
}

} // namespace boolsurf

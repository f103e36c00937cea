#include "Support/PieceSplits.h"

#include "Geodesic/CurveTracer.h"

#include <algorithm>
#include <numeric>
#include <queue>
#include <random>

namespace boolsurf
{
namespace testing
{
namespace
{

Vec3 Centroid(const TriangleMesh& mesh, int t)
{
  return (1.0 / 3.0) *
    (mesh.GetCornerPosition(t, 0) + mesh.GetCornerPosition(t, 1) + mesh.GetCornerPosition(t, 2));
}

} // namespace

//------------------------------------------------------------------------------
std::vector<int> SlabOwners(const TriangleMesh& mesh, int pieces, int axis)
{
  const int nt = mesh.GetNumberOfTriangles();
  std::vector<int> order(nt);
  std::iota(order.begin(), order.end(), 0);
  const auto coordinate = [&](int t)
  {
    const Vec3 c = Centroid(mesh, t);
    return axis == 0 ? c.x : (axis == 1 ? c.y : c.z);
  };
  std::stable_sort(
    order.begin(), order.end(), [&](int a, int b) { return coordinate(a) < coordinate(b); });
  std::vector<int> owner(nt);
  for (int i = 0; i < nt; ++i)
  {
    owner[order[i]] = static_cast<int>(static_cast<long long>(i) * pieces / nt);
  }
  return owner;
}

//------------------------------------------------------------------------------
std::vector<int> RegionOwners(const TriangleMesh& mesh, int pieces, unsigned seed, int emptyPiece)
{
  const int nt = mesh.GetNumberOfTriangles();
  std::mt19937 rng(seed);
  std::vector<int> owner(nt, -1);
  std::vector<std::queue<int>> fronts(pieces);
  for (int p = 0; p < pieces; ++p)
  {
    if (p == emptyPiece)
    {
      continue;
    }
    int t = std::uniform_int_distribution<int>(0, nt - 1)(rng);
    while (owner[t] >= 0)
    {
      t = (t + 1) % nt;
    }
    owner[t] = p;
    fronts[p].push(t);
  }
  for (bool grew = true; grew;)
  {
    grew = false;
    for (int p = 0; p < pieces; ++p)
    {
      while (!fronts[p].empty())
      {
        const int t = fronts[p].front();
        bool added = false;
        for (int k = 0; k < 3 && !added; ++k)
        {
          const int n = mesh.GetNeighbor(t, k);
          if (n >= 0 && owner[n] < 0)
          {
            owner[n] = p;
            fronts[p].push(n);
            added = grew = true;
          }
        }
        if (added)
        {
          break;
        }
        fronts[p].pop();
      }
    }
  }
  for (int& o : owner)
  {
    o = o < 0 ? 0 : o;
  }
  return owner;
}

//------------------------------------------------------------------------------
PieceInput MakePiece(const TriangleMesh& mesh, const std::vector<int>& owner, int p)
{
  const int nt = mesh.GetNumberOfTriangles();
  std::vector<char> touched(mesh.GetNumberOfVertices(), 0);
  for (int t = 0; t < nt; ++t)
  {
    for (int k = 0; k < 3 && owner[t] == p; ++k)
    {
      touched[mesh.GetTriangle(t)[k]] = 1;
    }
  }
  PieceInput in;
  std::vector<int> localOf(mesh.GetNumberOfVertices(), -1);
  for (int t = nt - 1; t >= 0; --t)
  {
    const Triangle& tri = mesh.GetTriangle(t);
    if (owner[t] != p && !touched[tri[0]] && !touched[tri[1]] && !touched[tri[2]])
    {
      continue;
    }
    Triangle local;
    for (int k = 0; k < 3; ++k)
    {
      if (localOf[tri[k]] < 0)
      {
        localOf[tri[k]] = static_cast<int>(in.Positions.size());
        in.Positions.push_back(mesh.GetPosition(tri[k]));
        in.PointGlobalIds.push_back(tri[k]);
      }
      local[k] = localOf[tri[k]];
    }
    in.Triangles.push_back(local);
    in.TriangleGlobalIds.push_back(t);
    in.Ghost.push_back(owner[t] != p ? 1 : 0);
  }
  return in;
}

//------------------------------------------------------------------------------
std::vector<TracedCurve> RandomGeodesicCurves(const TriangleMesh& mesh, unsigned seed, int count)
{
  CurveTracer tracer(mesh);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> triangle(0, mesh.GetNumberOfTriangles() - 1);
  std::uniform_real_distribution<double> weight(0.1, 0.45);
  std::vector<TracedCurve> curves;
  for (int id = 0; static_cast<int>(curves.size()) < count && id < 4 * count; ++id)
  {
    std::vector<SurfacePoint> points(std::uniform_int_distribution<int>(3, 5)(rng));
    for (SurfacePoint& x : points)
    {
      x = { triangle(rng), weight(rng), weight(rng) };
    }
    CurveTrace trace;
    std::string error;
    if (tracer.Trace(points, CurveType::GeodesicPolygon, true, trace, error, id) &&
      trace.Curve.Points.size() >= 3)
    {
      trace.Curve.ShapeId = static_cast<int>(curves.size());
      trace.Curve.CurveId = static_cast<int>(curves.size());
      curves.push_back(trace.Curve);
    }
  }
  return curves;
}

//------------------------------------------------------------------------------
MeshData SphereWithHoles()
{
  const MeshData sphere = MakeIcosphere(3);
  const Vec3 centers[] = { { 1, 0, 0 }, { -0.6, 0.8, 0 }, { 0, -0.6, 0.8 }, { 0, 0, -1 } };
  const double radii[] = { 0.3, 0.2, 0.35, 0.25 };
  MeshData out;
  out.Positions = sphere.Positions;
  for (const Triangle& t : sphere.Triangles)
  {
    const Vec3 c =
      (1.0 / 3.0) * (sphere.Positions[t[0]] + sphere.Positions[t[1]] + sphere.Positions[t[2]]);
    bool keep = true;
    for (int h = 0; h < 4; ++h)
    {
      keep = keep && Distance(c, centers[h]) > radii[h];
    }
    if (keep)
    {
      out.Triangles.push_back(t);
    }
  }
  return out;
}

//------------------------------------------------------------------------------
double RefinedArea(const TriangleMesh& mesh, const Arrangement& arr, int r)
{
  const Triangle c = arr.GetTriangle(mesh, r);
  const Vec3 a = arr.GetPosition(mesh, c[0]);
  return 0.5 * Length(Cross(arr.GetPosition(mesh, c[1]) - a, arr.GetPosition(mesh, c[2]) - a));
}

//------------------------------------------------------------------------------
std::vector<double> CellAreas(const TriangleMesh& mesh, const Arrangement& arr)
{
  std::vector<double> areas(arr.NumberOfCells, 0.0);
  for (int r = 0; r < arr.GetNumberOfTriangles(); ++r)
  {
    const int c = arr.CellOfTriangle(r);
    if (c >= 0)
    {
      areas[c] += RefinedArea(mesh, arr, r);
    }
  }
  return areas;
}

} // namespace testing
} // namespace boolsurf

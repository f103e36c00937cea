// Helpers shared by the arrangement tests: mesh construction, area bookkeeping, and an
// independent count of the planar arrangement of straight polygons.
#ifndef boolsurf_ArrangementTestUtils_h
#define boolsurf_ArrangementTestUtils_h

#include "Arrangement/Arrangement.h"
#include "Arrangement/RefinedSurfaceArrays.h"
#include "Mesh/ProceduralMeshes.h"
#include "Mesh/TriangleMesh.h"
#include "Support/SyntheticCurves.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <set>
#include <unordered_map>
#include <vector>

namespace boolsurf
{
namespace testing
{

inline TriangleMesh MeshOf(const MeshData& d)
{
  return TriangleMesh(d.Positions, d.Triangles);
}

inline double TriangleArea(const Vec3& a, const Vec3& b, const Vec3& c)
{
  return 0.5 * Length(Cross(b - a, c - a));
}

/// Signed area in the xy plane (flat meshes: every refined triangle must stay CCW).
inline double SignedPlanarArea(const Vec3& a, const Vec3& b, const Vec3& c)
{
  return 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

inline std::vector<double> CellAreas(const TriangleMesh& mesh, const Arrangement& arr)
{
  const RefinedSurfaceArrays whole = RefinedSurfaceArrays::Of(mesh, arr);
  std::vector<double> areas(arr.NumberOfCells, 0.0);
  for (size_t r = 0; r < whole.Triangles.size(); ++r)
  {
    const auto& t = whole.Triangles[r];
    areas[arr.CellOfTriangle(static_cast<int>(r))] +=
      TriangleArea(whole.Positions[t[0]], whole.Positions[t[1]], whole.Positions[t[2]]);
  }
  return areas;
}

/// Every refined triangle's pieces sum to its source's area, and cells sum to the mesh area.
inline void ExpectAreasConserved(const TriangleMesh& mesh, const Arrangement& arr)
{
  const RefinedSurfaceArrays whole = RefinedSurfaceArrays::Of(mesh, arr);
  std::vector<double> pieces(mesh.GetNumberOfTriangles(), 0.0);
  for (size_t r = 0; r < whole.Triangles.size(); ++r)
  {
    const auto& t = whole.Triangles[r];
    pieces[whole.SourceTriangle[r]] +=
      TriangleArea(whole.Positions[t[0]], whole.Positions[t[1]], whole.Positions[t[2]]);
  }
  double total = 0.0;
  for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    const double a = TriangleArea(
      mesh.GetCornerPosition(t, 0), mesh.GetCornerPosition(t, 1), mesh.GetCornerPosition(t, 2));
    total += a;
    EXPECT_NEAR(pieces[t], a, 1e-9 * a) << "source triangle " << t;
  }
  const std::vector<double> cells = CellAreas(mesh, arr);
  const double sum = std::accumulate(cells.begin(), cells.end(), 0.0);
  EXPECT_NEAR(sum, total, 1e-9 * total);
  for (double c : cells)
  {
    EXPECT_GT(c, 0.0);
  }
}

/// The refined surface is a conforming, consistently oriented triangulation with the same
/// Euler characteristic as the input.
inline void ExpectConforming(const TriangleMesh& mesh, const Arrangement& arr)
{
  const RefinedSurfaceArrays whole = RefinedSurfaceArrays::Of(mesh, arr);
  TriangleMesh refined(whole.Positions, whole.Triangles);
  EXPECT_TRUE(refined.GetNonManifoldEdges().empty());
  EXPECT_TRUE(refined.GetMisorientedEdges().empty());
  std::set<int> used;
  for (const auto& t : whole.Triangles)
    used.insert(t.begin(), t.end());
  const int chiIn =
    mesh.GetNumberOfVertices() - mesh.GetNumberOfEdges() + mesh.GetNumberOfTriangles();
  const int chiOut =
    static_cast<int>(used.size()) - refined.GetNumberOfEdges() + refined.GetNumberOfTriangles();
  EXPECT_EQ(chiIn, chiOut);
}

/// Independent count for straight closed polygons in general position in a disc: with X
/// crossing points (self-crossings included) and C connected components of the union of the
/// curves, the planar graph has V = X vertices of degree 4 and E = 2X edges (plus one vertex
/// and one edge per curve that meets nothing), so Euler's V - E + F = 1 + C gives
/// F = X + 1 + C faces, the outer one included.
struct PlanarCount
{
  int Crossings = 0, Components = 0;
  int Faces() const { return this->Crossings + 1 + this->Components; }
};

inline PlanarCount CountPlanarArrangement(const std::vector<std::vector<Vec2>>& polygons)
{
  struct Side
  {
    Vec2 A, B;
    int Poly;
    int Index;
  };
  std::vector<Side> sides;
  for (size_t p = 0; p < polygons.size(); ++p)
  {
    const int n = static_cast<int>(polygons[p].size());
    for (int i = 0; i < n; ++i)
      sides.push_back({ polygons[p][i], polygons[p][(i + 1) % n], static_cast<int>(p), i });
  }
  std::vector<int> parent(polygons.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x)
  {
    while (parent[x] != x)
      x = parent[x] = parent[parent[x]];
    return x;
  };
  auto orient = [](Vec2 a, Vec2 b, Vec2 c) { return Cross(b - a, c - a); };
  int crossings = 0;
  for (size_t i = 0; i < sides.size(); ++i)
  {
    for (size_t j = i + 1; j < sides.size(); ++j)
    {
      const Side &s = sides[i], &r = sides[j];
      if (s.Poly == r.Poly)
      {
        const int n = static_cast<int>(polygons[s.Poly].size());
        if (std::abs(s.Index - r.Index) == 1 || std::abs(s.Index - r.Index) == n - 1)
          continue; // consecutive sides share a vertex
      }
      const double o1 = orient(s.A, s.B, r.A), o2 = orient(s.A, s.B, r.B);
      const double o3 = orient(r.A, r.B, s.A), o4 = orient(r.A, r.B, s.B);
      if (o1 * o2 < 0 && o3 * o4 < 0)
      {
        ++crossings;
        parent[find(s.Poly)] = find(r.Poly);
      }
    }
  }
  PlanarCount count;
  count.Crossings = crossings;
  for (size_t p = 0; p < polygons.size(); ++p)
    count.Components += find(static_cast<int>(p)) == static_cast<int>(p);
  return count;
}

inline std::vector<Vec2> RandomPolygon(std::mt19937& rng, int n, double lo, double hi)
{
  std::uniform_real_distribution<double> coord(lo, hi);
  std::vector<Vec2> p(n);
  for (Vec2& q : p)
    q = { coord(rng), coord(rng) };
  return p;
}

inline TracedCurve TraceOrDie(const FlatPolygonTracer& tracer,
  const std::vector<Vec2>& polygon,
  bool closed = true,
  int shape = 0,
  int curveId = 0)
{
  TracedCurve c;
  EXPECT_TRUE(tracer.Trace(polygon, closed, shape, curveId, c));
  return c;
}

/// Independent check of the partition: a sequential breadth-first flood fill over refined
/// triangles sharing an edge (exactly two of them) that no closed patch runs along, seeded in
/// triangle order, must give exactly the arrangement's cells.
inline void ExpectCellsAreFloodFill(const TriangleMesh& mesh, const Arrangement& arr)
{
  const std::vector<Triangle> triangles = RefinedSurfaceArrays::Of(mesh, arr).Triangles;
  auto key = [](int a, int b)
  {
    return (static_cast<std::uint64_t>(std::min(a, b)) << 32) |
      static_cast<std::uint32_t>(std::max(a, b));
  };
  std::unordered_map<std::uint64_t, std::vector<int>> edgeTriangles;
  for (size_t r = 0; r < triangles.size(); ++r)
  {
    for (int j = 0; j < 3; ++j)
    {
      edgeTriangles[key(triangles[r][j], triangles[r][(j + 1) % 3])].push_back(static_cast<int>(r));
    }
  }
  std::set<std::uint64_t> cut;
  for (const ArrangementPatch& p : arr.Patches)
  {
    for (size_t k = 0; p.Closed && k + 1 < p.Points.size(); ++k)
    {
      cut.insert(key(p.Points[k], p.Points[k + 1]));
    }
  }
  std::vector<int> cell(triangles.size(), -1);
  int cells = 0;
  for (size_t seed = 0; seed < triangles.size(); ++seed)
  {
    if (cell[seed] >= 0)
    {
      continue;
    }
    std::vector<int> queue{ static_cast<int>(seed) };
    cell[seed] = cells;
    for (size_t head = 0; head < queue.size(); ++head)
    {
      const int r = queue[head];
      for (int j = 0; j < 3; ++j)
      {
        const std::uint64_t e = key(triangles[r][j], triangles[r][(j + 1) % 3]);
        const std::vector<int>& around = edgeTriangles[e];
        if (around.size() != 2 || cut.count(e))
        {
          continue;
        }
        const int n = around[0] == r ? around[1] : around[0];
        if (cell[n] < 0)
        {
          cell[n] = cells;
          queue.push_back(n);
        }
      }
    }
    ++cells;
  }
  EXPECT_EQ(cells, arr.NumberOfCells);
  std::vector<int> cellOf;
  WriteTriangleCells(arr, cellOf);
  EXPECT_TRUE(cell == cellOf) << "partition differs from a sequential flood fill";
  // Each cell's contents (clean tiles, loose triangles) list exactly its triangles, once.
  std::vector<int> listed(triangles.size(), -1);
  int twice = 0;
  for (int c = 0; c < arr.NumberOfCells; ++c)
  {
    ForEachCellTriangle(arr,
      c,
      [&](int r)
      {
        twice += listed[r] >= 0;
        listed[r] = c;
      });
  }
  EXPECT_EQ(twice, 0);
  EXPECT_TRUE(listed == cellOf) << "cell contents differ from the partition";
}

inline Arrangement ArrangeOrDie(const TriangleMesh& mesh,
  const std::vector<TracedCurve>& curves,
  int threads = 0)
{
  Arrangement arr;
  std::string error;
  ArrangementOptions options;
  options.Threads = threads;
  EXPECT_TRUE(ComputeArrangement(mesh, curves, options, arr, error)) << error;
  ExpectCellsAreFloodFill(mesh, arr);
  return arr;
}

/// Euler characteristic of the patch graph embedded in the surface: V - E + F.
inline int PatchGraphEuler(const Arrangement& arr)
{
  return arr.NumberOfPatchGraphVertices - static_cast<int>(arr.Patches.size()) + arr.NumberOfCells;
}

} // namespace testing
} // namespace boolsurf

#endif

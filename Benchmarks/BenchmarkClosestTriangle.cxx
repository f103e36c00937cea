// Projecting points given by coordinates onto a large shared mesh (control points and SVG
// centers, at every edit): the closest-point grid's build, once per surface, and a query for
// points near the surface. Run: BoolSurfBenchmarks --benchmark_filter=ClosestTriangle
#include "Mesh/ClosestTriangleGrid.h"
#include "Mesh/TriangleMesh.h"
#include "SharedMeshes.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <map>
#include <memory>
#include <random>
#include <string>

namespace
{

/// The shared mesh `name` with its adjacency, built once per process; null after reporting the
/// reason to `state`.
const boolsurf::TriangleMesh* MeshOrSkip(benchmark::State& state, const std::string& name)
{
  static std::map<std::string, std::unique_ptr<boolsurf::TriangleMesh>> cache;
  std::unique_ptr<boolsurf::TriangleMesh>& mesh = cache[name];
  if (!mesh)
  {
    std::string error;
    const boolsurf::MeshData* data = benchutil::LoadSharedMesh(name, error);
    if (!data)
    {
      state.SkipWithError(error.c_str());
      return nullptr;
    }
    mesh = std::make_unique<boolsurf::TriangleMesh>(data->Positions, data->Triangles);
  }
  return mesh.get();
}

void BM_ClosestTriangleBuild(benchmark::State& state, const std::string& name)
{
  const boolsurf::TriangleMesh* mesh = MeshOrSkip(state, name);
  if (!mesh)
  {
    return;
  }
  for (auto _ : state)
  {
    boolsurf::ClosestTriangleGrid grid(*mesh);
    benchmark::DoNotOptimize(&grid);
  }
  state.counters["triangles"] = mesh->GetNumberOfTriangles();
}

// Points within 0.01 % of the bounding-box diagonal of random surface points (a picked point,
// or one read back from a file, lies on the surface up to rounding).
void BM_ClosestTriangleQuery(benchmark::State& state, const std::string& name)
{
  const boolsurf::TriangleMesh* mesh = MeshOrSkip(state, name);
  if (!mesh)
  {
    return;
  }
  const boolsurf::ClosestTriangleGrid grid(*mesh);
  std::mt19937 rng(5);
  boolsurf::Vec3 lo = mesh->GetPosition(0), hi = lo;
  for (const boolsurf::Vec3& p : mesh->GetPositions())
  {
    lo = { std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z) };
    hi = { std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z) };
  }
  const double reach = 1e-4 * boolsurf::Distance(lo, hi);
  std::uniform_real_distribution<double> unit(0.0, 1.0), offset(-reach, reach);
  std::vector<boolsurf::Vec3> points;
  for (int i = 0; i < 1024; ++i)
  {
    const int t = static_cast<int>(rng() % mesh->GetNumberOfTriangles());
    const double u = unit(rng), v = unit(rng) * (1 - u);
    points.push_back(
      mesh->Evaluate(t, u, v) + boolsurf::Vec3{ offset(rng), offset(rng), offset(rng) });
  }
  std::size_t i = 0;
  for (auto _ : state)
  {
    benchmark::DoNotOptimize(grid.FindClosest(points[i++ % points.size()]));
  }
}

} // namespace

BENCHMARK_CAPTURE(BM_ClosestTriangleBuild, igea_1m, std::string("igea_1m.ply"))
  ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ClosestTriangleQuery, igea_1m, std::string("igea_1m.ply"))
  ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ClosestTriangleBuild, stanford_bunny_1m, std::string("stanford-bunny_1m.ply"))
  ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ClosestTriangleQuery, stanford_bunny_1m, std::string("stanford-bunny_1m.ply"))
  ->Unit(benchmark::kMicrosecond);

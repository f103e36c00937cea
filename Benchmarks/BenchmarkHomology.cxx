// Homology generators (tree-cotree, once per surface) and the class of every traced curve.
//
// - BM_HomologyGenerators/<mesh>: HomologyBasis::Compute on a mesh already converted (adjacency
//   and topology built outside the timing): what the first labeling of a surface pays once.
//   Meshes: procedural torus 400x200 (160k triangles) and, from BOOLSURF_SHARED_DATA_DIR/meshes,
//   eight_200k, 3torus_200k, fertility (a missing mesh skips the benchmark).
// - BM_CurveClasses: classes of 10 random closed geodesic polygons on the procedural torus
//   (traced outside the timing): what every edit pays.
//
// Run: BoolSurfBenchmarks --benchmark_filter=Homology
#include "Geodesic/CurveTracer.h"
#include "Homology/HomologyBasis.h"
#include "Mesh/PlyReader.h"
#include "Mesh/ProceduralMeshes.h"

#include <benchmark/benchmark.h>

#include <random>

namespace
{
/// The message of the last failed trace or path (a test reads it only after a failure).
std::string traceError;
}

namespace
{

bool LoadMesh(const std::string& name, boolsurf::MeshData& data, std::string& error)
{
  if (name == "torus400x200")
  {
    data = boolsurf::MakeTorus(3.0, 1.0, 400, 200);
    return true;
  }
  return boolsurf::ReadPly(std::string(BOOLSURF_SHARED_DATA_DIR) + "/meshes/" + name, data, error);
}

void BM_HomologyGenerators(benchmark::State& state, std::string name)
{
  boolsurf::MeshData data;
  std::string error;
  if (!LoadMesh(name, data, error))
  {
    state.SkipWithError(error.c_str());
    return;
  }
  const boolsurf::TriangleMesh mesh(data.Positions, data.Triangles);
  const boolsurf::MeshTopology topology = boolsurf::MeshTopology::Compute(mesh);
  boolsurf::HomologyBasis basis;
  for (auto _ : state)
  {
    if (!basis.Compute(mesh, topology, boolsurf::HomologyOptions(), error))
    {
      state.SkipWithError(error.c_str());
      return;
    }
    benchmark::DoNotOptimize(basis.GetNumberOfGenerators());
  }
  state.counters["Triangles"] = mesh.GetNumberOfTriangles();
  state.counters["Generators"] = basis.GetNumberOfGenerators();
}
BENCHMARK_CAPTURE(BM_HomologyGenerators, torus400x200, std::string("torus400x200"))
  ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_HomologyGenerators, eight_200k, std::string("eight_200k.ply"))
  ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_HomologyGenerators, 3torus_200k, std::string("3torus_200k.ply"))
  ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_HomologyGenerators, fertility, std::string("fertility.ply"))
  ->Unit(benchmark::kMillisecond);

void BM_CurveClasses(benchmark::State& state)
{
  const boolsurf::MeshData data = boolsurf::MakeTorus(3.0, 1.0, 400, 200);
  const boolsurf::TriangleMesh mesh(data.Positions, data.Triangles);
  const boolsurf::MeshTopology topology = boolsurf::MeshTopology::Compute(mesh);
  boolsurf::HomologyBasis basis;
  std::string error;
  basis.Compute(mesh, topology, boolsurf::HomologyOptions(), error);
  boolsurf::CurveTracer tracer(mesh);
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> triangle(0, mesh.GetNumberOfTriangles() - 1);
  std::vector<boolsurf::TracedCurve> curves;
  size_t points = 0;
  while (curves.size() < 10)
  {
    std::vector<boolsurf::SurfacePoint> control;
    for (int k = 0; k < 5; ++k)
    {
      control.push_back({ triangle(rng), 0.3, 0.3 });
    }
    boolsurf::CurveTrace trace;
    if (tracer.Trace(control, boolsurf::CurveType::GeodesicPolygon, true, trace, traceError))
    {
      points += trace.Curve.Points.size();
      curves.push_back(trace.Curve);
    }
  }
  std::vector<int> h;
  for (auto _ : state)
  {
    for (const boolsurf::TracedCurve& c : curves)
    {
      basis.ClassOf(c, h, error);
      benchmark::DoNotOptimize(h.data());
    }
  }
  state.counters["TracedPoints"] = static_cast<double>(points);
}
BENCHMARK(BM_CurveClasses)->Unit(benchmark::kMicrosecond);

} // namespace

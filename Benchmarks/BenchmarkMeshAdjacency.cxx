// Adjacency (the dual graph of adjacencies) and topology build times on the large meshes of
// the shared collection. Run: BoolSurfBenchmarks --benchmark_filter=Adjacency
#include "Mesh/MeshTopology.h"
#include "Mesh/TriangleMesh.h"
#include "SharedMeshes.h"

#include <benchmark/benchmark.h>

#include <string>

namespace
{
using benchutil::LoadSharedMesh;

// The adjacency alone, or followed by the topology (components, fans, loops, genus).
void BuildSharedMesh(benchmark::State& state, const std::string& name, bool withTopology)
{
  std::string error;
  const boolsurf::MeshData* data = LoadSharedMesh(name, error);
  if (!data)
  {
    state.SkipWithError(error.c_str());
    return;
  }
  for (auto _ : state)
  {
    boolsurf::TriangleMesh mesh(data->Positions, data->Triangles);
    benchmark::DoNotOptimize(mesh.GetNumberOfEdges());
    if (withTopology)
    {
      boolsurf::MeshTopology topo = boolsurf::MeshTopology::Compute(mesh);
      benchmark::DoNotOptimize(topo.Components.size());
    }
  }
  state.counters["triangles"] = static_cast<double>(data->Triangles.size());
}

void BM_Adjacency(benchmark::State& state, const std::string& name)
{
  BuildSharedMesh(state, name, false);
}

void BM_AdjacencyAndTopology(benchmark::State& state, const std::string& name)
{
  BuildSharedMesh(state, name, true);
}
} // namespace

BENCHMARK_CAPTURE(BM_Adjacency, igea_1m, std::string("igea_1m.ply"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Adjacency, 3torus_800k, std::string("3torus_800k.ply"))
  ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_AdjacencyAndTopology, igea_1m, std::string("igea_1m.ply"))
  ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_AdjacencyAndTopology, 3torus_800k, std::string("3torus_800k.ply"))
  ->Unit(benchmark::kMillisecond);

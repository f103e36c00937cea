// What the boundary loops' plugs (Labeling/BoundaryPlugs.h) add to a labeling update: on a flat
// square of 1M triangles (a terrain tile: one boundary loop of 2,832 edges) with ten polygons
// along its sides, around its corners and from side to side, the plugs alone, and the whole
// labeling input and labels as an edit recomputes them. The plugs walk the boundary loops'
// refined sub-edges once: their cost grows with the boundary, not the mesh.
#include "Arrangement/Arrangement.h"
#include "Labeling/ArrangementLabelingInput.h"
#include "Labeling/BoundaryPlugs.h"
#include "Mesh/MeshTopology.h"
#include "Mesh/ProceduralMeshes.h"
#include "Support/SyntheticCurves.h"

#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

using namespace boolsurf;

namespace
{

struct PlugScene
{
  std::unique_ptr<TriangleMesh> Mesh;
  MeshTopology Topology;
  std::vector<TracedCurve> Curves;
  Arrangement Arr;
  std::string Error;
};

const PlugScene& Scene()
{
  static PlugScene scene = []()
  {
    PlugScene s;
    const MeshData d = MakeFlatSquare(708, 1.0, 0.3, 5);
    s.Mesh = std::make_unique<TriangleMesh>(d.Positions, d.Triangles);
    s.Topology = MeshTopology::Compute(*s.Mesh);
    FlatPolygonTracer tracer(*s.Mesh);
    // Along one side, at the four corners, from side to side, a comb of three stretches, and
    // three away from the boundary.
    const std::vector<std::vector<Vec2>> polygons = {
      { { 0.4, 0 }, { 0.6, 0 }, { 0.6, 0.2 }, { 0.4, 0.2 } },
      { { 0, 0 }, { 0.1, 0 }, { 0.1, 0.1 }, { 0, 0.1 } },
      { { 1, 0 }, { 1, 0.1 }, { 0.9, 0.1 }, { 0.9, 0 } },
      { { 1, 1 }, { 0.9, 1 }, { 0.9, 0.9 }, { 1, 0.9 } },
      { { 0, 1 }, { 0, 0.9 }, { 0.1, 0.9 }, { 0.1, 1 } },
      { { 0, 0.6 }, { 1, 0.6 }, { 1, 0.4 }, { 0, 0.4 } },
      { { 0.2, 1 },
        { 0.25, 1 },
        { 0.25, 0.95 },
        { 0.3, 0.95 },
        { 0.3, 1 },
        { 0.35, 1 },
        { 0.35, 0.8 },
        { 0.2, 0.8 } },
      { { 0.3, 0.3 }, { 0.35, 0.3 }, { 0.35, 0.35 }, { 0.3, 0.35 } },
      { { 0.7, 0.7 }, { 0.75, 0.7 }, { 0.75, 0.75 }, { 0.7, 0.75 } },
      { { 0.5, 0.7 }, { 0.55, 0.7 }, { 0.55, 0.75 }, { 0.5, 0.75 } },
    };
    for (size_t i = 0; i < polygons.size(); ++i)
    {
      TracedCurve c;
      if (tracer.Trace(polygons[i], true, static_cast<int>(i % 3), static_cast<int>(i), c))
      {
        s.Curves.push_back(std::move(c));
      }
    }
    ArrangementOptions options;
    if (!ComputeArrangement(*s.Mesh, s.Curves, options, s.Arr, s.Error))
    {
      s.Curves.clear();
    }
    return s;
  }();
  return scene;
}

void Counters(benchmark::State& state, const PlugScene& s)
{
  std::size_t boundaryEdges = 0;
  for (const BoundaryLoop& loop : s.Topology.BoundaryLoops)
  {
    boundaryEdges += loop.HalfEdges.size();
  }
  state.counters["triangles"] = s.Mesh->GetNumberOfTriangles();
  state.counters["boundary_edges"] = static_cast<double>(boundaryEdges);
  state.counters["curves"] = static_cast<double>(s.Curves.size());
  state.counters["cells"] = s.Arr.NumberOfCells;
}

// The plugs alone: the boundary's sub-edges, their links and the arcs of patches along it.
void BoundaryPlugsOnly(benchmark::State& state)
{
  const PlugScene& s = Scene();
  if (s.Curves.empty())
  {
    state.SkipWithError(("no arrangement: " + s.Error).c_str());
    return;
  }
  std::size_t links = 0;
  for (auto _ : state)
  {
    const BoundaryPlugs plugs = FindBoundaryPlugs(*s.Mesh, s.Topology, s.Arr);
    links = plugs.Links.size();
    benchmark::DoNotOptimize(links);
  }
  Counters(state, s);
  state.counters["links"] = static_cast<double>(links);
}

// The labeling an edit runs: its input (cell graph, components, plugs) and the labels.
void LabelingWithPlugs(benchmark::State& state)
{
  const PlugScene& s = Scene();
  if (s.Curves.empty())
  {
    state.SkipWithError(("no arrangement: " + s.Error).c_str());
    return;
  }
  for (auto _ : state)
  {
    const LabelingResult labels =
      LabelCells(MakeLabelingInput(*s.Mesh, s.Topology, s.Curves, s.Arr));
    benchmark::DoNotOptimize(labels.Labels.data());
  }
  Counters(state, s);
}

} // namespace

BENCHMARK(BoundaryPlugsOnly)
  ->Unit(benchmark::kMillisecond)
  ->Repetitions(5)
  ->ReportAggregatesOnly(true);
BENCHMARK(LabelingWithPlugs)
  ->Unit(benchmark::kMillisecond)
  ->Repetitions(5)
  ->ReportAggregatesOnly(true);

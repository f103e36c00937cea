// A crowded triangle (issue 28): random lattice drawings (two shapes, with repeated points,
// spikes and runs shared between polygons) on a square of two mesh triangles, so that all the
// pieces and crossings fall in one or two triangles. Arguments: the lattice size and the number
// of polygons; one thread. Counters: the arrangement's stages (refinement is the one that
// used to be quadratic in a triangle's points), the drawing's segments and the most refined
// triangles any mesh triangle was cut into.
#include "Arrangement/Arrangement.h"
#include "Arrangement/SegmentIntersection.h"
#include "Arrangement/TriangleRefinement.h"
#include "Mesh/ProceduralMeshes.h"
#include "Support/PlanarWinding.h"
#include "Support/SyntheticCurves.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace boolsurf;
using namespace boolsurf::testing;

namespace
{

void BM_CrowdedTriangle(benchmark::State& state)
{
  const int lattice = static_cast<int>(state.range(0));
  const int polygons = static_cast<int>(state.range(1));
  MeshData square = MakeFlatSquare(1, lattice + 2.0, 0.0, 0);
  for (Vec3& p : square.Positions)
  {
    p.x -= 1;
    p.y -= 1;
  }
  const TriangleMesh mesh(square.Positions, square.Triangles);
  std::mt19937 rng(static_cast<std::uint32_t>(lattice * 1000 + polygons));
  std::vector<LatticePolygon> drawing;
  for (int p = 0; p < polygons; ++p)
  {
    drawing.push_back({ p % 2, LatticePolygonPoints(rng, lattice, drawing) });
  }
  FlatPolygonTracer tracer(mesh);
  std::vector<TracedCurve> curves;
  std::size_t segments = 0;
  for (std::size_t i = 0; i < drawing.size(); ++i)
  {
    std::vector<Vec2> points;
    for (const auto& q : drawing[i].Points)
    {
      points.push_back({ double(q[0]), double(q[1]) });
    }
    TracedCurve c;
    if (tracer.Trace(points, true, drawing[i].Shape, static_cast<int>(i), c))
    {
      segments += points.size();
      curves.push_back(std::move(c));
    }
  }
  ArrangementOptions options;
  options.Threads = 1;
  Arrangement arr;
  std::string error;
  double refine = 0, intersect = 0, flood = 0, total = 0;
  for (auto _ : state)
  {
    if (!ComputeArrangement(mesh, curves, options, arr, error))
    {
      state.SkipWithError(error.c_str());
      return;
    }
    refine += arr.Times.Refinement;
    intersect += arr.Times.Intersections;
    flood += arr.Times.FloodFill;
    total += arr.Times.Total;
  }
  int most = 0;
  for (int t = 0; t < arr.NumberOfMeshTriangles; ++t)
  {
    most = std::max(most, CountRefinedTriangles(mesh, arr, t));
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["segments"] = static_cast<double>(segments);
  state.counters["refined_per_triangle"] = most;
  state.counters["points"] = static_cast<double>(arr.GetNumberOfPoints());
  state.counters["intersect_ms"] = intersect / n;
  state.counters["refine_ms"] = refine / n;
  state.counters["flood_ms"] = flood / n;
  state.counters["total_ms"] = total / n;
}

} // namespace

BENCHMARK(BM_CrowdedTriangle)
  ->Args({ 16, 16 })
  ->Args({ 24, 48 })
  ->Args({ 48, 96 })
  ->Args({ 96, 192 })
  // Ten thousand segments on a 7 x 7 lattice: thousands of segments along shared lines.
  ->Args({ 6, 1500 })
  ->Unit(benchmark::kMillisecond);

namespace
{

// Stage 3 alone on one triangle, as the number of pieces k grows: random short segments (about
// three crossings each), cut exactly by stage 2 once, then triangulated by the sweep on a fresh
// copy per iteration. The counter ns_per_k_log_k stays flat when the cost is O(k log k).
void BM_TriangleRefinementScaling(benchmark::State& state)
{
  const int segments = static_cast<int>(state.range(0));
  std::mt19937 rng(28);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  LocalArrangement drawn;
  drawn.Triangle = 0;
  drawn.Points = { { { 0, 0 }, 0, 3 }, { { 1, 0 }, 1, 4 }, { { 0, 1 }, 2, 5 } };
  drawn.Boundary = { 0, 1, 2 };
  const double length = 2.0 / std::sqrt(static_cast<double>(segments));
  for (int k = 0; k < segments; ++k)
  {
    double u = unit(rng), v = unit(rng);
    if (u + v > 1)
    {
      u = 1 - u;
      v = 1 - v;
    }
    const Vec2 a{ 0.01 + 0.9 * u, 0.01 + 0.9 * v };
    const double angle = 6.283185307179586 * unit(rng);
    Vec2 b{ a.x + length * std::cos(angle), a.y + length * std::sin(angle) };
    b = { std::min(0.98, std::max(0.01, b.x)), std::min(0.98, std::max(0.01, b.y)) };
    if (b.x + b.y > 0.98)
    {
      const double s = 0.98 / (b.x + b.y);
      b = { b.x * s, b.y * s };
    }
    const int ia = static_cast<int>(drawn.Points.size());
    drawn.Points.push_back({ a, -1, -1 });
    drawn.Points.push_back({ b, -1, -1 });
    drawn.Chains.push_back({ ia, ia + 1 });
    drawn.ChainClosed.push_back(1);
  }
  CutSegmentsAtIntersections(drawn, 0.0);
  std::size_t pieces = 0;
  for (const std::vector<int>& chain : drawn.Chains)
  {
    pieces += chain.size() - 1;
  }
  std::size_t triangles = 0;
  for (auto _ : state)
  {
    LocalArrangement arr = drawn;
    if (!RefineTriangle(arr))
    {
      state.SkipWithError(arr.Error.c_str());
      return;
    }
    triangles = arr.Triangles.size();
    benchmark::DoNotOptimize(arr.Triangles.data());
  }
  const double k = static_cast<double>(pieces);
  state.counters["pieces"] = k;
  state.counters["points"] = static_cast<double>(drawn.Points.size());
  state.counters["triangles"] = static_cast<double>(triangles);
  state.counters["ns_per_k_log_k"] = benchmark::Counter(
    k * std::log2(k), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

} // namespace

BENCHMARK(BM_TriangleRefinementScaling)
  ->Arg(1000)
  ->Arg(10000)
  ->Arg(100000)
  ->Unit(benchmark::kMillisecond);

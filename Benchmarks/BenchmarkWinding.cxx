// Surface winding numbers (Core/Winding) of ten broken circles on igea_1m and on igea_1m
// subdivided once (4.3M triangles), what a user waits for:
//  * WindingFirstUpdate: a new surface: the arrangement of the broken curves, the Laplacian's
//    factorization (analysis + numeric), the lifts, the back-substitution and the field, from a
//    fresh SurfaceWinding each iteration. Counters split the stages (ms) and give the factor's
//    nonzeros and the process's peak resident memory above the mesh.
//  * WindingEdit: one circle moved, on the same surface: arrangement and winding again with the
//    kept factorization (a right-hand side and a back-substitution per shape).
//  * WindingEditAll: all ten circles moved at once.
// Each circle is broken by two gaps of 2% of its points; each is a shape of its own, or the ten
// are one shape. Circles are plane sections
// near the mesh's extreme points in ten directions (small loops), as in the other benchmarks.
#include "SharedMeshes.h"

#include "Arrangement/Arrangement.h"
#include "Mesh/TriangleMesh.h"
#include "Support/SyntheticCurves.h"
#include "Winding/SurfaceWinding.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <string>

using namespace boolsurf;

namespace
{

/// Peak (VmHWM) or current (VmRSS) resident memory of this process, MB.
double ResidentMB(const char* which = "VmHWM:")
{
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key)
  {
    if (key == which)
    {
      double kb = 0;
      status >> kb;
      return kb / 1024.0;
    }
  }
  return 0.0;
}

/// One 1-to-4 midpoint subdivision.
MeshData Subdivide(const MeshData& in)
{
  const TriangleMesh mesh(in.Positions, in.Triangles);
  MeshData out;
  out.Positions = in.Positions;
  const int nv = static_cast<int>(in.Positions.size());
  std::vector<int> middle(mesh.GetNumberOfEdges(), -1);
  for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    int m[3];
    for (int k = 0; k < 3; ++k)
    {
      const int e = mesh.GetEdgeId(t, k);
      if (middle[e] < 0)
      {
        const std::array<int, 2> ends = mesh.GetEdgeVertices(e);
        middle[e] = static_cast<int>(out.Positions.size());
        out.Positions.push_back(0.5 * (in.Positions[ends[0]] + in.Positions[ends[1]]));
      }
      m[k] = middle[e];
    }
    const auto& c = in.Triangles[t];
    out.Triangles.push_back({ c[0], m[0], m[2] });
    out.Triangles.push_back({ c[1], m[1], m[0] });
    out.Triangles.push_back({ c[2], m[2], m[1] });
    out.Triangles.push_back({ m[0], m[1], m[2] });
  }
  (void)nv;
  return out;
}

struct WindingScene
{
  std::unique_ptr<TriangleMesh> Mesh;
  std::vector<Vec3> Normals;
  std::vector<double> Offsets;
  std::string Error;
};

/// The broken circles of the scene, circle `moved` (all when -1) shifted by `shift`; each its
/// own shape, or all one shape.
std::vector<TracedCurve> BrokenCircles(const WindingScene& s,
  int moved,
  double shift,
  bool oneShape)
{
  std::vector<TracedCurve> curves;
  for (size_t c = 0; c < s.Normals.size(); ++c)
  {
    const double offset = s.Offsets[c] + (moved < 0 || moved == static_cast<int>(c) ? shift : 0.0);
    const std::vector<TracedCurve> loops =
      PlaneSectionCurves(*s.Mesh, s.Normals[c], offset, static_cast<int>(c));
    if (loops.empty() || !loops[0].Closed)
    {
      continue;
    }
    const std::vector<CanonicalPoint>& points = loops[0].Points;
    const int n = static_cast<int>(points.size());
    const int gap = std::max(1, n / 50);
    for (int g = 0; g < 2; ++g)
    {
      TracedCurve piece;
      piece.Closed = false;
      piece.ShapeId = oneShape ? 0 : static_cast<int>(c);
      piece.CurveId = oneShape ? static_cast<int>(2 * c) + g : g;
      for (int i = g * n / 2; i <= (g + 1) * n / 2 - gap; ++i)
      {
        piece.Points.push_back(points[i % n]);
      }
      curves.push_back(std::move(piece));
    }
  }
  return curves;
}

const WindingScene& Scene(int subdivisions)
{
  static std::map<int, WindingScene> scenes;
  auto it = scenes.find(subdivisions);
  if (it != scenes.end())
  {
    return it->second;
  }
  WindingScene& s = scenes[subdivisions];
  const MeshData* data = benchutil::LoadSharedMesh("igea_1m.ply", s.Error);
  if (!data)
  {
    return s;
  }
  MeshData d = *data;
  for (int i = 0; i < subdivisions; ++i)
  {
    d = Subdivide(d);
  }
  s.Mesh = std::make_unique<TriangleMesh>(d.Positions, d.Triangles);
  // Ten directions; each circle cuts 3% of the mesh's extent below its extreme point.
  const Vec3 directions[10] = { { 1, 0.1, 0.2 },
    { -1, 0.2, 0.1 },
    { 0.1, 1, 0.3 },
    { 0.2, -1, 0.1 },
    { 0.3, 0.1, 1 },
    { 0.7, 0.7, 0.1 },
    { -0.7, 0.6, 0.2 },
    { 0.6, -0.7, 0.3 },
    { -0.6, -0.6, 0.4 },
    { 0.5, 0.2, 0.8 } };
  for (const Vec3& d0 : directions)
  {
    const Vec3 n = (1.0 / Length(d0)) * d0;
    double lo = 1e300, hi = -1e300;
    for (const Vec3& p : d.Positions)
    {
      lo = std::min(lo, Dot(n, p));
      hi = std::max(hi, Dot(n, p));
    }
    s.Normals.push_back(n);
    s.Offsets.push_back(hi - 0.03 * (hi - lo));
  }
  return s;
}

void Counters(benchmark::State& state,
  const WindingScene& s,
  const Arrangement& arr,
  const WindingResult& w,
  size_t curves)
{
  state.counters["triangles"] = s.Mesh->GetNumberOfTriangles();
  state.counters["curves"] = static_cast<double>(curves);
  state.counters["shapes"] = w.GetNumberOfShapes();
  state.counters["curve_points"] = arr.GetNumberOfPoints() - arr.NumberOfMeshVertices;
  state.counters["jump_triangles"] = static_cast<double>(w.JumpTriangles.size());
}

void WindingFirstUpdate(benchmark::State& state)
{
  const WindingScene& s = Scene(static_cast<int>(state.range(0)));
  if (!s.Mesh)
  {
    state.SkipWithError(s.Error.c_str());
    return;
  }
  const std::vector<TracedCurve> curves = BrokenCircles(s, -1, 0.0, state.range(1) == 1);
  // Peak above what the process holds now (the mesh, read and built): run this benchmark in a
  // process of its own (--benchmark_filter) so that no earlier peak hides it.
  const double before = ResidentMB("VmRSS:");
  Arrangement arr;
  WindingResult w;
  double arrangeMs = 0;
  for (auto _ : state)
  {
    const auto start = std::chrono::steady_clock::now();
    Arrangement fresh;
    std::string error;
    if (!ComputeArrangement(*s.Mesh, curves, ArrangementOptions(), fresh, error))
    {
      state.SkipWithError(error.c_str());
      return;
    }
    arrangeMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    SurfaceWinding winding;
    if (!winding.Compute(*s.Mesh, fresh, curves, WindingOptions(), w, error))
    {
      state.SkipWithError(error.c_str());
      return;
    }
    arr = std::move(fresh);
  }
  Counters(state, s, arr, w, curves.size());
  state.counters["arrangement_ms"] = arrangeMs;
  state.counters["factorization_ms"] = w.Times.Factorization;
  state.counters["lift_ms"] = w.Times.Lift;
  state.counters["solve_ms"] = w.Times.Solve;
  state.counters["outputs_ms"] = w.Times.Outputs;
  state.counters["solves"] = w.Times.BackSubstitutions;
  state.counters["dropped_edges"] = w.Times.DroppedEdges;
  state.counters["peak_MB_above_mesh"] = ResidentMB() - before;
}

void Edit(benchmark::State& state, bool all)
{
  const WindingScene& s = Scene(static_cast<int>(state.range(0)));
  if (!s.Mesh)
  {
    state.SkipWithError(s.Error.c_str());
    return;
  }
  // Two positions of the moved circle(s), alternated, on one kept arrangement and winding.
  const bool oneShape = state.range(1) == 1;
  const std::vector<TracedCurve> at[2] = { BrokenCircles(s, all ? -1 : 0, 0.0, oneShape),
    BrokenCircles(s, all ? -1 : 0, 0.002, oneShape) };
  Arrangement arr;
  SurfaceWinding winding;
  WindingResult w;
  std::string error;
  if (!ComputeArrangement(*s.Mesh, at[0], ArrangementOptions(), arr, error) ||
    !winding.Compute(*s.Mesh, arr, at[0], WindingOptions(), w, error))
  {
    state.SkipWithError(error.c_str());
    return;
  }
  int k = 0;
  double arrangeMs = 0;
  for (auto _ : state)
  {
    k = 1 - k;
    const auto start = std::chrono::steady_clock::now();
    if (!ComputeArrangement(*s.Mesh, at[k], ArrangementOptions(), arr, error))
    {
      state.SkipWithError(error.c_str());
      return;
    }
    arrangeMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (!winding.Compute(*s.Mesh, arr, at[k], WindingOptions(), w, error))
    {
      state.SkipWithError(error.c_str());
      return;
    }
  }
  Counters(state, s, arr, w, at[k].size());
  state.counters["arrangement_ms"] = arrangeMs;
  state.counters["lift_ms"] = w.Times.Lift;
  state.counters["solve_ms"] = w.Times.Solve;
  state.counters["outputs_ms"] = w.Times.Outputs;
  state.counters["solves"] = w.Times.BackSubstitutions;
  state.counters["dropped_edges"] = w.Times.DroppedEdges;
}

void WindingEdit(benchmark::State& state)
{
  Edit(state, false);
}

void WindingEditAll(benchmark::State& state)
{
  Edit(state, true);
}

} // namespace

// Arguments: subdivisions of igea_1m (0: 1.07M triangles, 1: 4.3M), shapes (10: one per
// circle, 1: the ten circles one shape).
BENCHMARK(WindingFirstUpdate)
  ->Args({ 0, 10 })
  ->Args({ 0, 1 })
  ->Args({ 1, 10 })
  ->Unit(benchmark::kMillisecond)
  ->Iterations(1)
  ->Repetitions(3);
BENCHMARK(WindingEdit)
  ->Args({ 0, 10 })
  ->Args({ 0, 1 })
  ->Args({ 1, 10 })
  ->Args({ 1, 1 })
  ->Unit(benchmark::kMillisecond)
  ->Repetitions(5);
BENCHMARK(WindingEditAll)
  ->Args({ 0, 10 })
  ->Args({ 1, 10 })
  ->Unit(benchmark::kMillisecond)
  ->Repetitions(3);

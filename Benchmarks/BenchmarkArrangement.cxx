// Arrangement time per stage (hash, intersections, refinement, flood fill, cell graph) on
// ~1M-triangle meshes:
//  * FlatSquare: 1M-triangle jittered square, random self-intersecting polygons of straight
//    chords (the tracing stage's exact output on a flat mesh);
//  * Icosphere8: level-8 icosphere (1.3M triangles), great and small circles (plane sections);
//  * igea_1m / 3torus_800k from the shared data, closed geodesic polygons traced by
//    CurveTracer through random nearby points (skipped when the files are missing);
//  * BoolSurf reference scenes (../shared/data/boolsurf-scenes) on their 5k-200k meshes;
//  * EditTime*: the same curves (an icosphere's plane sections) on a ~100k and a ~1M mesh.
// Curve construction is outside the timed loop. The argument is the thread count; per-stage
// milliseconds are reported as counters (averages over iterations, and minima: min_*).
#include "Arrangement/Arrangement.h"
#include "Geodesic/CurveTracer.h"
#include "Mesh/PlyReader.h"
#include "Mesh/ProceduralMeshes.h"
#include "Support/SyntheticCurves.h"

#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp> // header-only (system include)

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <random>
#include <string>

using namespace boolsurf;

namespace
{
/// The message of the last failed trace or path (a test reads it only after a failure).
std::string traceError;
}

namespace
{

struct Scene
{
  std::unique_ptr<TriangleMesh> Mesh;
  std::vector<TracedCurve> Curves;
  std::string Error;
  size_t CurvePoints = 0;
};

void CountPoints(Scene& s)
{
  for (const TracedCurve& c : s.Curves)
    s.CurvePoints += c.Points.size();
}

Scene MakeFlatScene(int polygons, int sides, int cells = 708)
{
  Scene s;
  const MeshData d = MakeFlatSquare(cells, 1.0, 0.3, 17); // 708: 1,002,528 triangles
  s.Mesh.reset(new TriangleMesh(d.Positions, d.Triangles));
  FlatPolygonTracer tracer(*s.Mesh);
  std::mt19937 rng(123);
  std::uniform_real_distribution<double> center(0.15, 0.85), radius(0.03, 0.15);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int p = 0; p < polygons; ++p)
  {
    // Random points around a random center: self-intersecting star-like polygons.
    const double cx = center(rng), cy = center(rng), r = radius(rng);
    std::vector<Vec2> poly;
    for (int k = 0; k < sides; ++k)
    {
      const double a = 2.0 * 3.14159265358979 * unit(rng), q = r * (0.3 + 0.7 * unit(rng));
      poly.push_back({ cx + q * std::cos(a), cy + q * std::sin(a) });
    }
    TracedCurve c;
    if (tracer.Trace(poly, true, p % 8, p, c))
      s.Curves.push_back(std::move(c));
  }
  CountPoints(s);
  return s;
}

Scene MakeSphereScene(int circles)
{
  Scene s;
  const MeshData d = MakeIcosphere(8);
  s.Mesh.reset(new TriangleMesh(d.Positions, d.Triangles));
  std::mt19937 rng(7);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> offset(-0.6, 0.6);
  for (int c = 0; c < circles; ++c)
  {
    Vec3 n{ g(rng), g(rng), g(rng) };
    n = (1.0 / Length(n)) * n;
    // Half great circles, half small circles.
    for (TracedCurve& curve : PlaneSectionCurves(*s.Mesh, n, c % 2 ? offset(rng) : 0.0, c % 8, c))
      s.Curves.push_back(std::move(curve));
  }
  CountPoints(s);
  return s;
}

Scene MakeTracedScene(const std::string& name, int polygons)
{
  Scene s;
  MeshData d;
  if (!ReadPly(std::string(BOOLSURF_SHARED_DATA_DIR) + "/meshes/" + name, d, s.Error))
    return s;
  s.Mesh.reset(new TriangleMesh(d.Positions, d.Triangles));
  const TriangleMesh& mesh = *s.Mesh;
  const int nt = mesh.GetNumberOfTriangles();
  // Polygon size: a few percent of the bounding box diagonal.
  Vec3 lo{ 1e300, 1e300, 1e300 }, hi{ -1e300, -1e300, -1e300 };
  for (const Vec3& p : mesh.GetPositions())
  {
    lo = { std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z) };
    hi = { std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z) };
  }
  const double reach = 0.06 * Distance(lo, hi);
  std::vector<Vec3> centroid(nt);
  for (int t = 0; t < nt; ++t)
    centroid[t] = (1.0 / 3.0) *
      (mesh.GetCornerPosition(t, 0) + mesh.GetCornerPosition(t, 1) + mesh.GetCornerPosition(t, 2));
  CurveTracer tracer(mesh);
  std::mt19937 rng(99);
  std::uniform_int_distribution<int> anyTriangle(0, nt - 1);
  for (int p = 0; p < polygons; ++p)
  {
    const int seed = anyTriangle(rng);
    if (!mesh.IsUsable(seed))
      continue;
    std::vector<CanonicalPoint> points;
    for (int attempt = 0; attempt < 20000 && points.size() < 5; ++attempt)
    {
      const int t = anyTriangle(rng);
      if (mesh.IsUsable(t) && Distance(centroid[t], centroid[seed]) < reach)
      {
        CanonicalPoint c;
        c.Location = PointLocation::Face;
        c.Id = t;
        c.U = c.V = 1.0 / 3.0;
        points.push_back(c);
      }
    }
    if (points.size() < 3)
      continue;
    CurveTrace trace;
    if (tracer.TraceGeodesicPolygon(points, true, trace, traceError, p))
    {
      trace.Curve.ShapeId = p % 8;
      trace.Curve.CurveId = p;
      s.Curves.push_back(trace.Curve);
    }
  }
  CountPoints(s);
  return s;
}

// A BoolSurf reference scene (../shared/data/boolsurf-scenes; see TestReferenceScenes.cxx):
// its geodesic polygons traced through the control points.
Scene MakeReferenceScene(const std::string& file, const std::string& meshName)
{
  Scene s;
  const std::string root = std::string(BOOLSURF_SHARED_DATA_DIR);
  MeshData d;
  if (!ReadPly(root + "/meshes/" + meshName, d, s.Error))
    return s;
  s.Mesh.reset(new TriangleMesh(d.Positions, d.Triangles));
  std::ifstream in(root + "/boolsurf-scenes/" + file);
  nlohmann::json scene;
  try
  {
    in >> scene;
  }
  catch (const std::exception& e)
  {
    s.Error = file + ": " + e.what();
    s.Mesh.reset();
    return s;
  }
  std::vector<SurfacePoint> points;
  for (const nlohmann::json& p : scene.at("points"))
    points.push_back(
      { p.at("face").get<int>(), p.at("uv")[0].get<double>(), p.at("uv")[1].get<double>() });
  CurveTracer tracer(*s.Mesh);
  const nlohmann::json& polygons = scene.at("polygons");
  for (size_t i = 0; i < polygons.size(); ++i)
  {
    std::vector<SurfacePoint> control;
    for (const nlohmann::json& k : polygons[i])
      control.push_back(points.at(k.get<size_t>()));
    const bool closed = !scene.contains("are_closed") || i >= scene.at("are_closed").size() ||
      scene.at("are_closed")[i].get<bool>();
    CurveTrace trace;
    if (control.size() >= 2 &&
      tracer.Trace(
        control, CurveType::GeodesicPolygon, closed, trace, traceError, static_cast<int>(i)))
    {
      trace.Curve.ShapeId = static_cast<int>(i);
      s.Curves.push_back(trace.Curve);
    }
  }
  CountPoints(s);
  return s;
}

Scene& GetScene(const std::string& key)
{
  static std::map<std::string, Scene> cache;
  auto it = cache.find(key);
  if (it != cache.end())
    return it->second;
  Scene& s = cache[key];
  if (key == "flat")
    s = MakeFlatScene(40, 12);
  else if (key == "flat100k")
    s = MakeFlatScene(40, 12, 224); // 100,352 triangles, the same polygons
  else if (key == "sphere")
    s = MakeSphereScene(30);
  else if (key.find(".json") != std::string::npos)
  {
    const size_t bar = key.find('|');
    s = MakeReferenceScene(key.substr(0, bar), key.substr(bar + 1));
  }
  else
    s = MakeTracedScene(key, 40);
  return s;
}

void RunArrangement(benchmark::State& state, const std::string& key)
{
  Scene& scene = GetScene(key);
  if (!scene.Mesh || scene.Curves.empty())
  {
    state.SkipWithError(("scene unavailable: " + scene.Error).c_str());
    return;
  }
  ArrangementOptions options;
  options.Threads = static_cast<int>(state.range(0));
  ArrangementStageTimes sum, best;
  best.Hash = best.Intersections = best.Refinement = best.FloodFill = best.CellGraph = best.Total =
    1e300;
  Arrangement arr;
  std::string error;
  for (auto _ : state)
  {
    if (!ComputeArrangement(*scene.Mesh, scene.Curves, options, arr, error))
    {
      state.SkipWithError(error.c_str());
      return;
    }
    sum.Hash += arr.Times.Hash;
    sum.Intersections += arr.Times.Intersections;
    sum.Refinement += arr.Times.Refinement;
    sum.FloodFill += arr.Times.FloodFill;
    sum.CellGraph += arr.Times.CellGraph;
    sum.Total += arr.Times.Total;
    best.Hash = std::min(best.Hash, arr.Times.Hash);
    best.Intersections = std::min(best.Intersections, arr.Times.Intersections);
    best.Refinement = std::min(best.Refinement, arr.Times.Refinement);
    best.FloodFill = std::min(best.FloodFill, arr.Times.FloodFill);
    best.CellGraph = std::min(best.CellGraph, arr.Times.CellGraph);
    best.Total = std::min(best.Total, arr.Times.Total);
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["hash_ms"] = sum.Hash / n;
  state.counters["intersect_ms"] = sum.Intersections / n;
  state.counters["refine_ms"] = sum.Refinement / n;
  state.counters["flood_ms"] = sum.FloodFill / n;
  state.counters["cellgraph_ms"] = sum.CellGraph / n;
  state.counters["total_ms"] = sum.Total / n;
  // Minimum over iterations: robust when other processes share the cores.
  state.counters["min_hash_ms"] = best.Hash;
  state.counters["min_intersect_ms"] = best.Intersections;
  state.counters["min_refine_ms"] = best.Refinement;
  state.counters["min_flood_ms"] = best.FloodFill;
  state.counters["min_cellgraph_ms"] = best.CellGraph;
  state.counters["min_total_ms"] = best.Total;
  state.counters["triangles"] = scene.Mesh->GetNumberOfTriangles();
  state.counters["curves"] = static_cast<double>(scene.Curves.size());
  state.counters["curve_points"] = static_cast<double>(scene.CurvePoints);
  state.counters["refined_tris"] = arr.NumberOfRefinedSourceTriangles;
  state.counters["cells"] = arr.NumberOfCells;
  state.counters["patches"] = static_cast<double>(arr.Patches.size());
}

} // namespace

BENCHMARK_CAPTURE(RunArrangement, FlatSquare1M, std::string("flat"))
  ->Arg(1)
  ->Arg(2)
  ->Unit(benchmark::kMillisecond);
// Edit time: the same 40 polygons on a 100k and on the 1M square (FlatSquare1M).
BENCHMARK_CAPTURE(RunArrangement, EditTimeFlatSquare100k, std::string("flat100k"))
  ->Arg(1)
  ->Arg(2)
  ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(RunArrangement, Icosphere8, std::string("sphere"))
  ->Arg(1)
  ->Arg(2)
  ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(RunArrangement, Igea1M, std::string("igea_1m.ply"))
  ->Arg(1)
  ->Arg(2)
  ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(RunArrangement, ThreeTorus800k, std::string("3torus_800k.ply"))
  ->Arg(1)
  ->Arg(2)
  ->Unit(benchmark::kMillisecond);

// BoolSurf reference scenes on the largest available meshes ("scene|mesh").
BENCHMARK_CAPTURE(RunArrangement, SceneBimba100k, std::string("final_tests/bimba.json|bimba.ply"))
  ->Arg(1)
  ->Arg(2)
  ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(RunArrangement,
  SceneBunny2_144k,
  std::string("tests/bunny2.json|bunny_boolsurf.ply"))
  ->Arg(1)
  ->Arg(2)
  ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(RunArrangement,
  SceneTritorus13Loops200k,
  std::string("tests/examples/tritorus-13loops.json|3torus_200k.ply"))
  ->Arg(1)
  ->Arg(2)
  ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(RunArrangement,
  SceneSpiral3Torus200k,
  std::string("tests/3torus-spiral-rev.json|3torus_200k.ply"))
  ->Arg(1)
  ->Arg(2)
  ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(RunArrangement,
  SceneBitorusHomotopy5_200k,
  std::string("tests/bitorus-homotopy5.json|eight_200k.ply"))
  ->Arg(1)
  ->Arg(2)
  ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(RunArrangement,
  SceneSphere2,
  std::string("tests/sphere2.json|sphere_complete.ply"))
  ->Arg(1)
  ->Arg(2)
  ->Unit(benchmark::kMillisecond);

// Exact geodesic time against the exact oracle's: GeodesicPathSolver (window search stopped at
// the target, then the funnel) and CGAL's Surface_mesh_shortest_path (sequence tree from the
// source over the whole mesh, then one query) on the same face-point pairs of shared meshes.
// Short pairs: 2-4 % of the bounding-box diagonal apart; far pairs: the farthest of 2000
// random candidates. Counters: ours_median_ms, cgal_median_ms (per pair, wall clock, one
// thread), max_relative (length difference, relative), ours_windows (mean).
#include "Geodesic/GeodesicPath.h"
#include "Mesh/PlyReader.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_shortest_path.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace boolsurf;

namespace
{
/// The message of the last failed trace or path (a test reads it only after a failure).
std::string traceError;
}

namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalMesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Traits = CGAL::Surface_mesh_shortest_path_traits<Kernel, CgalMesh>;
using ShortestPaths = CGAL::Surface_mesh_shortest_path<Traits>;

double Milliseconds(std::chrono::steady_clock::time_point since)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - since)
    .count();
}

double Median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

void GeodesicVsCgal(benchmark::State& state, const std::string& name, bool far)
{
  MeshData data;
  std::string error;
  if (!ReadPly(std::string(BOOLSURF_SHARED_DATA_DIR) + "/meshes/" + name, data, error))
  {
    state.SkipWithError(error.c_str());
    return;
  }
  CgalMesh cgal;
  for (const Vec3& p : data.Positions)
  {
    cgal.add_vertex(Kernel::Point_3(p.x, p.y, p.z));
  }
  for (const auto& t : data.Triangles)
  {
    cgal.add_face(
      CgalMesh::Vertex_index(t[0]), CgalMesh::Vertex_index(t[1]), CgalMesh::Vertex_index(t[2]));
  }
  const TriangleMesh mesh(std::move(data.Positions), std::move(data.Triangles));
  GeodesicPathSolver solver(mesh);
  const int nt = mesh.GetNumberOfTriangles();
  Vec3 lo = mesh.GetPosition(0), hi = lo;
  for (const Vec3& p : mesh.GetPositions())
  {
    lo = { std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z) };
    hi = { std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z) };
  }
  const double diagonal = Distance(lo, hi);
  std::mt19937 rng(far ? 5 : 6);
  auto facePoint = [&](int t)
  {
    CanonicalPoint c;
    c.Id = t;
    c.U = 0.3;
    c.V = 0.25;
    return c;
  };
  auto location = [&](const CanonicalPoint& c)
  {
    const auto h = cgal.halfedge(CgalMesh::Face_index(c.Id));
    const Triangle& tri = mesh.GetTriangle(c.Id);
    const std::array<double, 3> w = WeightsInTriangle(mesh, c, c.Id);
    std::array<double, 3> b{};
    const int order[3] = { static_cast<int>(cgal.source(h)),
      static_cast<int>(cgal.target(h)),
      static_cast<int>(cgal.target(cgal.next(h))) };
    for (int i = 0; i < 3; ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        b[i] += tri[k] == order[i] ? w[k] : 0.0;
      }
    }
    return ShortestPaths::Face_location(
      CgalMesh::Face_index(c.Id), Traits::Barycentric_coordinates{ b[0], b[1], b[2] });
  };
  std::vector<double> ours, theirs;
  double worst = 0, windows = 0;
  for (auto _ : state)
  {
    const CanonicalPoint a = facePoint(static_cast<int>(rng() % nt));
    CanonicalPoint b = facePoint(static_cast<int>(rng() % nt));
    double best = far ? -1.0 : 0.0;
    for (int i = 0; i < 2000; ++i)
    {
      const CanonicalPoint q = facePoint(static_cast<int>(rng() % nt));
      const double d = Distance(PositionOf(mesh, a), PositionOf(mesh, q));
      if (far ? d > best : (d > 0.02 * diagonal && d < 0.04 * diagonal))
      {
        b = q;
        best = d;
        if (!far)
        {
          break;
        }
      }
    }
    GeodesicPath path;
    auto start = std::chrono::steady_clock::now();
    solver.Compute(a, b, path, traceError);
    ours.push_back(Milliseconds(start));
    windows += solver.GetLastStatistics().Windows;
    start = std::chrono::steady_clock::now();
    ShortestPaths oracle(cgal);
    oracle.add_source_point(location(a));
    const double expected =
      oracle.shortest_distance_to_source_points(location(b).first, location(b).second).first;
    theirs.push_back(Milliseconds(start));
    worst = std::max(worst, std::abs(path.Length - expected) / expected);
  }
  state.counters["ours_median_ms"] = Median(ours);
  state.counters["cgal_median_ms"] = Median(theirs);
  state.counters["max_relative"] = worst;
  state.counters["ours_windows"] = windows / static_cast<double>(state.iterations());
  state.counters["triangles"] = nt;
}
} // namespace

BENCHMARK_CAPTURE(GeodesicVsCgal, kitten_short, std::string("kitten.ply"), false)
  ->Iterations(8)
  ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(GeodesicVsCgal, kitten_far, std::string("kitten.ply"), true)
  ->Iterations(8)
  ->Unit(benchmark::kMillisecond);
// No larger mesh: CGAL builds its tree over the whole mesh whatever the pair, and on igea
// (134k triangles) one pair took over five minutes.

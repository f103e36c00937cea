// GeodesicPathSolver against VTK's vtkDijkstraGraphGeodesicPath on the same vertex pairs of
// large shared meshes (igea_1m, 3torus_800k): short pairs (2-4 % of the bounding-box
// diagonal apart) and long ones (the farthest of many random candidates, near-antipodal).
//
// Each iteration traces one pair with both and times each call separately (CPU time of the
// calling thread, so a busy machine does not skew the ratio; both run on one thread). VTK's graph
// adjacency is built on the first Update() after a new input: that build is timed once per mesh
// (Dijkstra_AdjacencyBuild) and kept out of the per-path times, which are taken with
// StopWhenEndReachedOn. Counters: ours_ms / vtk_ms (mean per path), vtk_over_ours (time ratio),
// length_ratio_max / length_ratio_mean (our length over Dijkstra's edge-path length: never above
// 1), ours_setup_s (TriangleMesh adjacency and solver construction), ours_landmarks_s and
// ours_landmarks_MB (the edge-path search's landmark table, built once per mesh).
#include "Geodesic/GeodesicPath.h"

#include <vtkCellArray.h>
#include <vtkDijkstraGraphGeodesicPath.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPLYReader.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <ctime>
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
struct Clock
{
  using time_point = double;
  static double now()
  {
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
  }
};

double Seconds(double a, double b)
{
  return b - a;
}

struct LoadedMesh
{
  vtkSmartPointer<vtkPolyData> PolyData;
  std::unique_ptr<TriangleMesh> Mesh;
  std::unique_ptr<GeodesicPathSolver> Solver;
  vtkSmartPointer<vtkDijkstraGraphGeodesicPath> Dijkstra; // adjacency built once
  double DijkstraBuildSeconds = 0;
  double SolverSetupSeconds = 0;
  double LandmarkSeconds = 0;
  std::vector<std::pair<int, int>> ShortPairs, LongPairs;
  std::string Error;
};

double VtkPathLength(vtkPolyData* pd, vtkIdList* ids)
{
  double length = 0;
  for (vtkIdType i = 1; i < ids->GetNumberOfIds(); ++i)
  {
    double a[3], b[3];
    pd->GetPoint(ids->GetId(i - 1), a);
    pd->GetPoint(ids->GetId(i), b);
    length += Distance(Vec3{ a[0], a[1], a[2] }, Vec3{ b[0], b[1], b[2] });
  }
  return length;
}

LoadedMesh& Load(const std::string& name)
{
  static std::map<std::string, LoadedMesh> cache;
  auto it = cache.find(name);
  if (it != cache.end())
  {
    return it->second;
  }
  LoadedMesh& m = cache[name];
  const std::string path = std::string(BOOLSURF_SHARED_DATA_DIR) + "/meshes/" + name;
  vtkNew<vtkPLYReader> reader;
  if (!vtkPLYReader::CanReadFile(path.c_str()))
  {
    m.Error = "cannot read " + path;
    return m;
  }
  reader->SetFileName(path.c_str());
  reader->Update();
  m.PolyData = reader->GetOutput();
  vtkPolyData* pd = m.PolyData;
  if (!pd || pd->GetNumberOfPolys() == 0)
  {
    m.Error = "no triangles in " + path;
    return m;
  }

  // Same points and triangles (same ids) for our solver.
  const auto setup0 = Clock::now();
  std::vector<Vec3> positions(pd->GetNumberOfPoints());
  for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i)
  {
    double p[3];
    pd->GetPoint(i, p);
    positions[i] = { p[0], p[1], p[2] };
  }
  std::vector<Triangle> triangles;
  triangles.reserve(pd->GetNumberOfPolys());
  vtkCellArray* polys = pd->GetPolys();
  vtkNew<vtkIdList> cell;
  for (polys->InitTraversal(); polys->GetNextCell(cell);)
  {
    if (cell->GetNumberOfIds() == 3)
    {
      triangles.push_back({ static_cast<int>(cell->GetId(0)),
        static_cast<int>(cell->GetId(1)),
        static_cast<int>(cell->GetId(2)) });
    }
  }
  m.Mesh = std::make_unique<TriangleMesh>(std::move(positions), std::move(triangles));
  m.Solver = std::make_unique<GeodesicPathSolver>(*m.Mesh);
  // Exact: the comparison is the shortest path against the shortest edge path (a routed
  // Bounded leg may be longer than the shortest edge path).
  GeodesicPathOptions options;
  options.Method = GeodesicMethod::Exact;
  m.Solver->SetOptions(options);
  m.SolverSetupSeconds = Seconds(setup0, Clock::now());
  // The landmark table of the edge-path search (built lazily otherwise), timed apart.
  const auto landmarks0 = Clock::now();
  m.Solver->PrepareLandmarks();
  m.LandmarkSeconds = Seconds(landmarks0, Clock::now());

  // VTK's adjacency build: the first Update on the new input, for a trivial pair (a vertex
  // and itself) so the search itself costs nothing.
  const TriangleMesh& mesh = *m.Mesh;
  m.Dijkstra = vtkSmartPointer<vtkDijkstraGraphGeodesicPath>::New();
  m.Dijkstra->SetInputData(pd);
  m.Dijkstra->StopWhenEndReachedOn();
  const int firstVertex = mesh.GetTriangle(0)[0];
  m.Dijkstra->SetStartVertex(firstVertex);
  m.Dijkstra->SetEndVertex(firstVertex);
  const auto build0 = Clock::now();
  m.Dijkstra->Update();
  m.DijkstraBuildSeconds = Seconds(build0, Clock::now());

  // Vertex pairs on one connected component, used by some triangle.
  Vec3 lo = mesh.GetPosition(0), hi = lo;
  for (const Vec3& p : mesh.GetPositions())
  {
    lo = { std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z) };
    hi = { std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z) };
  }
  const double diagonal = Distance(lo, hi);
  std::mt19937 rng(2024);
  auto randomVertex = [&](int& component)
  {
    for (;;)
    {
      const int t = static_cast<int>(rng() % mesh.GetNumberOfTriangles());
      if (mesh.IsUsable(t))
      {
        component = m.Solver->GetComponent(t);
        return mesh.GetTriangle(t)[rng() % 3];
      }
    }
  };
  while (m.ShortPairs.size() < 24)
  {
    int ca = 0, cb = 0;
    const int a = randomVertex(ca);
    for (int tries = 0; tries < 2000000; ++tries)
    {
      const int b = randomVertex(cb);
      const double d = Distance(mesh.GetPosition(a), mesh.GetPosition(b));
      if (ca == cb && d > 0.02 * diagonal && d < 0.04 * diagonal)
      {
        m.ShortPairs.push_back({ a, b });
        break;
      }
    }
  }
  while (m.LongPairs.size() < 6)
  {
    int ca = 0, cb = 0;
    const int a = randomVertex(ca);
    int best = -1;
    double bestDistance = -1;
    for (int tries = 0; tries < 20000; ++tries)
    {
      const int b = randomVertex(cb);
      const double d = Distance(mesh.GetPosition(a), mesh.GetPosition(b));
      if (ca == cb && d > bestDistance)
      {
        best = b;
        bestDistance = d;
      }
    }
    m.LongPairs.push_back({ a, best });
  }
  return m;
}

void GeodesicVsDijkstra(benchmark::State& state, const std::string& name, bool longPaths)
{
  LoadedMesh& m = Load(name);
  if (!m.Mesh)
  {
    state.SkipWithError(m.Error.c_str());
    return;
  }
  const auto& pairs = longPaths ? m.LongPairs : m.ShortPairs;
  GeodesicPath path;
  CanonicalPoint a, b;
  a.Location = b.Location = PointLocation::Vertex;
  size_t i = 0;
  double ours = 0, vtk = 0, ratioSum = 0, ratioMax = 0;
  for (auto _ : state)
  {
    const auto& pair = pairs[i++ % pairs.size()];
    a.Id = pair.first;
    b.Id = pair.second;
    const auto t0 = Clock::now();
    const bool traced = m.Solver->Compute(a, b, path, traceError);
    const auto t1 = Clock::now();
    m.Dijkstra->SetStartVertex(pair.first);
    m.Dijkstra->SetEndVertex(pair.second);
    m.Dijkstra->Update();
    const auto t2 = Clock::now();
    if (!traced)
    {
      state.SkipWithError(traceError.c_str());
      return;
    }
    const double oursSeconds = Seconds(t0, t1), vtkSeconds = Seconds(t1, t2);
    state.SetIterationTime(oursSeconds + vtkSeconds);
    ours += oursSeconds;
    vtk += vtkSeconds;
    const double vtkLength = VtkPathLength(m.PolyData, m.Dijkstra->GetIdList());
    const double ratio = vtkLength > 0 ? path.Length / vtkLength : 1.0;
    ratioSum += ratio;
    ratioMax = std::max(ratioMax, ratio);
    if (ratio > 1 + 1e-12)
    {
      state.SkipWithError(("longer than the Dijkstra edge path between vertices " +
        std::to_string(pair.first) + " and " + std::to_string(pair.second))
                            .c_str());
      return;
    }
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["triangles"] = m.Mesh->GetNumberOfTriangles();
  state.counters["ours_ms"] = 1e3 * ours / n;
  state.counters["vtk_ms"] = 1e3 * vtk / n;
  state.counters["vtk_over_ours"] = vtk / ours;
  state.counters["length_ratio_mean"] = ratioSum / n;
  state.counters["length_ratio_max"] = ratioMax;
  state.counters["vtk_build_s"] = m.DijkstraBuildSeconds;
  state.counters["ours_setup_s"] = m.SolverSetupSeconds;
  state.counters["ours_landmarks_s"] = m.LandmarkSeconds;
  state.counters["ours_landmarks_MB"] = m.Solver->GetEdgeSearch().GetLandmarkMemory() / 1048576.0;
}
} // namespace

BENCHMARK_CAPTURE(GeodesicVsDijkstra, igea_1m_short, std::string("igea_1m.ply"), false)
  ->UseManualTime()
  ->Iterations(24)
  ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(GeodesicVsDijkstra, igea_1m_long, std::string("igea_1m.ply"), true)
  ->UseManualTime()
  ->Iterations(6)
  ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(GeodesicVsDijkstra, torus3_800k_short, std::string("3torus_800k.ply"), false)
  ->UseManualTime()
  ->Iterations(24)
  ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(GeodesicVsDijkstra, torus3_800k_long, std::string("3torus_800k.ply"), true)
  ->UseManualTime()
  ->Iterations(6)
  ->Unit(benchmark::kMillisecond);

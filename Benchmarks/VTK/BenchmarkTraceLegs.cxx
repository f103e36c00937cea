// One geodesic leg through the Trace Surface Curves filter, as a user waits for it (issue 27):
// a fresh filter update for an open two-point polygon on a large shared mesh, the surface
// converted and cached beforehand (BoolSurf filters keep it across updates, as in ParaView).
// Short legs: 2-4 % of the bounding-box diagonal; in-triangle legs: a corner and the middle
// of the opposite side of one triangle (the filter's fixed cost per update); far legs: the
// farthest of 20,000 random vertices from a random one (near-antipodal). Every iteration uses
// a pair never traced before, so neither the tracer's memory nor the path cache answers it.
// Counters: median_ms / max_ms (per update), sites / site_graph_ms / site_graph_MB (the
// per-surface structure of the Bounded method, built on the first far leg, outside the timed
// loop).
// PassCurvesYardstick: the same updates through a filter that only passes its curves through,
// i.e. what VTK's pipeline itself costs per update, the floor under the in-triangle legs.
// Run: BoolSurfVTKBenchmarks --benchmark_filter='TraceLeg|PassCurves'
#include "vtkBoolSurfTraceCurves.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPLYReader.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataAlgorithm.h>
#include <vtkSmartPointer.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace
{
using Point = std::array<double, 3>;

struct LegMesh
{
  vtkSmartPointer<vtkPolyData> Surface;
  std::vector<std::pair<Point, Point>> Short, Far, InTriangle;
  std::string Error;
};

double Distance(const Point& a, const Point& b)
{
  return std::sqrt(
    (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

LegMesh& Load(const std::string& name)
{
  static std::map<std::string, LegMesh> meshes;
  auto it = meshes.find(name);
  if (it != meshes.end())
  {
    return it->second;
  }
  LegMesh& m = meshes[name];
  const std::string path = std::string(BOOLSURF_SHARED_DATA_DIR) + "/meshes/" + name;
  if (!vtkPLYReader::CanReadFile(path.c_str()))
  {
    m.Error = "cannot read " + path;
    return m;
  }
  vtkNew<vtkPLYReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  m.Surface = reader->GetOutput();
  const vtkIdType n = m.Surface->GetNumberOfPoints();
  double bounds[6];
  m.Surface->GetBounds(bounds);
  const double diagonal =
    Distance({ bounds[0], bounds[2], bounds[4] }, { bounds[1], bounds[3], bounds[5] });
  auto point = [&](vtkIdType i)
  {
    Point p;
    m.Surface->GetPoint(i, p.data());
    return p;
  };
  std::mt19937 rng(2027);
  while (m.Short.size() < 400)
  {
    const Point a = point(static_cast<vtkIdType>(rng() % n));
    for (int tries = 0; tries < 100000; ++tries)
    {
      const Point b = point(static_cast<vtkIdType>(rng() % n));
      const double d = Distance(a, b);
      if (d > 0.02 * diagonal && d < 0.04 * diagonal)
      {
        m.Short.push_back({ a, b });
        break;
      }
    }
  }
  // Two points of one triangle (a corner and a point of the opposite side): the leg is a
  // straight segment, so the update's time is the filter's own fixed cost.
  for (vtkIdType c = 0; m.InTriangle.size() < 400 && c < m.Surface->GetNumberOfCells(); c += 997)
  {
    vtkIdType npts = 0;
    const vtkIdType* ids = nullptr;
    m.Surface->GetCellPoints(c, npts, ids);
    if (npts == 3)
    {
      const Point a = point(ids[0]), b = point(ids[1]), d = point(ids[2]);
      m.InTriangle.push_back(
        { a, { 0.5 * (b[0] + d[0]), 0.5 * (b[1] + d[1]), 0.5 * (b[2] + d[2]) } });
    }
  }
  while (m.Far.size() < 40)
  {
    const Point a = point(static_cast<vtkIdType>(rng() % n));
    Point best = a;
    for (int tries = 0; tries < 20000; ++tries)
    {
      const Point b = point(static_cast<vtkIdType>(rng() % n));
      if (Distance(a, b) > Distance(a, best))
      {
        best = b;
      }
    }
    m.Far.push_back({ a, best });
  }
  return m;
}

vtkSmartPointer<vtkPolyData> Leg(const Point& a, const Point& b)
{
  auto curves = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->InsertNextPoint(a.data());
  points->InsertNextPoint(b.data());
  vtkNew<vtkCellArray> lines;
  const vtkIdType ids[2] = { 0, 1 };
  lines->InsertNextCell(2, ids);
  curves->SetPoints(points);
  curves->SetLines(lines);
  return curves;
}

/// Fresh updates of `filter` (its surface input already set), one per iteration, each on the
/// next pair as a two-point curve: each update's real time is the iteration's, counters
/// median_ms / max_ms. False (and stops) when an output has fewer than `minimumPoints` points.
bool TimeLegUpdates(benchmark::State& state,
  vtkPolyDataAlgorithm* filter,
  const std::vector<std::pair<Point, Point>>& pairs,
  vtkIdType minimumPoints)
{
  std::vector<double> times;
  std::size_t i = 0;
  for (auto _ : state)
  {
    const auto& pair = pairs[i++ % (pairs.size() - 1)];
    filter->SetInputData(1, Leg(pair.first, pair.second));
    const auto t0 = std::chrono::steady_clock::now();
    filter->Update();
    times.push_back(
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    state.SetIterationTime(times.back() / 1000.0);
    if (filter->GetOutput()->GetNumberOfPoints() < minimumPoints)
    {
      return false;
    }
  }
  std::sort(times.begin(), times.end());
  state.counters["median_ms"] = times.empty() ? 0.0 : times[times.size() / 2];
  state.counters["max_ms"] = times.empty() ? 0.0 : times.back();
  return true;
}

enum class LegKind
{
  InTriangle,
  Short,
  Far
};

void TraceLeg(benchmark::State& state, const std::string& name, LegKind kind)
{
  LegMesh& m = Load(name);
  if (!m.Surface)
  {
    state.SkipWithError(m.Error.c_str());
    return;
  }
  vtkNew<vtkBoolSurfTraceCurves> trace;
  trace->SetInputData(0, m.Surface);
  // Surface conversion and, through one far leg, the site graph: not part of a leg.
  trace->SetInputData(1, Leg(m.Far.back().first, m.Far.back().second));
  trace->Update();
  const auto& pairs =
    kind == LegKind::Far ? m.Far : (kind == LegKind::Short ? m.Short : m.InTriangle);
  if (!TimeLegUpdates(state, trace, pairs, 2))
  {
    state.SkipWithError("the leg was not traced");
    return;
  }
  if (vtkDataArray* graph = trace->GetOutput()->GetFieldData()->GetArray("GeodesicSiteGraph"))
  {
    state.counters["sites"] = graph->GetComponent(0, 0);
    state.counters["site_graph_ms"] = graph->GetComponent(0, 1);
    state.counters["site_graph_MB"] = graph->GetComponent(0, 2);
  }
}

/// The yardstick of the in-triangle legs: a filter with Trace Surface Curves' two inputs that
/// only passes its curves through, so an update is VTK's own pipeline work (requests up and
/// down both inputs, the output emptied and refilled) and nothing of BoolSurf's.
class PassCurvesFilter : public vtkPolyDataAlgorithm
{
public:
  static PassCurvesFilter* New();
  vtkTypeMacro(PassCurvesFilter, vtkPolyDataAlgorithm);

protected:
  PassCurvesFilter() { this->SetNumberOfInputPorts(2); }
  // The executive BoolSurf's filters use outside ParaView (vtkBoolSurfAlgorithm).
  vtkExecutive* CreateDefaultExecutive() override
  {
    return vtkStreamingDemandDrivenPipeline::New();
  }
  int RequestData(vtkInformation*,
    vtkInformationVector** inputs,
    vtkInformationVector* outputs) override
  {
    vtkPolyData::GetData(outputs)->ShallowCopy(vtkPolyData::GetData(inputs[1]));
    return 1;
  }
};
vtkStandardNewMacro(PassCurvesFilter);

/// A fresh update of PassCurvesFilter per in-triangle leg: counter median_ms.
void PassCurvesYardstick(benchmark::State& state, const std::string& name)
{
  LegMesh& m = Load(name);
  if (!m.Surface)
  {
    state.SkipWithError(m.Error.c_str());
    return;
  }
  vtkNew<PassCurvesFilter> pass;
  pass->SetInputData(0, m.Surface);
  TimeLegUpdates(state, pass, m.InTriangle, 0);
}

// A fixed number of legs; BOOLSURF_BENCHMARK_ITERATIONS sets another (under callgrind).
int LegIterations(int fallback)
{
  const char* iterations = std::getenv("BOOLSURF_BENCHMARK_ITERATIONS");
  return iterations ? std::atoi(iterations) : fallback;
}
} // namespace

BENCHMARK_CAPTURE(TraceLeg, igea_1m_in_triangle, std::string("igea_1m.ply"), LegKind::InTriangle)
  ->UseManualTime()
  ->Iterations(LegIterations(399))
  ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(PassCurvesYardstick, igea_1m, std::string("igea_1m.ply"))
  ->UseManualTime()
  ->Iterations(LegIterations(399))
  ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(PassCurvesYardstick, kitten, std::string("kitten.ply"))
  ->UseManualTime()
  ->Iterations(LegIterations(399))
  ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(TraceLeg, igea_1m_short, std::string("igea_1m.ply"), LegKind::Short)
  ->UseManualTime()
  ->Iterations(LegIterations(399))
  ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(TraceLeg, igea_1m_far, std::string("igea_1m.ply"), LegKind::Far)
  ->UseManualTime()
  ->Iterations(LegIterations(39))
  ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(TraceLeg, torus3_800k_far, std::string("3torus_800k.ply"), LegKind::Far)
  ->UseManualTime()
  ->Iterations(LegIterations(39))
  ->Unit(benchmark::kMillisecond);

// Offset Shapes as a user waits for it (issue 30): a fresh update of the filter for a 12-point
// geodesic circle of radius 2 % of the bounding-box diagonal, grown by 1 % of the diagonal, on a
// large shared mesh whose conversion is cached (the filter keeps it across updates, as in
// ParaView). Every iteration draws the circle around a different vertex, so nothing of the
// previous update answers it.
// Counters: median_ms / max_ms per update; field_ms / contour_ms (the distance computation and
// the contour, medians, from the output's OffsetStatistics), stage_ms (the whole offset stage:
// tracing, arrangement, labels, field, contour, output arrays; the rest of median_ms is VTK's
// pipeline), windows, crossed (triangles the offset crosses), loops.
// Run: BoolSurfVTKBenchmarks --benchmark_filter=Offset
#include "vtkBoolSurfOffset.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPLYReader.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStaticCellLocator.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace
{
using Point = std::array<double, 3>;

Point Sub(const Point& a, const Point& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}
Point CrossOf(const Point& a, const Point& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
Point Unit(const Point& a)
{
  const double l = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  return { a[0] / l, a[1] / l, a[2] / l };
}

// A circle of `radius` around vertex `center` in its tangent plane (the normal of one of its
// triangles), each point moved to the closest surface point.
vtkSmartPointer<vtkPolyData> CircleAround(vtkPolyData* surface,
  vtkStaticCellLocator* locator,
  vtkIdType center,
  double radius)
{
  vtkNew<vtkIdList> cells;
  surface->GetPointCells(center, cells);
  vtkIdType n;
  const vtkIdType* ids;
  surface->GetCellPoints(cells->GetId(0), n, ids);
  Point p[3], c;
  for (int k = 0; k < 3; ++k)
  {
    surface->GetPoint(ids[k], p[k].data());
  }
  surface->GetPoint(center, c.data());
  const Point normal = Unit(CrossOf(Sub(p[1], p[0]), Sub(p[2], p[0])));
  const Point u = Unit(Sub(p[1], p[0]));
  const Point v = CrossOf(normal, u);
  auto curves = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> polys;
  polys->InsertNextCell(12);
  for (int i = 0; i < 12; ++i)
  {
    const double a = 2.0 * 3.14159265358979323846 * i / 12;
    Point x;
    for (int k = 0; k < 3; ++k)
    {
      x[k] = c[k] + radius * (std::cos(a) * u[k] + std::sin(a) * v[k]);
    }
    double closest[3], d2;
    vtkIdType cell;
    int sub;
    locator->FindClosestPoint(x.data(), closest, cell, sub, d2);
    polys->InsertCellPoint(points->InsertNextPoint(closest));
  }
  curves->SetPoints(points);
  curves->SetPolys(polys);
  return curves;
}

double Median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

void OffsetCircle(benchmark::State& state, const std::string& name)
{
  const std::string path = std::string(BOOLSURF_SHARED_DATA_DIR) + "/meshes/" + name;
  if (!vtkPLYReader::CanReadFile(path.c_str()))
  {
    state.SkipWithError(("cannot read " + path).c_str());
    return;
  }
  vtkNew<vtkPLYReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkSmartPointer<vtkPolyData> surface = reader->GetOutput();
  surface->BuildLinks();
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(surface);
  locator->BuildLocator();
  const double diagonal = surface->GetLength();
  std::mt19937 rng(30);
  std::vector<vtkSmartPointer<vtkPolyData>> circles;
  for (int i = 0; i < 41; ++i)
  {
    const vtkIdType center = static_cast<vtkIdType>(rng() % surface->GetNumberOfPoints());
    circles.push_back(CircleAround(surface, locator, center, 0.02 * diagonal));
  }
  vtkNew<vtkBoolSurfOffset> offset;
  offset->SetInputData(0, surface);
  offset->SetDistance(0.01 * diagonal);
  offset->SetProjectionTolerance(0.05);
  offset->SetNumberOfThreads(2);
  // Surface conversion: not part of an edit.
  offset->SetInputData(1, circles.back());
  offset->Update();
  std::vector<double> times, field, contour, stage, windows, crossed, loops;
  std::size_t i = 0;
  for (auto _ : state)
  {
    offset->SetInputData(1, circles[i++ % (circles.size() - 1)]);
    const auto t0 = std::chrono::steady_clock::now();
    offset->Update();
    times.push_back(
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    vtkDataArray* stats = offset->GetOutput()->GetFieldData()->GetArray("OffsetStatistics");
    if (!stats)
    {
      state.SkipWithError("the offset failed");
      return;
    }
    windows.push_back(stats->GetComponent(0, 1));
    crossed.push_back(stats->GetComponent(0, 3));
    field.push_back(stats->GetComponent(0, 5));
    contour.push_back(stats->GetComponent(0, 6));
    stage.push_back(stats->GetComponent(0, 7));
    auto* marked =
      vtkIntArray::SafeDownCast(offset->GetOutput()->GetCellData()->GetArray("OffsetCurve"));
    int n = 0;
    for (vtkIdType c = 0; marked && c < marked->GetNumberOfValues(); ++c)
    {
      n += marked->GetValue(c);
    }
    loops.push_back(n);
  }
  state.counters["median_ms"] = Median(times);
  state.counters["max_ms"] = *std::max_element(times.begin(), times.end());
  state.counters["field_ms"] = Median(field);
  state.counters["contour_ms"] = Median(contour);
  state.counters["stage_ms"] = Median(stage);
  state.counters["windows"] = Median(windows);
  state.counters["crossed"] = Median(crossed);
  state.counters["loops"] = Median(loops);
}

} // namespace

BENCHMARK_CAPTURE(OffsetCircle, igea_1m, std::string("igea_1m.ply"))
  ->Unit(benchmark::kMillisecond)
  ->Iterations(40);
BENCHMARK_CAPTURE(OffsetCircle, bunny_1m, std::string("stanford-bunny_1m.ply"))
  ->Unit(benchmark::kMillisecond)
  ->Iterations(40);

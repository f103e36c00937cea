// Resolve Inconsistent Shapes through VTK: fresh Update()s of vtkBoolSurfResolve on a procedural
// torus (400x200 quads, 160k triangles) with 4 shapes of meridians and parallels (all
// inconsistent), Strategy DuplicateReversed.
//
// - BM_ResolveCurveEdit: the surface stays the same input object (its conversion and homology
//   generators are cached); each iteration marks the curves modified and updates: reading the
//   curves, tracing them for their classes, resolving, writing.
// - BM_ResolveFirstUpdate: a new filter per iteration: surface conversion and the generators
//   included (what the first update of a surface costs).
//
// Run: BoolSurfVTKBenchmarks --benchmark_filter=Resolve
#include "Mesh/ProceduralMeshes.h"
#include "vtkBoolSurfResolve.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <benchmark/benchmark.h>

#include <cmath>

namespace
{

const double R = 3.0, r = 1.0;

vtkSmartPointer<vtkPolyData> Torus()
{
  const boolsurf::MeshData d = boolsurf::MakeTorus(R, r, 400, 200);
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const auto& p : d.Positions)
  {
    points->InsertNextPoint(p.x, p.y, p.z);
  }
  vtkNew<vtkCellArray> polys;
  for (const auto& t : d.Triangles)
  {
    polys->InsertNextCell({ t[0], t[1], t[2] });
  }
  pd->SetPoints(points);
  pd->SetPolys(polys);
  return pd;
}

// Shape s: a meridian at angle 0.4 + 1.5 s (and, for odd s, a parallel at tube angle s).
vtkSmartPointer<vtkPolyData> Curves()
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkIntArray> shape;
  shape->SetName("ShapeId");
  auto add = [&](int s, auto position, int n)
  {
    polys->InsertNextCell(n);
    for (int k = 0; k < n; ++k)
    {
      double x[3];
      position(2 * M_PI * k / n, x);
      polys->InsertCellPoint(points->InsertNextPoint(x));
    }
    shape->InsertNextValue(s);
  };
  for (int s = 0; s < 4; ++s)
  {
    const double u = 0.4 + 1.5 * s;
    add(
      s,
      [&](double v, double* x)
      {
        x[0] = (R + r * std::cos(v + 0.1)) * std::cos(u);
        x[1] = (R + r * std::cos(v + 0.1)) * std::sin(u);
        x[2] = r * std::sin(v + 0.1);
      },
      16);
    if (s % 2)
    {
      const double v = s;
      add(
        s,
        [&](double a, double* x)
        {
          x[0] = (R + r * std::cos(v)) * std::cos(a + 0.05);
          x[1] = (R + r * std::cos(v)) * std::sin(a + 0.05);
          x[2] = r * std::sin(v);
        },
        32);
    }
  }
  pd->SetPoints(points);
  pd->SetPolys(polys);
  pd->GetCellData()->AddArray(shape);
  return pd;
}

void BM_ResolveCurveEdit(benchmark::State& state)
{
  auto surface = Torus();
  auto curves = Curves();
  vtkNew<vtkBoolSurfResolve> resolve;
  resolve->SetInputData(0, surface);
  resolve->SetInputData(1, curves);
  resolve->Update();
  for (auto _ : state)
  {
    curves->Modified();
    resolve->Update();
  }
  state.counters["OutputCurves"] = resolve->GetOutput()->GetNumberOfCells();
}
BENCHMARK(BM_ResolveCurveEdit)->Unit(benchmark::kMillisecond);

void BM_ResolveFirstUpdate(benchmark::State& state)
{
  auto surface = Torus();
  auto curves = Curves();
  for (auto _ : state)
  {
    vtkNew<vtkBoolSurfResolve> resolve;
    resolve->SetInputData(0, surface);
    resolve->SetInputData(1, curves);
    resolve->Update();
    benchmark::DoNotOptimize(resolve->GetOutput()->GetNumberOfCells());
  }
}
BENCHMARK(BM_ResolveFirstUpdate)->Unit(benchmark::kMillisecond);

} // namespace

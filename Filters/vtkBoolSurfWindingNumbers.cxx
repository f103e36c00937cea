#include "vtkBoolSurfWindingNumbers.h"

#include "vtkBoolSurfArrayNames.h"

#include "Mesh/ParallelRange.h"
#include "Selection/RegionExtraction.h"
#include "vtkBoolSurfArrangementOutput.h"
#include "vtkBoolSurfControlCurveWriter.h"
#include "vtkBoolSurfRegionOutput.h"
#include "vtkBoolSurfStageHandoff.h"
#include "vtkBoolSurfSurfaceCache.h"
#include "vtkBoolSurfTraceStage.h"
#include "vtkBoolSurfWindingStage.h"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <array>
#include <chrono>
#include <cmath>
#include <sstream>

vtkStandardNewMacro(vtkBoolSurfWindingNumbers);

namespace
{
using Clock = std::chrono::steady_clock;
double Milliseconds(Clock::time_point from, Clock::time_point to)
{
  return std::chrono::duration<double, std::milli>(to - from).count();
}

// A double array of `tuples` x one component per shape, components named by the shapes.
vtkSmartPointer<vtkDoubleArray> PerShapeArray(const char* name,
  vtkIdType tuples,
  const std::vector<std::string>& labels)
{
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(static_cast<int>(labels.size()));
  for (std::size_t s = 0; s < labels.size(); ++s)
  {
    a->SetComponentName(static_cast<vtkIdType>(s), labels[s].c_str());
  }
  a->SetNumberOfTuples(tuples);
  return a;
}
} // namespace

struct vtkBoolSurfWindingNumbers::Internals
{
  /// The factorized Laplacian and harmonic fields of the last surface, kept for edits.
  boolsurf::SurfaceWinding Winding;
  /// Port 0's arrangement handed downstream (as Surface Arrangement does); an edit reuses the
  /// buffers of one no output holds any more.
  boolsurf::ResultPool<boolsurf::ArrangementResult> Results;
  std::shared_ptr<boolsurf::Arrangement::WorkBuffers> Work;
};

//------------------------------------------------------------------------------
vtkBoolSurfWindingNumbers::vtkBoolSurfWindingNumbers()
  : Internal(new Internals)
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(4);
}

//------------------------------------------------------------------------------
vtkBoolSurfWindingNumbers::~vtkBoolSurfWindingNumbers() = default;

//------------------------------------------------------------------------------
bool vtkBoolSurfWindingNumbers::Execute(const std::vector<vtkPolyData*>& inputs,
  const std::vector<vtkPolyData*>& outputs,
  std::string& error)
{
  const Clock::time_point start = Clock::now();
  vtkPolyData* refined = outputs[0];
  vtkPolyData* region = outputs[1];
  vtkPolyData* completed = outputs[2];
  vtkPolyData* traced = outputs[3];
  const boolsurf::vtkSurfaceInput* surface = this->GetSurface(inputs[0], error);
  if (!surface)
  {
    return false;
  }
  if (!inputs[1])
  {
    error = "no control curves on input port 1";
    return false;
  }
  if (boolsurf::PassOnDrawingStart(inputs[1], outputs))
  {
    return true; // a drawing being started: nothing to compute yet, and no message
  }
  std::vector<int> shapes;
  if (!boolsurf::ParseShapeList(this->Shapes, "Shapes", shapes, error))
  {
    return false;
  }
  if (!std::isfinite(this->Threshold))
  {
    error = "Threshold is not a finite number";
    return false;
  }
  const boolsurf::TriangleMesh& mesh = *surface->Mesh;
  this->UpdateProgress(0.05);

  // 1. the curves, traced (port 3 written on the way)
  std::shared_ptr<boolsurf::ArrangementResult> result = this->Internal->Results.Acquire();
  if (this->Internal->Work)
  {
    result->Arrangement.Work = this->Internal->Work;
  }
  result->Surface = *surface;
  std::vector<boolsurf::TracedCurve>& curves = result->Curves;
  boolsurf::TraceOptions traceOptions = this->GetTraceOptions();
  result->Method = traceOptions.Method;
  std::vector<boolsurf::InputControlCurve> controls;
  std::vector<std::string> problems, notes;
  const bool tracedOk = boolsurf::TraceControlCurves(this->GetSurfaceCache(),
    inputs[1],
    traceOptions,
    nullptr,
    curves,
    traced,
    problems,
    notes,
    &result->Sources,
    &controls);
  this->ReportWarnings(notes);
  if (!tracedOk)
  {
    error = "Cannot trace the curves:" + boolsurf::JoinLines(problems);
    return false;
  }
  if (curves.empty())
  {
    error = "the curves input has no curves to compute winding numbers of";
    return false;
  }
  if (!boolsurf::CheckShapesExist(curves, shapes, "Shapes", error))
  {
    return false;
  }
  const std::map<int, std::string> shapeNames = boolsurf::ReadShapeNames(inputs[1], controls);
  const Clock::time_point tracedTime = Clock::now();
  this->UpdateProgress(0.25);
  if (this->CheckAbort())
  {
    error = "aborted";
    return false;
  }

  // 2. the arrangement (port 0 as Surface Arrangement writes it)
  boolsurf::ArrangementOptions arrangementOptions;
  arrangementOptions.Threads = this->GetNumberOfThreads();
  if (!boolsurf::ArrangeResult(
        result, result->Sources, arrangementOptions, refined, nullptr, error))
  {
    this->Internal->Work = result->Arrangement.Work;
    return false;
  }
  this->Internal->Work = result->Arrangement.Work;
  const boolsurf::Arrangement& arr = result->Arrangement;
  const Clock::time_point arrangedTime = Clock::now();
  this->UpdateProgress(0.45);
  if (this->CheckAbort())
  {
    error = "aborted";
    return false;
  }

  // 3. the winding numbers
  boolsurf::WindingOptions options;
  options.Shapes = shapes;
  options.RemoveNonBounding = this->RemoveNonBounding;
  options.Threshold = this->Threshold;
  options.Threads = this->GetNumberOfThreads();
  boolsurf::WindingResult winding;
  if (!this->Internal->Winding.Compute(mesh, arr, curves, options, winding, error))
  {
    error = "Winding numbers: " + error;
    return false;
  }
  this->UpdateProgress(0.75);
  if (this->CheckAbort())
  {
    error = "aborted";
    return false;
  }

  // 4. the level sets
  const Clock::time_point levelStart = Clock::now();
  std::vector<boolsurf::LevelSetLoop> loops;
  std::vector<int> loopShape;
  if (!boolsurf::ExtractCompletedLoops(
        mesh, arr, winding, this->Threshold, this->GetNumberOfThreads(), loops, loopShape, error))
  {
    error = "Completed curves: " + error;
    return false;
  }
  const Clock::time_point levelTime = Clock::now();
  this->UpdateProgress(0.85);
  if (this->CheckAbort())
  {
    error = "aborted";
    return false;
  }

  // 5. outputs
  const int ns = winding.GetNumberOfShapes();
  std::vector<std::string> labels(ns);
  for (int s = 0; s < ns; ++s)
  {
    labels[s] = boolsurf::ShapeLabel(winding.ShapeIds[s], shapeNames);
  }
  // Port 0: w per point, per triangle (the refined triangles but holes, in order, as
  // WriteArrangementSurface writes them), per cell.
  // (Over blocks of points and triangles on the filter's threads: each writes its own tuples,
  // so the arrays do not depend on the threads; one triangle's corners are read once for all
  // shapes.)
  const int np = arr.GetNumberOfPoints();
  auto pointW = PerShapeArray(boolsurf::names::WindingNumber, np, labels);
  {
    std::vector<double> values(np);
    for (int s = 0; s < ns; ++s)
    {
      winding.WritePoints(s, np, values.data());
      boolsurf::ParallelBlocks(
        this->GetNumberOfThreads(),
        np > 65536,
        np,
        [&](int first, int last)
        {
          for (int p = first; p < last; ++p)
          {
            pointW->SetTypedComponent(p, s, values[p]);
          }
        },
        16384);
    }
  }
  const int nr = arr.GetNumberOfTriangles();
  std::vector<int> written; // refined triangle of each output triangle
  written.reserve(nr);
  for (int r = 0; r < nr; ++r)
  {
    if (arr.NumberOfHoles == 0 || arr.GetSourceTriangle(mesh, r) >= 0)
    {
      written.push_back(r);
    }
  }
  if (static_cast<vtkIdType>(written.size()) != refined->GetNumberOfCells())
  {
    error = "internal: the refined surface has " + std::to_string(refined->GetNumberOfCells()) +
      " triangles, the arrangement " + std::to_string(written.size());
    return false;
  }
  const vtkIdType nt = static_cast<vtkIdType>(written.size());
  auto cellW = PerShapeArray(boolsurf::names::WindingNumber, nt, labels);
  std::vector<char> inRegion(nt, 0);
  boolsurf::ParallelBlocks(
    this->GetNumberOfThreads(),
    nt > 65536,
    static_cast<int>(nt),
    [&](int first, int last)
    {
      for (int t = first; t < last; ++t)
      {
        const int r = written[t];
        const boolsurf::Triangle tri = arr.GetTriangle(mesh, r);
        const int slot = winding.JumpSlot[r];
        bool in = false;
        for (int s = 0; s < ns; ++s)
        {
          double sum = winding.Base(s, tri[0]) + winding.Base(s, tri[1]) + winding.Base(s, tri[2]);
          if (slot >= 0)
          {
            const double* lift = winding.CornerLift[s].data() + 3 * slot;
            sum += lift[0] + lift[1] + lift[2];
          }
          const double w = sum / 3.0;
          cellW->SetTypedComponent(t, s, w);
          in = in || w >= this->Threshold;
        }
        inRegion[t] = in;
      }
    },
    8192);
  std::vector<int> inside; // refined triangles of the region
  for (vtkIdType t = 0; t < nt; ++t)
  {
    if (inRegion[t])
    {
      inside.push_back(written[t]);
    }
  }
  refined->GetPointData()->AddArray(pointW);
  refined->GetCellData()->AddArray(cellW);
  vtkFieldData* fd = refined->GetFieldData();
  vtkNew<vtkIntArray> shapeIds;
  shapeIds->SetName(boolsurf::names::WindingShapeIds);
  for (int id : winding.ShapeIds)
  {
    shapeIds->InsertNextValue(id);
  }
  fd->AddArray(shapeIds);
  auto cellMean = PerShapeArray(boolsurf::names::CellWindingNumber, arr.NumberOfCells, labels);
  for (int c = 0; c < arr.NumberOfCells; ++c)
  {
    for (int s = 0; s < ns; ++s)
    {
      cellMean->SetTypedComponent(c, s, winding.CellMean[s][c]);
    }
  }
  if (cellMean->GetNumberOfTuples() > 0) // never an empty numeric field array
  {
    fd->AddArray(cellMean);
  }

  // Port 1: the region, as BoolSurf's (the surface's own arrays carried), with w per triangle.
  boolsurf::RegionMesh regionMesh;
  boolsurf::RegionExtractor extractor;
  extractor.Extract(
    inside,
    np,
    [&](int r) { return arr.GetTriangle(mesh, r); },
    regionMesh,
    this->GetNumberOfThreads());
  boolsurf::WriteRegion(*surface, arr, regionMesh, region, this->GetNumberOfThreads());
  auto regionW =
    PerShapeArray(boolsurf::names::WindingNumber, static_cast<vtkIdType>(inside.size()), labels);
  for (std::size_t i = 0; i < inside.size(); ++i)
  {
    for (int s = 0; s < ns; ++s)
    {
      regionW->SetTypedComponent(
        static_cast<vtkIdType>(i), s, winding.Triangle(arr, mesh, s, regionMesh.Triangles[i]));
    }
  }
  region->GetCellData()->AddArray(regionW);
  region->GetFieldData()->AddArray(shapeIds);

  // Port 2: the loops as control curves (closed geodesic polygons through all their points).
  boolsurf::ControlCurveWriter writer(mesh, nullptr, true, !shapeNames.empty());
  for (std::size_t i = 0; i < loops.size(); ++i)
  {
    const int id = winding.ShapeIds[loopShape[i]];
    const auto name = shapeNames.find(id);
    boolsurf::ControlCurve loop;
    loop.CurveId = static_cast<int>(i);
    loop.ShapeId = id;
    loop.Type = boolsurf::CurveType::GeodesicPolygon;
    loop.Closed = true;
    loop.Points = loops[i].SurfacePoints;
    writer.Add(loop, 0, name != shapeNames.end() ? name->second : std::string());
  }
  writer.Write(completed);
  completed->GetFieldData()->AddArray(shapeIds);

  // Port 3: each traced curve's residual, and the curves that bound nothing.
  const vtkIdType nc = traced->GetNumberOfCells();
  vtkNew<vtkDoubleArray> residual;
  residual->SetName(boolsurf::names::WindingResidual);
  residual->SetNumberOfTuples(nc);
  residual->FillValue(-1);
  vtkNew<vtkIntArray> bounds;
  bounds->SetName(boolsurf::names::BoundsRegion);
  bounds->SetNumberOfTuples(nc);
  bounds->FillValue(-1);
  vtkNew<vtkIntArray> nonBounding;
  nonBounding->SetName(boolsurf::names::NonBoundingCurves);
  nonBounding->SetNumberOfComponents(2);
  nonBounding->SetComponentName(0, boolsurf::names::ShapeId);
  nonBounding->SetComponentName(1, boolsurf::names::CurveId);
  std::vector<std::string> warnings;
  for (const boolsurf::WindingCurveReport& report : winding.Curves)
  {
    if (report.Curve < 0 || report.Curve >= nc)
    {
      continue;
    }
    residual->SetValue(report.Curve, report.Residual);
    bounds->SetValue(report.Curve, report.Bounds ? 1 : 0);
    if (!report.Bounds)
    {
      nonBounding->InsertNextTypedTuple(
        std::array<int, 2>{ report.ShapeId, report.CurveId }.data());
      warnings.push_back(boolsurf::DescribeWindingCurve(report) +
        (report.AroundHandle
            ? " bounds nothing (it winds around a handle of the surface and the shape's other "
              "curves do not bound it with it)"
            : " bounds nothing (a spur, an overshooting piece or an isolated arc: w on its two "
              "sides sits half-way between whole levels)") +
        ": it takes no part in the shape's winding number");
    }
  }
  traced->GetCellData()->AddArray(residual);
  traced->GetCellData()->AddArray(bounds);
  if (nonBounding->GetNumberOfTuples() > 0)
  {
    traced->GetFieldData()->AddArray(nonBounding);
  }
  this->ReportWarnings(warnings);

  // Times, on port 0.
  const Clock::time_point end = Clock::now();
  const boolsurf::WindingStageTimes& t = winding.Times;
  const std::array<double, 9> times{ Milliseconds(start, tracedTime),
    Milliseconds(tracedTime, arrangedTime),
    t.Factorization,
    t.Lift,
    t.Solve,
    t.Homology,
    Milliseconds(levelStart, levelTime),
    Milliseconds(levelTime, end),
    Milliseconds(start, end) };
  const char* timeNames[] = { "Trace",
    "Arrangement",
    "Factorization",
    "Lift",
    "Solve",
    "Homology",
    "LevelSet",
    "Outputs",
    "Total" };
  vtkNew<vtkDoubleArray> stageTimes;
  stageTimes->SetName(boolsurf::names::WindingTimes);
  stageTimes->SetNumberOfComponents(9);
  for (int k = 0; k < 9; ++k)
  {
    stageTimes->SetComponentName(k, timeNames[k]);
  }
  stageTimes->InsertNextTypedTuple(times.data());
  fd->AddArray(stageTimes);

  // The arrangement in Core form for a labeling or Boolean downstream of port 0.
  boolsurf::AttachStageResult<boolsurf::ArrangementResult>(
    refined->GetCellData()->GetArray(boolsurf::names::ArrangementCell), std::move(result));
  return true;
}

//------------------------------------------------------------------------------
void vtkBoolSurfWindingNumbers::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Shapes: " << this->Shapes << "\n";
  os << indent << "Threshold: " << this->Threshold << "\n";
  os << indent << "RemoveNonBounding: " << this->RemoveNonBounding << "\n";
}

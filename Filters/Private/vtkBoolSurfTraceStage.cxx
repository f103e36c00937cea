#include "vtkBoolSurfTraceStage.h"

#include "vtkBoolSurfArrayNames.h"
#include "vtkBoolSurfArrayView.h"

#include "vtkBoolSurfControlCurves.h"

#include "Geodesic/WrittenCurvePoints.h"

#include <vtkAlgorithm.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace boolsurf
{
//------------------------------------------------------------------------------
void WriteTracedCurves(const TriangleMesh* mesh,
  const std::vector<InputControlCurve>& controls,
  const std::vector<CurveTrace>& traces,
  vtkPolyData* output)
{
  // Arrays sized once and filled in place: a per-value insertion into ten arrays cost more
  // than the arrangement's reading of the curves.
  const vtkIdType nc = static_cast<vtkIdType>(traces.size());
  std::vector<vtkIdType> firstPoint(nc + 1, 0), firstCorner(nc + 1, 0);
  for (vtkIdType c = 0; c < nc; ++c)
  {
    const vtkIdType n = static_cast<vtkIdType>(traces[c].Curve.Points.size());
    const bool isClosed = traces[c].Curve.Closed && n > 1;
    firstPoint[c + 1] = firstPoint[c] + n;
    firstCorner[c + 1] = firstCorner[c] + n + (isClosed ? 1 : 0);
  }
  const vtkIdType np = firstPoint[nc];
  auto coordinates = NewSizedArray<vtkDoubleArray>(nullptr, 3, np);
  auto triangleId = NewSizedArray<vtkIdTypeArray>(boolsurf::names::TriangleId, 1, np);
  auto barycentric = NewSizedArray<vtkDoubleArray>(boolsurf::names::Barycentric, 2, np);
  auto parameter = NewSizedArray<vtkDoubleArray>(boolsurf::names::CurveParameter, 1, np);
  auto segment = NewSizedArray<vtkIntArray>(boolsurf::names::ControlSegment, 1, np);
  auto controlPoint = NewSizedArray<vtkIntArray>(boolsurf::names::ControlPointId, 1, np);
  auto offsets = NewSizedArray<vtkIdTypeArray>(nullptr, 1, nc + 1);
  auto connectivity = NewSizedArray<vtkIdTypeArray>(nullptr, 1, firstCorner[nc]);
  auto shape = NewSizedArray<vtkIntArray>(boolsurf::names::ShapeId, 1, nc);
  auto curveId = NewSizedArray<vtkIntArray>(boolsurf::names::CurveId, 1, nc);
  auto closed = NewSizedArray<vtkIntArray>(boolsurf::names::Closed, 1, nc);
  auto type = NewSizedArray<vtkIntArray>(boolsurf::names::CurveType, 1, nc);
  auto length = NewSizedArray<vtkDoubleArray>(boolsurf::names::Length, 1, nc);
  // Curves still being drawn (traced as far as they are valid, for display) keep their mark,
  // so that a filter reading these traced curves leaves them out as it would their controls.
  const bool anyBeingDrawn = std::any_of(
    controls.begin(), controls.end(), [](const InputControlCurve& c) { return c.BeingDrawn; });
  auto complete = NewSizedArray<vtkIntArray>(boolsurf::names::Complete, 1, anyBeingDrawn ? nc : 0);
  // Point `i` of curve `c`, as output point `id`.
  const auto writePoint = [&](vtkIdType c, std::size_t i, vtkIdType id)
  {
    const CurveTrace& trace = traces[c];
    const InputControlCurve& control = controls[c];
    const size_t n = trace.Curve.Points.size();
    // Every point is written canonically (exact zeros on edges and vertices), so Surface
    // Arrangement and every other reader locate it where the tracer did. A control point is
    // written in the user's triangle (then, off edges and vertices, the user's numbers bit for
    // bit); the user's values themselves stay in the field data ControlTriangleId/
    // ControlBarycentric. Other points go in a triangle they share with the next point of the
    // curve (WrittenCurvePoint); the tracer keeps those forms with the curves it remembers, so
    // a curve that an edit did not move is written by copying.
    const int k = trace.ControlPoint[i];
    const bool isControl = k >= 0 && k < static_cast<int>(control.Points.size());
    // Without a mesh (tracing on pieces) every form is known, a control point's included.
    const bool known = trace.Written.size() == n && trace.Positions.size() == n;
    const Vec3 x = known ? trace.Positions[i] : PositionOf(*mesh, trace.Curve.Points[i]);
    double* xyz = coordinates->GetPointer(3 * id);
    xyz[0] = x.x;
    xyz[1] = x.y;
    xyz[2] = x.z;
    const SurfacePoint sp = known && (!isControl || !mesh)
      ? trace.Written[i]
      : WrittenCurvePoint(*mesh, trace.Curve, i, isControl ? control.Points[k].Triangle : -1);
    triangleId->SetValue(id, sp.Triangle);
    barycentric->SetValue(2 * id, sp.U);
    barycentric->SetValue(2 * id + 1, sp.V);
    parameter->SetValue(id, trace.Parameter[i]);
    segment->SetValue(id, trace.Segment[i]);
    controlPoint->SetValue(id, isControl ? static_cast<int>(control.PointIds[k]) : -1);
  };
  // Output points [from, to), whichever curves they belong to.
  const auto writePoints = [&](vtkIdType from, vtkIdType to)
  {
    vtkIdType c = static_cast<vtkIdType>(
      std::upper_bound(firstPoint.begin(), firstPoint.end(), from) - firstPoint.begin() - 1);
    for (vtkIdType id = from; id < to; ++id)
    {
      while (id >= firstPoint[c + 1])
      {
        ++c;
      }
      writePoint(c, static_cast<std::size_t>(id - firstPoint[c]), id);
    }
  };
  // Each point is written independently (positions, canonical surface points: about half the
  // filter's time on a long drawing that an edit traced anew), so long drawings are written on
  // every core; a few thousand points are not worth waking other threads.
  constexpr vtkIdType Grain = 1 << 12;
  if (np <= Grain)
  {
    writePoints(0, np);
  }
  else
  {
    tbb::parallel_for(tbb::blocked_range<vtkIdType>(0, np, Grain),
      [&](const tbb::blocked_range<vtkIdType>& range) { writePoints(range.begin(), range.end()); });
  }
  for (vtkIdType c = 0; c < nc; ++c)
  {
    const CurveTrace& trace = traces[c];
    const InputControlCurve& control = controls[c];
    const vtkIdType first = firstPoint[c];
    const size_t n = trace.Curve.Points.size();
    vtkIdType corner = firstCorner[c];
    offsets->SetValue(c, corner);
    for (size_t i = 0; i < n; ++i)
    {
      connectivity->SetValue(corner++, first + static_cast<vtkIdType>(i));
    }
    if (trace.Curve.Closed && n > 1)
    {
      connectivity->SetValue(corner, first);
    }
    shape->SetValue(c, control.ShapeId);
    curveId->SetValue(c, control.CurveId);
    closed->SetValue(c, trace.Curve.Closed ? 1 : 0);
    type->SetValue(c, static_cast<int>(control.Type));
    length->SetValue(c, trace.Length);
    if (anyBeingDrawn)
    {
      complete->SetValue(c, control.BeingDrawn ? 0 : 1);
    }
  }
  offsets->SetValue(nc, firstCorner[nc]);
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  output->SetPoints(points);
  vtkNew<vtkCellArray> lines;
  lines->SetData(offsets, connectivity);
  output->SetLines(lines);
  vtkPointData* pd = output->GetPointData();
  pd->AddArray(triangleId);
  pd->AddArray(barycentric);
  pd->AddArray(parameter);
  pd->AddArray(segment);
  pd->AddArray(controlPoint);
  // The control points themselves (Bezier handles are not on the traced curve), so that the
  // arrangement and the Boolean can give results back as control points (field data:
  // ControlOffsets[c]..ControlOffsets[c + 1] index curve c's points).
  vtkIdType nControls = 0;
  for (const InputControlCurve& control : controls)
  {
    nControls += static_cast<vtkIdType>(control.Points.size());
  }
  auto controlOffsets = NewSizedArray<vtkIntArray>(boolsurf::names::ControlOffsets, 1, nc + 1);
  auto controlTriangle =
    NewSizedArray<vtkIdTypeArray>(boolsurf::names::ControlTriangleId, 1, nControls);
  auto controlUV = NewSizedArray<vtkDoubleArray>(boolsurf::names::ControlBarycentric, 2, nControls);
  vtkIdType written = 0;
  for (vtkIdType c = 0; c < nc; ++c)
  {
    controlOffsets->SetValue(c, static_cast<int>(written));
    for (const SurfacePoint& p : controls[c].Points)
    {
      controlTriangle->SetValue(written, p.Triangle);
      controlUV->SetTypedComponent(written, 0, p.U);
      controlUV->SetTypedComponent(written, 1, p.V);
      ++written;
    }
  }
  controlOffsets->SetValue(nc, static_cast<int>(written));
  output->GetFieldData()->AddArray(controlOffsets);
  if (controlTriangle->GetNumberOfTuples() > 0) // never an empty numeric field array
  {
    output->GetFieldData()->AddArray(controlTriangle);
    output->GetFieldData()->AddArray(controlUV);
  }
  vtkCellData* cd = output->GetCellData();
  cd->AddArray(shape);
  cd->AddArray(curveId);
  cd->AddArray(closed);
  cd->AddArray(type);
  cd->AddArray(length);
  if (anyBeingDrawn)
  {
    cd->AddArray(complete);
  }
}

//------------------------------------------------------------------------------
std::string DescribeCurvePoint(const std::vector<TracedCurve>& curves,
  const std::vector<CurveSource>& sources,
  int curve,
  int point)
{
  if (curve < 0 || curve >= static_cast<int>(curves.size()))
  {
    return "";
  }
  const TracedCurve& traced = curves[curve];
  std::string text = "curve " + std::to_string(traced.CurveId);
  const CurveSource* source = curve < static_cast<int>(sources.size()) ? &sources[curve] : nullptr;
  if (source && source->InputCurveId >= 0 && source->InputCurveId != traced.CurveId)
  {
    text += " (input CurveId " + std::to_string(source->InputCurveId) + ")";
  }
  text += " of shape " + std::to_string(traced.ShapeId);
  if (!source || point < 0 || point >= static_cast<int>(source->Parameter.size()) ||
    source->Points.empty())
  {
    return text;
  }
  // Parameter = segment index + fraction: the control points at the ends of that segment.
  const int n = static_cast<int>(source->Points.size());
  const int segment = static_cast<int>(source->Parameter[point]);
  const bool bezier = source->Type == CurveType::CubicBezier;
  const int first = bezier ? 3 * segment : segment;
  const int last = bezier ? 3 * segment + 3 : segment + 1;
  return text + ", between its control points " + std::to_string(first % n) + " and " +
    std::to_string(source->Closed ? last % n : std::min(last, n - 1)) + " (traced point " +
    std::to_string(point) + ")";
}

//------------------------------------------------------------------------------
void AddSiteGraphField(const TriangleMesh& mesh, vtkFieldData* fieldData)
{
  const std::shared_ptr<const SurfaceSiteGraph> graph = SurfaceSiteGraph::Find(mesh);
  if (!graph)
  {
    return;
  }
  vtkNew<vtkDoubleArray> field;
  field->SetName(boolsurf::names::GeodesicSiteGraph);
  field->SetNumberOfComponents(4);
  field->SetComponentName(0, "Sites");
  field->SetComponentName(1, "BuildMilliseconds");
  field->SetComponentName(2, "MemoryMB");
  field->SetComponentName(3, "BuildNumber");
  const double values[4] = { static_cast<double>(graph->GetNumberOfSites()),
    1000.0 * graph->GetBuildSeconds(),
    graph->GetMemory() / 1048576.0,
    static_cast<double>(graph->GetBuildNumber()) };
  field->InsertNextTuple(values);
  fieldData->AddArray(field);
}

//------------------------------------------------------------------------------
void ReadSurfaceControlCurves(vtkSurfaceCache& cache,
  vtkPolyData* controlCurves,
  const TraceOptions& trace,
  std::vector<InputControlCurve>& controls,
  std::vector<std::string>& problems,
  std::vector<std::string>& notes)
{
  const vtkSurfaceInput& surface = cache.GetCurrent();
  ControlCurveOptions options;
  options.MaximumDistance = trace.ProjectionTolerance * surface.Triangles->GetLength();
  options.TraceValidPartOfIncompleteCurves = trace.TraceValidPartOfIncompleteCurves;
  ReadControlCurves(
    controlCurves,
    [&cache]() -> const ClosestTriangleGrid& { return cache.GetClosestTriangles(); },
    *surface.Mesh,
    options,
    controls,
    problems,
    notes);
}

//------------------------------------------------------------------------------
bool TraceControlCurves(vtkSurfaceCache& cache,
  vtkPolyData* controlCurves,
  const TraceOptions& options,
  vtkAlgorithm* progress,
  std::vector<TracedCurve>& traced,
  vtkPolyData* output,
  std::vector<std::string>& problems,
  std::vector<std::string>& notes,
  std::vector<CurveSource>* sources,
  std::vector<InputControlCurve>* controlsRead)
{
  std::vector<InputControlCurve> own;
  std::vector<InputControlCurve>& controls = controlsRead ? *controlsRead : own;
  controls.clear();
  ReadSurfaceControlCurves(cache, controlCurves, options, controls, problems, notes);
  return TraceInputCurves(cache, controls, options, progress, traced, output, problems, sources);
}

//------------------------------------------------------------------------------
bool TraceInputCurves(vtkSurfaceCache& cache,
  const std::vector<InputControlCurve>& controls,
  const TraceOptions& options,
  vtkAlgorithm* progress,
  std::vector<TracedCurve>& traced,
  vtkPolyData* output,
  std::vector<std::string>& problems,
  std::vector<CurveSource>* sources)
{
  traced.clear();
  const TriangleMesh& mesh = *cache.GetCurrent().Mesh;
  CurveTracer& tracer = cache.GetTracer();
  tracer.SetResolution(options.Resolution);
  tracer.SetKeepWrittenForms(output != nullptr); // see WriteTraces
  GeodesicPathOptions pathOptions = tracer.GetPathSolver().GetOptions();
  pathOptions.Method = options.Method;
  tracer.GetPathSolver().SetOptions(pathOptions);
  tracer.StartPass(); // curves of the update before the last one are forgotten
  std::vector<const ControlCurve*> requests(controls.size());
  for (size_t c = 0; c < controls.size(); ++c)
  {
    requests[c] = &controls[c];
  }
  std::vector<CurveTrace> traces;
  std::vector<std::string> errors;
  bool aborted = false;
  tracer.TraceCurves(requests,
    options.Threads,
    traces,
    errors,
    [&](double fraction)
    {
      if (progress)
      {
        progress->UpdateProgress(fraction);
        aborted = aborted || progress->CheckAbort();
      }
      return !aborted;
    });
  if (aborted)
  {
    return false;
  }
  for (size_t c = 0; c < controls.size(); ++c)
  {
    if (!errors[c].empty())
    {
      problems.push_back(errors[c]);
      continue;
    }
    traces[c].Curve.ShapeId = controls[c].ShapeId;
    traces[c].Curve.CurveId = controls[c].CurveId;
  }
  if (!problems.empty())
  {
    return false;
  }
  // Written first, so that the curves and their parameters can then be moved out, not copied.
  if (output)
  {
    WriteTracedCurves(&mesh, controls, traces, output);
  }
  if (sources)
  {
    sources->resize(controls.size());
    for (size_t c = 0; c < controls.size(); ++c)
    {
      CurveSource& s = (*sources)[c];
      static_cast<ControlCurve&>(s) = controls[c];
      s.Parameter = std::move(traces[c].Parameter);
      s.InputCurveId = controls[c].InputCurveId;
    }
  }
  traced.reserve(traces.size());
  for (CurveTrace& t : traces)
  {
    traced.push_back(std::move(t.Curve));
  }
  return true;
}

} // namespace boolsurf

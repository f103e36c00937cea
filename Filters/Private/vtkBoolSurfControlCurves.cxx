#include "vtkBoolSurfControlCurves.h"

#include "vtkBoolSurfArrayNames.h"

#include "vtkBoolSurfTracedCurves.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace boolsurf
{
namespace
{

std::string CurveLabel(int curveId, long long pointId = -1)
{
  std::string s = "curve " + std::to_string(curveId);
  if (pointId >= 0)
  {
    s += ", control point " + std::to_string(pointId);
  }
  return s;
}

// A value as the user gave it (1e+12, nan, 2.5), not as it would look after a cast to int.
std::string AsGiven(double value)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.17g", value);
  return text;
}

// True when `value` is an integer in [0, INT_MAX]: a valid ShapeId or triangle id.
/// CheckSurfacePoint without the triangle, for a surface split across ranks.
bool CheckBarycentric(const SurfacePoint& p, std::string& problem)
{
  if (!std::isfinite(p.U) || !std::isfinite(p.V) || !IsInsideTriangle(p.U, p.V))
  {
    char text[128];
    std::snprintf(text, sizeof(text), "barycentric coordinates (%.17g, %.17g)", p.U, p.V);
    problem = std::string(text) + " in triangle " + std::to_string(p.Triangle) +
      " are not finite or lie outside it (u, v >= 0 and u + v <= 1 are needed)";
    return false;
  }
  return true;
}

bool IsIndex(double value)
{
  return value >= 0 && value <= std::numeric_limits<int>::max() && value == std::floor(value);
}

/// The control curves of traced curves (Trace Surface Curves' output, Surface Curves' Traced
/// Curves port), from the control points they carry in field data (ControlOffsets,
/// ControlTriangleId, ControlBarycentric; cell data Closed, ShapeId, CurveType, CurveId); null
/// when `curves` is not traced curves.
vtkSmartPointer<vtkPolyData> ControlCurvesOfTraced(vtkPolyData* curves, const TriangleMesh& mesh)
{
  vtkFieldData* fd = curves->GetFieldData();
  vtkDataArray* offsets = fd ? fd->GetArray(boolsurf::names::ControlOffsets) : nullptr;
  vtkDataArray* triangles = fd ? fd->GetArray(boolsurf::names::ControlTriangleId) : nullptr;
  vtkDataArray* uv = fd ? fd->GetArray(boolsurf::names::ControlBarycentric) : nullptr;
  vtkDataArray* closed = curves->GetCellData()->GetArray(boolsurf::names::Closed);
  const vtkIdType cells = curves->GetNumberOfCells();
  if (!offsets || !triangles || !uv || uv->GetNumberOfComponents() != 2 || !closed ||
    offsets->GetNumberOfTuples() != cells + 1 || closed->GetNumberOfTuples() != cells ||
    curves->GetNumberOfLines() != cells ||
    uv->GetNumberOfTuples() != triangles->GetNumberOfTuples())
  {
    return nullptr;
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkIdTypeArray> triangleId;
  triangleId->SetName(boolsurf::names::TriangleId);
  vtkNew<vtkDoubleArray> barycentric;
  barycentric->SetName(boolsurf::names::Barycentric);
  barycentric->SetNumberOfComponents(2);
  vtkNew<vtkCellArray> lines;
  for (vtkIdType c = 0; c < cells; ++c)
  {
    const vtkIdType from = static_cast<vtkIdType>(offsets->GetComponent(c, 0));
    const vtkIdType to = static_cast<vtkIdType>(offsets->GetComponent(c + 1, 0));
    if (from < 0 || to < from || to > triangles->GetNumberOfTuples())
    {
      return nullptr;
    }
    const vtkIdType first = points->GetNumberOfPoints();
    for (vtkIdType k = from; k < to; ++k)
    {
      const double t = triangles->GetComponent(k, 0), u = uv->GetComponent(k, 0),
                   v = uv->GetComponent(k, 1);
      Vec3 x{ 0, 0, 0 };
      if (t >= 0 && t < mesh.GetNumberOfTriangles())
      {
        x = mesh.Evaluate(static_cast<int>(t), u, v);
      }
      points->InsertNextPoint(x.x, x.y, x.z);
      triangleId->InsertNextValue(static_cast<vtkIdType>(t));
      barycentric->InsertNextTuple2(u, v);
    }
    const bool isClosed = closed->GetComponent(c, 0) != 0 && to - from > 1;
    lines->InsertNextCell(to - from + (isClosed ? 1 : 0));
    for (vtkIdType k = 0; k < to - from; ++k)
    {
      lines->InsertCellPoint(first + k);
    }
    if (isClosed)
    {
      lines->InsertCellPoint(first);
    }
  }
  out->SetPoints(points);
  out->SetLines(lines);
  out->GetPointData()->AddArray(triangleId);
  out->GetPointData()->AddArray(barycentric);
  for (const char* name : { boolsurf::names::ShapeId,
         boolsurf::names::CurveType,
         boolsurf::names::CurveId,
         boolsurf::names::Complete })
  {
    if (vtkDataArray* a = curves->GetCellData()->GetArray(name))
    {
      out->GetCellData()->AddArray(a);
    }
  }
  return out;
}

} // namespace

//------------------------------------------------------------------------------
std::vector<int> ShapesBeingDrawn(vtkPolyData* curves)
{
  std::vector<int> shapes;
  vtkDataArray* complete =
    curves ? curves->GetCellData()->GetArray(boolsurf::names::Complete) : nullptr;
  if (!complete || complete->GetRange(0)[0] != 0)
  {
    return shapes;
  }
  vtkDataArray* shapeIds = curves->GetCellData()->GetArray(boolsurf::names::ShapeId);
  for (vtkIdType c = 0; c < complete->GetNumberOfTuples(); ++c)
  {
    if (complete->GetComponent(c, 0) == 0)
    {
      const double id = shapeIds && c < shapeIds->GetNumberOfTuples() ? shapeIds->GetComponent(c, 0)
                                                                      : static_cast<double>(c);
      if (IsIndex(id))
      {
        shapes.push_back(static_cast<int>(id));
      }
    }
  }
  std::sort(shapes.begin(), shapes.end());
  shapes.erase(std::unique(shapes.begin(), shapes.end()), shapes.end());
  return shapes;
}

//------------------------------------------------------------------------------
bool IsDrawing(vtkPolyData* curves)
{
  vtkDataArray* drawing =
    curves ? curves->GetFieldData()->GetArray(boolsurf::names::Drawing) : nullptr;
  return drawing && drawing->GetNumberOfTuples() == 1 && drawing->GetComponent(0, 0) == 1;
}

//------------------------------------------------------------------------------
bool IsDrawingWithoutCurves(vtkPolyData* curves)
{
  if (!IsDrawing(curves))
  {
    return false;
  }
  vtkDataArray* complete = curves->GetCellData()->GetArray(boolsurf::names::Complete);
  return curves->GetNumberOfCells() == 0 ||
    (complete && complete->GetNumberOfTuples() >= curves->GetNumberOfCells() &&
      complete->GetRange(0)[1] == 0);
}

//------------------------------------------------------------------------------
bool PassOnDrawingStart(vtkPolyData* input, const std::vector<vtkPolyData*>& outputs)
{
  if (!IsDrawingWithoutCurves(input))
  {
    return false;
  }
  MarkDrawingStart(outputs);
  return true;
}

//------------------------------------------------------------------------------
void MarkDrawingStart(const std::vector<vtkPolyData*>& outputs)
{
  for (vtkPolyData* output : outputs)
  {
    if (output)
    {
      output->Initialize();
      vtkNew<vtkIntArray> drawing;
      drawing->SetName(boolsurf::names::Drawing);
      drawing->InsertNextValue(1);
      output->GetFieldData()->AddArray(drawing);
    }
  }
}

//------------------------------------------------------------------------------
bool NamesSurfacePoints(vtkPolyData* curves)
{
  if (!curves)
  {
    return false;
  }
  const TriangleMesh none; // positions are not read: the points are named exactly
  vtkSmartPointer<vtkPolyData> traced = ControlCurvesOfTraced(curves, none);
  vtkPolyData* read = traced ? traced.Get() : curves;
  vtkDataArray* triangleIds = read->GetPointData()->GetArray(boolsurf::names::TriangleId);
  vtkDataArray* barycentric = read->GetPointData()->GetArray(boolsurf::names::Barycentric);
  return triangleIds && barycentric && barycentric->GetNumberOfComponents() == 2;
}

//------------------------------------------------------------------------------
void ReadControlCurves(vtkPolyData* curves,
  const std::function<const ClosestTriangleGrid&()>& closestTriangles,
  const TriangleMesh& mesh,
  const ControlCurveOptions& options,
  std::vector<InputControlCurve>& out,
  std::vector<std::string>& problems,
  std::vector<std::string>& notes)
{
  out.clear();
  if (!curves || curves->GetNumberOfCells() == 0)
  {
    problems.push_back("the curves input holds no line or polygon cell");
    return;
  }
  // Traced curves are read as the control curves they were traced from: either output of
  // Surface Curves (or Trace Surface Curves' output) gives the same answer.
  vtkSmartPointer<vtkPolyData> traced = ControlCurvesOfTraced(curves, mesh);
  if (traced)
  {
    curves = traced;
  }
  if (curves->GetNumberOfVerts() + curves->GetNumberOfStrips() > 0)
  {
    notes.push_back("ignored " +
      std::to_string(curves->GetNumberOfVerts() + curves->GetNumberOfStrips()) +
      " vertex/strip cell(s) of the curves input: curves are line and polygon cells");
  }
  vtkDataArray* shapeIds = curves->GetCellData()->GetArray(boolsurf::names::ShapeId);
  vtkDataArray* types = curves->GetCellData()->GetArray(boolsurf::names::CurveType);
  vtkDataArray* inputCurveIds = curves->GetCellData()->GetArray(boolsurf::names::CurveId);
  vtkDataArray* complete = curves->GetCellData()->GetArray(boolsurf::names::Complete);
  vtkDataArray* triangleIds = curves->GetPointData()->GetArray(boolsurf::names::TriangleId);
  vtkDataArray* barycentric = curves->GetPointData()->GetArray(boolsurf::names::Barycentric);
  const bool exact = triangleIds && barycentric && barycentric->GetNumberOfComponents() == 2;
  if ((triangleIds || barycentric) && !exact)
  {
    notes.push_back("point data TriangleId/Barycentric is incomplete (both arrays needed, "
                    "Barycentric with 2 components): control points are projected instead");
  }
  // Arrays shorter than the cells or points they describe would be read past their end.
  const vtkIdType cells = curves->GetNumberOfCells(), points = curves->GetNumberOfPoints();
  for (vtkDataArray* a : { shapeIds, types, complete })
  {
    if (a && a->GetNumberOfTuples() < cells)
    {
      problems.push_back(std::string("cell data ") + a->GetName() + " has " +
        std::to_string(a->GetNumberOfTuples()) + " value(s) for " + std::to_string(cells) +
        " cells");
    }
  }
  for (vtkDataArray* a : { exact ? triangleIds : nullptr, exact ? barycentric : nullptr })
  {
    if (a && a->GetNumberOfTuples() < points)
    {
      problems.push_back(std::string("point data ") + a->GetName() + " has " +
        std::to_string(a->GetNumberOfTuples()) + " tuple(s) for " + std::to_string(points) +
        " points");
    }
  }
  if (!problems.empty())
  {
    return;
  }
  ForEachCurveCell(curves,
    [&](vtkIdType cellId, vtkIdType n, const vtkIdType* ids, bool polygon)
    {
      InputControlCurve curve;
      curve.CurveId = static_cast<int>(cellId);
      if (inputCurveIds && cellId < inputCurveIds->GetNumberOfTuples())
      {
        const double id = inputCurveIds->GetComponent(cellId, 0);
        curve.InputCurveId = IsIndex(id) ? static_cast<long long>(id) : -1;
      }
      const double shape = shapeIds ? shapeIds->GetComponent(cellId, 0) : double(cellId);
      const double type = types ? types->GetComponent(cellId, 0) : 0.0;
      if (!IsIndex(shape))
      {
        problems.push_back(CurveLabel(curve.CurveId) + ": ShapeId " + AsGiven(shape) +
          " is not an integer in [0, " + std::to_string(std::numeric_limits<int>::max()) + "]");
        return;
      }
      curve.ShapeId = static_cast<int>(shape);
      if (type != 0 && type != 1)
      {
        problems.push_back(CurveLabel(curve.CurveId) + ": CurveType " + AsGiven(type) +
          " is neither 0 (geodesic polygon) nor 1 (cubic Bezier)");
        return;
      }
      curve.Type = static_cast<CurveType>(static_cast<int>(type));
      curve.Closed = polygon;
      // A polyline whose last point repeats its first (same id, or same point: the same
      // surface point when given exactly, else the same coordinates) is closed.
      if (!polygon && n >= 3)
      {
        bool same = ids[0] == ids[n - 1];
        if (!same && exact)
        {
          same = triangleIds->GetComponent(ids[0], 0) == triangleIds->GetComponent(ids[n - 1], 0) &&
            barycentric->GetComponent(ids[0], 0) == barycentric->GetComponent(ids[n - 1], 0) &&
            barycentric->GetComponent(ids[0], 1) == barycentric->GetComponent(ids[n - 1], 1);
        }
        else if (!same)
        {
          double p[3], q[3];
          curves->GetPoint(ids[0], p);
          curves->GetPoint(ids[n - 1], q);
          same = p[0] == q[0] && p[1] == q[1] && p[2] == q[2];
        }
        if (same)
        {
          curve.Closed = true;
          --n;
        }
      }
      // A curve being drawn is no error: left out, or read as far as it is valid.
      const bool beingDrawn = complete && complete->GetComponent(cellId, 0) == 0;
      if (beingDrawn && !options.TraceValidPartOfIncompleteCurves)
      {
        return;
      }
      curve.BeingDrawn = beingDrawn;
      bool ok = true;
      for (vtkIdType i = 0; i < n && ok; ++i)
      {
        const vtkIdType pid = ids[i];
        if (pid < 0 || pid >= points)
        {
          problems.push_back(CurveLabel(curve.CurveId) + " names point id " + std::to_string(pid) +
            ", outside [0, " + std::to_string(points) + ")");
          ok = false;
          break;
        }
        SurfacePoint sp;
        if (exact)
        {
          const double triangle = triangleIds->GetComponent(pid, 0);
          if (!IsIndex(triangle))
          {
            problems.push_back(CurveLabel(curve.CurveId, pid) + ": TriangleId " +
              AsGiven(triangle) + " is not a triangle id");
            ok = false;
            break;
          }
          sp.Triangle = static_cast<int>(triangle);
          sp.U = barycentric->GetComponent(pid, 0);
          sp.V = barycentric->GetComponent(pid, 1);
          std::string why;
          if (options.TrianglesOnPieces ? !CheckBarycentric(sp, why)
                                        : !CheckSurfacePoint(mesh, sp, why))
          {
            problems.push_back(CurveLabel(curve.CurveId, pid) + ": " + why);
            ok = false;
          }
        }
        else
        {
          double x[3];
          curves->GetPoint(pid, x);
          if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
          {
            problems.push_back(CurveLabel(curve.CurveId, pid) + ": NaN or infinite coordinates");
            ok = false;
            break;
          }
          const ClosestTriangleGrid::Hit hit = closestTriangles().FindClosest({ x[0], x[1], x[2] });
          const int triangle = hit.Triangle;
          const double dist2 = hit.Distance2;
          if (triangle < 0)
          {
            problems.push_back(
              CurveLabel(curve.CurveId, pid) + ": no surface triangle found to project onto");
            ok = false;
            break;
          }
          if (std::sqrt(dist2) > options.MaximumDistance)
          {
            problems.push_back(CurveLabel(curve.CurveId, pid) + " is " +
              std::to_string(std::sqrt(dist2)) + " away from the surface (tolerance " +
              std::to_string(options.MaximumDistance) + ")");
            ok = false;
            break;
          }
          sp = PointInTriangle(mesh, triangle, hit.Point);
        }
        curve.Points.push_back(sp);
        curve.PointIds.push_back(pid);
      }
      if (!ok)
      {
        return;
      }
      if (!AcceptControlCurve(curve, problems, notes))
      {
        return;
      }
      out.push_back(std::move(curve));
    });
}

//------------------------------------------------------------------------------
bool AcceptControlCurve(InputControlCurve& curve,
  std::vector<std::string>& problems,
  std::vector<std::string>& notes)
{
  if (curve.BeingDrawn && curve.Type == CurveType::CubicBezier)
  {
    // Its complete segments, open: anchor, handle, handle, anchor, ...
    const std::size_t segments = (curve.Points.size() - 1) / 3;
    curve.Points.resize(3 * segments + 1);
    curve.PointIds.resize(3 * segments + 1);
    curve.Closed = false;
  }
  const int count = static_cast<int>(curve.Points.size());
  const bool distinct = HasDistinctPoints(curve);
  if (curve.BeingDrawn && (count < 2 || !distinct))
  {
    return false; // nothing to show yet
  }
  if (count < 2 || !distinct)
  {
    // A curve of one point (or of one point repeated) has zero length and bounds nothing:
    // skipped with a note rather than failing the other curves.
    notes.push_back(CurveLabel(curve.CurveId) + " has " + std::to_string(count) +
      " control point(s)" + (count >= 2 ? ", all at the same surface point" : "") +
      ": skipped, a curve needs two distinct points");
    return false;
  }
  if (curve.Type == CurveType::CubicBezier)
  {
    const std::string needs = WhatCurveNeeds(true, curve.Closed, count);
    if (!needs.empty())
    {
      problems.push_back(CurveLabel(curve.CurveId) + ": " + needs);
      return false;
    }
  }
  return true;
}

} // namespace boolsurf

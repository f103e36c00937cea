#include "vtkBoolSurfControlOutput.h"

#include "vtkBoolSurfArrayNames.h"

#include "vtkBoolSurfTracedCurves.h"

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

namespace boolsurf
{

//------------------------------------------------------------------------------
void WriteControlSubCurves(const std::vector<ControlSubCurve>& curves,
  const char* groupName,
  bool boundary,
  vtkPolyData* output)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkIdTypeArray> triangleId;
  triangleId->SetName(boolsurf::names::TriangleId);
  vtkNew<vtkDoubleArray> barycentric;
  barycentric->SetName(boolsurf::names::Barycentric);
  barycentric->SetNumberOfComponents(2);
  vtkNew<vtkCellArray> lines;
  auto intArray = [](const char* name)
  {
    auto a = vtkSmartPointer<vtkIntArray>::New();
    a->SetName(name);
    return a;
  };
  auto shape = intArray(boolsurf::names::ShapeId), type = intArray(boolsurf::names::CurveType),
       closed = intArray(boolsurf::names::Closed), sourceCurve = intArray("SourceCurveId"),
       sourceShape = intArray("SourceShapeId"), reversed = intArray("Reversed"),
       group = intArray(groupName);
  vtkNew<vtkDoubleArray> range;
  range->SetName("ParameterRange");
  range->SetNumberOfComponents(2);
  for (const ControlSubCurve& c : curves)
  {
    const vtkIdType first = points->GetNumberOfPoints();
    for (std::size_t i = 0; i < c.Points.size(); ++i)
    {
      const SurfacePoint& p = c.Points[i];
      const Vec3& x = c.Positions[i];
      points->InsertNextPoint(x.x, x.y, x.z);
      triangleId->InsertNextValue(p.Triangle);
      barycentric->InsertNextTuple2(p.U, p.V);
    }
    const vtkIdType n = static_cast<vtkIdType>(c.Points.size());
    lines->InsertNextCell(n + (c.Whole ? 1 : 0));
    for (vtkIdType i = 0; i < n; ++i)
    {
      lines->InsertCellPoint(first + i);
    }
    if (c.Whole)
    {
      lines->InsertCellPoint(first);
    }
    shape->InsertNextValue(boundary ? 0 : c.SourceShapeId);
    type->InsertNextValue(static_cast<int>(c.Type));
    closed->InsertNextValue(c.Whole ? 1 : 0);
    sourceCurve->InsertNextValue(c.SourceCurveId);
    sourceShape->InsertNextValue(c.SourceShapeId);
    reversed->InsertNextValue(c.Reversed ? 1 : 0);
    group->InsertNextValue(c.Group);
    range->InsertNextTuple2(c.T0, c.T1);
  }
  output->SetPoints(points);
  output->SetLines(lines);
  output->GetPointData()->AddArray(triangleId);
  output->GetPointData()->AddArray(barycentric);
  for (vtkDataArray* a : { static_cast<vtkDataArray*>(shape),
         static_cast<vtkDataArray*>(type),
         static_cast<vtkDataArray*>(closed),
         static_cast<vtkDataArray*>(sourceCurve),
         static_cast<vtkDataArray*>(sourceShape),
         static_cast<vtkDataArray*>(reversed),
         static_cast<vtkDataArray*>(group),
         static_cast<vtkDataArray*>(range) })
  {
    output->GetCellData()->AddArray(a);
  }
}

//------------------------------------------------------------------------------
bool ReadCurveSources(vtkPolyData* traced,
  const std::vector<TracedCurve>& curves,
  std::vector<CurveSource>& out)
{
  out.clear();
  vtkFieldData* fd = traced ? traced->GetFieldData() : nullptr;
  vtkDataArray* offsets = fd ? fd->GetArray("ControlOffsets") : nullptr;
  vtkDataArray* triangles = fd ? fd->GetArray("ControlTriangleId") : nullptr;
  vtkDataArray* uv = fd ? fd->GetArray("ControlBarycentric") : nullptr;
  vtkDataArray* parameter =
    traced ? traced->GetPointData()->GetArray(boolsurf::names::CurveParameter) : nullptr;
  vtkDataArray* types =
    traced ? traced->GetCellData()->GetArray(boolsurf::names::CurveType) : nullptr;
  if (!offsets || !triangles || !uv || uv->GetNumberOfComponents() != 2 || !parameter ||
    offsets->GetNumberOfTuples() != static_cast<vtkIdType>(curves.size()) + 1)
  {
    return false;
  }
  bool ok = true;
  std::size_t c = 0;
  ForEachCurveCell(traced,
    [&](vtkIdType cellId, vtkIdType n, const vtkIdType* ids, bool)
    {
      if (!ok || c >= curves.size() || static_cast<std::size_t>(n) < curves[c].Points.size())
      {
        ok = false;
        return;
      }
      CurveSource s;
      s.Closed = curves[c].Closed;
      s.ShapeId = curves[c].ShapeId;
      s.CurveId = curves[c].CurveId;
      s.Type = types && types->GetComponent(cellId, 0) == 1 ? CurveType::CubicBezier
                                                            : CurveType::GeodesicPolygon;
      for (std::size_t i = 0; i < curves[c].Points.size(); ++i)
      {
        s.Parameter.push_back(parameter->GetComponent(ids[i], 0));
      }
      const vtkIdType from = static_cast<vtkIdType>(offsets->GetComponent(c, 0));
      const vtkIdType to = static_cast<vtkIdType>(offsets->GetComponent(c + 1, 0));
      if (from < 0 || to < from || to > triangles->GetNumberOfTuples())
      {
        ok = false;
        return;
      }
      for (vtkIdType k = from; k < to; ++k)
      {
        s.Controls.push_back({ static_cast<int>(triangles->GetComponent(k, 0)),
          uv->GetComponent(k, 0),
          uv->GetComponent(k, 1) });
      }
      ok = !s.Controls.empty();
      out.push_back(std::move(s));
      ++c;
    });
  return ok && c == curves.size();
}

//------------------------------------------------------------------------------
void WritePatchControlCurves(const std::vector<ControlSubCurve>& perPatch, vtkFieldData* fd)
{
  vtkNew<vtkIntArray> offsets, info;
  offsets->SetName("PatchControlOffsets");
  info->SetName("PatchControlInfo");
  info->SetNumberOfComponents(7);
  const char* names[] = { "CurveIndex",
    boolsurf::names::CurveType,
    "Segments",
    "CurveClosed",
    "SourceShapeId",
    "SourceCurveId",
    "Whole" };
  for (int k = 0; k < 7; ++k)
  {
    info->SetComponentName(k, names[k]);
  }
  vtkNew<vtkIdTypeArray> triangles;
  triangles->SetName("PatchControlTriangleId");
  vtkNew<vtkDoubleArray> uv, position, range;
  uv->SetName("PatchControlBarycentric");
  uv->SetNumberOfComponents(2);
  position->SetName("PatchControlPosition");
  position->SetNumberOfComponents(3);
  range->SetName("PatchParameterRange");
  range->SetNumberOfComponents(2);
  offsets->InsertNextValue(0);
  for (const ControlSubCurve& c : perPatch)
  {
    for (std::size_t i = 0; i < c.Points.size(); ++i)
    {
      triangles->InsertNextValue(c.Points[i].Triangle);
      uv->InsertNextTuple2(c.Points[i].U, c.Points[i].V);
      position->InsertNextTuple3(c.Positions[i].x, c.Positions[i].y, c.Positions[i].z);
    }
    offsets->InsertNextValue(static_cast<int>(triangles->GetNumberOfTuples()));
    const int values[7] = { c.Curve,
      static_cast<int>(c.Type),
      c.Segments,
      c.CurveClosed ? 1 : 0,
      c.SourceShapeId,
      c.SourceCurveId,
      c.Whole ? 1 : 0 };
    info->InsertNextTypedTuple(values);
    range->InsertNextTuple2(c.T0, c.T1);
  }
  if (perPatch.empty() || triangles->GetNumberOfTuples() == 0)
  {
    return; // never an empty numeric field array (VTK's XML reader cannot read it back)
  }
  for (vtkDataArray* a : { static_cast<vtkDataArray*>(offsets),
         static_cast<vtkDataArray*>(info),
         static_cast<vtkDataArray*>(triangles),
         static_cast<vtkDataArray*>(uv),
         static_cast<vtkDataArray*>(position),
         static_cast<vtkDataArray*>(range) })
  {
    fd->AddArray(a);
  }
}

//------------------------------------------------------------------------------
bool ReadPatchControlCurves(vtkFieldData* fd, std::vector<ControlSubCurve>& perPatch)
{
  perPatch.clear();
  vtkDataArray* offsets = fd ? fd->GetArray("PatchControlOffsets") : nullptr;
  vtkDataArray* info = fd ? fd->GetArray("PatchControlInfo") : nullptr;
  vtkDataArray* triangles = fd ? fd->GetArray("PatchControlTriangleId") : nullptr;
  vtkDataArray* uv = fd ? fd->GetArray("PatchControlBarycentric") : nullptr;
  vtkDataArray* position = fd ? fd->GetArray("PatchControlPosition") : nullptr;
  vtkDataArray* range = fd ? fd->GetArray("PatchParameterRange") : nullptr;
  if (!offsets || !info || !triangles || !uv || !position || !range ||
    info->GetNumberOfComponents() != 7 || uv->GetNumberOfComponents() != 2 ||
    position->GetNumberOfComponents() != 3 || range->GetNumberOfComponents() != 2)
  {
    return false;
  }
  const vtkIdType patches = offsets->GetNumberOfTuples() - 1;
  if (patches < 0 || info->GetNumberOfTuples() != patches || range->GetNumberOfTuples() != patches)
  {
    return false;
  }
  perPatch.resize(static_cast<std::size_t>(patches));
  for (vtkIdType p = 0; p < patches; ++p)
  {
    ControlSubCurve& c = perPatch[p];
    c.Curve = static_cast<int>(info->GetComponent(p, 0));
    c.Type = info->GetComponent(p, 1) == 1 ? CurveType::CubicBezier : CurveType::GeodesicPolygon;
    c.Segments = static_cast<int>(info->GetComponent(p, 2));
    c.CurveClosed = info->GetComponent(p, 3) != 0;
    c.SourceShapeId = static_cast<int>(info->GetComponent(p, 4));
    c.SourceCurveId = static_cast<int>(info->GetComponent(p, 5));
    c.Whole = info->GetComponent(p, 6) != 0;
    c.T0 = range->GetComponent(p, 0);
    c.T1 = range->GetComponent(p, 1);
    const vtkIdType from = static_cast<vtkIdType>(offsets->GetComponent(p, 0));
    const vtkIdType to = static_cast<vtkIdType>(offsets->GetComponent(p + 1, 0));
    if (from < 0 || to < from || to > triangles->GetNumberOfTuples())
    {
      perPatch.clear();
      return false;
    }
    for (vtkIdType k = from; k < to; ++k)
    {
      c.Points.push_back({ static_cast<int>(triangles->GetComponent(k, 0)),
        uv->GetComponent(k, 0),
        uv->GetComponent(k, 1) });
      c.Positions.push_back({ position->GetComponent(k, 0),
        position->GetComponent(k, 1),
        position->GetComponent(k, 2) });
    }
  }
  return true;
}

} // namespace boolsurf

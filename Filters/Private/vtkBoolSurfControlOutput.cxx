#include "vtkBoolSurfControlOutput.h"

#include "vtkBoolSurfArrayNames.h"
#include "vtkBoolSurfArrayView.h"

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
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>

namespace boolsurf
{

//------------------------------------------------------------------------------
namespace
{
/// Number of control points of all `curves`.
vtkIdType CountPoints(const std::vector<ControlSubCurve>& curves)
{
  vtkIdType n = 0;
  for (const ControlSubCurve& c : curves)
  {
    n += static_cast<vtkIdType>(c.Points.size());
  }
  return n;
}
} // namespace

//------------------------------------------------------------------------------
void WriteControlSubCurves(const std::vector<ControlSubCurve>& curves,
  const char* groupName,
  bool boundary,
  vtkPolyData* output)
{
  const vtkIdType np = CountPoints(curves);
  const vtkIdType nc = static_cast<vtkIdType>(curves.size());
  vtkIdType corners = np;
  for (const ControlSubCurve& c : curves)
  {
    corners += c.Whole ? 1 : 0;
  }
  auto coordinates = NewSizedArray<vtkDoubleArray>(nullptr, 3, np);
  auto triangleId = NewSizedArray<vtkIdTypeArray>(boolsurf::names::TriangleId, 1, np);
  auto barycentric = NewSizedArray<vtkDoubleArray>(boolsurf::names::Barycentric, 2, np);
  auto offsets = NewSizedArray<vtkIdTypeArray>(nullptr, 1, nc + 1);
  auto connectivity = NewSizedArray<vtkIdTypeArray>(nullptr, 1, corners);
  auto shape = NewSizedArray<vtkIntArray>(boolsurf::names::ShapeId, 1, nc);
  auto type = NewSizedArray<vtkIntArray>(boolsurf::names::CurveType, 1, nc);
  auto closed = NewSizedArray<vtkIntArray>(boolsurf::names::Closed, 1, nc);
  auto sourceCurve = NewSizedArray<vtkIntArray>(boolsurf::names::SourceCurveId, 1, nc);
  auto sourceShape = NewSizedArray<vtkIntArray>(boolsurf::names::SourceShapeId, 1, nc);
  auto reversed = NewSizedArray<vtkIntArray>(boolsurf::names::Reversed, 1, nc);
  auto group = NewSizedArray<vtkIntArray>(groupName, 1, nc);
  auto range = NewSizedArray<vtkDoubleArray>(boolsurf::names::ParameterRange, 2, nc);
  double* xyz = coordinates->GetPointer(0);
  vtkIdType* tri = triangleId->GetPointer(0);
  double* uv = barycentric->GetPointer(0);
  vtkIdType* offset = offsets->GetPointer(0);
  vtkIdType* corner = connectivity->GetPointer(0);
  vtkIdType point = 0, k = 0;
  for (vtkIdType ci = 0; ci < nc; ++ci)
  {
    const ControlSubCurve& c = curves[ci];
    const vtkIdType first = point;
    offset[ci] = k;
    for (std::size_t i = 0; i < c.Points.size(); ++i, ++point)
    {
      const SurfacePoint& p = c.Points[i];
      const Vec3& x = c.Positions[i];
      xyz[3 * point] = x.x;
      xyz[3 * point + 1] = x.y;
      xyz[3 * point + 2] = x.z;
      tri[point] = p.Triangle;
      uv[2 * point] = p.U;
      uv[2 * point + 1] = p.V;
      corner[k++] = point;
    }
    if (c.Whole)
    {
      corner[k++] = first;
    }
    shape->SetValue(ci, boundary ? 0 : c.SourceShapeId);
    type->SetValue(ci, static_cast<int>(c.Type));
    closed->SetValue(ci, c.Whole ? 1 : 0);
    sourceCurve->SetValue(ci, c.SourceCurveId);
    sourceShape->SetValue(ci, c.SourceShapeId);
    reversed->SetValue(ci, c.Reversed ? 1 : 0);
    group->SetValue(ci, c.Group);
    range->SetTypedComponent(ci, 0, c.T0);
    range->SetTypedComponent(ci, 1, c.T1);
  }
  offset[nc] = k;
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  output->SetPoints(points);
  vtkNew<vtkCellArray> lines;
  lines->SetData(offsets, connectivity);
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
  vtkDataArray* offsets = fd ? fd->GetArray(boolsurf::names::ControlOffsets) : nullptr;
  vtkDataArray* triangles = fd ? fd->GetArray(boolsurf::names::ControlTriangleId) : nullptr;
  vtkDataArray* uv = fd ? fd->GetArray(boolsurf::names::ControlBarycentric) : nullptr;
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
        s.Points.push_back({ static_cast<int>(triangles->GetComponent(k, 0)),
          uv->GetComponent(k, 0),
          uv->GetComponent(k, 1) });
      }
      ok = !s.Points.empty();
      out.push_back(std::move(s));
      ++c;
    });
  return ok && c == curves.size();
}

//------------------------------------------------------------------------------
void WritePatchControlCurves(const std::vector<ControlSubCurve>& perPatch, vtkFieldData* fd)
{
  const vtkIdType np = CountPoints(perPatch);
  const vtkIdType nc = static_cast<vtkIdType>(perPatch.size());
  if (nc == 0 || np == 0)
  {
    return; // never an empty numeric field array (VTK's XML reader cannot read it back)
  }
  auto offsets = NewSizedArray<vtkIntArray>(boolsurf::names::PatchControlOffsets, 1, nc + 1);
  auto info = NewSizedArray<vtkIntArray>(boolsurf::names::PatchControlInfo, 7, nc);
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
  auto triangles = NewSizedArray<vtkIdTypeArray>(boolsurf::names::PatchControlTriangleId, 1, np);
  auto uv = NewSizedArray<vtkDoubleArray>(boolsurf::names::PatchControlBarycentric, 2, np);
  auto position = NewSizedArray<vtkDoubleArray>(boolsurf::names::PatchControlPosition, 3, np);
  auto range = NewSizedArray<vtkDoubleArray>(boolsurf::names::PatchParameterRange, 2, nc);
  vtkIdType* tri = triangles->GetPointer(0);
  double* bary = uv->GetPointer(0);
  double* xyz = position->GetPointer(0);
  int* values = info->GetPointer(0);
  vtkIdType point = 0;
  for (vtkIdType ci = 0; ci < nc; ++ci)
  {
    const ControlSubCurve& c = perPatch[ci];
    offsets->SetValue(ci, static_cast<int>(point));
    for (std::size_t i = 0; i < c.Points.size(); ++i, ++point)
    {
      tri[point] = c.Points[i].Triangle;
      bary[2 * point] = c.Points[i].U;
      bary[2 * point + 1] = c.Points[i].V;
      xyz[3 * point] = c.Positions[i].x;
      xyz[3 * point + 1] = c.Positions[i].y;
      xyz[3 * point + 2] = c.Positions[i].z;
    }
    int* v = values + 7 * ci;
    v[0] = c.Curve;
    v[1] = static_cast<int>(c.Type);
    v[2] = c.Segments;
    v[3] = c.CurveClosed ? 1 : 0;
    v[4] = c.SourceShapeId;
    v[5] = c.SourceCurveId;
    v[6] = c.Whole ? 1 : 0;
    range->SetTypedComponent(ci, 0, c.T0);
    range->SetTypedComponent(ci, 1, c.T1);
  }
  offsets->SetValue(nc, static_cast<int>(point));
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

} // namespace boolsurf

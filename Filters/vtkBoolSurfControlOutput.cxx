#include "vtkBoolSurfControlOutput.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace boolsurf
{

//------------------------------------------------------------------------------
void WriteControlSubCurves(const std::function<Vec3(const SurfacePoint&)>& position,
  const std::vector<ControlSubCurve>& curves,
  const char* groupName,
  bool boundary,
  vtkPolyData* output)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkIdTypeArray> triangleId;
  triangleId->SetName("TriangleId");
  vtkNew<vtkDoubleArray> barycentric;
  barycentric->SetName("Barycentric");
  barycentric->SetNumberOfComponents(2);
  vtkNew<vtkCellArray> lines;
  auto intArray = [](const char* name)
  {
    auto a = vtkSmartPointer<vtkIntArray>::New();
    a->SetName(name);
    return a;
  };
  auto shape = intArray("ShapeId"), type = intArray("CurveType"), closed = intArray("Closed"),
       sourceCurve = intArray("SourceCurveId"), sourceShape = intArray("SourceShapeId"),
       reversed = intArray("Reversed"), group = intArray(groupName);
  vtkNew<vtkDoubleArray> range;
  range->SetName("ParameterRange");
  range->SetNumberOfComponents(2);
  for (const ControlSubCurve& c : curves)
  {
    const vtkIdType first = points->GetNumberOfPoints();
    for (const SurfacePoint& p : c.Points)
    {
      const Vec3 x = position(p);
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

} // namespace boolsurf

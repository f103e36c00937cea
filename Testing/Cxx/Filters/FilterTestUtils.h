// Helpers shared by the filter tests: procedural meshes and curve sets as vtkPolyData, areas.
#ifndef FilterTestUtils_h
#define FilterTestUtils_h

#include "Mesh/ProceduralMeshes.h"

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkIntArray.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <string>
#include <vector>

namespace testutils
{

inline vtkSmartPointer<vtkPolyData> ToPolyData(const boolsurf::MeshData& mesh)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const auto& p : mesh.Positions)
  {
    points->InsertNextPoint(p.x, p.y, p.z);
  }
  vtkNew<vtkCellArray> polys;
  for (const auto& t : mesh.Triangles)
  {
    polys->InsertNextCell({ t[0], t[1], t[2] });
  }
  pd->SetPoints(points);
  pd->SetPolys(polys);
  return pd;
}

struct ControlPolygon
{
  std::vector<std::array<double, 3>> Points;
  int ShapeId = 0;
  bool Closed = true;
  int Type = 0; ///< 0 geodesic polygon, 1 cubic Bezier
};

/// Control polygons as the curves input of the BoolSurf filters (polygon cells when closed).
inline vtkSmartPointer<vtkPolyData> ToCurves(const std::vector<ControlPolygon>& curves)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> lines, polys;
  vtkNew<vtkIntArray> shape, type;
  shape->SetName("ShapeId");
  type->SetName("CurveType");
  // Lines come before polygons in vtkPolyData cell ids: insert open curves first so cell
  // data follows the cells.
  for (int pass = 0; pass < 2; ++pass)
  {
    for (const ControlPolygon& c : curves)
    {
      if (c.Closed != (pass == 1))
      {
        continue;
      }
      vtkCellArray* cells = c.Closed ? polys.GetPointer() : lines.GetPointer();
      cells->InsertNextCell(static_cast<vtkIdType>(c.Points.size()));
      for (const auto& p : c.Points)
      {
        cells->InsertCellPoint(points->InsertNextPoint(p.data()));
      }
      shape->InsertNextValue(c.ShapeId);
      type->InsertNextValue(c.Type);
    }
  }
  pd->SetPoints(points);
  pd->SetLines(lines);
  pd->SetPolys(polys);
  pd->GetCellData()->AddArray(shape);
  pd->GetCellData()->AddArray(type);
  return pd;
}

/// Collects the error and warning messages a filter emits (AddObserver for ErrorEvent and/or
/// WarningEvent).
class MessageCatcher : public vtkCommand
{
public:
  static MessageCatcher* New() { return new MessageCatcher; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    (event == vtkCommand::ErrorEvent ? this->Errors : this->Warnings) +=
      static_cast<const char*>(data) + std::string("\n");
  }
  std::string Errors, Warnings;
};

/// Errors reported by one update of `filter` (empty when it succeeded).
inline std::string ErrorsOf(vtkAlgorithm* filter)
{
  std::string errors;
  vtkNew<vtkCallbackCommand> catcher;
  catcher->SetClientData(&errors);
  catcher->SetCallback([](vtkObject*, unsigned long, void* text, void* data)
    { *static_cast<std::string*>(text) += static_cast<const char*>(data); });
  const unsigned long tag = filter->AddObserver(vtkCommand::ErrorEvent, catcher);
  filter->Update();
  filter->RemoveObserver(tag);
  return errors;
}

/// Total area of the triangles of pd.
inline double Area(vtkPolyData* pd)
{
  double area = 0;
  vtkCellArray* polys = pd->GetPolys();
  vtkIdType n;
  const vtkIdType* ids;
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    double a[3], b[3], c[3], ab[3], ac[3], cross[3];
    pd->GetPoint(ids[0], a);
    pd->GetPoint(ids[1], b);
    pd->GetPoint(ids[2], c);
    vtkMath::Subtract(b, a, ab);
    vtkMath::Subtract(c, a, ac);
    vtkMath::Cross(ab, ac, cross);
    area += 0.5 * vtkMath::Norm(cross);
  }
  return area;
}

} // namespace testutils

#endif

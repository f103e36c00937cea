#include "vtkBoolSurfBooleanStage.h"

#include "Selection/RegionBoundary.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

namespace boolsurf
{
namespace
{

bool CheckShapeId(int id, int n, const char* which, std::string& error)
{
  if (id < -1 || id >= n)
  {
    error = std::string(which) + " = " + std::to_string(id) + " is not a shape of the input (" +
      std::to_string(n) + " shape(s): 0.." + std::to_string(n - 1) + ", or -1 for all)";
    return false;
  }
  return true;
}

void ExtractRegion(vtkPolyData* input, const std::vector<char>& selectedCells, vtkPolyData* region)
{
  vtkDataArray* cellOf = input->GetCellData()->GetArray("ArrangementCell");
  const vtkIdType nt = input->GetNumberOfCells();
  std::vector<vtkIdType> pointMap(input->GetNumberOfPoints(), -1);
  vtkNew<vtkPoints> points;
  points->SetDataType(input->GetPoints()->GetDataType());
  vtkNew<vtkCellArray> polys;
  vtkPointData* inPD = input->GetPointData();
  vtkCellData* inCD = input->GetCellData();
  region->GetPointData()->CopyAllocate(inPD);
  region->GetCellData()->CopyAllocate(inCD);
  vtkNew<vtkIdList> ids;
  vtkIdType newCell = 0;
  for (vtkIdType t = 0; t < nt; ++t)
  {
    if (!selectedCells[static_cast<int>(cellOf->GetComponent(t, 0))])
    {
      continue;
    }
    input->GetCellPoints(t, ids);
    vtkIdType out[3];
    for (int k = 0; k < 3; ++k)
    {
      vtkIdType& m = pointMap[ids->GetId(k)];
      if (m < 0)
      {
        m = points->InsertNextPoint(input->GetPoint(ids->GetId(k)));
        region->GetPointData()->CopyData(inPD, ids->GetId(k), m);
      }
      out[k] = m;
    }
    polys->InsertNextCell(3, out);
    region->GetCellData()->CopyData(inCD, t, newCell++);
  }
  region->SetPoints(points);
  region->SetPolys(polys);
}

void WriteBoundary(vtkPolyData* input,
  const std::vector<BoundaryPolyline>& lines,
  vtkPolyData* boundary)
{
  vtkNew<vtkPoints> points;
  points->SetDataType(input->GetPoints()->GetDataType());
  vtkNew<vtkCellArray> cells;
  vtkPointData* inPD = input->GetPointData();
  vtkPointData* outPD = boundary->GetPointData();
  // Only the surface-point arrays: the boundary is a set of curves, not the surface.
  vtkNew<vtkPointData> surfacePoints;
  for (const char* name : { "TriangleId", "Barycentric" })
  {
    if (vtkDataArray* a = inPD->GetArray(name))
    {
      surfacePoints->AddArray(a);
    }
  }
  outPD->CopyAllocate(surfacePoints);
  vtkNew<vtkIntArray> closed;
  closed->SetName("Closed");
  for (const BoundaryPolyline& line : lines)
  {
    const vtkIdType first = points->GetNumberOfPoints();
    for (int p : line.Points)
    {
      const vtkIdType id = points->InsertNextPoint(input->GetPoint(p));
      outPD->CopyData(surfacePoints, p, id);
    }
    const vtkIdType n = static_cast<vtkIdType>(line.Points.size());
    cells->InsertNextCell(n + (line.Closed ? 1 : 0));
    for (vtkIdType i = 0; i < n; ++i)
    {
      cells->InsertCellPoint(first + i);
    }
    if (line.Closed)
    {
      cells->InsertCellPoint(first); // closed loops repeat their first point id
    }
    closed->InsertNextValue(line.Closed ? 1 : 0);
  }
  boundary->SetPoints(points);
  boundary->SetLines(cells);
  boundary->GetCellData()->AddArray(closed);
}

} // namespace

//------------------------------------------------------------------------------
bool ExpressionText(const BooleanRequest& request, int n, std::string& text, std::string& error)
{
  if (n <= 0)
  {
    error = "the input has no shapes";
    return false;
  }
  if (request.Operation == BooleanOperation::Expression)
  {
    text = request.Expression;
    return true;
  }
  if (!CheckShapeId(request.ShapeA, n, "ShapeA", error) ||
    !CheckShapeId(request.ShapeB, n, "ShapeB", error))
  {
    return false;
  }
  const int a = request.ShapeA, b = request.ShapeB;
  switch (request.Operation)
  {
    case BooleanOperation::Union:
      text = BooleanExpression::Union(a, b, n);
      break;
    case BooleanOperation::Intersection:
      text = BooleanExpression::Intersection(a, b, n);
      break;
    case BooleanOperation::Difference:
      text = BooleanExpression::Difference(a, b, n);
      break;
    case BooleanOperation::SymmetricDifference:
    default:
      text = BooleanExpression::SymmetricDifference(a, b, n);
      break;
  }
  return true;
}

//------------------------------------------------------------------------------
bool ComputeBoolean(vtkPolyData* labeled,
  const ArrangementFields& fields,
  const LabelingResult& labels,
  const BooleanRequest& request,
  vtkPolyData* region,
  vtkPolyData* boundary,
  std::string& error)
{
  region->Initialize();
  boundary->Initialize();
  std::string text;
  if (!ExpressionText(request, fields.NumberOfShapes, text, error))
  {
    return false;
  }
  BooleanExpression expression;
  if (!expression.Parse(text, fields.NumberOfShapes, error))
  {
    return false;
  }
  std::vector<char> selected;
  if (!SelectCells(labels, expression, request.Rule, selected, error))
  {
    return false;
  }
  ExtractRegion(labeled, selected, region);
  WriteBoundary(labeled, ExtractRegionBoundary(fields.Patches, selected), boundary);
  for (vtkPolyData* out : { region, boundary })
  {
    vtkNew<vtkStringArray> e;
    e->SetName("Expression");
    e->InsertNextValue(text);
    out->GetFieldData()->AddArray(e);
  }
  return true;
}

} // namespace boolsurf

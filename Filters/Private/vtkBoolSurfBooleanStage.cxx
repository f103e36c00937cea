#include "vtkBoolSurfBooleanStage.h"

#include "vtkBoolSurfArrayNames.h"

#include "vtkBoolSurfStageHandoff.h"

#include "Selection/RegionBoundary.h"
#include "vtkBoolSurfControlOutput.h"
#include "vtkBoolSurfRegionOutput.h"

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <algorithm>

namespace boolsurf
{
namespace
{

bool CheckShapeId(int id, const std::vector<int>& ids, const char* which, std::string& error)
{
  if (id != -1 && !std::binary_search(ids.begin(), ids.end(), id))
  {
    error = std::string(which) + " = " + std::to_string(id) + " is not a shape of the input (" +
      ShapeList(ids) + "; or -1 for all)";
    return false;
  }
  return true;
}

} // namespace

//------------------------------------------------------------------------------
bool ExpressionText(const BooleanRequest& request,
  const std::vector<int>& ids,
  std::string& text,
  std::string& error)
{
  if (ids.empty())
  {
    error = "the input has no shapes";
    return false;
  }
  if (request.Operation == BooleanOperation::Expression)
  {
    text = request.Expression;
    return true;
  }
  if (!CheckShapeId(request.ShapeA, ids, "ShapeA", error) ||
    !CheckShapeId(request.ShapeB, ids, "ShapeB", error))
  {
    return false;
  }
  const int a = request.ShapeA, b = request.ShapeB;
  switch (request.Operation)
  {
    case BooleanOperation::Union:
      text = BooleanExpression::Union(a, b, ids);
      break;
    case BooleanOperation::Intersection:
      text = BooleanExpression::Intersection(a, b, ids);
      break;
    case BooleanOperation::Difference:
      text = BooleanExpression::Difference(a, b, ids);
      break;
    case BooleanOperation::SymmetricDifference:
    default:
      text = BooleanExpression::SymmetricDifference(a, b, ids);
      break;
  }
  return true;
}

//------------------------------------------------------------------------------
bool SelectRequestedCells(const LabelingResult& labels,
  const BooleanRequest& request,
  std::vector<char>& selected,
  std::string& text,
  std::string& error)
{
  std::vector<int> ids = labels.ShapeIds;
  if (ids.empty())
  {
    for (int s = 0; s < labels.NumberOfShapes; ++s)
    {
      ids.push_back(s);
    }
  }
  if (!ExpressionText(request, ids, text, error))
  {
    return false;
  }
  BooleanExpression expression;
  return expression.Parse(text, ids, error) &&
    SelectCells(labels, expression, request.Rule, selected, error);
}

//------------------------------------------------------------------------------
void AddExpressionField(vtkPolyData* output, const std::string& text)
{
  vtkNew<vtkStringArray> e;
  e->SetName(boolsurf::names::Expression);
  e->InsertNextValue(text);
  output->GetFieldData()->AddArray(e);
}

} // namespace boolsurf

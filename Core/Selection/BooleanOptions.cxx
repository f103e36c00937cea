#include "Selection/BooleanOptions.h"

#include <algorithm>
#include <cctype>
#include <limits>

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
bool ExpressionText(const BooleanOptions& options,
  const std::vector<int>& ids,
  std::string& text,
  std::string& error)
{
  if (ids.empty())
  {
    error = "the input has no shapes";
    return false;
  }
  if (options.Operation == BooleanOperation::Expression)
  {
    text = options.Expression;
    return true;
  }
  if (!CheckShapeId(options.ShapeA, ids, "ShapeA", error) ||
    !CheckShapeId(options.ShapeB, ids, "ShapeB", error))
  {
    return false;
  }
  const int a = options.ShapeA, b = options.ShapeB;
  switch (options.Operation)
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
bool SelectBooleanCells(const LabelingResult& labels,
  const BooleanOptions& options,
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
  if (!ExpressionText(options, ids, text, error))
  {
    return false;
  }
  BooleanExpression expression;
  return expression.Parse(text, ids, error) &&
    SelectCells(labels, expression, options.Rule, selected, error);
}

//------------------------------------------------------------------------------
std::vector<int> ShapesNamed(const BooleanOptions& options)
{
  std::vector<int> shapes;
  if (options.Operation != BooleanOperation::Expression) // ShapeA and ShapeB (-1: all shapes)
  {
    for (int id : { options.ShapeA, options.ShapeB })
    {
      if (id >= 0)
      {
        shapes.push_back(id);
      }
    }
    return shapes;
  }
  const std::string& expression = options.Expression;
  // S<digits> tokens; the expression's own parser checks everything else.
  for (std::size_t i = 0; i + 1 < expression.size(); ++i)
  {
    if ((expression[i] == 'S' || expression[i] == 's') && std::isdigit(expression[i + 1]) &&
      (i == 0 || !std::isalnum(static_cast<unsigned char>(expression[i - 1]))))
    {
      long long id = 0;
      std::size_t k = i + 1;
      for (; k < expression.size() && std::isdigit(static_cast<unsigned char>(expression[k])) &&
           id <= std::numeric_limits<int>::max();
           ++k)
      {
        id = 10 * id + (expression[k] - '0');
      }
      if (id <= std::numeric_limits<int>::max())
      {
        shapes.push_back(static_cast<int>(id));
      }
      i = k - 1;
    }
  }
  return shapes;
}

} // namespace boolsurf

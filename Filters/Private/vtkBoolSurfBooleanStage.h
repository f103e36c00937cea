// The Boolean selection stage on VTK data, shared by vtkBoolSurfBoolean and the one-step
// vtkBoolSurf filter (a private header of the module).
#ifndef vtkBoolSurfBooleanStage_h
#define vtkBoolSurfBooleanStage_h

#include "Selection/BooleanSelection.h"
#include "vtkBoolSurfArrangementOutput.h"

#include <string>
#include <vector>

class vtkPolyData;

namespace boolsurf
{

enum class BooleanOperation : int
{
  Union = 0,
  Intersection = 1,
  Difference = 2,
  SymmetricDifference = 3,
  Expression = 4,
};

struct BooleanRequest
{
  BooleanOperation Operation = BooleanOperation::Union;
  int ShapeA = 0, ShapeB = 1; ///< -1: all shapes (variadic)
  std::string Expression;     ///< for BooleanOperation::Expression
  FillRule Rule = FillRule::NonZero;
};

/// A request from the filters' integer properties (the enumerations' values).
inline BooleanRequest MakeBooleanRequest(int operation,
  int shapeA,
  int shapeB,
  const std::string& expression,
  int fillRule)
{
  BooleanRequest request;
  request.Operation = static_cast<BooleanOperation>(operation);
  request.ShapeA = shapeA;
  request.ShapeB = shapeB;
  request.Expression = expression;
  request.Rule = static_cast<FillRule>(fillRule);
  return request;
}

/// The expression text of a request over the shapes `shapeIds` (sorted), or false and a
/// message (unknown shape ids, no shapes).
bool ExpressionText(const BooleanRequest& request,
  const std::vector<int>& shapeIds,
  std::string& text,
  std::string& error);

/// Evaluates a request once per cell: selected[cell], and the expression text it ran. False
/// with a named error: malformed expression, unknown shape, inconsistent operand.
bool SelectRequestedCells(const LabelingResult& labels,
  const BooleanRequest& request,
  std::vector<char>& selected,
  std::string& text,
  std::string& error);

/// The field data `Expression` (the expression a result was selected with).
void AddExpressionField(vtkPolyData* output, const std::string& text);

} // namespace boolsurf

#endif

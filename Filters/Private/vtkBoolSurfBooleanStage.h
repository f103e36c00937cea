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

/// Writes the cells with selected[cell] != 0 of a refined surface (its triangles with all their
/// arrays, and the labels table when present) and their boundary (oriented loops, region on
/// the left, with point data TriangleId/Barycentric): the Boolean and BSC filters' writer for
/// an input that carries no Core arrangement (a file, a deep copy; see WriteSelectedCells).
/// When `controls`/`clipped` are given and the arrangement carries its patches' control points
/// (field data of vtkBoolSurfArrangement when its curves came from vtkBoolSurfTraceCurves), also
/// writes the boundary as control points of sub-curves of the input curves and the clipped open
/// curves (see vtkBoolSurf ports 2 and 3); without them those outputs stay empty and `note`
/// says why.
void WriteSelection(vtkPolyData* labeled,
  const ArrangementFields& fields,
  const std::vector<char>& selected,
  vtkPolyData* region,
  vtkPolyData* boundary,
  vtkPolyData* controls = nullptr,
  vtkPolyData* clipped = nullptr,
  std::string* note = nullptr);

} // namespace boolsurf

#endif

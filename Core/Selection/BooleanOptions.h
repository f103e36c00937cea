// What a Boolean selects (BoolSurf step 6): the operation, its operand shapes or expression and
// the fill rule, as one options struct held by the Surface Boolean and one-step filters and
// taken by the selection whole.
#ifndef boolsurf_BooleanOptions_h
#define boolsurf_BooleanOptions_h

#include "Selection/BooleanSelection.h"

#include <string>
#include <vector>

namespace boolsurf
{

/// The operations (the values of the filters' Operation property).
enum class BooleanOperation : int
{
  Union = 0,
  Intersection = 1,
  Difference = 2,
  SymmetricDifference = 3,
  Expression = 4,
};

struct BooleanOptions
{
  BooleanOperation Operation = BooleanOperation::Union;
  /// The operands of a two-shape operation, by ShapeId; -1: all shapes (the variadic form).
  int ShapeA = 0, ShapeB = 1;
  /// Read when Operation is Expression (grammar: BooleanExpression).
  std::string Expression = "S0 | S1";
  FillRule Rule = FillRule::NonZero;
};

/// The expression text of `options` over the shapes `shapeIds` (sorted), or false and a
/// message (unknown shape ids, no shapes).
bool ExpressionText(const BooleanOptions& options,
  const std::vector<int>& shapeIds,
  std::string& text,
  std::string& error);

/// Evaluates `options` once per cell: selected[cell], and the expression text it ran. False
/// with a named error: malformed expression, unknown shape, inconsistent operand.
bool SelectBooleanCells(const LabelingResult& labels,
  const BooleanOptions& options,
  std::vector<char>& selected,
  std::string& text,
  std::string& error);

/// The shape ids `options` names: ShapeA and ShapeB (those >= 0) of a two-shape operation, or
/// the S<id> of an expression (its parser checks the rest).
std::vector<int> ShapesNamed(const BooleanOptions& options);

} // namespace boolsurf

#endif

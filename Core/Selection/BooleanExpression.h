// Boolean expressions over shapes, e.g. "(S0 & S1) ^ ~S2 | S3 - S4".
//
// Grammar (precedence from high to low; binary operators are left associative):
//   primary := "S" <id> | "(" expr ")" | "~" primary        (not)
//   and     := primary { ("&" | "-") primary }               (and, minus: A - B = A & ~B)
//   xor     := and { "^" and }
//   expr    := xor { "|" xor }                                (or)
// Whitespace is ignored. The expression is compiled once into postfix code and evaluated per
// cell over the cell's inside/outside bits, so any expression costs one pass over the cells.
#ifndef boolsurf_BooleanExpression_h
#define boolsurf_BooleanExpression_h

#include <string>
#include <vector>

namespace boolsurf
{

/// "3 shape(s): S0, S5, S1000000" (the first few and the last when there are many).
std::string ShapeList(const std::vector<int>& shapeIds);

class BooleanExpression
{
public:
  /// Parses `text`. On failure returns false and a message naming the position and what was
  /// expected; shape ids >= numberOfShapes are "unknown shape" errors (pass -1 to accept any).
  bool Parse(const std::string& text, int numberOfShapes, std::string& error);

  /// Parses `text` over the shapes `shapeIds` (sorted, distinct; any int ids, e.g. 7 and
  /// 1000000): S<id> names a shape by its id and is evaluated on its index in `shapeIds`, so
  /// Evaluate's `inside` and GetShapes() use indices. Ids not in the list are "unknown shape"
  /// errors.
  bool Parse(const std::string& text, const std::vector<int>& shapeIds, std::string& error);

  /// Value for one cell; inside[s] tells whether the cell is inside shape s.
  bool Evaluate(const std::vector<char>& inside) const;

  /// Shapes the expression reads (ids, or indices in the shapeIds given to Parse), sorted,
  /// without repeats.
  const std::vector<int>& GetShapes() const { return this->Shapes; }

  ///@{
  /// Expressions for the named operations; shape -1 in a variadic position means "all
  /// shapes" (Union, Intersection, SymmetricDifference over 0..n-1; Difference: S0 minus the
  /// union of the others).
  static std::string Union(int a, int b, int numberOfShapes);
  static std::string Intersection(int a, int b, int numberOfShapes);
  static std::string Difference(int a, int b, int numberOfShapes);
  static std::string SymmetricDifference(int a, int b, int numberOfShapes);
  ///@}

  ///@{
  /// The same over the shapes `shapeIds` (sorted ids; "all shapes" means all of them).
  static std::string Union(int a, int b, const std::vector<int>& shapeIds);
  static std::string Intersection(int a, int b, const std::vector<int>& shapeIds);
  static std::string Difference(int a, int b, const std::vector<int>& shapeIds);
  static std::string SymmetricDifference(int a, int b, const std::vector<int>& shapeIds);
  ///@}

private:
  bool Compile(const std::string& text,
    int numberOfShapes,
    const std::vector<int>* shapeIds,
    std::string& error);

  enum Op : int
  {
    Push = 0, // followed by the shape id in Code
    Not,
    And,
    Or,
    Xor,
    Minus
  };
  std::vector<int> Code;
  std::vector<int> Shapes;
  mutable std::vector<char> Stack;
};

} // namespace boolsurf

#endif

// Selection of arrangement cells by a Boolean expression over shapes (BoolSurf step 6).
//
// A cell is inside shape s when its winding label passes the fill rule; the expression is
// evaluated once per cell over those bits. Shapes whose labels are not path independent
// (inconsistent) cannot be answered for: an expression that reads one is refused.
#ifndef boolsurf_BooleanSelection_h
#define boolsurf_BooleanSelection_h

#include "Labeling/CellLabeling.h"
#include "Selection/BooleanExpression.h"

#include <string>
#include <vector>

namespace boolsurf
{

/// How a winding label turns into inside/outside (the names of Clipper2's fill rules).
enum class FillRule : int
{
  NonZero = 0,  ///< label != 0
  EvenOdd = 1,  ///< odd label
  Positive = 2, ///< label > 0
  Negative = 3, ///< label < 0
};

inline bool IsInside(int label, FillRule rule)
{
  switch (rule)
  {
    case FillRule::EvenOdd:
      return (label & 1) != 0;
    case FillRule::Positive:
      return label > 0;
    case FillRule::Negative:
      return label < 0;
    case FillRule::NonZero:
    default:
      return label != 0;
  }
}

/// Selected[cell] = expression value. Returns false with a message naming the inconsistent
/// shapes the expression reads (and the cells where their labels conflict).
bool SelectCells(const LabelingResult& labels,
  const BooleanExpression& expression,
  FillRule rule,
  std::vector<char>& selected,
  std::string& error);

} // namespace boolsurf

#endif

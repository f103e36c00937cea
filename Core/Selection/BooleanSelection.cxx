#include "Selection/BooleanSelection.h"

namespace boolsurf
{

//------------------------------------------------------------------------------
bool SelectCells(const LabelingResult& labels,
  const BooleanExpression& expression,
  FillRule rule,
  std::vector<char>& selected,
  std::string& error)
{
  std::string bad;
  for (int s : expression.GetShapes())
  {
    if (s >= labels.NumberOfShapes)
    {
      error = "the expression reads shape index " + std::to_string(s) +
        " but the arrangement has " + std::to_string(labels.NumberOfShapes) + " shape(s)";
      return false;
    }
    if (!labels.ShapeConsistent[s])
    {
      std::string where;
      for (const LabelConflict& c : labels.Conflicts)
      {
        if (c.Shape == s)
        {
          where = " (cell " + std::to_string(c.Cell) + " is reached with labels " +
            std::to_string(c.FirstLabel) + " and " + std::to_string(c.SecondLabel) + ")";
        }
      }
      bad +=
        (bad.empty() ? "" : ", ") + std::string("S") + std::to_string(labels.ShapeIdOf(s)) + where;
    }
  }
  if (!bad.empty())
  {
    error = "the operation involves inconsistent shape(s) whose curves do not bound a region "
            "(not null-homologous or open): " +
      bad + "; resolve them first";
    return false;
  }
  const int ns = labels.NumberOfShapes;
  const int nc = ns > 0 ? static_cast<int>(labels.Labels.size()) / ns : 0;
  // Once per cell, reading only the shapes the expression names: the cost is cells x operands,
  // never triangles.
  selected.assign(nc, 0);
  std::vector<char> inside(ns, 0);
  const std::vector<int>& operands = expression.GetShapes();
  const int* row = labels.Labels.data();
  for (int c = 0; c < nc; ++c, row += ns)
  {
    for (int s : operands)
    {
      inside[s] = IsInside(row[s], rule);
    }
    selected[c] = expression.Evaluate(inside);
  }
  return true;
}

} // namespace boolsurf

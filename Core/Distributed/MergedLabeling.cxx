#include "Distributed/MergedLabeling.h"

namespace boolsurf
{

//------------------------------------------------------------------------------
LabelingInput MergedLabelingInput(const MergedArrangement& merged, const std::vector<int>& shapeIds)
{
  // The crossings between cells and those with plugs, each at a place of its own: equal
  // crossings found on several pieces are one already, and the labeling crosses one place's
  // curves at once, as it crosses the patches of one place on the whole arrangement.
  std::vector<CellCrossing> crossings = merged.Crossings;
  crossings.insert(crossings.end(), merged.PlugCrossings.begin(), merged.PlugCrossings.end());
  LabelingInput in = LabelingInputOfCrossings(merged.NumberOfCells, crossings, shapeIds);
  in.NumberOfPlugs = merged.NumberOfPlugs;
  in.CellComponent = merged.NodeComponent;
  in.ZeroCells = merged.ZeroNodes;
  return in;
}

//------------------------------------------------------------------------------
std::vector<std::pair<int, int>> MergedPlugLinks(const MergedArrangement& merged)
{
  std::vector<std::pair<int, int>> links;
  for (const CellCrossing& c : merged.PlugCrossings)
  {
    if (c.Delta.empty())
    {
      links.emplace_back(c.FromCell, c.ToCell); // normalized: the cell, then the plug node
    }
  }
  return links; // PlugCrossings are sorted and distinct
}

//------------------------------------------------------------------------------
LabelingResult LabelMergedArrangement(const MergedArrangement& merged,
  const std::vector<int>& shapeIds,
  int zeroCell)
{
  LabelingInput in = MergedLabelingInput(merged, shapeIds);
  if (zeroCell >= 0 && zeroCell < merged.NumberOfCells)
  {
    in.SetZeroCell(zeroCell);
  }
  return LabelCells(in);
}

} // namespace boolsurf

// The labeling stage (Labeling/CellLabeling.h) on the merged cell graph of a distributed
// arrangement (MergedArrangement.h): the cell graph is small, bounded by the curves, so every
// process that has it (message 3 gives it to every piece) labels it whole, replicated, and
// gets the labels the labeling stage gives on the whole surface's arrangement.
//
// The input is MakeLabelingInput's on the whole arrangement, rebuilt from the merge: the same
// cells (canonical numbers) and crossings, the plugs of the surface's boundary loops numbered
// as MeshTopology numbers the loops, each component's zero node (the plug of its longest loop)
// and the cells' components. Labels of consistent shapes and every shape's consistency are
// therefore the whole surface's. An inconsistent shape's labels are those of one search of the
// graph, as on the whole surface, where they have no meaning of their own: the search meets the
// cells in the same order as on the whole arrangement (crossings are sorted by their cells, which
// are numbered alike), so they are equal too, except where two crossings join the same two cells
// with different changes or curves of one shape cancel along a stretch between two cells (one
// crossing there, several places on the whole arrangement). Which cell a conflict is reported at
// (LabelingResult::Conflicts) may differ the same way.
#ifndef boolsurf_MergedLabeling_h
#define boolsurf_MergedLabeling_h

#include "Distributed/MergedArrangement.h"
#include "Labeling/CellLabeling.h"

#include <utility>
#include <vector>

namespace boolsurf
{

/// The labeling input of `merged` (shapes: those of `shapeIds`, the curves' distinct ShapeIds,
/// and of the crossings, as indices into their sorted union), cells and plugs as nodes.
LabelingInput MergedLabelingInput(const MergedArrangement& merged,
  const std::vector<int>& shapeIds);

/// The (cell, plug node) links of the merged graph, as BoundaryPlugs::Links lists them (sorted,
/// distinct): its plug crossings without a change. Where curves of one shape cancel along a
/// stretch of boundary the merge keeps one crossing without a change, a link the whole
/// arrangement does not list (its patches there are arcs): the list then has that pair more.
std::vector<std::pair<int, int>> MergedPlugLinks(const MergedArrangement& merged);

/// LabelCells on MergedLabelingInput; `zeroCell` >= 0 (a global cell, the one holding the
/// user's ZeroCellPoint) is made its component's zero cell, as the labeling stage's Point mode
/// does.
LabelingResult LabelMergedArrangement(const MergedArrangement& merged,
  const std::vector<int>& shapeIds,
  int zeroCell = -1);

} // namespace boolsurf

#endif

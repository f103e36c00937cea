// The global arrangement's cells and cell graph from the pieces' summaries (PieceSummary.h):
// the distributed union-find of Docs/Parallel.md, stage 3, and the cell graph of stage 4.
//
// Nodes are the pieces' local cells that hold owned triangles. Two nodes are one cell when
// they are the two sides of a piece-boundary sub-segment no cell-bounding curve runs along;
// within a piece, the flood fill already joined everything else. Global cells are numbered by
// their lowest refined triangle (the smallest RefinedTriangleKey of their nodes), as
// ComputeArrangement numbers them on the whole surface, so the numbering does not depend on
// how the surface was split. The cell graph is the pieces' arcs on global cells plus, for
// each curve step along the piece boundary, the arc between the cells of its two sides.
//
// Cost: O(S log S) for S the summaries' total size (sorting the boundary sub-segments and the
// cells' keys), independent of the surface's triangles. Run on one process after a gather of
// the summaries, or (not built) by pointer jumping over the processes' boundary pairs.
#ifndef boolsurf_MergedArrangement_h
#define boolsurf_MergedArrangement_h

#include "Distributed/PieceSummary.h"
#include "Labeling/CellLabeling.h"

#include <string>
#include <vector>

namespace boolsurf
{

struct MergedArrangement
{
  int NumberOfCells = 0;
  /// Per piece, per local cell: its global cell (-1 for a local cell of ghosts only).
  std::vector<std::vector<int>> GlobalCellOfLocal;
  std::vector<RefinedTriangleKey> CellLowestTriangle; ///< per global cell
  std::vector<double> CellArea;                       ///< per global cell
  /// The cell graph without repeats: one step per (right cell, left cell, shape id).
  std::vector<CellGraphStep> Arcs;
};

/// Merges the pieces' summaries (piece p's at index p). Fails, naming the edge's global
/// vertices, when the two sides of a boundary edge disagree (a piece without its ghost ring,
/// or pieces whose curves differ).
bool MergePieceSummaries(const std::vector<PieceSummary>& pieces,
  MergedArrangement& out,
  std::string& error);

/// The one-step-per-arc cell graph of a whole-surface arrangement (its CellGraph without
/// repeats), to compare with MergedArrangement::Arcs or label alike.
std::vector<CellGraphStep> DistinctCellGraphSteps(const std::vector<CellGraphArc>& arcs);

/// Labeling input for a cell graph given as distinct steps: shapes indexed by ascending id;
/// the steps between two cells are one crossing (curves of several shapes along the same
/// place are crossed at once). The labels of consistent shapes equal those of the
/// arrangement's own patch-by-patch graph.
LabelingInput LabelingInputOfSteps(int numberOfCells, const std::vector<CellGraphStep>& steps);

} // namespace boolsurf

#endif

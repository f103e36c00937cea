// The global arrangement's cells and cell graph from the pieces' summaries (PieceSummary.h):
// the distributed union-find of Docs/Parallel.md, stage 3, and the cell graph of stage 4.
//
// Nodes are the pieces' local cells that hold owned triangles. Two nodes are one cell when
// they are the two sides of a piece-boundary sub-segment no cell-bounding curve runs along
// (BoundaryJoins.h, matched between neighbours); within a piece, the flood fill already joined
// everything else. Global cells are numbered by
// their lowest refined triangle (the smallest RefinedTriangleKey of their nodes), as
// ComputeArrangement numbers them on the whole surface, so the numbering does not depend on
// how the surface was split. The cell graph is the pieces' crossings on global cells plus the
// crossings of the boundary sub-segments curves run along (their steps from one side, the
// cells from both).
//
// Cost: O(S log S) for S the size of what is merged (local cells, joins, crossings: bounded by
// the curves and the number of pieces, not the triangles), on the process that merges; the
// boundary records (O(shared boundary)) never reach it when neighbours match them first.
#ifndef boolsurf_MergedArrangement_h
#define boolsurf_MergedArrangement_h

#include "Distributed/BoundaryJoins.h"
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
  /// The cell graph as distinct crossings (normalized, sorted).
  std::vector<CellCrossing> Crossings;
  /// The surface's boundary loops (PieceBoundaryLoops.h), numbered as MeshTopology numbers them
  /// on the whole surface: loop l's plug is labeling node NumberOfCells + l.
  int NumberOfPlugs = 0;
  /// Surface component of each node (the cells, then the plugs), numbered as MeshTopology
  /// numbers the whole surface's components (by their lowest triangle, so by their lowest cell).
  std::vector<int> NodeComponent;
  /// Per component: the plug node of its longest boundary loop, -1 for a closed component.
  std::vector<int> ZeroNodes;
  /// Between a cell (FromCell) and a plug node (ToCell): the label change from the cell into
  /// the plug (normalized, sorted, distinct; no Delta: a link, one region).
  std::vector<CellCrossing> PlugCrossings;
};

/// The merge on the merging process: `pieces[p]` is piece p's summary, of which only
/// NumberOfLocalCells, Cells, Crossings, LoopFragments and PlugCrossings are read (its boundary
/// records stayed with its neighbours), and `joins` what the neighbours matched
/// (JoinPieceBoundaries, every piece's results appended). Fails, naming it, on a join or crossing
/// naming a cell out of range, or on boundary loop fragments that do not chain into loops.
bool MergeCellGraph(const std::vector<PieceSummary>& pieces,
  const BoundaryJoins& joins,
  MergedArrangement& out,
  std::string& error);

/// Both steps on one process: JoinPieceBoundaries over all pieces (piece p's summary at index
/// p), then MergeCellGraph. Fails, naming the edge's global vertices, when the two sides of a
/// boundary edge disagree (a piece without its ghost ring, or pieces whose curves differ).
bool MergePieceSummaries(const std::vector<PieceSummary>& pieces,
  MergedArrangement& out,
  std::string& error);

/// Labeling input for a cell graph given as crossings: shapes indexed by ascending id (those
/// of `shapeIds` and of the crossings), one Location per crossing, |count| arcs per shape, a
/// link for a crossing whose curves cancel; no plugs and no components (MergedLabeling.h has
/// the labeling stage's whole input). Labels agree with the labeling stage's on the whole
/// arrangement (MakeLabelingInput) up to each shape's zero; so does every shape's consistency
/// on a closed surface.
LabelingInput LabelingInputOfCrossings(int numberOfCells,
  const std::vector<CellCrossing>& crossings,
  const std::vector<int>& shapeIds = {});

} // namespace boolsurf

#endif

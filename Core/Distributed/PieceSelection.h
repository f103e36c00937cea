// A Boolean's region on one piece of a distributed surface (Docs/Parallel.md, stage 5): the
// labels are global (MergedLabeling.h, the same on every piece), so each piece selects the
// global cells once with the selection stage's own evaluation (Selection/BooleanOptions.h) and
// keeps the refined triangles of its owned triangles that lie in selected cells. The union over
// pieces is the whole surface's region, triangle for triangle (each refined triangle of an owned
// triangle is the whole surface's, PieceSummary.h). Cost: O(owned triangles) per piece, and
// the selection's O(cells x shapes) on the labels.
#ifndef boolsurf_PieceSelection_h
#define boolsurf_PieceSelection_h

#include "Arrangement/Arrangement.h"
#include "Distributed/PieceMesh.h"
#include "Labeling/CellLabeling.h"
#include "Selection/BooleanOptions.h"

#include <string>
#include <vector>

namespace boolsurf
{

struct PieceRegion
{
  /// Refined triangles of the piece's arrangement (ids on piece.Mesh), by owned source triangle
  /// (ascending global id), then in ForEachRefinedTriangle's order.
  std::vector<int> Triangles;
  std::vector<int> SourceTriangles; ///< the global source triangle of each
  std::vector<int> Cells;           ///< the global cell of each
};

/// The owned refined triangles whose global cell (globalCellOfLocal[local cell]) is selected
/// (selected[global cell] != 0).
void SelectOwnedTriangles(const PieceMesh& piece,
  const Arrangement& arr,
  const std::vector<int>& globalCellOfLocal,
  const std::vector<char>& selected,
  PieceRegion& out);

/// SelectBooleanCells on the global labels (selected per global cell, the expression text it
/// ran), then SelectOwnedTriangles. False with the selection's error (the same on every piece).
bool SelectPieceBoolean(const PieceMesh& piece,
  const Arrangement& arr,
  const std::vector<int>& globalCellOfLocal,
  const LabelingResult& labels,
  const BooleanOptions& options,
  PieceRegion& out,
  std::vector<char>& selected,
  std::string& text,
  std::string& error);

} // namespace boolsurf

#endif

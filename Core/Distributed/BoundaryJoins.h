// What neighbouring pieces learn from each other's piece-boundary records (PieceSummary's
// Boundary and BoundarySteps): which of their local cells are one cell, and the crossings of
// the curves that run along their shared sub-segments.
//
// This is the only step that reads the boundary records, which grow with the pieces' shared
// boundary: a process exchanges them with its neighbours only (the pieces its ghosts belong
// to), matches them here, and sends on what it found -- distinct cell pairs and crossings,
// which grow with the curves -- to wherever the cell graph is merged (MergedArrangement.h).
// Sub-segments are matched by (edge's global vertices, index from the lower vertex); each
// shared sub-segment is reported by the lower-numbered of its two pieces only.
//
// Cost: O(B log B) for B the records given.
#ifndef boolsurf_BoundaryJoins_h
#define boolsurf_BoundaryJoins_h

#include "Distributed/PieceSummary.h"

#include <string>
#include <utility>
#include <vector>

namespace boolsurf
{

/// A local cell of a piece.
struct PieceCellRef
{
  int Piece = -1, Cell = -1;
  bool operator<(const PieceCellRef& o) const
  {
    return this->Piece != o.Piece ? this->Piece < o.Piece : this->Cell < o.Cell;
  }
  bool operator==(const PieceCellRef& o) const
  {
    return this->Piece == o.Piece && this->Cell == o.Cell;
  }
};

/// A crossing along the piece boundary, between local cells of two pieces (CellCrossing's
/// meaning, not normalized: cells of different pieces have no common order yet).
struct BoundaryCrossing
{
  PieceCellRef From, To;
  std::vector<std::pair<int, int>> Delta; ///< (shape id, count)
};

struct BoundaryJoins
{
  /// Pairs of local cells that are one cell, distinct.
  std::vector<std::pair<PieceCellRef, PieceCellRef>> Joins;
  std::vector<BoundaryCrossing> Crossings;
  /// Bytes a process would send on.
  std::size_t GetBytes() const;
};

/// Matches the boundary records of the given pieces (`pieces[i]` is piece `pieceIds[i]`'s
/// summary) and appends the joins and crossings of the sub-segments both of whose sides are
/// given. With `focus` >= 0 only the sub-segments of that piece are reported, and a
/// sub-segment of `focus` whose other side is missing is an error (the caller gave every
/// neighbour); with -1, all, and any sub-segment with one side is an error. Errors name the
/// edge's global vertices: a piece without its ring of ghosts, or pieces that disagree on how
/// curves split an edge (different curves).
bool JoinPieceBoundaries(const std::vector<int>& pieceIds,
  const std::vector<const PieceSummary*>& pieces,
  int focus,
  BoundaryJoins& out,
  std::string& error);

} // namespace boolsurf

#endif

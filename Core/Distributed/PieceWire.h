// The distributed arrangement's records as processes send them (Docs/Parallel.md, "Plan for a
// distributed arrangement"): flat buffers of 64-bit integers, the element type every
// message-passing layer sends as it is (vtkMultiProcessController's vtkTypeInt64 arrays), with
// no padding, no pointer and no byte order question between processes of one machine type.
//
// Three messages, in the order a distributed run sends them:
//  1. a piece's boundary records (PieceSummary's Boundary and BoundarySteps), to each neighbour
//     (the owners of its ghosts), which matches them with its own (JoinPieceBoundaries);
//  2. what a piece sends to the merge: its local cells and crossings and the joins and crossings
//     it matched with its neighbours (MergeCellGraph reads nothing else);
//  3. what the merge sends back to a piece: the number of cells, the global cell of each of its
//     local cells, and the cell graph (small: for the labeling, on every piece or one).
// Sizes: 6 integers per boundary sub-segment, 4 per curve step along the boundary, 4 per local
// cell, 2 + 2 per shape per crossing, 4 per join: what PieceSummary::GetBytes() counts, in
// 8-byte words.
//
// Unpacking checks every count against the buffer's length, so a short or corrupt message is an
// error naming the message, never a read out of bounds.
#ifndef boolsurf_PieceWire_h
#define boolsurf_PieceWire_h

#include "Distributed/BoundaryJoins.h"
#include "Distributed/MergedArrangement.h"
#include "Distributed/PieceSummary.h"

#include <string>
#include <vector>

namespace boolsurf
{

using WireBuffer = std::vector<long long>;

/// Message 1: `summary`'s Boundary and BoundarySteps.
void PackBoundaryRecords(const PieceSummary& summary, WireBuffer& out);
/// Fills out.Boundary and out.BoundarySteps (the rest of `out` is left as it is).
bool UnpackBoundaryRecords(const WireBuffer& in, PieceSummary& out, std::string& error);

/// Message 2: NumberOfLocalCells, Cells and Crossings of `summary`, and `joins` (what the piece
/// matched with its neighbours).
void PackMergeInput(const PieceSummary& summary, const BoundaryJoins& joins, WireBuffer& out);
/// `summary` gets the piece's cells and crossings (no boundary records); `joins` gets the joins
/// and crossings appended, so that one BoundaryJoins collects every piece's.
bool UnpackMergeInput(const WireBuffer& in,
  PieceSummary& summary,
  BoundaryJoins& joins,
  std::string& error);

/// Message 3: of `merged`, NumberOfCells, piece `piece`'s row of GlobalCellOfLocal, CellArea
/// and Crossings.
void PackMergedForPiece(const MergedArrangement& merged, int piece, WireBuffer& out);
/// `out` as the merge has it, with one row of GlobalCellOfLocal (the piece's) and no
/// CellLowestTriangle.
bool UnpackMergedForPiece(const WireBuffer& in, MergedArrangement& out, std::string& error);

} // namespace boolsurf

#endif

// The distributed arrangement's records as processes send them (Docs/Parallel.md, "Plan for a
// distributed arrangement"): flat buffers of 64-bit integers, the element type every
// message-passing layer sends as it is (vtkMultiProcessController's vtkTypeInt64 arrays), with
// no padding, no pointer and no byte order question between processes of one machine type.
//
// Four messages, in the order a distributed run sends them:
//  0. the traced curves, from the process that traced them to every piece: points on global
//     ids, an edge point naming its edge by its global vertices (PieceCurves.h needs them);
//  1. a piece's boundary records (PieceSummary's Boundary and BoundarySteps), to each neighbour
//     (the owners of its ghosts), which matches them with its own (JoinPieceBoundaries);
//  2. what a piece sends to the merge: its local cells and crossings, the joins and crossings
//     it matched with its neighbours, and the fragments of the surface's boundary loops on its
//     owned triangles with the cells along them (MergeCellGraph reads nothing else);
//  3. what the merge sends back to a piece: the number of cells, the global cell of each of its
//     local cells, the cells' areas and the cell graph with the boundary loops' plugs, the
//     nodes' components and zero nodes: everything the labeling reads (MergedLabeling.h), so
//     that every piece labels the graph itself.
// Sizes: 6 integers per boundary sub-segment, 4 per curve step along the boundary, 4 per local
// cell, 2 + 2 per shape per crossing, 4 per join, 5 per boundary loop fragment and 1 per
// boundary edge of the surface: what PieceSummary::GetBytes() counts, in 8-byte words.
//
// Unpacking checks every count against the buffer's length, so a short or corrupt message is an
// error naming the message, never a read out of bounds.
#ifndef boolsurf_PieceWire_h
#define boolsurf_PieceWire_h

#include "Distributed/BoundaryJoins.h"
#include "Distributed/MergedArrangement.h"
#include "Distributed/PieceSummary.h"

#include "Geodesic/TracedCurve.h"
#include "Mesh/TriangleMesh.h"

#include <array>
#include <string>
#include <vector>

namespace boolsurf
{

using WireBuffer = std::vector<long long>;

/// A double as a message entry, bit for bit (so a value read back is the value sent).
long long WireBitsOf(double x);
/// The double a message entry holds (WireBitsOf's inverse).
double WireDoubleOf(long long bits);

/// Message 0: `curves`, traced on `mesh`, with their points named by the undistributed
/// surface's ids: vertexGlobalId[v] and triangleGlobalId[t] for the mesh's vertex v and
/// triangle t (empty: the mesh's own ids), an edge by its two global vertices in the direction
/// its parameter runs. 6 words per point, 2 per distinct edge.
void PackTracedCurves(const std::vector<TracedCurve>& curves,
  const TriangleMesh& mesh,
  const std::vector<int>& vertexGlobalId,
  const std::vector<int>& triangleGlobalId,
  WireBuffer& out);
/// The curves on global ids; an edge point's Id indexes `edgeVertices` (its edge's global
/// vertices, from the end where its parameter is 0): what RestrictCurvesToPiece's
/// GlobalEdgeVertices gives.
bool UnpackTracedCurves(const WireBuffer& in,
  std::vector<TracedCurve>& curves,
  std::vector<std::array<int, 2>>& edgeVertices,
  std::string& error);

/// Message 1: `summary`'s Boundary and BoundarySteps.
void PackBoundaryRecords(const PieceSummary& summary, WireBuffer& out);
/// Fills out.Boundary and out.BoundarySteps (the rest of `out` is left as it is).
bool UnpackBoundaryRecords(const WireBuffer& in, PieceSummary& out, std::string& error);

/// Message 2: NumberOfLocalCells, Cells, Crossings, LoopFragments and PlugCrossings of
/// `summary`, and `joins` (what the piece matched with its neighbours).
void PackMergeInput(const PieceSummary& summary, const BoundaryJoins& joins, WireBuffer& out);
/// `summary` gets the piece's cells and crossings (no boundary records); `joins` gets the joins
/// and crossings appended, so that one BoundaryJoins collects every piece's.
bool UnpackMergeInput(const WireBuffer& in,
  PieceSummary& summary,
  BoundaryJoins& joins,
  std::string& error);

/// Message 3: of `merged`, NumberOfCells, piece `piece`'s row of GlobalCellOfLocal, CellArea,
/// Crossings, PlugCrossings, NumberOfPlugs, NodeComponent and ZeroNodes.
void PackMergedForPiece(const MergedArrangement& merged, int piece, WireBuffer& out);
/// `out` as the merge has it, with one row of GlobalCellOfLocal (the piece's) and no
/// CellLowestTriangle.
bool UnpackMergedForPiece(const WireBuffer& in, MergedArrangement& out, std::string& error);

} // namespace boolsurf

#endif

// What one piece of a distributed surface tells the others about its part of the arrangement
// (Docs/Parallel.md, "Plan for a distributed arrangement", stages 2 to 4).
//
// Each piece arranges its own triangles and ghost ring (ComputeArrangementOfRuns on its
// PieceMesh with its PieceCurves): its owned triangles are refined exactly as on the whole surface
// (the piece has every segment of them and of their neighbours, in the same order), and its flood
// fill gives local cells, each a subset of one global cell (a path through ghost triangles is
// a path on the surface too; ghost triangles are never reported). What the merge needs of it
// is small:
//  * per local cell holding owned triangles: its lowest owned refined triangle as (global
//    source triangle, index among that triangle's refined triangles) -- the global numbering
//    orders cells by their lowest refined triangle, and refined ids order pieces that way -- and
//    its owned area;
//  * per sub-segment of an edge between an owned triangle and another piece's triangle (the
//    piece boundary, split wherever curves meet it): the local cell on the owned side and
//    whether a cell-bounding curve runs along it. Both pieces split the edge at the same points
//    (each has all the segments of both triangles), so sub-segment i from the edge's lower
//    global vertex is the same on both sides;
//  * the crossings of the cell graph whose two sides are owned (local cells, and per shape how
//    the labels change across: curves along one place are crossed together, as the labeling
//    stage crosses the arcs of one place), and the curve steps along the piece boundary, whose
//    other side only the neighbour knows;
//  * the fragments of the surface's own boundary loops on its owned triangles and the cells
//    along them, for the loops' plugs (PieceBoundaryLoops.h).
// The boundary records (sub-segments and the curve steps along them: O(piece-boundary edges))
// go to the neighbours only, which match them (BoundaryJoins.h); the cells and crossings
// (O(local cells + curve places in owned triangles)) go to the merge (MergedArrangement.h).
// Nothing is O(triangles). Computing the summary reads the triangles of the tiles curves touch,
// one entry per clean tile (PieceTileSums.h, kept from edit to edit) and the piece border's
// sides (listed with the PieceMesh), as an edit's flood fill reads them; a hash of the curves'
// steps costs O(curve points).
//
// Measured (Benchmarks/BenchmarkPieceArrangement.cxx, ten plane sections): igea_1m (1.07M
// triangles) in 4 slabs, the largest piece 8.6 MB as received, its boundary records 86 KB, at
// most 2.8 KB per piece (8.1 KB in all) sent to the merge; a 102k torus in 4: 0.85 MB, 19 KB,
// 0.7 KB.
#ifndef boolsurf_PieceSummary_h
#define boolsurf_PieceSummary_h

#include "Arrangement/Arrangement.h"
#include "Distributed/PieceBoundaryLoops.h"
#include "Distributed/PieceCurves.h"
#include "Distributed/PieceMesh.h"
#include "Distributed/PieceTileSums.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace boolsurf
{

/// A refined triangle named independently of pieces: its global source triangle and its index
/// among that triangle's refined triangles (0: the one that keeps the source's id). Ordered as
/// the whole surface's refined ids: every index-0 triangle by source, then the others by
/// (source, index).
struct RefinedTriangleKey
{
  int Source = -1;
  int Index = 0;
  bool operator<(const RefinedTriangleKey& o) const
  {
    if ((this->Index == 0) != (o.Index == 0))
    {
      return this->Index == 0;
    }
    return this->Source != o.Source ? this->Source < o.Source : this->Index < o.Index;
  }
  bool operator==(const RefinedTriangleKey& o) const
  {
    return this->Source == o.Source && this->Index == o.Index;
  }
};

struct PieceCell
{
  int LocalCell = -1;
  RefinedTriangleKey Lowest; ///< its lowest owned refined triangle
  double Area = 0;           ///< of its owned refined triangles
};

/// A sub-segment of an edge on the piece boundary, seen from the owned side.
struct BoundarySubSegment
{
  std::uint64_t Edge = 0; ///< UndirectedPointPair of the edge's global vertices
  int Index = 0;          ///< from the edge's lower global vertex
  int Count = 0;          ///< sub-segments of the edge (both sides must agree)
  int Cell = -1;          ///< local cell on the owned side
  bool Forward = false;   ///< the owned triangle runs the edge from lower to higher global vertex
  bool Blocked = false;   ///< a cell-bounding curve runs along it
};

/// A step of a cell-bounding curve along a boundary sub-segment, reported by the piece whose
/// owned side runs the edge from lower to higher global vertex (each step once, repeats kept:
/// two curves of one shape along the sub-segment cross it twice).
struct BoundaryCurveStep
{
  std::uint64_t Edge = 0;
  int Index = 0;
  int Shape = 0;
  bool Forward = false; ///< the curve runs from lower to higher global vertex
  bool operator<(const BoundaryCurveStep& o) const;
};

/// What crossing one place of the curves does to the labels (CellLabeling.h: curves along the
/// same place are crossed at once): from FromCell to ToCell, shape id s changes by its count in
/// Delta. Normalized so that FromCell <= ToCell (and, within one cell, the first count is
/// positive), so that equal crossings found by several pieces are one.
struct CellCrossing
{
  int FromCell = -1, ToCell = -1;
  std::vector<std::pair<int, int>> Delta; ///< (shape id, count): ascending ids, no zero count
  bool operator<(const CellCrossing& o) const;
  bool operator==(const CellCrossing& o) const;
  /// FromCell <= ToCell, Delta's signs to match.
  void Normalize();
};

/// The (shape id, count) pairs summed per shape: ascending ids, zero counts dropped.
std::vector<std::pair<int, int>> SumByShape(std::vector<std::pair<int, int>> steps);

struct PieceSummary
{
  int NumberOfLocalCells = 0;
  std::vector<PieceCell> Cells; ///< local cells holding owned triangles, by local cell
  std::vector<BoundarySubSegment> Boundary;
  std::vector<BoundaryCurveStep> BoundarySteps; ///< sorted
  std::vector<CellCrossing> Crossings;          ///< on local cells, sorted, distinct
  /// The surface's own boundary loops on the owned triangles (PieceBoundaryLoops.h): for the
  /// plugs of the labeling, sent to the merge with the cells.
  std::vector<BoundaryLoopFragment> LoopFragments;
  std::vector<PlugCrossing> PlugCrossings;
  /// Bytes a process would send (the vectors' payloads): all of it, and the boundary records
  /// alone (Boundary and BoundarySteps, which only its neighbours need).
  std::size_t GetBytes() const;
  std::size_t GetBoundaryBytes() const;
};

/// The summary of a piece's arrangement `arr`, computed on piece.Mesh with `curves`. `sums`,
/// kept from update to update on the same mesh (computed again when its tiles are not the
/// arrangement's), lets the cells' areas and lowest triangles read only the tiles curves touch
/// (PieceTileSums.h); without it every owned triangle is read.
void SummarizePiece(const PieceMesh& piece,
  const PieceCurves& curves,
  const Arrangement& arr,
  PieceSummary& out,
  PieceTileSums* sums = nullptr);

/// ComputeArrangementOfRuns on the piece, then SummarizePiece. Fails with the arrangement's
/// message.
bool ArrangePiece(const PieceMesh& piece,
  const PieceCurves& curves,
  const ArrangementOptions& options,
  Arrangement& arr,
  PieceSummary& out,
  std::string& error,
  PieceTileSums* sums = nullptr);

} // namespace boolsurf

#endif

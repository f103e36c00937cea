// What a piece of a distributed surface knows of the surface's own open boundary, for the
// boundary plugs of the labeling (Labeling/BoundaryPlugs.h) on the merged cell graph.
//
// A boundary loop of the surface is cut by the piece borders into fragments: maximal runs of
// the loop's half-edges on one piece's owned triangles, walked as MeshTopology walks the loop
// (the surface on the left). Each fragment names its first half-edge and the half-edge after
// its last (on another piece's triangle, or its own first for a loop the piece holds whole) by
// their global vertices, so the merge chains fragments into loops without any piece knowing
// the others. The merge numbers loops as MeshTopology numbers them on the whole surface (by
// their lowest half-edge, 3 * global triangle + corner) and sums each loop's length edge by edge
// from that half-edge on, the whole surface's sum bit for bit: each fragment sends its edges'
// lengths (one number per boundary edge of the surface: its own boundary, never its area).
//
// Along a fragment, every refined sub-edge is met by one cell: where no cell-bounding curve
// runs along it, the cell and the loop's plug are one region (a link); where such curves run,
// stepping from the plug into the cell crosses them (their steps summed per shape, as the
// labeling crosses the patches of one place at once). Records are per distinct (fragment,
// cell, change), O(boundary sub-edges) at most and usually a few per fragment.
#ifndef boolsurf_PieceBoundaryLoops_h
#define boolsurf_PieceBoundaryLoops_h

#include "Arrangement/Arrangement.h"
#include "Distributed/PieceCurves.h"
#include "Distributed/PieceMesh.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace boolsurf
{

struct BoundaryLoopFragment
{
  /// DirectedPointPair of the global vertices of its first half-edge, and of the boundary
  /// half-edge after its last (First itself for a loop the piece holds whole).
  std::uint64_t First = 0;
  std::uint64_t Next = 0;
  /// Its lowest half-edge as 3 * global triangle + corner, and that half-edge's index in
  /// EdgeLengths.
  long long LowestHalfEdge = -1;
  int LowestIndex = 0;
  /// 3D length of each of its half-edges, in walk order.
  std::vector<double> EdgeLengths;
};

/// A cell along a fragment: stepping from the loop's plug into local cell Cell changes shape id
/// s's label by its count in Delta (ascending ids, no zero count); empty: a link (one region).
struct PlugCrossing
{
  int Fragment = -1; ///< index in the piece's fragments
  int Cell = -1;     ///< local cell
  std::vector<std::pair<int, int>> Delta;
  bool operator<(const PlugCrossing& o) const;
  bool operator==(const PlugCrossing& o) const;
};

/// The fragments of the surface's boundary loops on the piece's owned triangles, and the cells
/// along them (sorted, distinct), from the piece's arrangement `arr` of `curves`.
void SummarizeBoundaryLoops(const PieceMesh& piece,
  const PieceCurves& curves,
  const Arrangement& arr,
  std::vector<BoundaryLoopFragment>& fragments,
  std::vector<PlugCrossing>& crossings);

} // namespace boolsurf

#endif

// Arrangement stages 4 and 5: cells by flood fill over the dual graph of adjacencies, then
// patches and the cell graph.
//
// The dual graph of adjacencies (DGA) has one node per refined triangle. It is never stored:
// an unrefined triangle's arcs are the base mesh's adjacency (TriangleMesh, built once by the
// caller and reused while only the curves change); a refined triangle finds its neighbours
// among its siblings, or across a mesh edge among the sub-triangles of the neighbouring source
// triangle, by the shared refined point ids (the refinement is conforming). An arc is cut
// where a closed curve runs: sub-edges inside a source triangle carry a flag from the
// refinement, sub-edges on mesh edges are looked up in the set of edge-segment pieces.
//
// Patches are the pieces of each curve between consecutive intersection points (points that
// curves visit more than once, in total) and the points where a curve steps onto or off an
// open boundary of the surface. Each patch knows the cells on its left and right; the cell
// graph has one arc per patch of a closed curve whose two sides are cells, from its right cell
// to its left cell (left = counter-clockwise side seen from where the normals point, because
// refined triangles keep their source triangle's orientation: the triangle holding the
// directed sub-edge P -> Q is on the left of a curve going from P to Q). A patch along the
// boundary has no cell on one side: the labeling joins it to the boundary loop's plug
// (Labeling/BoundaryPlugs.h).
#ifndef boolsurf_CellPartition_h
#define boolsurf_CellPartition_h

#include "Arrangement/RefinedTriangles.h"
#include "Geodesic/TracedCurve.h"
#include "Mesh/EdgeIndex.h"
#include "Mesh/SurfacePoint.h"
#include "Mesh/ZeroPageArray.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace boolsurf
{

/// The refined surface as the flood fill sees it. Refined triangles keep the mesh's indices: an
/// unrefined mesh triangle t is refined triangle t, a refined one is refined triangle t (its first
/// piece) plus its other pieces, appended after the mesh's triangles. An edit therefore writes
/// only the triangles curves cross (and restores those the previous edit crossed).
struct RefinedSurfaceView
{
  const TriangleMesh* Mesh = nullptr;
  /// Per mesh triangle: 0 when unrefined, else its slot s + 1 (Arrangement::RefinedSlot); the
  /// slot's pieces other than the first are the refined triangles [PieceOffset[s],
  /// PieceOffset[s + 1]). Read it with SlotOf().
  const ZeroPageVector<int>* SlotOfTriangle = nullptr;
  const std::vector<int>* PieceOffset = nullptr;
  /// The refined triangles (the pieces; the rest read from Mesh).
  const RefinedTriangles* Layout = nullptr;
  Triangle Corners(int r) const { return this->Layout->GetTriangle(*this->Mesh, r); }
  int SourceOf(int r) const { return this->Layout->GetSourceTriangle(*this->Mesh, r); }
  int GetNumberOfTriangles() const { return this->Layout->GetNumberOfTriangles(); }
  /// Per source triangle: bit 0 (RefinedBit) when it was refined, bit 1 (BlockedEdgeBit) when
  /// one of its mesh edges carries a closed curve running along it.
  const ZeroPageVector<char>* Refined = nullptr;
  static constexpr char RefinedBit = 1;
  static constexpr char BlockedEdgeBit = 2;
  /// Per refined triangle: bit j when its edge j (vertex j -> j+1) lies on a closed curve
  /// inside its source triangle.
  const ZeroPageVector<unsigned char>* Blocked = nullptr;
  /// Sub-edges on mesh edges covered by closed curves (undirected refined point pairs), and a
  /// per-mesh-edge flag telling whether to look there at all.
  const std::unordered_set<std::uint64_t>* BlockedMeshSubEdges = nullptr;
  const ZeroPageVector<char>* MeshEdgeHasBlocked = nullptr;

  /// Per slot: for a crowded source triangle (more than CrowdedSize refined triangles, where
  /// scanning them for every neighbour would make the flood fill quadratic in their number),
  /// its refined triangles' directed edges (DirectedPointPair) -> refined triangle; empty for
  /// the others. Filled by SetPieceNeighbors.
  const std::vector<EdgeIndex>* CrowdedHalfEdges = nullptr;
  static constexpr int CrowdedSize = 16;

  /// Per piece of a refined source triangle, what lies across each of its edges, found once
  /// when the triangle is refined (SetPieceNeighbors) so the flood fill does not search the
  /// triangle's pieces for every edge: a refined triangle of the same source triangle (>= 0),
  /// AcrossMeshEdge(k) when the edge lies on the source triangle's local edge k, AcrossNothing
  /// when no piece holds the reversed edge. Piece i of slot s (ForEachPiece order) is entry
  /// PieceOffset[s] - NumberOfMeshTriangles + s + i.
  const std::vector<std::array<int, 3>>* PieceAcross = nullptr;
  static constexpr int AcrossNothing = -4;
  static constexpr int AcrossMeshEdge(int k) { return -1 - k; }
  /// Entry of refined triangle r, a piece of the source triangle in slot s, in PieceAcross.
  int PieceAcrossIndex(int r, int s) const
  {
    const int nt = this->Mesh->GetNumberOfTriangles();
    return (r >= nt ? r + 1 : (*this->PieceOffset)[s]) - nt + s;
  }

  /// Slot of mesh triangle t, -1 when unrefined.
  int SlotOf(int t) const { return (*this->SlotOfTriangle)[t] - 1; }
  /// Number of refined triangles of mesh triangle t (0 for an unusable one).
  int CountPieces(int t) const
  {
    const int s = this->SlotOf(t);
    return s < 0 ? (this->Mesh->IsUsable(t) ? 1 : 0)
                 : 1 + (*this->PieceOffset)[s + 1] - (*this->PieceOffset)[s];
  }
  /// Calls f(r) for every refined triangle r of usable mesh triangle t, t itself first.
  template <class F>
  void ForEachPiece(int t, F f) const
  {
    f(t);
    const int s = this->SlotOf(t);
    if (s >= 0)
    {
      for (int r = (*this->PieceOffset)[s]; r < (*this->PieceOffset)[s + 1]; ++r)
      {
        f(r);
      }
    }
  }
  /// Calls f(r, n) for every arc of the DGA from a piece r of refined mesh triangle t to a
  /// neighbour n that no closed curve blocks.
  template <class F>
  void ForEachOpenArcOfPieces(int t, F f) const
  {
    this->ForEachPiece(t,
      [&](int r)
      {
        for (int j = 0; j < 3; ++j)
        {
          bool blocked = false;
          const int n = this->Neighbor(r, j, blocked);
          if (n >= 0 && !blocked)
          {
            f(r, n);
          }
        }
      });
  }
  /// Refined triangle among those of source triangle t holding the directed edge a -> b.
  int FindDirected(int t, int a, int b) const;
  /// Neighbour across edge j of refined triangle r (-1 on the boundary); `blocked` tells
  /// whether a closed curve runs along that edge.
  int Neighbor(int r, int j, bool& blocked) const;
  /// Whether a closed curve covers the sub-edge x-y (refined point ids) of local edge k of mesh
  /// triangle t.
  bool IsMeshSubEdgeBlocked(int t, int k, int x, int y) const
  {
    return (*this->MeshEdgeHasBlocked)[this->Mesh->GetEdgeId(t, k)] &&
      this->BlockedMeshSubEdges->count(UndirectedPointPair(x, y)) > 0;
  }
};

/// The base mesh cut into tiles: connected groups of about `size` triangles (grown breadth-first
/// from the lowest unassigned triangle across manifold edges), built once per mesh. A tile with
/// no curve inside or on its edges lies in one cell, so the flood fill of an edit treats it as
/// one node: the persistent part of the dual graph of adjacencies.
struct MeshTiles
{
  std::uint64_t MeshSerial = 0;    ///< TriangleMesh::GetSerial() of the mesh they were built on
  std::vector<int> TileOfTriangle; ///< -1 for unusable triangles
  std::vector<int> Offset;         ///< members of tile k: Members[Offset[k] .. Offset[k + 1])
  std::vector<int> Members;        ///< ascending within each tile
  std::vector<int> FirstMember;    ///< per tile: Members[Offset[k]], its lowest triangle
  // Tiles in groups of about `groupSize` (grown breadth-first over tile adjacency from the
  // lowest unassigned tile), so that an edit unites the arcs between clean tiles group by
  // group: a group with no dirty tile starts from its precomputed components (GroupRoot).
  // Groups are in blocks of about `groupSize` groups the same way, one level up: a block with
  // no dirty tile starts from its precomputed components (BlockRoot), so what an edit unites
  // is the touched groups' and blocks' arcs and the arcs between blocks, not every arc of the
  // tile graph (the arcs between groups alone were a tenth of an edit's flood fill at 4.3M
  // triangles).
  std::vector<int> GroupOffset;    ///< tiles of group g: GroupTiles[GroupOffset[g] .. [g + 1])
  std::vector<int> GroupTiles;     ///< ascending within each group
  std::vector<int> GroupOf;        ///< per tile
  std::vector<int> GroupRoot;      ///< per tile: the lowest tile of its component in its group
  std::vector<int> GroupArcOffset; ///< arcs inside group g: GroupArcs[GroupArcOffset[g] ..)
  std::vector<std::pair<int, int>> GroupArcs; ///< tile pairs (a < b) of one group sharing an edge
  std::vector<int> BlockOffset;    ///< groups of block b: BlockGroups[BlockOffset[b] .. [b + 1])
  std::vector<int> BlockGroups;    ///< ascending within each block
  std::vector<int> BlockOf;        ///< per group
  std::vector<int> BlockRoot;      ///< per tile: the lowest tile of its component in its block
  std::vector<int> BlockArcOffset; ///< arcs between groups of block b: BlockArcs[.. [b] ..)
  std::vector<std::pair<int, int>> BlockArcs;      ///< tile pairs of two groups of one block
  std::vector<std::pair<int, int>> CrossBlockArcs; ///< the other tile pairs sharing an edge
  int GetNumberOfTiles() const
  {
    return this->Offset.empty() ? 0 : static_cast<int>(this->Offset.size()) - 1;
  }
  int GetNumberOfGroups() const
  {
    return this->GroupOffset.empty() ? 0 : static_cast<int>(this->GroupOffset.size()) - 1;
  }
  int GetNumberOfBlocks() const
  {
    return this->BlockOffset.empty() ? 0 : static_cast<int>(this->BlockOffset.size()) - 1;
  }
};

void BuildMeshTiles(const TriangleMesh& mesh, int size, MeshTiles& tiles, int groupSize = 32);
/// The groups and blocks of BuildMeshTiles from the tile pairs sharing an edge (a < b,
/// distinct, sorted).
void BuildTileGroups(const std::vector<std::pair<int, int>>& adjacent,
  int groupSize,
  MeshTiles& tiles);

/// Fills RefinedSurfaceView::PieceAcross for the `count` pieces of one refined source triangle.
/// `piece(i)`: the refined id of piece i (ForEachPiece order); `pieces[i]`: its corners (global
/// point ids); `edgeBits(i, j)`: the local edges of the source triangle that
/// vertex j of piece i lies on (bit k for edge k, two bits at a corner). `across` receives one
/// entry per piece; `crowded` the triangle's entry of RefinedSurfaceView::CrowdedHalfEdges.
template <class PieceId, class EdgeBits>
void SetPieceNeighbors(int count,
  const PieceId& piece,
  const Triangle* pieces,
  const EdgeBits& edgeBits,
  std::array<int, 3>* across,
  EdgeIndex& crowded)
{
  // The piece holding the reversed edge: the first one in ForEachPiece order, as a scan would
  // find. A few pieces (the usual crossed triangle) are scanned; many (a crowded triangle)
  // are looked up in the index of their half-edges, filled in piece order, which the flood
  // fill's lookups from neighbouring triangles use too.
  const bool isCrowded = count > RefinedSurfaceView::CrowdedSize;
  crowded = EdgeIndex();
  if (isCrowded)
  {
    crowded.Reset(3 * static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i)
    {
      const int r = piece(i);
      const std::array<int, 3>& v = pieces[i];
      for (int j = 0; j < 3; ++j)
      {
        const std::uint64_t key = DirectedPointPair(v[j], v[(j + 1) % 3]);
        if (!crowded.Contains(key))
        {
          crowded.Set(key, r);
        }
      }
    }
  }
  // A few pieces: their corners copied next to each other for the scans.
  std::array<std::array<int, 3>, RefinedSurfaceView::CrowdedSize> corners;
  if (!isCrowded)
  {
    for (int i = 0; i < count; ++i)
    {
      corners[i] = pieces[i];
    }
  }
  const auto holder = [&](int x, int y)
  {
    if (isCrowded)
    {
      const int r = crowded.Find(DirectedPointPair(x, y));
      return r >= 0 ? r : RefinedSurfaceView::AcrossNothing;
    }
    for (int i = 0; i < count; ++i)
    {
      const std::array<int, 3>& v = corners[i];
      if ((v[0] == x && v[1] == y) || (v[1] == x && v[2] == y) || (v[2] == x && v[0] == y))
      {
        return piece(i);
      }
    }
    return RefinedSurfaceView::AcrossNothing;
  };
  for (int i = 0; i < count; ++i)
  {
    const std::array<int, 3>& v = isCrowded ? pieces[i] : corners[i];
    const int bits[3] = { edgeBits(i, 0), edgeBits(i, 1), edgeBits(i, 2) };
    for (int j = 0; j < 3; ++j)
    {
      const int common = bits[j] & bits[(j + 1) % 3];
      across[i][j] = common != 0
        ? RefinedSurfaceView::AcrossMeshEdge(common & 1 ? 0 : (common & 2 ? 1 : 2))
        : holder(v[(j + 1) % 3], v[j]);
    }
  }
}

/// What each cell is made of: clean tiles (all their triangles are in the cell, each unrefined:
/// member t is refined triangle t) and loose refined triangles (those of tiles that
/// curves touch). Lists a cell's triangles without scanning the mesh.
struct CellContents
{
  std::vector<int> TileOffset, Tiles;         ///< tiles of cell c: [TileOffset[c], TileOffset[c+1])
  std::vector<int> TriangleOffset, Triangles; ///< loose refined triangles of cell c
};

/// The cell of each refined triangle, without a write per triangle: a clean tile's triangles
/// (unrefined, so refined index = mesh index) take their tile's cell, the others (triangles of
/// tiles curves touch, and the appended pieces) their own entry in LooseCell. LooseCell's other
/// entries are stale.
struct TriangleCellLookup
{
  const int* TileOfTriangle = nullptr;
  const int* TileCell = nullptr; ///< -1 for tiles curves touch
  const int* LooseCell = nullptr;
  int NumberOfMeshTriangles = 0;
  int operator()(int r) const
  {
    if (r < this->NumberOfMeshTriangles)
    {
      const int k = this->TileOfTriangle[r];
      if (k < 0)
      {
        return -1; // unusable triangle
      }
      if (this->TileCell[k] >= 0)
      {
        return this->TileCell[k];
      }
    }
    return this->LooseCell[r];
  }
};

/// How FloodFillCellsByTiles floods: Automatic picks Tiles when curves touch few tiles and
/// Triangles (the whole surface as one parallel union-find) when they touch most of them.
enum class FloodFillMethod
{
  Automatic,
  Tiles,
  Triangles
};

/// Scratch memory of FloodFillCellsByTiles, kept between edits, and the method to use.
struct TileFloodBuffers
{
  FloodFillMethod Method = FloodFillMethod::Automatic;
  // Tiled flood fill: nodes are the tiles (node k: tile k), then the dirty tiles' triangles.
  std::vector<char> Dirty;   ///< per tile; reset after each call
  std::vector<int> TileNode; ///< per tile: its cell (-1 when dirty)
  std::vector<int> DirtyTiles;
  std::vector<char> DirtyGroup; ///< per tile group; reset after each call
  std::vector<int> DirtyGroups;
  std::vector<char> DirtyBlock; ///< per block of groups; reset after each call
  std::vector<int> DirtyBlocks;
  ZeroPageVector<int> NodeOfTriangle;  ///< per refined triangle of a dirty tile (others stale)
  std::vector<int> NodeKey;            ///< per node: its lowest refined triangle
  std::vector<int> NodeParent;         ///< union-find over nodes
  std::vector<int> CellOfRoot;         ///< per node
  std::vector<int> NodeCell;           ///< per node of a dirty tile: its cell
  std::vector<int> DirtyTileFirstNode; ///< per dirty tile, and the end (first its piece counts)
  std::vector<std::vector<std::pair<int, int>>> TileCrossing; ///< arcs between tiles, per task
  // Whole-surface flood fill.
  std::unique_ptr<std::atomic<int>[]> AtomicParent;
  size_t AtomicCapacity = 0;
  std::vector<int> UnrefinedIndex;
  std::vector<std::vector<std::pair<int, int>>> Crossing;
  std::vector<int> BlockRoots;
};

/// Connected components of the DGA without the blocked arcs (the flood fill of the method),
/// with clean tiles as single nodes: the cost is the tiles plus the triangles of the tiles that
/// curves touch, never a pass over the mesh's triangles. Every set's root is its lowest refined
/// triangle and cells are numbered in that order, so the result is that of a sequential
/// breadth-first flood fill seeded in refined-triangle order, whatever the number of threads.
/// `changedTriangles` must list every mesh triangle whose state in `surface.Refined` is not 0
/// (repeats allowed). Writes each clean tile's cell to `tileCell` (-1 for the others) and the
/// cells of the other tiles' refined triangles and of the appended pieces to `looseCell` (read
/// both through TriangleCellLookup). Returns the number of cells; `cellFirstTriangle`, when
/// given, receives each cell's lowest triangle; `contents`, when given, each cell's tiles and
/// loose triangles.
int FloodFillCellsByTiles(const RefinedSurfaceView& surface,
  const MeshTiles& tiles,
  const std::vector<int>& changedTriangles,
  std::vector<int>& tileCell,
  ZeroPageVector<int>& looseCell,
  std::vector<int>* cellFirstTriangle,
  TileFloodBuffers& buffers,
  CellContents* contents = nullptr);

/// A curve on the refined surface: its refined point ids and, per sub-edge i (from point i to
/// i+1, and for closed curves the last back to the first), the source triangle holding it or,
/// for sub-edges on a mesh edge, -(edge id) - 1.
struct RefinedCurve
{
  std::vector<int> Points;
  std::vector<int> SubEdgeSource;
};

struct ArrangementPatch
{
  int Curve = -1; ///< index in the input curve vector
  int ShapeId = -1;
  int CurveId = -1;
  bool Closed = true;                ///< of a closed curve (bounds cells)
  int LeftCell = -1, RightCell = -1; ///< -1 beyond an open mesh boundary
  /// The mesh half-edge its first sub-edge lies on when the patch runs along an open boundary
  /// of the surface (one of its sides is no cell), else -1. Patches end where a curve steps
  /// onto or off the boundary, so all of a patch's sub-edges lie on the boundary, or none.
  int BoundaryHalfEdge = -1;
  int FirstIndex = -1; ///< index of the first point in the curve's refined points
  double Length = 0;
  /// Refined point ids; a closed curve met by no other curve is one patch whose last point
  /// repeats the first.
  std::vector<int> Points;
  std::vector<SurfacePoint> SurfacePoints; ///< the same points as triangle + barycentric
};

struct CellGraphArc
{
  int RightCell = -1, LeftCell = -1; ///< equal for a curve that does not separate cells
  int Shape = -1;
  int Patch = -1;
};

/// Scratch memory of BuildPatchesAndCellGraph (per refined point, zero between calls), kept by
/// callers that arrange repeatedly.
struct PatchGraphBuffers
{
  ZeroPageVector<int> Visits;
  ZeroPageVector<char> IsEnd;
};

/// Cuts the curves into patches and builds the cell graph (one arc per patch of a closed
/// curve whose two sides are cells). Returns the number of patch-graph vertices (distinct
/// patch end points). `curvePositions` and `curvePointSurface` hold the positions and surface
/// points of the refined points past the mesh's vertices (Arrangement::CurvePositions,
/// CurvePointSurface).
int BuildPatchesAndCellGraph(const RefinedSurfaceView& surface,
  const std::vector<TracedCurve>& curves,
  const std::vector<RefinedCurve>& refinedCurves,
  const std::vector<Vec3>& curvePositions,
  const std::vector<SurfacePoint>& curvePointSurface,
  const TriangleCellLookup& cellOfTriangle,
  std::vector<ArrangementPatch>& patches,
  std::vector<CellGraphArc>& arcs,
  PatchGraphBuffers* buffers = nullptr);

} // namespace boolsurf

#endif

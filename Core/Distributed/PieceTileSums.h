// What a piece's clean tiles add to its arrangement's summary (PieceSummary.h), computed once
// per mesh so that an edit's summary reads only the tiles curves touch.
//
// A clean tile of the arrangement (Arrangement::TileCell >= 0: no curve inside it or on its
// edges) lies in one cell and is made of unrefined mesh triangles, so what its owned triangles
// give that cell -- their area and their lowest global id -- does not depend on the curves.
// Tiles mix owned and ghost triangles (they are grown over the piece's whole mesh): each tile's
// figures count its owned members only. Summed per tile, a cell's area is the same sum in
// another order than triangle by triangle (within rounding, 1e-16 relative per term).
#ifndef boolsurf_PieceTileSums_h
#define boolsurf_PieceTileSums_h

#include "Arrangement/CellPartition.h"
#include "Distributed/PieceMesh.h"

#include <cstdint>
#include <vector>

namespace boolsurf
{

struct PieceTileSums
{
  std::uint64_t TilesSerial = 0; ///< MeshTiles::MeshSerial they were computed for (0: none)
  int NumberOfTiles = 0;
  std::vector<double> OwnedArea; ///< per tile: its owned triangles' areas, in member order
  std::vector<int> LowestOwned;  ///< per tile: its lowest owned global triangle, -1 when none
  /// Owned triangles in no tile (unusable ones), ascending: read one by one.
  std::vector<int> Untiled;

  /// Whether these sums are those of `tiles` (a mesh whose serial is 0 is never trusted).
  bool Matches(const MeshTiles& tiles) const;
  /// Computes them for `tiles` of piece.Mesh: O(piece), once per mesh.
  void Compute(const PieceMesh& piece, const MeshTiles& tiles);
};

} // namespace boolsurf

#endif

// The triangles of the refined surface, stored without a copy of the mesh's own.
//
// Refined triangles keep the mesh's indices, so that an edit writes only what curves cross:
// refined triangle t (t below the mesh's triangle count) is mesh triangle t when no curve
// crosses it, else the first piece of its triangulation; the other pieces follow the mesh's
// triangles. Only the pieces are stored: an unrefined triangle is read from the mesh (a copy
// of the mesh's triangles and sources was 68 MB on 4.3M triangles, written once per mesh and
// held by every arrangement). Outputs that need the whole list write it with
// RefinedSurfaceArrays.
#ifndef boolsurf_RefinedTriangles_h
#define boolsurf_RefinedTriangles_h

#include "Mesh/TriangleMesh.h"
#include "Mesh/ZeroPageArray.h"

#include <array>
#include <vector>

namespace boolsurf
{

struct RefinedTriangles
{
  int NumberOfMeshTriangles = 0;
  int NumberOfHoles = 0; ///< unusable mesh triangles: corners -1, source -1, no cell
  /// Per mesh triangle: 0 when unrefined, else s + 1, where s is its slot: its pieces other
  /// than refined triangle t are [PieceOffset[s], PieceOffset[s + 1]) and RefinedSources[s] is
  /// t. Zero pages (ZeroPageVector), so an edit writes the entries of what it refines only.
  /// Read it with GetRefinedSlot().
  ZeroPageVector<int> RefinedSlot;
  std::vector<int> PieceOffset;
  std::vector<int> RefinedSources;
  /// Per slot: the piece that takes its source triangle's index.
  std::vector<Triangle> FirstPieces;
  /// Refined triangles from NumberOfMeshTriangles on (entry r - NumberOfMeshTriangles), and
  /// the mesh triangle each comes from.
  std::vector<Triangle> AppendedPieces;
  std::vector<int> AppendedSources;

  /// Slot of mesh triangle t among the refined ones, -1 when unrefined.
  int GetRefinedSlot(int t) const { return this->RefinedSlot[t] - 1; }
  int GetNumberOfTriangles() const
  {
    return this->NumberOfMeshTriangles + static_cast<int>(this->AppendedPieces.size());
  }
  /// Corners of refined triangle r (refined point ids, oriented like its source triangle;
  /// -1 for a hole). `mesh`: the mesh the arrangement was computed on.
  Triangle GetTriangle(const TriangleMesh& mesh, int r) const
  {
    if (r >= this->NumberOfMeshTriangles)
    {
      return this->AppendedPieces[r - this->NumberOfMeshTriangles];
    }
    const int s = this->GetRefinedSlot(r);
    if (s >= 0)
    {
      return this->FirstPieces[s];
    }
    return mesh.IsUsable(r) ? mesh.GetTriangle(r) : Triangle{ -1, -1, -1 };
  }
  /// Mesh triangle refined triangle r lies in (-1 for a hole).
  int GetSourceTriangle(const TriangleMesh& mesh, int r) const
  {
    return r < this->NumberOfMeshTriangles && !mesh.IsUsable(r) ? -1 : this->GetSourceOfPiece(r);
  }
  /// GetSourceTriangle for an r known not to be a hole (a triangle of a cell, a neighbour met by
  /// the flood fill): no read of the mesh's usable flags in hot loops.
  int GetSourceOfPiece(int r) const
  {
    return r < this->NumberOfMeshTriangles ? r
                                           : this->AppendedSources[r - this->NumberOfMeshTriangles];
  }
};

} // namespace boolsurf

#endif

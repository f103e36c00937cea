#include "Distributed/PieceTileSums.h"

#include <algorithm>

namespace boolsurf
{

//------------------------------------------------------------------------------
bool PieceTileSums::Matches(const MeshTiles& tiles) const
{
  return tiles.MeshSerial != 0 && this->TilesSerial == tiles.MeshSerial &&
    this->NumberOfTiles == tiles.GetNumberOfTiles();
}

//------------------------------------------------------------------------------
void PieceTileSums::Compute(const PieceMesh& piece, const MeshTiles& tiles)
{
  const TriangleMesh& mesh = piece.Mesh;
  const int n = tiles.GetNumberOfTiles();
  this->OwnedArea.assign(n, 0.0);
  this->LowestOwned.assign(n, -1);
  for (int k = 0; k < n; ++k)
  {
    for (int m = tiles.Offset[k]; m < tiles.Offset[k + 1]; ++m)
    {
      const int t = tiles.Members[m];
      if (!piece.Owned[t])
      {
        continue;
      }
      // As the summary measures a refined triangle (an unrefined one is the mesh's).
      const Triangle& c = mesh.GetTriangle(t);
      const Vec3 a = mesh.GetPosition(c[0]);
      this->OwnedArea[k] +=
        0.5 * Length(Cross(mesh.GetPosition(c[1]) - a, mesh.GetPosition(c[2]) - a));
      const int g = piece.GlobalTriangle[t];
      this->LowestOwned[k] = this->LowestOwned[k] < 0 ? g : std::min(this->LowestOwned[k], g);
    }
  }
  this->Untiled.clear();
  for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    if (piece.Owned[t] && tiles.TileOfTriangle[t] < 0)
    {
      this->Untiled.push_back(t);
    }
  }
  this->TilesSerial = tiles.MeshSerial;
  this->NumberOfTiles = n;
}

} // namespace boolsurf

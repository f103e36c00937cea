#include "vtkBoolSurfTriangleLabels.h"

#include "Arrangement/EditBuffers.h"
#include "Mesh/ParallelRange.h"
#include "vtkBoolSurfArrayView.h"

#include <tbb/task_arena.h>

#include <algorithm>

namespace boolsurf
{

//------------------------------------------------------------------------------
vtkSmartPointer<vtkIntArray> KeptTriangleLabels::Update(const Arrangement* arrangement,
  const int* cells,
  vtkIdType count,
  const std::vector<int>& rows,
  int components)
{
  std::shared_ptr<Buffer> buffer = this->Buffers.Acquire(); // held by no array handed out
  Buffer& b = *buffer;
  static const Arrangement none;
  const Arrangement& arr = arrangement ? *arrangement : none;
  const MeshTiles* tiles = arr.Tiles.get();
  const vtkIdType nt = arr.NumberOfMeshTriangles;
  // Entries below nt are the mesh triangles' (the first piece of a refined one) only when no
  // hole was compacted away; tiles and written state must be those of this mesh.
  const bool perTile = tiles && tiles->MeshSerial != 0 && arr.NumberOfHoles == 0 &&
    count == arr.GetNumberOfTriangles() && b.TilesSerial == tiles->MeshSerial &&
    b.TileCell.size() == arr.TileCell.size() && b.Components == components &&
    static_cast<vtkIdType>(b.Values.size()) >= nt * components;
  b.TilesSerial = 0; // until consistent again
  ResizeForEdits(b.Values, static_cast<std::size_t>(count) * components);
  int* out = b.Values.data();
  const auto write = [&](vtkIdType t)
  {
    std::copy_n(rows.data() + static_cast<std::size_t>(cells[t]) * components,
      components,
      out + t * components);
  };
  tbb::task_arena arena(tbb::task_arena::automatic);
  if (!perTile)
  {
    ParallelRange(arena, static_cast<int>(count), [&](int t) { write(t); });
  }
  else
  {
    ParallelRange(
      arena,
      tiles->GetNumberOfTiles(),
      [&](int k)
      {
        const int now = arr.TileCell[k];
        const int then = b.TileCell[k];
        if (now >= 0 && then >= 0 &&
          std::equal(rows.begin() + static_cast<std::ptrdiff_t>(now) * components,
            rows.begin() + static_cast<std::ptrdiff_t>(now + 1) * components,
            b.Rows.begin() + static_cast<std::ptrdiff_t>(then) * components))
        {
          return; // in one cell then and now, with the same labels: its entries hold them
        }
        for (int m = tiles->Offset[k]; m < tiles->Offset[k + 1]; ++m)
        {
          write(tiles->Members[m]);
        }
      },
      256);
    for (vtkIdType t = nt; t < count; ++t)
    {
      write(t); // the pieces of refined triangles past the mesh's
    }
  }
  if (tiles && tiles->MeshSerial != 0 && arr.NumberOfHoles == 0)
  {
    b.TileCell = arr.TileCell;
    b.Rows = rows;
    b.Components = components;
    b.TilesSerial = tiles->MeshSerial;
  }
  return MakeArrayView<vtkIntArray>(b.Values.data(), count, components, buffer);
}

} // namespace boolsurf

// Per-triangle label arrays kept from edit to edit (a private header of the module): Label
// Arrangement Cells' `ShapeLabel` and `Labels` give each refined triangle its cell's labels, an
// array as long as the refined surface. An edit changes the labels of a few triangles (those
// curves cross, before or after) and of the cells whose labels changed, so the array of the
// previous update is written again only there, the way Surface Arrangement keeps its
// `ArrangementCell` (UpdateTriangleCells): a tile of the mesh that is in one cell now and was
// in one cell then keeps its entries when the two cells' labels are the same values, whatever
// their numbers. Buffers are reused only when no output holds them any more (copy on write:
// an array handed out is never written again).
#ifndef vtkBoolSurfTriangleLabels_h
#define vtkBoolSurfTriangleLabels_h

#include "Arrangement/Arrangement.h"
#include "vtkBoolSurfStageHandoff.h"

#include <vtkIntArray.h>
#include <vtkSmartPointer.h>

#include <cstdint>
#include <vector>

namespace boolsurf
{

/// One per-triangle label array of a filter, kept between its updates.
class KeptTriangleLabels
{
public:
  /// The array of triangle t's row of `rows` (`components` values per cell): row cells[t]
  /// for each of the `count` refined triangles of `arrangement` (`cells` is their
  /// ArrangementCell). Written in place into a buffer of an earlier update where its values
  /// differ, or whole when the tiles, the row width or the numbering (holes) do not allow it,
  /// or when `arrangement` is null (a rank's piece, whose tiles are not the whole mesh's).
  vtkSmartPointer<vtkIntArray> Update(const Arrangement* arrangement,
    const int* cells,
    vtkIdType count,
    const std::vector<int>& rows,
    int components);

private:
  /// A buffer and what it holds: the rows and the cell each tile was written with.
  struct Buffer
  {
    std::vector<int> Values;
    std::uint64_t TilesSerial = 0; ///< 0: not written per tile (written whole next time)
    std::vector<int> TileCell;     ///< per tile: the cell of its entries, -1 when not one
    std::vector<int> Rows;
    int Components = 0;
  };
  ResultPool<Buffer> Buffers;
};

} // namespace boolsurf

#endif

// The region to offset, read from an arrangement: the cells a Boolean expression (or BSC)
// selected become an OffsetRegion (boundary loops plus the side of each mesh vertex).
#ifndef boolsurf_OffsetRegionOfCells_h
#define boolsurf_OffsetRegionOfCells_h

#include "Arrangement/Arrangement.h"
#include "Offset/GeodesicOffset.h"

#include <vector>

namespace boolsurf
{

/// What an offset edit reuses on one mesh: the distance searches (per-vertex state, angle sums)
/// and the arrangement of the shapes offset (its buffers and the mesh's tiles), so an edit costs
/// what its curves and band cost.
struct OffsetWorkspace
{
  explicit OffsetWorkspace(const TriangleMesh& mesh)
    : Buffers(mesh)
  {
  }
  OffsetBuffers Buffers;
  Arrangement Shapes;
};

/// The region made of the cells with selected[c] != 0: its boundary (the patches between a
/// selected and an unselected cell, chained with the region on their left) and each vertex's
/// side (the cell of a refined triangle at that corner). `mesh`, `arrangement` and `selected` must
/// outlive the returned region, whose InsideVertex reads them. The surface's own open boundary
/// does not bound the region: shrinking does not eat into it from there.
OffsetRegion MakeOffsetRegion(const TriangleMesh& mesh,
  const Arrangement& arrangement,
  const std::vector<char>& selected);

} // namespace boolsurf

#endif

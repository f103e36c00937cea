// How the labeling sees a surface's open boundary: every boundary loop is closed by a plug.
//
// A plug is a disk glued along a boundary loop, one more node of the cell graph (node
// NumberOfCells + loop). A cell meets a plug along each refined sub-edge of the loop:
//  - where no closed curve covers the sub-edge, the cell and the plug are one region (a link:
//    equal labels), as the cells along a free stretch of the boundary are one region beyond it;
//  - where closed curves run along the sub-edge, stepping from the plug into the cell crosses
//    them (an arc from the patch's right side to its left side, as between two cells).
// The plug of each component's longest loop is that component's zero node: outside every
// shape. So a curve along a stretch of boundary bounds the cells on its inner side whatever part
// of the boundary it covers (its first sub-edge, a whole loop, a corner), and the outside stays
// one region where curves along the boundary cut it into pieces that no arc between cells joins.
// Plugging every loop makes each component a closed surface: a shape is consistent exactly when
// its closed curves are null-homologous there, which is the paper's condition with holes
// plugged (a curve around a hole bounds the plug; the hole's plug takes the label of the cells
// along its free stretches).
#ifndef boolsurf_BoundaryPlugs_h
#define boolsurf_BoundaryPlugs_h

#include "Arrangement/Arrangement.h"
#include "Mesh/MeshTopology.h"

#include <utility>
#include <vector>

namespace boolsurf
{

struct BoundaryPlugs
{
  int NumberOfCells = 0; ///< plug of loop l is node NumberOfCells + l
  int NumberOfPlugs = 0; ///< one per boundary loop of the mesh
  /// Surface component of each plug (that of its loop).
  std::vector<int> PlugComponent;
  /// Arcs between a plug and a cell, one per closed curve's patch along the boundary (Shape is
  /// the user's ShapeId, Patch the patch index), oriented as CellGraph's arcs.
  std::vector<CellGraphArc> Arcs;
  /// (cell, plug node) pairs that meet along a boundary sub-edge no closed curve covers; each
  /// pair once.
  std::vector<std::pair<int, int>> Links;
  /// Per surface component: the plug of its longest boundary loop, -1 for closed components.
  std::vector<int> ZeroNodes;

  int PlugOf(int loop) const { return this->NumberOfCells + loop; }
};

/// The plugs of `arrangement`'s surface, computed from its patches along the boundary
/// (ArrangementPatch::BoundaryHalfEdge) and the refined triangles on the boundary loops. The
/// cost is the boundary loops' length, not the mesh's size.
BoundaryPlugs FindBoundaryPlugs(const TriangleMesh& mesh,
  const MeshTopology& topology,
  const Arrangement& arrangement);

} // namespace boolsurf

#endif

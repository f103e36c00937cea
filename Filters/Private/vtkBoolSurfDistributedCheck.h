// Check Surface on a surface distributed across MPI ranks, without gathering it (a private
// header of the module).
//
// Each rank checks its owned triangles (vtkBoolSurfSurfacePiece) as one process checks a whole
// surface; what crosses ranks is combined on the shared border only:
// - components: a distributed union-find of the ranks' local components across the edges two
//   pieces share (matched by the positions of their end points), numbered by their smallest
//   global cell id, as one process numbers them by their first triangle;
// - Euler characteristic: triangles, edges (a shared edge counted by its lower rank) and vertex
//   fans (fans at shared points joined across the shared edges) summed per component;
// - orientation: a parity union-find over the same shared edges;
// - boundary loops: the pieces of boundary on each rank joined at the points they share,
//   numbered by their first half-edge in global cell id order;
// - problems: per rank, named by global cell ids, and summed.
// The union-find runs on the first rank over records proportional to the ranks' shared border;
// each rank gets back its own components' and loops' numbers, and every rank the field data.
#ifndef vtkBoolSurfDistributedCheck_h
#define vtkBoolSurfDistributedCheck_h

#include "Mesh/MeshTopology.h"

#include <string>
#include <vector>

class vtkBoolSurfSurfacePiece;

namespace boolsurf
{

/// What Check Surface writes, on one rank's piece (or on the whole surface in one process).
struct SurfaceCheckOutput
{
  std::vector<int> ComponentId;    ///< per triangle of the (piece's) converted surface
  std::vector<int> BoundaryLoopId; ///< per point of it
  std::vector<ComponentTopology> Components;
  std::vector<double> BoundaryLoopLengths;
  bool IsManifold = true;
  std::vector<std::string> Problems; ///< "Error <Kind>: ..." / "Warning <Kind>: ..."
};

/// Collective: every rank of the piece's controller calls it. Field data (Components,
/// BoundaryLoopLengths, IsManifold, Problems) come out the same on every rank.
void CheckDistributedSurface(const vtkBoolSurfSurfacePiece& piece, SurfaceCheckOutput& out);

} // namespace boolsurf

#endif

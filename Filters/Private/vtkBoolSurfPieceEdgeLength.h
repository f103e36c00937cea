/**
 * @brief   the whole surface's EstimateMeanEdgeLength from its pieces on MPI ranks, bit for bit
 *
 * The Bounded geodesic method's budget test reads the surface's mean edge length as one rank
 * estimates it (Core/Geodesic/GeodesicPath.h, EstimateMeanEdgeLength): the mean over edges
 * 0, s, 2s, ... in edge order, s = max(1, edges / 2^16), summed in that order. An edge belongs
 * to its lowest half-edge (corner 3t + k) and edges are numbered in that order, so a rank
 * knows which of its owned triangles' half-edges own an edge (the ring holds every triangle on
 * it) but not their ranks. Each rank sends, per owned triangle, its owned half-edges' lengths
 * to the rank holding that range of global triangle ids; a prefix over the ranges numbers the
 * edges, the sampled lengths go to rank 0, which sums them in edge order and broadcasts the
 * mean. Cost, once per surface: about five numbers per owned triangle to one rank, at most
 * 2^16 + 1 lengths to rank 0.
 */
#ifndef vtkBoolSurfPieceEdgeLength_h
#define vtkBoolSurfPieceEdgeLength_h

#include "Distributed/PieceMesh.h"

class vtkMultiProcessController;

namespace boolsurf
{
/// Collective: EstimateMeanEdgeLength of the undistributed surface, on every rank. `piece`:
/// this rank's owned triangles and their ring of ghosts.
double PieceMeanEdgeLength(vtkMultiProcessController* controller, const PieceMesh& piece);
}

#endif

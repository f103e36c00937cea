/**
 * @brief   Surface Curves' control points placed on a surface split across MPI ranks
 *
 * Surface Curves on pieces (Docs/Parallel.md, "Surface Curves on pieces"): its properties live
 * on rank 0, which alone writes the control curves; the surface is on every rank, each holding
 * its piece. PlaceOnPieces asks every rank about every control point at once: a point named
 * exactly (a global cell id) is answered by the rank owning that triangle, a point given by
 * position by every rank with its closest owned triangle (vtkBoolSurfClosestTriangles.h); one
 * gather to rank 0 then keeps the nearest answer, ties to the lowest global id, so rank 0 places
 * each point on the very triangle, at the very weights, the whole surface on one rank gives.
 * The messages grow with the number of control points and ranks, never with the surface.
 *
 * IsClosedOnPieces says whether the split surface is closed (every edge has a triangle on each
 * side: the curve editor then hides the markers on the far side), from each rank's ringed piece
 * and one reduction.
 */
#ifndef vtkBoolSurfPieceSnapping_h
#define vtkBoolSurfPieceSnapping_h

#include "vtkBoolSurfClosestTriangles.h"

#include "Distributed/PieceMesh.h"

#include <cstddef>
#include <vector>

class vtkMultiProcessController;
class vtkPolyData;

namespace boolsurf
{
/// What a rank did to place the points (field data PieceSnapping, names in
/// vtkBoolSurfArrayNames.h).
struct SnappingTraffic
{
  std::size_t Sent = 0;         ///< bytes: the queries broadcast (rank 0) and this rank's answers
  std::size_t Received = 0;     ///< bytes: the queries (other ranks), every rank's answers (rank 0)
  long long OwnedTriangles = 0; ///< the triangles this rank searched: its own
  long long Points = 0;         ///< control points placed
};

/// Collective: `queries` (read on rank 0, sent to every rank) answered by every rank from
/// `finder` (its own triangles: SetSurface(piece, true)); rank 0 keeps per query the answer of
/// the owner of the triangle named, or the nearest one (ties to the lowest global id), in
/// `placed`, and in `triangles` the number of triangles of the whole surface. The other ranks'
/// `placed` is empty.
void PlaceOnPieces(vtkMultiProcessController* controller,
  const ClosestTriangles& finder,
  std::vector<PointQuery> queries,
  std::vector<PlacedPoint>& placed,
  long long& triangles,
  SnappingTraffic& traffic);

/// Collective: whether every edge of the split surface is shared by two triangles, each rank
/// checking its owned triangles' edges in `ringed` (BuildRingedPiece: every triangle sharing a
/// point with an owned one is there).
bool IsClosedOnPieces(vtkMultiProcessController* controller, const PieceInput& ringed);

/// The field array PieceSnapping of `traffic`.
void AddPieceSnapping(const SnappingTraffic& traffic, vtkPolyData* output);
}

#endif

/**
 * @brief   Surface Boolean's ports 1 to 3 on pieces (the region's boundary loops, the
 *          boundary's control points, the clipped open curves): each rank walks the boundary
 *          and the open curves on its owned triangles, rank 0 chains and writes them
 *
 * Collective. Each rank's runs (Core/Distributed/PieceRegionBoundary.h: O(boundary points on
 * its owned triangles)) go to rank 0 as message 4; rank 0 chains them into the whole region's
 * loops and writes them as the one-rank port 1 is written (polylines, `Closed`,
 * TriangleId/Barycentric on global triangle ids). The other ranks' ports are empty: whole loops
 * on one rank, never a loop cut at a piece border. The surface never travels.
 *
 * With the vector output asked for, rank 0 first sends every rank the curves' control points
 * (the sources it read from the traced curves); message 4 then also carries, per boundary
 * segment, the curve it runs along and its stations, the open curves' segments inside the
 * region (with a selected cell on one side), and the positions of the control points on the
 * rank's owned triangles. Rank 0 turns them into ports 2 and 3 as one rank does
 * (Core/Distributed/PieceVectorOutput.h): geodesic polygons need no geodesic; a cubic Bezier's
 * pieces would (split on the whole surface), so the ports then stay empty and the note says so.
 */
#ifndef vtkBoolSurfPieceRegionBoundary_h
#define vtkBoolSurfPieceRegionBoundary_h

#include <string>
#include <vector>

class vtkMultiProcessController;
class vtkPolyData;

namespace boolsurf
{
struct PieceArrangementResult;

/// Ports 2 and 3 on pieces: where they go, and on rank 0 why they are empty when they are.
struct PieceVectorPorts
{
  vtkPolyData* Controls = nullptr; ///< port 2: the boundary's control points
  vtkPolyData* Clipped = nullptr;  ///< port 3: the open curves' pieces inside the region
  std::string Note;                ///< rank 0: why they are empty (else empty)
};

/// Writes the boundary of the cells with selected[global cell] != 0 into `boundary` on rank 0
/// (emptied on the others), and with `vector` its control curves and the clipped open curves
/// (from arranged.Sources on rank 0: none there, the ports stay empty). False on every rank,
/// with `error`, when rank 0 cannot read a rank's message. `sent` and `received` get the bytes
/// of message 4 and of the control points on this rank.
bool WritePieceRegionBoundary(vtkMultiProcessController* controller,
  const PieceArrangementResult& arranged,
  const std::vector<char>& selected,
  vtkPolyData* boundary,
  std::string& error,
  std::size_t* sent = nullptr,
  std::size_t* received = nullptr,
  PieceVectorPorts* vector = nullptr);

} // namespace boolsurf

#endif

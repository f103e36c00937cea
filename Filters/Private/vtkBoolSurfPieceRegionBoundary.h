/**
 * @brief   Surface Boolean's port 1 (the region's boundary loops) on pieces: each rank walks
 *          the boundary on its owned triangles, rank 0 chains every rank's runs into loops
 *
 * Collective. Each rank's runs (Core/Distributed/PieceRegionBoundary.h: O(boundary points on
 * its owned triangles)) go to rank 0 as message 4; rank 0 chains them into the whole region's
 * loops and writes them as the one-rank port 1 is written (polylines, `Closed`,
 * TriangleId/Barycentric on global triangle ids). The other ranks' port 1 is empty: whole loops
 * on one rank, never a loop cut at a piece border. The surface never travels.
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

/// Writes the boundary of the cells with selected[global cell] != 0 into `boundary` on rank 0
/// (emptied on the others). False on every rank, with `error`, when rank 0 cannot read a
/// rank's runs. `sent` and `received` get the bytes of message 4 on this rank.
bool WritePieceRegionBoundary(vtkMultiProcessController* controller,
  const PieceArrangementResult& arranged,
  const std::vector<char>& selected,
  vtkPolyData* boundary,
  std::string& error,
  std::size_t* sent = nullptr,
  std::size_t* received = nullptr);

} // namespace boolsurf

#endif

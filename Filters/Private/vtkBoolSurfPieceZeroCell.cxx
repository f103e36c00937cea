#include "vtkBoolSurfPieceZeroCell.h"

#include "vtkBoolSurfPieceArrangementStage.h"

#include "Labeling/ArrangementLabelingInput.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkGenericCell.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkStaticCellLocator.h>
#include <vtkUnsignedCharArray.h>

#include <limits>
#include <vector>

namespace boolsurf
{

//------------------------------------------------------------------------------
int PieceZeroCellAt(vtkMultiProcessController* controller,
  const PieceArrangementResult& arranged,
  vtkStaticCellLocator* locator,
  const double point[3],
  std::string& error)
{
  // This rank's offer: (squared distance, global triangle, global cell); none is infinitely far.
  double offer[3] = { std::numeric_limits<double>::infinity(), -1, -1 };
  vtkPolyData* surface = arranged.Surface;
  vtkDataArray* ids = surface ? surface->GetCellData()->GetGlobalIds() : nullptr;
  if (locator && ids && surface->GetNumberOfCells() > 0)
  {
    double closest[3], dist2 = 0;
    vtkIdType cell = -1;
    int sub = 0;
    vtkNew<vtkGenericCell> scratch;
    locator->FindClosestPoint(point, closest, scratch, cell, sub, dist2);
    vtkUnsignedCharArray* ghosts = surface->GetCellGhostArray();
    // A ghost is offered by its owner, at the same distance.
    if (cell >= 0 && (!ghosts || ghosts->GetValue(cell) == 0))
    {
      const int global = static_cast<int>(ids->GetTuple1(cell));
      const int local = arranged.Piece->LocalTriangle(global);
      if (local >= 0 && arranged.Piece->Owned[local])
      {
        const TriangleMesh& mesh = arranged.Piece->Mesh;
        const Arrangement& arr = arranged.Run.GetArrangement();
        const SurfacePoint at =
          PointInTriangle(mesh, local, Vec3{ closest[0], closest[1], closest[2] });
        const int localCell = CellAtSurfacePoint(mesh, arr, at.Triangle, at.U, at.V);
        offer[0] = dist2;
        offer[1] = global;
        offer[2] = localCell >= 0 ? arranged.Run.GetGlobalCell(localCell) : -1;
      }
    }
  }
  const int ranks = controller->GetNumberOfProcesses();
  std::vector<double> offers(3 * static_cast<std::size_t>(ranks));
  controller->AllGather(offer, offers.data(), 3);
  int best = -1;
  for (int r = 0; r < ranks; ++r)
  {
    const double* o = &offers[3 * r];
    if (o[1] >= 0 &&
      (best < 0 || o[0] < offers[3 * best] ||
        (o[0] == offers[3 * best] && o[1] < offers[3 * best + 1])))
    {
      best = r;
    }
  }
  if (best < 0)
  {
    error = "no surface cell found near ZeroCellPoint on any rank's piece";
    return -1;
  }
  const int zero = static_cast<int>(offers[3 * best + 2]);
  if (zero < 0)
  {
    error = "ZeroCellPoint lies on triangle " +
      std::to_string(static_cast<long long>(offers[3 * best + 1])) +
      ", which is not part of the surface";
  }
  return zero;
}

} // namespace boolsurf

#include "vtkBoolSurfPieceArrangementStage.h"

#include "vtkBoolSurfArrayNames.h"
#include "vtkBoolSurfControlCurves.h"
#include "vtkBoolSurfCurvesMessage.h"
#include "vtkBoolSurfPieceArrangementOutput.h"
#include "vtkBoolSurfRingedPiece.h"
#include "vtkBoolSurfSurfacePiece.h"

#include "Distributed/PieceCurves.h"
#include "Distributed/PieceWire.h"
#include "Labeling/ArrangementLabelingInput.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

#include <unordered_map>

namespace boolsurf
{

const char* const ArraysNotOnPieces =
  "the cell graph (CellGraphArcs, CellGraphShape, CellGraphPatch, CellGraphLocation, "
  "CellGraphDirection), the patches (PatchOffsets, PatchPoints, PatchLeftCell, PatchRightCell, "
  "PatchShape, PatchCurve, PatchClosed, PatchControl*), the rebuild fields (Arranged*), "
  "CurveHomology and "
  "the homology generators, StageTimes, the surface's own point and cell arrays, and port 1 "
  "(the patches as polylines, empty)";

namespace
{
/// What rank 0 says of its curves before the message.
constexpr long long DrawingStart = -1;
constexpr long long NoMessage = -2;

/// Collective: rank 0's message 0 on every rank (`status` the length, or one of the codes above).
void BroadcastCurves(vtkMultiProcessController* controller,
  vtkPolyData* curves,
  WireBuffer& message,
  long long& status)
{
  if (controller->GetLocalProcessId() == 0)
  {
    status = IsDrawingWithoutCurves(curves)     ? DrawingStart
      : ReadPieceCurvesMessage(curves, message) ? static_cast<long long>(message.size())
                                                : NoMessage;
  }
  controller->Broadcast(&status, 1, 0);
  if (status > 0)
  {
    message.resize(static_cast<std::size_t>(status));
    controller->Broadcast(message.data(), status, 0);
  }
}

/// Per local triangle of `piece`, its cell in `local` (by the cells' GlobalIds; -1 for ghosts).
std::vector<vtkIdType> SurfaceCells(vtkPolyData* local, const PieceMesh& piece)
{
  std::vector<vtkIdType> cells(piece.GlobalTriangle.size(), -1);
  vtkDataArray* ids = local ? local->GetCellData()->GetGlobalIds() : nullptr;
  if (!ids)
  {
    return cells;
  }
  vtkUnsignedCharArray* ghosts = local->GetCellGhostArray();
  std::unordered_map<long long, vtkIdType> cellOf;
  cellOf.reserve(static_cast<std::size_t>(local->GetNumberOfCells()));
  for (vtkIdType c = 0; c < local->GetNumberOfCells(); ++c)
  {
    if (!ghosts || ghosts->GetValue(c) == 0)
    {
      cellOf.emplace(static_cast<long long>(ids->GetTuple1(c)), c);
    }
  }
  for (std::size_t t = 0; t < cells.size(); ++t)
  {
    const auto found = piece.Owned[t] ? cellOf.find(piece.GlobalTriangle[t]) : cellOf.end();
    cells[t] = found == cellOf.end() ? -1 : found->second;
  }
  return cells;
}

vtkSmartPointer<vtkIntArray> IntField(const char* name, const std::vector<int>& values)
{
  auto array = vtkSmartPointer<vtkIntArray>::New();
  array->SetName(name);
  for (int v : values)
  {
    array->InsertNextValue(v);
  }
  return array;
}
} // namespace

//------------------------------------------------------------------------------
bool ArrangeOnPiece(vtkMultiProcessController* controller,
  vtkPolyData* local,
  vtkPolyData* curves,
  const ArrangementOptions& options,
  vtkPolyData* output,
  std::shared_ptr<PieceArrangementResult>& result,
  bool& drawingStart,
  std::string& error,
  std::vector<std::string>& warnings)
{
  drawingStart = false;
  WireBuffer message;
  long long status = 0;
  BroadcastCurves(controller, curves, message, status);
  if (status == DrawingStart)
  {
    drawingStart = true;
    return true;
  }
  if (status == NoMessage)
  {
    error = "Surface Arrangement on each rank's piece needs the traced curves as Trace Surface "
            "Curves packs them under MPI (its result, or its field array PieceCurvesMessage, on "
            "rank 0), for the surface with point and cell GlobalIds; the curves given have "
            "neither";
    return false;
  }

  // The piece (owned triangles; its neighbour ranks; overlapping pieces refused on every rank).
  vtkBoolSurfSurfacePiece owned;
  if (!owned.Build(controller, local, error, warnings))
  {
    return false;
  }
  std::vector<int> neighbours;
  for (const vtkBoolSurfSurfacePiece::Neighbour& n : owned.GetNeighbours())
  {
    neighbours.push_back(n.Rank);
  }

  // Its ring of ghosts, and the curves restricted to it.
  result = std::make_shared<PieceArrangementResult>();
  PieceInput ringed;
  bool ok = BuildRingedPiece(controller, local, ringed, error) &&
    BuildPieceMesh(ringed, result->Piece, error);
  std::vector<TracedCurve> global;
  std::vector<std::array<int, 2>> edgeTable;
  ok = ok && UnpackTracedCurves(message, global, edgeTable, error);
  if (!vtkBoolSurfPieceArrangement::AllSucceeded(controller, ok, error))
  {
    return false;
  }
  PieceCurves restricted;
  RestrictCurvesToPiece(
    result->Piece, global, [&](int e) { return edgeTable[e]; }, restricted);
  if (!result->Run.Run(controller, result->Piece, restricted, neighbours, options, error))
  {
    return false;
  }

  // Port 0: the owned triangles refined, with what every rank knows of the whole.
  WritePieceArrangement(result->Piece, result->Run, output);
  result->ShapeIds = DistinctShapeIds(global);
  output->GetFieldData()->AddArray(
    IntField(names::NumberOfShapes, { static_cast<int>(result->ShapeIds.size()) }));
  output->GetFieldData()->AddArray(IntField(names::ShapeIds, result->ShapeIds));
  output->GetFieldData()->AddArray(
    IntField(names::ArrangementOnPieces, { controller->GetNumberOfProcesses() }));
  result->Surface = local;
  result->SurfaceCell = SurfaceCells(local, result->Piece);
  return true;
}

}

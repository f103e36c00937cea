#include "vtkBoolSurfPieceArrangementStage.h"

#include "vtkBoolSurfArrayNames.h"
#include "vtkBoolSurfControlCurves.h"
#include "vtkBoolSurfCurvesMessage.h"
#include "vtkBoolSurfPieceArrangementOutput.h"
#include "vtkBoolSurfPieceCosts.h"
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
  "CurveHomology and the homology generators, the surface's own point and cell arrays, and port 1 "
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

/// Bytes a rank gets of its ring from vtkGhostCellsGenerator, estimated from what it got (the
/// generator's own traffic is not visible): per ghost triangle its three point ids, its global
/// id and its offset, per ghost point its position and global id.
std::size_t RingBytesReceived(const PieceInput& ringed)
{
  std::size_t triangles = 0;
  for (char ghost : ringed.Ghost)
  {
    triangles += ghost ? 1 : 0;
  }
  std::vector<char> owned(ringed.Positions.size(), 0);
  for (std::size_t t = 0; t < ringed.Triangles.size(); ++t)
  {
    for (int k = 0; !ringed.Ghost[t] && k < 3; ++k)
    {
      owned[static_cast<std::size_t>(ringed.Triangles[t][k])] = 1;
    }
  }
  std::size_t points = 0;
  for (char o : owned)
  {
    points += o ? 0 : 1;
  }
  return triangles * 5 * sizeof(long long) + points * (3 * sizeof(double) + sizeof(long long));
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
vtkSmartPointer<vtkIntArray> OnPiecesField(vtkMultiProcessController* controller)
{
  return IntField(names::ArrangementOnPieces, { controller->GetNumberOfProcesses() });
}

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
  PieceStopwatch watch, total;
  PieceCosts costs;
  WireBuffer message;
  long long status = 0;
  BroadcastCurves(controller, curves, message, status);
  costs.AddTime("Curves", watch.Lap());
  {
    // The root counted as sending the buffer to every other rank.
    const int ranks = controller->GetNumberOfProcesses();
    const std::size_t bytes = status > 0 ? WireBytes(message.size()) : sizeof(long long);
    const bool root = controller->GetLocalProcessId() == 0;
    costs.AddBytes(
      "Curves", root ? bytes * static_cast<std::size_t>(ranks - 1) : 0, root ? 0 : bytes);
  }
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
  if (!ArrangeMessageOnPiece(
        controller, local, message, options, output, result, costs, error, warnings))
  {
    return false;
  }
  costs.AddTime("Total", total.Lap());
  WritePieceCosts(costs, output);
  return true;
}

//------------------------------------------------------------------------------
bool ArrangeMessageOnPiece(vtkMultiProcessController* controller,
  vtkPolyData* local,
  const WireBuffer& message,
  const ArrangementOptions& options,
  vtkPolyData* output,
  std::shared_ptr<PieceArrangementResult>& result,
  PieceCosts& costs,
  std::string& error,
  std::vector<std::string>& warnings)
{
  PieceStopwatch watch;

  // The piece (owned triangles; its neighbour ranks; overlapping pieces refused on every rank).
  vtkBoolSurfSurfacePiece owned;
  if (!owned.Build(controller, local, error, warnings))
  {
    return false;
  }
  costs.AddTime("Piece", watch.Lap());
  costs.AddBytes("Border", owned.GetBuildBytesSent(), owned.GetBuildBytesReceived());
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
  costs.AddTime("Ring", watch.Lap());
  costs.AddBytes("RingEstimate", 0, RingBytesReceived(ringed));
  PieceCurves restricted;
  RestrictCurvesToPiece(
    result->Piece, global, [&](int e) { return edgeTable[e]; }, restricted);
  costs.AddTime("Restrict", watch.Lap());
  if (!result->Run.Run(controller, result->Piece, restricted, neighbours, options, error))
  {
    return false;
  }
  watch.Lap();

  // Port 0: the owned triangles refined, with what every rank knows of the whole.
  result->ShapeIds = DistinctShapeIds(global);
  if (output)
  {
    WritePieceArrangement(result->Piece, result->Run, output);
    output->GetFieldData()->AddArray(
      IntField(names::NumberOfShapes, { static_cast<int>(result->ShapeIds.size()) }));
    output->GetFieldData()->AddArray(IntField(names::ShapeIds, result->ShapeIds));
    output->GetFieldData()->AddArray(OnPiecesField(controller));
  }
  result->Surface = local;
  result->SurfaceCell = SurfaceCells(local, result->Piece);

  // This rank's costs: the local arrangement's own stages, then the exchanges.
  const ArrangementStageTimes& t = result->Run.GetArrangement().Times;
  const vtkBoolSurfPieceArrangement::StepTimes& steps = result->Run.GetTimes();
  const vtkBoolSurfPieceArrangement::Traffic& traffic = result->Run.GetTraffic();
  costs.AddTime("Arrange", steps.Arrange);
  costs.AddTime("Hash", t.Hash);
  costs.AddTime("Intersections", t.Intersections);
  costs.AddTime("Refinement", t.Refinement);
  costs.AddTime("FloodFill", t.FloodFill);
  costs.AddTime("CellGraph", t.CellGraph);
  costs.AddTime("Boundary", steps.Boundary);
  costs.AddTime("Merge", steps.Merge);
  costs.AddTime("Output", watch.Lap());
  costs.AddBytes("Boundary", traffic.BoundarySent, traffic.BoundaryReceived);
  costs.AddBytes("Merge", traffic.MergeSent, traffic.MergeReceived);
  costs.AddBytes("Back", traffic.BackSent, traffic.BackReceived);
  return true;
}

}

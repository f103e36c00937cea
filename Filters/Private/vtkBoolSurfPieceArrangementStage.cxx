#include "vtkBoolSurfPieceArrangementStage.h"

#include "vtkBoolSurfArrayNames.h"
#include "vtkBoolSurfControlCurves.h"
#include "vtkBoolSurfControlOutput.h"
#include "vtkBoolSurfCurvesMessage.h"
#include "vtkBoolSurfPieceArrangementOutput.h"
#include "vtkBoolSurfPieceCosts.h"
#include "vtkBoolSurfRingedPiece.h"
#include "vtkBoolSurfSurfacePiece.h"

#include "Distributed/PieceCurves.h"
#include "Distributed/PieceWire.h"
#include "Labeling/ArrangementLabelingInput.h"

#include <vtkCellData.h>
#include <vtkCommunicator.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
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

/// Collective: builds this rank's piece of `local` into `state` (its neighbours, its ring, its
/// mesh, the surface's cell per local triangle), timing the steps Piece and Ring. False on
/// every rank, with `error`, when any rank fails; `state` is then empty.
bool BuildPiece(vtkMultiProcessController* controller,
  vtkPolyData* local,
  PieceArrangementState& state,
  PieceCosts& costs,
  PieceStopwatch& watch,
  std::string& error)
{
  state.Clear();
  // The piece (owned triangles; its neighbour ranks; overlapping pieces refused on every rank),
  // gone before the ring is built: only its neighbours and traffic are kept, and its converted
  // triangles add to the rank's peak beside the ring (igea_1m on 4 ranks: 9-17 MB of the
  // first update's 200-240 MB above an idle pvbatch).
  {
    vtkBoolSurfSurfacePiece owned;
    if (!owned.Build(controller, local, error, state.BuildWarnings))
    {
      state.Clear();
      return false;
    }
    state.BorderSent = owned.GetBuildBytesSent();
    state.BorderReceived = owned.GetBuildBytesReceived();
    for (const vtkBoolSurfSurfacePiece::Neighbour& n : owned.GetNeighbours())
    {
      state.Neighbours.push_back(n.Rank);
    }
  }
  costs.AddTime("Piece", watch.Lap());

  // Its ring of ghosts, as a mesh.
  auto piece = std::make_shared<PieceMesh>();
  PieceInput ringed;
  const bool ok =
    BuildRingedPiece(controller, local, ringed, error) && BuildPieceMesh(ringed, *piece, error);
  if (!vtkBoolSurfPieceArrangement::AllSucceeded(controller, ok, error))
  {
    state.Clear();
    return false;
  }
  state.RingReceived = RingBytesReceived(ringed);
  state.SurfaceCell = std::make_shared<const std::vector<vtkIdType>>(SurfaceCells(local, *piece));
  state.Piece = std::move(piece);
  state.Surface = local;
  state.SurfaceTime = local ? local->GetMTime() : 0;
  state.HasPiece = true;
  costs.AddTime("Ring", watch.Lap());
  return true;
}

/// The field array PieceArrangementReuse: what this update kept (names in
/// vtkBoolSurfArrayNames.h).
void AddReuseField(bool keptPiece,
  bool keptArrangement,
  const PieceMesh& piece,
  const Arrangement& arr,
  vtkPolyData* output)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(names::PieceArrangementReuse);
  const char* components[] = {
    "KeptPiece", "KeptArrangement", "RefinedTriangles", "OwnedTriangles", "RingedTriangles"
  };
  const double values[] = { keptPiece ? 1.0 : 0.0,
    keptArrangement ? 1.0 : 0.0,
    static_cast<double>(arr.NumberOfRefinedSourceTriangles),
    static_cast<double>(piece.NumberOfOwnedTriangles),
    static_cast<double>(piece.Mesh.GetNumberOfTriangles()) };
  array->SetNumberOfComponents(5);
  for (int k = 0; k < 5; ++k)
  {
    array->SetComponentName(k, components[k]);
  }
  array->InsertNextTuple(values);
  output->GetFieldData()->AddArray(array);
}
} // namespace

//------------------------------------------------------------------------------
vtkSmartPointer<vtkIntArray> OnPiecesField(vtkMultiProcessController* controller)
{
  return IntField(names::ArrangementOnPieces, { controller->GetNumberOfProcesses() });
}

//------------------------------------------------------------------------------
void PieceArrangementState::Clear()
{
  this->Surface = nullptr;
  this->SurfaceTime = 0;
  this->HasPiece = false;
  this->Neighbours.clear();
  this->BuildWarnings.clear();
  this->BorderSent = this->BorderReceived = this->RingReceived = 0;
  this->Piece.reset();
  this->SurfaceCell.reset();
  this->TileSums = PieceTileSums();
  this->Results.Clear();
}

//------------------------------------------------------------------------------
bool ArrangeOnPiece(vtkMultiProcessController* controller,
  vtkPolyData* local,
  vtkPolyData* curves,
  const ArrangementOptions& options,
  PieceArrangementState& state,
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
  vtkPolyData* traced = controller->GetLocalProcessId() == 0 ? curves : nullptr;
  if (!ArrangeMessageOnPiece(
        controller, local, traced, message, options, state, output, result, costs, error, warnings))
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
  vtkPolyData* traced,
  const WireBuffer& message,
  const ArrangementOptions& options,
  PieceArrangementState& state,
  vtkPolyData* output,
  std::shared_ptr<PieceArrangementResult>& result,
  PieceCosts& costs,
  std::string& error,
  std::vector<std::string>& warnings)
{
  PieceStopwatch watch;
  std::vector<TracedCurve> global;
  std::vector<std::array<int, 2>> edgeTable;
  bool ok = UnpackTracedCurves(message, global, edgeTable, error);
  if (!vtkBoolSurfPieceArrangement::AllSucceeded(controller, ok, error))
  {
    return false;
  }
  costs.AddTime("Unpack", watch.Lap());

  // The piece, its ring and its mesh: kept while every rank's piece is the same object,
  // unmodified (one all-reduce), else built again.
  int same =
    state.HasPiece && local == state.Surface && (!local || local->GetMTime() == state.SurfaceTime)
    ? 1
    : 0;
  int allSame = 0;
  controller->AllReduce(&same, &allSame, 1, vtkCommunicator::MIN_OP);
  if (allSame)
  {
    costs.AddTime("Piece", watch.Lap());
    costs.AddTime("Ring", 0.0);
  }
  else if (!BuildPiece(controller, local, state, costs, watch, error))
  {
    return false;
  }
  warnings.insert(warnings.end(), state.BuildWarnings.begin(), state.BuildWarnings.end());
  costs.AddBytes("Border", allSame ? 0 : state.BorderSent, allSame ? 0 : state.BorderReceived);
  costs.AddBytes("RingEstimate", 0, allSame ? 0 : state.RingReceived);

  // The curves restricted to the piece, arranged in a result no output holds any more: on the
  // kept mesh its arrangement is computed again in place (Core's edit path).
  result = state.Results.Acquire();
  result->Piece = state.Piece;
  result->SurfaceCell = state.SurfaceCell;
  result->Surface = local;
  const PieceMesh& piece = *state.Piece;
  if (state.Work)
  {
    result->Run.WorkBuffers() = state.Work;
  }
  const bool keptArrangement = result->Run.KeepsArrangementOf(piece);
  PieceCurves restricted;
  RestrictCurvesToPiece(
    piece, global, [&](int e) { return edgeTable[e]; }, restricted);
  result->CurveRuns = CurveRunsOf(restricted);
  if (!traced || !ReadCurveSources(traced, global, result->Sources))
  {
    result->Sources.clear();
  }
  costs.AddTime("Restrict", watch.Lap());
  ok = result->Run.Run(
    controller, piece, restricted, state.Neighbours, options, error, &state.TileSums);
  state.Work = result->Run.WorkBuffers();
  if (!ok)
  {
    // A failed computation leaves its arrangement unspecified: none is computed again.
    result.reset();
    state.Results.Clear();
    return false;
  }
  watch.Lap();

  // Port 0: the owned triangles refined, with what every rank knows of the whole.
  result->ShapeIds = DistinctShapeIds(global);
  if (output)
  {
    WritePieceArrangement(piece, result->Run, output);
    output->GetFieldData()->AddArray(
      IntField(names::NumberOfShapes, { static_cast<int>(result->ShapeIds.size()) }));
    output->GetFieldData()->AddArray(IntField(names::ShapeIds, result->ShapeIds));
    output->GetFieldData()->AddArray(OnPiecesField(controller));
    AddReuseField(allSame != 0, keptArrangement, piece, result->Run.GetArrangement(), output);
  }

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

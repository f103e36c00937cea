// The distributed arrangement on real MPI ranks (Filters/Private/vtkBoolSurfPieceArrangement):
// run as `mpiexec -np P BoolSurfMpiTests`. Every rank builds the same surface and curves,
// keeps its piece (owned triangles plus the ring of ghosts, as vtkGhostCellsGenerator's one
// layer gives it) and the curves rank 0 broadcasts (Distributed/PieceWire.h), arranges it, talks to
// its neighbours and rank 0 only, and must end with the whole surface's arrangement: for every
// owned triangle the same refined triangles in the cells of the same numbers, the same cell areas,
// the labels and consistency verdicts each rank computes on the merged cell graph equal to the
// labeling stage's on the whole arrangement (with the plugs of the surface's boundary loops),
// and each Boolean's region on the rank its owned triangles' share of the whole surface's region
// (per source triangle, areas to 1e-12). Surfaces: a sphere, a sphere with four holes, a flat
// square, a torus and the genus-2 eight.ply, with random closed geodesic polygons crossing the
// ranks' boundaries many times; splits in slabs and in random
// regions, one with an empty rank. Each rank's piece arrives as VTK data (owned triangles with cell
// and point GlobalIds) and gets its ring of ghosts from vtkGhostCellsGenerator
// (vtkBoolSurfRingedPiece.h), checked against the ring Core's tests build. Prints, per rank, the
// bytes it sent and received per message.
#include "vtkBoolSurfPieceArrangement.h"
#include "vtkBoolSurfPieceArrangementOutput.h"
#include "vtkBoolSurfRingedPiece.h"

#include "OwnedTriangles.h"

#include "Arrangement/Arrangement.h"
#include "Distributed/MergedArrangement.h"
#include "Distributed/MergedLabeling.h"
#include "Distributed/PieceRegionBoundary.h"
#include "Distributed/PieceSelection.h"
#include "Distributed/PieceWire.h"
#include "Geodesic/CurveTracer.h"
#include "Labeling/ArrangementLabelingInput.h"
#include "Mesh/MeshTopology.h"
#include "Mesh/PlyReader.h"
#include "Mesh/ProceduralMeshes.h"
#include "Support/PieceRegions.h"
#include "Support/PieceSplits.h"
#include "Support/SourceTree.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCommunicator.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkMPIController.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

using namespace boolsurf;
using boolsurf::testing::CellAreas;
using boolsurf::testing::OwnedTriangles;
using boolsurf::testing::RandomGeodesicCurves;
using boolsurf::testing::RefinedArea;

namespace
{

int failures = 0;

void Fail(int rank, const std::string& what)
{
  if (++failures <= 10)
  {
    std::printf("rank %d: FAILED %s\n", rank, what.c_str());
  }
}

/// Ranks owning the piece's ghosts, ascending.
std::vector<int> NeighboursOf(const PieceMesh& piece, const std::vector<int>& owner, int rank)
{
  std::vector<int> ids;
  for (int g : piece.GlobalTriangle)
  {
    if (owner[g] != rank)
    {
      ids.push_back(owner[g]);
    }
  }
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

/// Area of output triangle i (corners as the arrangement orders them).
double OutputArea(vtkPolyData* output, vtkIdType i)
{
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  output->GetPolys()->GetCellAtId(i, n, ids);
  Vec3 x[3];
  for (int k = 0; k < 3; ++k)
  {
    double p[3];
    output->GetPoint(ids[k], p);
    x[k] = { p[0], p[1], p[2] };
  }
  return 0.5 * Length(Cross(x[1] - x[0], x[2] - x[0]));
}

/// This rank's part of Surface Arrangement's port 0 (vtkBoolSurfPieceArrangementOutput.h)
/// against the whole surface's arrangement: per owned source triangle, the same refined
/// triangles (areas bit for bit) in the same cells, in the same order.
void CompareOutputWithWhole(const TriangleMesh& mesh,
  const Arrangement& whole,
  const PieceMesh& piece,
  const vtkBoolSurfPieceArrangement& run,
  int rank,
  const std::string& what)
{
  vtkNew<vtkPolyData> output;
  WritePieceArrangement(piece, run, output);
  vtkDataArray* cells = output->GetCellData()->GetArray("ArrangementCell");
  vtkDataArray* sources = output->GetCellData()->GetArray("SourceTriangle");
  vtkDataArray* count = output->GetFieldData()->GetArray("NumberOfCells");
  if (!cells || !sources || !count || count->GetTuple1(0) != whole.NumberOfCells)
  {
    Fail(rank, what + ": output arrays missing or wrong NumberOfCells");
    return;
  }
  vtkDataArray* pointTriangle = output->GetPointData()->GetArray("TriangleId");
  vtkDataArray* pointBarycentric = output->GetPointData()->GetArray("Barycentric");
  if (!pointTriangle || !pointBarycentric)
  {
    Fail(rank, what + ": output point arrays missing");
    return;
  }
  for (vtkIdType p = 0; p < output->GetNumberOfPoints(); ++p)
  {
    double x[3];
    output->GetPoint(p, x);
    const double* uv = pointBarycentric->GetTuple2(p);
    const Vec3 y = mesh.Evaluate(static_cast<int>(pointTriangle->GetTuple1(p)), uv[0], uv[1]);
    if (Length(y - Vec3{ x[0], x[1], x[2] }) > 1e-12)
    {
      Fail(rank, what + ": output point " + std::to_string(p) + " is not at its surface point");
      return;
    }
  }
  vtkIdType i = 0;
  for (int t = 0; t < piece.Mesh.GetNumberOfTriangles(); ++t)
  {
    if (!piece.Owned[t])
    {
      continue;
    }
    const int g = piece.GlobalTriangle[t];
    bool same = true;
    ForEachRefinedTriangle(mesh,
      whole,
      g,
      [&](int r)
      {
        same = same && i < output->GetNumberOfCells() && sources->GetTuple1(i) == g &&
          cells->GetTuple1(i) == whole.CellOfTriangle(r) &&
          OutputArea(output, i) == RefinedArea(mesh, whole, r);
        ++i;
      });
    if (!same)
    {
      Fail(rank, what + ": output of triangle " + std::to_string(g) + " differs");
      return;
    }
  }
  if (i != output->GetNumberOfCells())
  {
    Fail(rank, what + ": output has triangles no owned triangle has");
  }
}

/// This rank's owned triangles against the whole surface's arrangement.
/// Message 4 of every rank (its runs of the region's boundary) to rank 0, which chains them
/// into loops: the whole surface's region boundary there. Collective. Returns the bytes this
/// rank sent (rank 0: received).
std::size_t CompareBoundaryWithWhole(vtkMultiProcessController* controller,
  const TriangleMesh& mesh,
  const Arrangement& whole,
  const std::vector<char>& selected,
  const std::vector<BoundaryRun>& mine,
  int rank,
  const std::string& what)
{
  std::vector<long long> message;
  PackBoundaryRuns(mine, message);
  std::size_t bytes = 0;
  if (rank != 0)
  {
    long long length = static_cast<long long>(message.size());
    controller->Send(&length, 1, 0, 56051);
    controller->Send(message.data(), length, 0, 56052);
    return (message.size() + 1) * sizeof(long long);
  }
  std::vector<BoundaryRun> runs;
  std::string error;
  bool ok = UnpackBoundaryRuns(message, runs, error);
  for (int r = 1; r < controller->GetNumberOfProcesses(); ++r)
  {
    long long length = 0;
    controller->Receive(&length, 1, r, 56051);
    std::vector<long long> theirs(static_cast<std::size_t>(length));
    controller->Receive(theirs.data(), length, r, 56052);
    bytes += (theirs.size() + 1) * sizeof(long long);
    ok = UnpackBoundaryRuns(theirs, runs, error) && ok;
  }
  const std::string difference =
    ok ? testing::CompareRegionBoundaries(ChainBoundaryRuns(runs), mesh, whole, selected) : error;
  if (!difference.empty())
  {
    Fail(rank, what + ": boundary loops differ: " + difference);
  }
  return bytes;
}

void CompareWithWhole(vtkMultiProcessController* controller,
  const TriangleMesh& mesh,
  const std::vector<TracedCurve>& curves,
  const Arrangement& whole,
  const PieceMesh& piece,
  const vtkBoolSurfPieceArrangement& run,
  int rank,
  const std::string& what)
{
  const Arrangement& arr = run.GetArrangement();
  const MergedArrangement& merged = run.GetMerged();
  if (merged.NumberOfCells != whole.NumberOfCells)
  {
    Fail(rank,
      what + ": " + std::to_string(merged.NumberOfCells) + " cells, whole surface " +
        std::to_string(whole.NumberOfCells));
    return;
  }
  for (int t = 0; t < piece.Mesh.GetNumberOfTriangles(); ++t)
  {
    if (!piece.Owned[t])
    {
      continue;
    }
    std::vector<int> mine, theirs;
    std::vector<double> myAreas, theirAreas;
    ForEachRefinedTriangle(piece.Mesh,
      arr,
      t,
      [&](int r)
      {
        mine.push_back(run.GetGlobalCell(arr.CellOfTriangle(r)));
        myAreas.push_back(RefinedArea(piece.Mesh, arr, r));
      });
    ForEachRefinedTriangle(mesh,
      whole,
      piece.GlobalTriangle[t],
      [&](int r)
      {
        theirs.push_back(whole.CellOfTriangle(r));
        theirAreas.push_back(RefinedArea(mesh, whole, r));
      });
    if (mine != theirs || myAreas != theirAreas)
    {
      Fail(rank, what + ": triangle " + std::to_string(piece.GlobalTriangle[t]) + " differs");
    }
  }
  const std::vector<double> areas = CellAreas(mesh, whole);
  for (int c = 0; c < whole.NumberOfCells; ++c)
  {
    if (std::abs(merged.CellArea[c] - areas[c]) > 1e-12 * std::max(1.0, areas[c]))
    {
      Fail(rank, what + ": area of cell " + std::to_string(c));
    }
  }
  // Labels of the merged cell graph, labeled on this rank from what rank 0 sent back: the
  // labeling stage's on the whole arrangement (plugs of the boundary loops and all).
  const MeshTopology topology = MeshTopology::Compute(mesh);
  const LabelingInput stageInput = MakeLabelingInput(mesh, topology, curves, whole);
  const LabelingResult stage = LabelCells(stageInput);
  const LabelingInput input = MergedLabelingInput(merged, DistinctShapeIds(curves));
  if (merged.NumberOfPlugs != static_cast<int>(topology.BoundaryLoops.size()) ||
    input.CellComponent != stageInput.CellComponent || input.ZeroCells != stageInput.ZeroCells)
  {
    Fail(rank, what + ": plugs, components or zero nodes differ");
  }
  const LabelingResult mine = LabelMergedArrangement(merged, DistinctShapeIds(curves));
  if (mine.ShapeIds != stage.ShapeIds || mine.ShapeConsistent != stage.ShapeConsistent ||
    mine.Labels.size() != stage.Labels.size())
  {
    Fail(rank, what + ": shapes or consistency verdicts differ");
    return;
  }
  if (mine.Labels != stage.Labels)
  {
    Fail(rank, what + ": labels differ");
  }
  // Each Boolean's region on this rank: its owned triangles' share of the whole region.
  for (const BooleanOptions& options : testing::TestBooleanOptions(stage.ShapeIds))
  {
    const std::string operation =
      what + ", operation " + std::to_string(static_cast<int>(options.Operation));
    std::vector<char> selected, mySelected;
    std::string text, error, myText, myError;
    const bool ok = SelectBooleanCells(stage, options, selected, text, error);
    PieceRegion region;
    const bool mineOk = SelectPieceBoolean(
      piece, arr, merged.GlobalCellOfLocal[0], mine, options, region, mySelected, myText, myError);
    if (mineOk != ok)
    {
      Fail(rank, operation + ": selected on one side only: " + error + myError);
    }
    if (!ok)
    {
      continue; // the same on every rank: the stage's labels are
    }
    // The region's boundary: this rank's runs to rank 0, chained there (every rank takes part).
    std::vector<BoundaryRun> runs;
    if (mineOk)
    {
      PieceRegionBoundaryRuns(piece, arr, merged.GlobalCellOfLocal[0], mySelected, runs);
    }
    const std::size_t boundaryBytes =
      CompareBoundaryWithWhole(controller, mesh, whole, selected, runs, rank, operation);
    if (options.Operation == BooleanOperation::Union)
    {
      std::printf("%s, rank %d: union's boundary, %zu bytes %s\n",
        what.c_str(),
        rank,
        boundaryBytes,
        rank == 0 ? "received" : "sent");
    }
    if (!mineOk)
    {
      continue;
    }
    std::vector<char> owned(mesh.GetNumberOfTriangles(), 0);
    for (int t = 0; t < piece.Mesh.GetNumberOfTriangles(); ++t)
    {
      owned[piece.GlobalTriangle[t]] = piece.Owned[t];
    }
    const std::string difference =
      testing::CompareRegions(testing::PieceRegionBySource(piece, arr, region),
        testing::WholeRegionBySource(mesh, whole, selected),
        &owned);
    if (mySelected != selected || !difference.empty())
    {
      Fail(rank, operation + ": region differs: " + difference);
    }
  }
}

void RunSplit(vtkMultiProcessController* controller,
  const TriangleMesh& mesh,
  const std::vector<TracedCurve>& curves,
  const std::vector<int>& owner,
  const std::string& what)
{
  const int rank = controller->GetLocalProcessId();
  std::string error;
  Arrangement whole;
  if (!ComputeArrangement(mesh, curves, ArrangementOptions(), whole, error))
  {
    Fail(rank, what + ": whole surface: " + error);
    return;
  }
  PieceInput ringed;
  if (!BuildRingedPiece(controller, OwnedTriangles(mesh, owner, rank), ringed, error))
  {
    Fail(rank, what + ": " + error);
  }
  PieceMesh piece, expected;
  if (!BuildPieceMesh(ringed, piece, error) ||
    !BuildPieceMesh(testing::MakePiece(mesh, owner, rank), expected, error))
  {
    Fail(rank, what + ": " + error);
  }
  if (piece.GlobalTriangle != expected.GlobalTriangle ||
    piece.GlobalVertex != expected.GlobalVertex || piece.Owned != expected.Owned)
  {
    Fail(rank, what + ": the ghost ring is not every triangle sharing a point with the piece");
  }
  // The curves as rank 0 (the tracer) broadcasts them: on global ids, edges by their vertices.
  WireBuffer message;
  if (rank == 0)
  {
    PackTracedCurves(curves, mesh, {}, {}, message);
  }
  long long length = static_cast<long long>(message.size());
  controller->Broadcast(&length, 1, 0);
  message.resize(static_cast<std::size_t>(length));
  controller->Broadcast(message.data(), length, 0);
  std::vector<TracedCurve> received;
  std::vector<std::array<int, 2>> edgeTable;
  if (!UnpackTracedCurves(message, received, edgeTable, error))
  {
    Fail(rank, what + ": " + error);
    return;
  }
  const GlobalEdgeVertices edgeVertices = [&](int e) { return edgeTable[e]; };
  PieceCurves local;
  RestrictCurvesToPiece(piece, received, edgeVertices, local);
  vtkBoolSurfPieceArrangement run;
  if (!run.Run(
        controller, piece, local, NeighboursOf(piece, owner, rank), ArrangementOptions(), error))
  {
    Fail(rank, what + ": " + error);
    return;
  }
  CompareWithWhole(controller, mesh, curves, whole, piece, run, rank, what);
  CompareOutputWithWhole(mesh, whole, piece, run, rank, what);
  const vtkBoolSurfPieceArrangement::Traffic& bytes = run.GetTraffic();
  std::printf("%s, rank %d of %d: %d owned triangles; bytes sent/received: curves %zu/%zu, "
              "boundary records "
              "%zu/%zu, to the merge %zu/%zu, merged cells %zu/%zu\n",
    what.c_str(),
    rank,
    controller->GetNumberOfProcesses(),
    piece.NumberOfOwnedTriangles,
    rank == 0 ? (controller->GetNumberOfProcesses() - 1) * (message.size() + 1) * sizeof(long long)
              : std::size_t(0),
    rank == 0 ? std::size_t(0) : (message.size() + 1) * sizeof(long long),
    bytes.BoundarySent,
    bytes.BoundaryReceived,
    bytes.MergeSent,
    bytes.MergeReceived,
    bytes.BackSent,
    bytes.BackReceived);
  std::fflush(stdout);
}

void RunSurface(vtkMultiProcessController* controller, const MeshData& data, const char* name)
{
  const TriangleMesh mesh(data.Positions, data.Triangles);
  const int ranks = controller->GetNumberOfProcesses();
  const std::vector<TracedCurve> curves = RandomGeodesicCurves(mesh, 5, 6);
  for (int axis = 0; axis < 3; ++axis)
  {
    RunSplit(controller,
      mesh,
      curves,
      testing::SlabOwners(mesh, ranks, axis),
      std::string(name) + ", slabs along axis " + std::to_string(axis));
  }
  RunSplit(controller,
    mesh,
    curves,
    testing::RegionOwners(mesh, ranks, 3, -1),
    std::string(name) + ", random regions");
  if (ranks >= 2)
  {
    RunSplit(controller,
      mesh,
      curves,
      testing::RegionOwners(mesh, ranks, 4, ranks - 1),
      std::string(name) + ", random regions, last rank empty");
  }
}

} // namespace

int main(int argc, char* argv[])
{
  vtkNew<vtkMPIController> controller;
  controller->Initialize(&argc, &argv);
  vtkMultiProcessController::SetGlobalController(controller);
  RunSurface(controller, MakeIcosphere(3), "sphere");
  RunSurface(controller, testing::SphereWithHoles(), "sphere with four holes");
  RunSurface(controller, MakeFlatSquare(24, 1.0, 0.2, 3), "square");
  RunSurface(controller, MakeTorus(1.0, 0.4, 40, 20), "torus");
  MeshData eight;
  std::string error;
  if (ReadPly((testing::SourceTree() / "Data" / "eight.ply").string(), eight, error))
  {
    RunSurface(controller, eight, "eight.ply");
  }
  else
  {
    Fail(controller->GetLocalProcessId(), "eight.ply: " + error);
  }
  int all = 0;
  controller->AllReduce(&failures, &all, 1, vtkCommunicator::SUM_OP);
  if (controller->GetLocalProcessId() == 0)
  {
    std::printf("%s: %d failures on %d ranks\n",
      all == 0 ? "PASSED" : "FAILED",
      all,
      controller->GetNumberOfProcesses());
  }
  controller->Finalize();
  return all == 0 ? 0 : 1;
}

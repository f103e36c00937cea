#include "vtkBoolSurfPieceArrangement.h"

#include "vtkBoolSurfPieceCosts.h"
#include "vtkBoolSurfSurfacePiece.h"

#include "Distributed/BoundaryJoins.h"
#include "Distributed/PieceSummary.h"
#include "Distributed/PieceWire.h"

#include <vtkCommunicator.h>
#include <vtkMultiProcessController.h>

namespace
{
/// Tags of the messages to and from rank 0 (length, then data).
constexpr int LengthTag = 56011;
constexpr int DataTag = 56012;

using boolsurf::WireBuffer;

} // namespace

//------------------------------------------------------------------------------
bool vtkBoolSurfPieceArrangement::AllSucceeded(vtkMultiProcessController* controller,
  bool ok,
  std::string& error)
{
  const int rank = controller->GetLocalProcessId();
  int failing = ok ? controller->GetNumberOfProcesses() : rank;
  int first = failing;
  controller->AllReduce(&failing, &first, 1, vtkCommunicator::MIN_OP);
  if (first == controller->GetNumberOfProcesses())
  {
    return true;
  }
  error = first == rank ? "rank " + std::to_string(rank) + ": " + error
                        : "the distributed arrangement failed on rank " + std::to_string(first);
  return false;
}

namespace
{
void SendBuffer(vtkMultiProcessController* controller, const WireBuffer& buffer, int to)
{
  long long length = static_cast<long long>(buffer.size());
  controller->Send(&length, 1, to, LengthTag);
  controller->Send(buffer.data(), length, to, DataTag);
}

WireBuffer ReceiveBuffer(vtkMultiProcessController* controller, int from)
{
  long long length = 0;
  controller->Receive(&length, 1, from, LengthTag);
  WireBuffer buffer(static_cast<std::size_t>(length));
  controller->Receive(buffer.data(), length, from, DataTag);
  return buffer;
}

std::size_t BytesOf(const WireBuffer& buffer)
{
  return (buffer.size() + 1) * sizeof(long long); // with its length
}
} // namespace

//------------------------------------------------------------------------------
bool vtkBoolSurfPieceArrangement::Run(vtkMultiProcessController* controller,
  const boolsurf::PieceMesh& piece,
  const boolsurf::PieceCurves& curves,
  const std::vector<int>& neighbours,
  const boolsurf::ArrangementOptions& options,
  std::string& error,
  boolsurf::PieceTileSums* tileSums)
{
  const int rank = controller->GetLocalProcessId();
  const int ranks = controller->GetNumberOfProcesses();
  this->Bytes = Traffic();
  this->Times = StepTimes();
  this->Merged = boolsurf::MergedArrangement();
  boolsurf::PieceStopwatch watch;
  boolsurf::PieceSummary summary;
  bool ok = boolsurf::ArrangePiece(piece, curves, options, this->Local, summary, error, tileSums);
  this->Times.Arrange = watch.Lap();
  if (!AllSucceeded(controller, ok, error))
  {
    return false;
  }

  // Boundary records to the neighbours, theirs matched with this piece's.
  WireBuffer records;
  boolsurf::PackBoundaryRecords(summary, records);
  const std::vector<WireBuffer> received = vtkBoolSurfSurfacePiece::ExchangeWith(
    controller, neighbours, std::vector<WireBuffer>(neighbours.size(), records));
  this->Bytes.BoundarySent = neighbours.size() * BytesOf(records);
  std::vector<boolsurf::PieceSummary> theirs(neighbours.size());
  std::vector<int> ids{ rank };
  std::vector<const boolsurf::PieceSummary*> given{ &summary };
  for (std::size_t i = 0; ok && i < neighbours.size(); ++i)
  {
    this->Bytes.BoundaryReceived += BytesOf(received[i]);
    ok = boolsurf::UnpackBoundaryRecords(received[i], theirs[i], error);
    ids.push_back(neighbours[i]);
    given.push_back(&theirs[i]);
  }
  boolsurf::BoundaryJoins joins;
  ok = ok && boolsurf::JoinPieceBoundaries(ids, given, rank, joins, error);
  const bool joined = AllSucceeded(controller, ok, error);
  this->Times.Boundary = watch.Lap();
  if (!joined)
  {
    return false;
  }

  // Cells, crossings and joins to rank 0, which merges them.
  WireBuffer toMerge;
  boolsurf::PackMergeInput(summary, joins, toMerge);
  this->Bytes.MergeSent = rank == 0 ? 0 : BytesOf(toMerge);
  if (rank != 0)
  {
    SendBuffer(controller, toMerge, 0);
  }
  std::vector<WireBuffer> back(ranks);
  if (rank == 0)
  {
    std::vector<boolsurf::PieceSummary> merging(ranks);
    boolsurf::BoundaryJoins all;
    for (int r = 0; r < ranks; ++r)
    {
      // Every rank's message is received, even after a bad one, so no send is left pending.
      const WireBuffer buffer = r == 0 ? toMerge : ReceiveBuffer(controller, r);
      this->Bytes.MergeReceived += r == 0 ? 0 : BytesOf(buffer);
      ok = ok && boolsurf::UnpackMergeInput(buffer, merging[r], all, error);
    }
    boolsurf::MergedArrangement merged;
    ok = ok && boolsurf::MergeCellGraph(merging, all, merged, error);
    for (int r = 0; r < ranks; ++r)
    {
      // A failed merge sends an empty buffer: every rank then reports it.
      if (ok)
      {
        boolsurf::PackMergedForPiece(merged, r, back[r]);
      }
      if (r != 0)
      {
        SendBuffer(controller, back[r], r);
        this->Bytes.BackSent += BytesOf(back[r]);
      }
    }
  }
  else
  {
    back[rank] = ReceiveBuffer(controller, 0);
    this->Bytes.BackReceived = BytesOf(back[rank]);
  }
  if (back[rank].empty())
  {
    if (rank != 0)
    {
      error = "the merge of the cell graph failed on rank 0";
    }
    return false;
  }
  ok = boolsurf::UnpackMergedForPiece(back[rank], this->Merged, error);
  if (ok &&
    this->Merged.GlobalCellOfLocal[0].size() !=
      static_cast<std::size_t>(summary.NumberOfLocalCells))
  {
    ok = false;
    error = "the merged cells do not match the piece's local cells";
  }
  ok = AllSucceeded(controller, ok, error);
  this->Times.Merge = watch.Lap();
  return ok;
}

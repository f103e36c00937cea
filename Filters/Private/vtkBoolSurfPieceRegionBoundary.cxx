#include "vtkBoolSurfPieceRegionBoundary.h"

#include "vtkBoolSurfPieceArrangementStage.h"
#include "vtkBoolSurfRegionOutput.h"

#include "Distributed/PieceRegionBoundary.h"

#include <vtkMultiProcessController.h>
#include <vtkPolyData.h>

namespace boolsurf
{
namespace
{
/// Tags of message 4 (length, then data), apart from the arrangement's.
constexpr int LengthTag = 56041;
constexpr int DataTag = 56042;
} // namespace

//------------------------------------------------------------------------------
bool WritePieceRegionBoundary(vtkMultiProcessController* controller,
  const PieceArrangementResult& arranged,
  const std::vector<char>& selected,
  vtkPolyData* boundary,
  std::string& error,
  std::size_t* sent,
  std::size_t* received)
{
  const int rank = controller->GetLocalProcessId();
  const int ranks = controller->GetNumberOfProcesses();
  const vtkBoolSurfPieceArrangement& run = arranged.Run;
  std::vector<BoundaryRun> runs;
  PieceRegionBoundaryRuns(
    *arranged.Piece, run.GetArrangement(), run.GetMerged().GlobalCellOfLocal[0], selected, runs);
  std::size_t bytesSent = 0, bytesReceived = 0;
  bool ok = true;
  boundary->Initialize();
  if (rank != 0)
  {
    std::vector<long long> message;
    PackBoundaryRuns(runs, message);
    long long length = static_cast<long long>(message.size());
    controller->Send(&length, 1, 0, LengthTag);
    controller->Send(message.data(), length, 0, DataTag);
    bytesSent = (message.size() + 1) * sizeof(long long);
  }
  else
  {
    for (int r = 1; r < ranks; ++r)
    {
      // Every rank's message is received, even after a bad one, so no send is left pending.
      long long length = 0;
      controller->Receive(&length, 1, r, LengthTag);
      std::vector<long long> message(static_cast<std::size_t>(length));
      controller->Receive(message.data(), length, r, DataTag);
      bytesReceived += (message.size() + 1) * sizeof(long long);
      ok = ok && UnpackBoundaryRuns(message, runs, error);
    }
    if (ok)
    {
      const std::vector<BoundaryRun> loops = ChainBoundaryRuns(runs);
      // WriteBoundary reads points by id: number them in order along the loops.
      std::vector<const BoundaryPointRecord*> records;
      std::vector<BoundaryPolyline> lines(loops.size());
      for (std::size_t l = 0; l < loops.size(); ++l)
      {
        lines[l].Closed = loops[l].Closed;
        for (const BoundaryPointRecord& p : loops[l].Points)
        {
          lines[l].Points.push_back(static_cast<int>(records.size()));
          records.push_back(&p);
        }
      }
      WriteBoundary(
        lines,
        [&](int p, double x[3])
        {
          x[0] = records[p]->Position.x;
          x[1] = records[p]->Position.y;
          x[2] = records[p]->Position.z;
        },
        [&](int p) { return records[p]->Surface; },
        true,
        boundary);
    }
  }
  if (sent)
  {
    *sent = bytesSent;
  }
  if (received)
  {
    *received = bytesReceived;
  }
  return vtkBoolSurfPieceArrangement::AllSucceeded(controller, ok, error);
}

} // namespace boolsurf

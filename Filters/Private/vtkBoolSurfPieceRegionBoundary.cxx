#include "vtkBoolSurfPieceRegionBoundary.h"

#include "vtkBoolSurfArrayNames.h"
#include "vtkBoolSurfControlOutput.h"
#include "vtkBoolSurfPieceArrangementStage.h"
#include "vtkBoolSurfRegionOutput.h"
#include "vtkBoolSurfStageHandoff.h"

#include "Distributed/PieceRegionBoundary.h"
#include "Distributed/PieceVectorOutput.h"
#include "Distributed/PieceWire.h"

#include <vtkMultiProcessController.h>
#include <vtkPolyData.h>

#include <cmath>
#include <limits>

namespace boolsurf
{
namespace
{
/// Tags of message 4 (length, then data), apart from the arrangement's.
constexpr int LengthTag = 56041;
constexpr int DataTag = 56042;

/// Collective: rank 0's control points of `sources` (none when it has no sources, or
/// `wanted` is false on rank 0) on every rank; `bytes` gets the buffer's size.
std::vector<std::vector<SurfacePoint>> BroadcastControls(vtkMultiProcessController* controller,
  bool wanted,
  const std::vector<CurveSource>& sources,
  std::size_t& bytes)
{
  WireBuffer words;
  if (controller->GetLocalProcessId() == 0 && wanted && !sources.empty())
  {
    words.push_back(static_cast<long long>(sources.size()));
    for (const CurveSource& s : sources)
    {
      words.push_back(static_cast<long long>(s.Points.size()));
      for (const SurfacePoint& p : s.Points)
      {
        words.insert(words.end(), { p.Triangle, WireBitsOf(p.U), WireBitsOf(p.V) });
      }
    }
  }
  long long length = static_cast<long long>(words.size());
  controller->Broadcast(&length, 1, 0);
  words.resize(static_cast<std::size_t>(length));
  if (length > 0)
  {
    controller->Broadcast(words.data(), length, 0);
  }
  bytes = (words.size() + 1) * sizeof(long long);
  std::vector<std::vector<SurfacePoint>> controls;
  std::size_t at = 0;
  if (!words.empty())
  {
    controls.resize(static_cast<std::size_t>(words[at++]));
    for (std::vector<SurfacePoint>& curve : controls)
    {
      curve.resize(static_cast<std::size_t>(words[at++]));
      for (SurfacePoint& p : curve)
      {
        p = {
          static_cast<int>(words[at]), WireDoubleOf(words[at + 1]), WireDoubleOf(words[at + 2])
        };
        at += 3;
      }
    }
  }
  return controls;
}

/// Rank 0: ports 2 and 3 from the chained loops, the clipped segments and the control points'
/// positions; false with `why` (the ports left empty) when they cannot be given on pieces.
bool WriteVectorPorts(const std::vector<BoundaryRun>& loops,
  const std::vector<ClippedSegment>& clipped,
  const std::vector<CurveSource>& sources,
  const ControlPointPositions& positions,
  PieceVectorPorts& ports,
  std::string& why)
{
  for (std::size_t c = 0; c < positions.size(); ++c)
  {
    for (const Vec3& x : positions[c])
    {
      if (std::isnan(x.x))
      {
        why = "a control point of curve " + std::to_string(c) + " names a triangle no rank owns";
        return false;
      }
    }
  }
  std::vector<ControlSubCurve> curves;
  if (!PieceBoundaryControlCurves(loops, sources, positions, curves, why))
  {
    return false;
  }
  WriteControlSubCurves(curves, names::BoundaryLoop, true, ports.Controls);
  if (!PieceClippedControlCurves(clipped, sources, positions, curves, why))
  {
    ports.Controls->Initialize();
    return false;
  }
  WriteControlSubCurves(curves, names::ClippedPiece, false, ports.Clipped);
  return true;
}
} // namespace

//------------------------------------------------------------------------------
bool WritePieceRegionBoundary(vtkMultiProcessController* controller,
  const PieceArrangementResult& arranged,
  const std::vector<char>& selected,
  vtkPolyData* boundary,
  std::string& error,
  std::size_t* sent,
  std::size_t* received,
  PieceVectorPorts* vector)
{
  const int rank = controller->GetLocalProcessId();
  const int ranks = controller->GetNumberOfProcesses();
  const vtkBoolSurfPieceArrangement& run = arranged.Run;
  const std::vector<int>& globalCellOfLocal = run.GetMerged().GlobalCellOfLocal[0];
  boundary->Initialize();
  if (vector)
  {
    vector->Controls->Initialize();
    vector->Clipped->Initialize();
    vector->Note.clear();
  }
  // Rank 0 decides whether the vector output is computed: it has the sources.
  std::size_t controlBytes = 0;
  const std::vector<std::vector<SurfacePoint>> controls =
    BroadcastControls(controller, vector != nullptr, arranged.Sources, controlBytes);
  const bool withVector = vector && !controls.empty();

  // This rank's message: its runs, then with the vector output its clipped segments and the
  // positions of the control points on its owned triangles.
  std::vector<BoundaryRun> runs;
  PieceRegionBoundaryRuns(*arranged.Piece,
    run.GetArrangement(),
    globalCellOfLocal,
    selected,
    runs,
    withVector ? &arranged.CurveRuns : nullptr);
  WireBuffer message;
  PackBoundaryRuns(runs, message);
  if (withVector)
  {
    std::vector<ClippedSegment> clipped;
    PieceClippedSegments(*arranged.Piece,
      run.GetArrangement(),
      globalCellOfLocal,
      selected,
      arranged.CurveRuns,
      clipped);
    PackClippedSegments(clipped, message);
    PackOwnedControlPositions(*arranged.Piece, controls, message);
  }

  std::size_t bytesSent = 0, bytesReceived = 0;
  bool ok = true;
  if (rank != 0)
  {
    long long length = static_cast<long long>(message.size());
    controller->Send(&length, 1, 0, LengthTag);
    controller->Send(message.data(), length, 0, DataTag);
    bytesSent = (message.size() + 1) * sizeof(long long);
    bytesReceived = controlBytes;
  }
  else
  {
    bytesSent = controlBytes * static_cast<std::size_t>(ranks - 1);
    runs.clear();
    std::vector<ClippedSegment> clipped;
    ControlPointPositions positions(controls.size());
    for (std::size_t c = 0; c < controls.size(); ++c)
    {
      positions[c].assign(
        controls[c].size(), Vec3{ std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0 });
    }
    const auto read = [&](const WireBuffer& in, int from)
    {
      std::size_t at = 0;
      const bool whole = UnpackBoundaryRuns(in, at, runs, error) &&
        (!withVector ||
          (UnpackClippedSegments(in, at, clipped, error) &&
            UnpackControlPositions(in, at, positions, error))) &&
        at == in.size();
      if (!whole)
      {
        error = "message 4 from rank " + std::to_string(from) + ": " +
          (error.empty() ? std::string("longer than its contents") : error);
      }
      return whole;
    };
    ok = read(message, 0);
    for (int r = 1; r < ranks; ++r)
    {
      // Every rank's message is received, even after a bad one, so no send is left pending.
      long long length = 0;
      controller->Receive(&length, 1, r, LengthTag);
      WireBuffer in(static_cast<std::size_t>(length));
      controller->Receive(in.data(), length, r, DataTag);
      bytesReceived += (in.size() + 1) * sizeof(long long);
      ok = ok && read(in, r);
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
      if (vector)
      {
        std::string why;
        if (!withVector)
        {
          vector->Note = NoControlPointsNote;
        }
        else if (!WriteVectorPorts(loops, clipped, arranged.Sources, positions, *vector, why))
        {
          vector->Note = "ports 2 and 3 (the boundary's control points, the clipped curves) "
                         "are empty: " +
            why;
        }
      }
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

/**
 * @class   vtkBoolSurfPieceTracing
 * @brief   curves traced on a surface split across MPI ranks, no rank holding the whole surface
 *
 * The processes' side of Core's tracing on pieces (Core/Distributed/PieceTracing.h,
 * Docs/Parallel.md): each curve is traced by one rank (the owner of its first control point's
 * triangle) on that rank's ringed piece, which fetches the fans its legs read from their
 * owners until every read is the whole surface's; the traces go to rank 0, which packs them
 * as message 0 (PackGlobalTraces: the buffer PackTracedCurves gives for the whole surface's
 * traces) and broadcasts it.
 *
 * Owners: a directory of global triangle ids (rank g % ranks knows who owns triangle g), built
 * once by one exchange, names the owners of the ring's ghosts and of the control points'
 * triangles; fetched triangles carry their owner. A vertex's fan is held whole by every rank
 * owning one of its triangles, so a request for vertex v goes to the owner of a held triangle
 * round v, which answers from its ringed piece.
 *
 * Rounds are bulk-synchronous: a rank whose tracer needs triangles starts a round, a rank done
 * with its curves joins rounds with no request, and every round begins with an all-reduce
 * saying whether any rank still asks, so all ranks leave together. Run() is collective and
 * fails on every rank with the same message (the lowest failing curve, named) when one fails;
 * GetFailures() lists every failing curve, the same on every rank. Trace Surface Curves on
 * pieces (vtkBoolSurfPieceTraceStage.h) keeps one between updates: SetReusePiece keeps the
 * piece, the directory and the tracer with what it fetched while the surface is unchanged,
 * and a curve given again unchanged (same place in the list, same points, type, closure and
 * ids, same settings) is not traced again: rank 0 packs its last trace, which is the surface's
 * trace bit for bit as a new one would be. An edit of one curve among many so traces one.
 */
#ifndef vtkBoolSurfPieceTracing_h
#define vtkBoolSurfPieceTracing_h

#include "Curves/ControlCurve.h"
#include "Distributed/PieceMesh.h"
#include "Distributed/PieceTracing.h"
#include "Distributed/PieceWire.h"
#include "Geodesic/GeodesicPath.h"
#include "Mesh/SurfacePoint.h"

#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

class vtkMultiProcessController;

class vtkBoolSurfPieceTracing
{
public:
  /// A curve to trace: control points naming triangles by global cell id.
  struct Curve
  {
    std::vector<boolsurf::SurfacePoint> Points;
    boolsurf::CurveType Type = boolsurf::CurveType::GeodesicPolygon;
    bool Closed = true;
    /// The trace's ShapeId and CurveId (messages name the curve by it); CurveId -1: the
    /// curve's index in the list, ShapeId then as the tracer leaves it.
    int ShapeId = 0;
    int CurveId = -1;
  };

  /// What this rank sent and received (bytes, lengths included) and did.
  struct Traffic
  {
    std::size_t DirectorySent = 0, DirectoryReceived = 0; ///< owners of ids, once
    std::size_t FetchSent = 0, FetchReceived = 0;         ///< requests and answers
    std::size_t TracesSent = 0, TracesReceived = 0;       ///< traces to rank 0, message 0 back
    int Rounds = 0;           ///< fetch rounds taken part in (the same on every rank)
    int OwnRounds = 0;        ///< rounds this rank asked in
    int TracedCurves = 0;     ///< curves this rank traced
    int RecalledCurves = 0;   ///< curves unchanged since the last Run, not traced again
    int FetchedTriangles = 0; ///< triangles its tracer holds beyond its ringed piece
    int HeldTriangles = 0;    ///< everything its tracer holds at the end
    int RingedTriangles = 0;  ///< its owned triangles and ring
    bool ReusedPiece = false; ///< the piece, directory and tracer of the last Run were kept
    /// Set by the filters sharing one tracing (vtkBoolSurfSharedPieceTrace.h): what was kept
    /// was another filter's (ReusedPiece then false).
    bool SharedPiece = false;
  };

  void SetOptions(const boolsurf::GeodesicPathOptions& options) { this->Options = options; }
  void SetResolution(int levels) { this->Resolution = levels; }
  /// The whole surface's EstimateMeanEdgeLength (Bounded's budget test). Default (negative):
  /// Run computes it from the pieces, bit for bit (PieceMeanEdgeLength).
  void SetMeanEdgeLength(double length) { this->MeanEdgeLength = length; }
  /// The mean edge length the last Run used.
  double GetMeanEdgeLength() const { return this->UsedMeanEdgeLength; }
  void SetMarginRings(int rings) { this->MarginRings = rings; }
  /// Whether the traces rank 0 gets (GetTraces) carry each point's position and written form
  /// (GlobalCurveTrace::Positions, Written), for writing the polylines there.
  void SetKeepWrittenForms(bool keep) { this->KeepWrittenForms = keep; }
  /// Whether the next Run keeps the last Run's piece mesh, owner directory, ring owners, mean
  /// edge length and tracer (with the triangles it fetched) instead of building them from
  /// `ringed` again: for an edit of the curves on an unchanged surface. The same on every rank
  /// (the caller decides it collectively); ignored when no Run built them yet. With it, the
  /// curves unchanged since the last successful Run are recalled, not traced.
  void SetReusePiece(bool reuse) { this->ReusePiece = reuse; }

  /// Collective. `ringed`: this rank's owned triangles and ring of ghosts (BuildRingedPiece);
  /// `curves`: the same list on every rank, curve c traced with curve id c. On success
  /// `message0` is, on every rank, PackTracedCurves of the whole surface's traces. False on
  /// every rank with the same `error` when any curve or rank fails.
  bool Run(vtkMultiProcessController* controller,
    const boolsurf::PieceInput& ringed,
    const std::vector<Curve>& curves,
    boolsurf::WireBuffer& message0,
    std::string& error);

  const Traffic& GetTraffic() const { return this->Bytes; }
  /// After a Run, on rank 0: every curve's trace, in the order of the list (empty on a
  /// failure and on the other ranks).
  const std::vector<boolsurf::GlobalCurveTrace>& GetTraces() const { return this->Traces; }
  /// After a failed Run, on every rank: every failing curve's index and message, in curve
  /// order (index -1: a failure of no one curve); Run's `error` is the first one's message.
  const std::vector<std::pair<int, std::string>>& GetFailures() const { return this->Failures; }

  vtkBoolSurfPieceTracing();
  ~vtkBoolSurfPieceTracing();

private:
  struct Held;
  boolsurf::GeodesicPathOptions Options;
  int Resolution = 4;
  double MeanEdgeLength = -1.0;
  double UsedMeanEdgeLength = -1.0;
  int MarginRings = 3;
  bool KeepWrittenForms = false;
  bool ReusePiece = false;
  Traffic Bytes;
  std::vector<boolsurf::GlobalCurveTrace> Traces;
  std::vector<std::pair<int, std::string>> Failures;
  /// What SetReusePiece keeps between Runs.
  std::unique_ptr<Held> Kept;
};

#endif

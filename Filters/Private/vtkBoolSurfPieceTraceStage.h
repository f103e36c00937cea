/**
 * @brief   Trace Surface Curves on each rank's piece of a surface split across MPI ranks
 *
 * The filter side of the tracing on pieces (Docs/Parallel.md, "Tracing on pieces"): rank 0
 * reads the control curves (their points must name surface points exactly: TriangleId and
 * Barycentric, global cell ids) and sends them to every rank; each rank builds its ringed piece
 * (vtkBoolSurfRingedPiece.h) and vtkBoolSurfPieceTracing traces the curves, each on the rank
 * owning its first control point's triangle, fetching from their owners the triangles its legs
 * read. Every rank gets message 0 (the very buffer the gathered path packs); rank 0 also gets
 * every curve's written points and writes the traced polylines, the one-rank output bit for
 * bit; the other ranks' polylines are empty. No rank holds the whole surface.
 *
 * What the tracing on pieces cannot do is decided the same way on every rank and done by the
 * gathered path instead (PieceTraceOutcome::Gather, with the reason): the LocallyShortest
 * method, control points given by position (projected onto the surface), and legs the exact
 * window search does not settle within its budget (known only once traced: Run fails them on
 * every rank alike).
 */
#ifndef vtkBoolSurfPieceTraceStage_h
#define vtkBoolSurfPieceTraceStage_h

#include "vtkBoolSurfPieceTracing.h"

#include "Distributed/PieceMesh.h"
#include "Geodesic/TraceOptions.h"

#include <vtkType.h>

#include <string>
#include <vector>

class vtkMultiProcessController;
class vtkPolyData;

namespace boolsurf
{

/// What Trace Surface Curves keeps between updates on pieces: the ringed piece and the tracing
/// (directory, mean edge length, the tracer with what it fetched), while this rank's piece of
/// the surface is the same object, unmodified (an edit of the curves builds none of them).
struct PieceTraceState
{
  vtkBoolSurfPieceTracing Tracing;
  PieceInput Ringed;
  vtkPolyData* Surface = nullptr; ///< compared, never dereferenced
  vtkMTimeType SurfaceTime = 0;
  bool HasPiece = false;
  /// Whether Tracing has run on Ringed since it was built (its next Run may keep what it built).
  bool Traced = false;
  /// How many times Ringed was built (the same count on every rank): what is derived from it
  /// (Surface Curves' closedness) is kept while it is unchanged.
  unsigned long long Builds = 0;
  /// The filters that traced on Ringed since it was built (the state is shared by the filters
  /// tracing on one piece, vtkBoolSurfSharedPieceTrace.h): a filter's traffic says whether it
  /// kept its own tracing (ReusedPiece) or used another filter's (SharedPiece).
  std::vector<const void*> Users;
};

enum class PieceTraceOutcome
{
  Traced,       ///< `output` written: message 0 on every rank, the polylines on rank 0
  DrawingStart, ///< rank 0's curves are a drawing being started: no curve, no message
  Gather,       ///< not on pieces (`reason` says why): gather and trace on one rank
  Failed,       ///< `problems` lists every problem, the same on every rank
};

/// Collective: `state.Ringed`, this rank's piece `local` with its ring of ghosts, built again
/// unless every rank's piece is the one it was built from, unmodified (one all-reduce). False
/// on every rank, with `problem` naming the rank whose piece cannot be used.
bool UpdateRingedPiece(vtkMultiProcessController* controller,
  vtkPolyData* local,
  PieceTraceState& state,
  std::string& problem);

/// Collective: Trace Surface Curves on this rank's piece `local` with the control curves
/// `curves` (read on rank 0 only). `notes` gets rank 0's reading notes (warnings). `user`
/// names the calling filter (its traffic tells its own tracing kept from another's).
PieceTraceOutcome TraceOnPieces(vtkMultiProcessController* controller,
  vtkPolyData* local,
  vtkPolyData* curves,
  const TraceOptions& options,
  PieceTraceState& state,
  vtkPolyData* output,
  std::vector<std::string>& problems,
  std::vector<std::string>& notes,
  std::string& reason,
  const void* user = nullptr);

/// The field array PieceTracingTraffic of `traffic` (names in vtkBoolSurfArrayNames.h).
void AddPieceTracingTraffic(const vtkBoolSurfPieceTracing::Traffic& traffic, vtkPolyData* output);

}

#endif

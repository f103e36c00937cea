/**
 * @brief   the one-step BoolSurf filter on each rank's piece of a surface split across MPI
 *          ranks: the stage filters' pieces chained, nothing gathered
 *
 * The same steps as Trace Surface Curves, Surface Arrangement, Label Arrangement Cells and
 * Surface Boolean run on pieces (Docs/Parallel.md), called in turn on the rank without the
 * stages' intermediate outputs: the tracing on pieces (vtkBoolSurfPieceTraceStage.h) gives
 * every rank message 0, the distributed arrangement takes it as it is (ArrangeMessageOnPiece,
 * no second broadcast), the merged cell graph is labeled on every rank (LabelPieceCells, with
 * the shapes a drawing names but has no curves of yet, as the one-step filter labels them) and
 * Surface Boolean's writing gives the four outputs (vtkBoolSurfPieceBoolean.h).
 *
 * What runs on the gathered surface instead is decided alike on every rank and returned as
 * OneStepPieceOutcome::Gather with the reason: the filter's own steps that need the whole
 * surface (given by the filter in OneStepPieceOptions::NotOnPieces: BSC, resolving, offsets,
 * closing broken shapes), and what the tracing on pieces cannot do (the LocallyShortest
 * method, control points given by position, legs past the window search's budget).
 */
#ifndef vtkBoolSurfPieceOneStep_h
#define vtkBoolSurfPieceOneStep_h

#include "vtkBoolSurfPieceArrangementStage.h"
#include "vtkBoolSurfPieceLabels.h"
#include "vtkBoolSurfPieceTraceStage.h"
#include "vtkBoolSurfStageHandoff.h"

#include "Arrangement/Arrangement.h"
#include "Geodesic/TraceOptions.h"
#include "Labeling/ZeroCellOptions.h"
#include "Selection/BooleanOptions.h"

#include <memory>
#include <string>
#include <vector>

class vtkMultiProcessController;
class vtkPolyData;

namespace boolsurf
{

struct OneStepPieceOptions
{
  TraceOptions Trace;
  ArrangementOptions Arrangement;
  ZeroCellOptions ZeroCell;
  BooleanOptions Boolean;
  /// Whether ports 2 and 3 (the control curves) are computed (ComputeControlCurves).
  bool ControlCurves = true;
  /// Why this rank's settings need the gathered surface (empty: they do not).
  std::string NotOnPieces;
  /// Whether this rank's inputs and labeling settings are those of State::Labeled (only the
  /// Boolean changed): the labeled arrangement is then reused when every rank says so.
  bool SameLabels = false;
};

/// What the one-step filter keeps between updates on pieces, as the stage filters keep theirs:
/// the tracing's ringed piece and tracer and the arrangement's piece (kept while the piece is
/// unchanged), the locator for the zero cell given by a point, and the labeled arrangement
/// (reused while only the Boolean changes).
struct OneStepPieceState
{
  PieceTraceState Tracing;
  /// The arrangement's piece, ring and pooled results (kept while the piece is unchanged).
  PieceArrangementState Arrangement;
  SurfaceLocator Locator;
  std::shared_ptr<const PieceLabeledResult> Labeled;
};

enum class OneStepPieceOutcome
{
  Done,         ///< the four outputs written
  DrawingStart, ///< rank 0's curves are a drawing being started: no region, and no message
  Gather,       ///< not on pieces (`reason` says why): gather and run on one rank
  Failed,       ///< `error`, the same on every rank
};

/// Collective: the one-step filter on this rank's piece `local` with the control curves
/// `curves` (read on rank 0 only) into `outputs` (four ports). `warnings` gets what this rank
/// reports (rank 0: the curves' reading notes and the labels' inconsistencies).
OneStepPieceOutcome RunOneStepOnPieces(vtkMultiProcessController* controller,
  vtkPolyData* local,
  vtkPolyData* curves,
  const OneStepPieceOptions& options,
  OneStepPieceState& state,
  const std::vector<vtkPolyData*>& outputs,
  std::string& error,
  std::vector<std::string>& warnings,
  std::string& reason);

} // namespace boolsurf

#endif

#include "vtkBoolSurfPieceOneStep.h"

#include "vtkBoolSurfArrayNames.h"
#include "vtkBoolSurfControlCurves.h"
#include "vtkBoolSurfCurvesMessage.h"
#include "vtkBoolSurfPieceArrangementStage.h"
#include "vtkBoolSurfPieceBoolean.h"
#include "vtkBoolSurfPieceCosts.h"
#include "vtkBoolSurfSurfaceAdapter.h"

#include <vtkAbstractArray.h>
#include <vtkCommunicator.h>
#include <vtkFieldData.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkPolyData.h>

#include <algorithm>

namespace boolsurf
{
namespace
{
/// Collective: the shapes the one-step filter labels without curves (vtkBoolSurf::LabelCurves:
/// those whose curves are all still being drawn, and in a drawing those the Boolean names),
/// read from rank 0's curves, with the drawing's `shapeIds`: sorted, distinct, on every rank.
std::vector<int> ShapesToLabel(vtkMultiProcessController* controller,
  vtkPolyData* curves,
  const BooleanOptions& boolean,
  std::vector<int> shapeIds)
{
  std::vector<int> extra;
  if (controller->GetLocalProcessId() == 0)
  {
    extra = ShapesBeingDrawn(curves);
    if (IsDrawing(curves))
    {
      const std::vector<int> named = ShapesNamed(boolean);
      extra.insert(extra.end(), named.begin(), named.end());
    }
  }
  int count = static_cast<int>(extra.size());
  controller->Broadcast(&count, 1, 0);
  extra.resize(static_cast<std::size_t>(count));
  if (count > 0)
  {
    controller->Broadcast(extra.data(), count, 0);
  }
  shapeIds.insert(shapeIds.end(), extra.begin(), extra.end());
  std::sort(shapeIds.begin(), shapeIds.end());
  shapeIds.erase(std::unique(shapeIds.begin(), shapeIds.end()), shapeIds.end());
  return shapeIds;
}

/// Collective: whether every rank says yes.
bool Everywhere(vtkMultiProcessController* controller, bool yes)
{
  int mine = yes ? 1 : 0, all = 0;
  controller->AllReduce(&mine, &all, 1, vtkCommunicator::MIN_OP);
  return all != 0;
}

/// Trace, arrange and label on the piece, into `labeled`; the outcome when not Done.
OneStepPieceOutcome LabelOnPieces(vtkMultiProcessController* controller,
  vtkPolyData* local,
  vtkPolyData* curves,
  const OneStepPieceOptions& options,
  OneStepPieceState& state,
  vtkPolyData* fields,
  PieceCosts& costs,
  std::string& error,
  std::vector<std::string>& warnings,
  std::string& reason)
{
  PieceStopwatch watch;
  vtkNew<vtkPolyData> traced;
  std::vector<std::string> problems;
  switch (TraceOnPieces(
    controller, local, curves, options.Trace, state.Tracing, traced, problems, warnings, reason))
  {
    case PieceTraceOutcome::Traced:
      break;
    case PieceTraceOutcome::DrawingStart:
      return OneStepPieceOutcome::DrawingStart;
    case PieceTraceOutcome::Gather:
      return OneStepPieceOutcome::Gather;
    case PieceTraceOutcome::Failed:
      error = "Cannot trace the curves:" + JoinLines(problems);
      return OneStepPieceOutcome::Failed;
  }
  costs.AddTime("Trace", watch.Lap());
  if (vtkAbstractArray* traffic =
        traced->GetFieldData()->GetAbstractArray(names::PieceTracingTraffic))
  {
    fields->GetFieldData()->AddArray(traffic);
  }
  // Message 0 is on every rank already: the arrangement takes it without a second broadcast.
  WireBuffer message;
  ReadPieceCurvesMessage(traced, message);
  std::shared_ptr<PieceArrangementResult> arranged;
  if (!ArrangeMessageOnPiece(controller,
        local,
        controller->GetLocalProcessId() == 0 ? traced.GetPointer() : nullptr,
        message,
        options.Arrangement,
        state.Arrangement,
        nullptr,
        arranged,
        costs,
        error,
        warnings))
  {
    error = "Arrangement failed: " + error;
    return OneStepPieceOutcome::Failed;
  }
  watch.Lap();
  auto labeled = std::make_shared<PieceLabeledResult>();
  const std::vector<int> shapes =
    ShapesToLabel(controller, curves, options.Boolean, arranged->ShapeIds);
  if (!LabelPieceCells(
        controller, state.Locator, arranged, options.ZeroCell, shapes, *labeled, error))
  {
    return OneStepPieceOutcome::Failed;
  }
  costs.AddTime("Labeling", watch.Lap());
  const std::string inconsistent = InconsistencyWarning(labeled->Labels);
  if (!inconsistent.empty() && controller->GetLocalProcessId() == 0)
  {
    // The labels are the same on every rank: one rank says what they mean. The generators in
    // excess that explain it on one rank need the homology basis of the whole surface.
    warnings.push_back(inconsistent);
  }
  state.Labeled = std::move(labeled);
  return OneStepPieceOutcome::Done;
}
} // namespace

//------------------------------------------------------------------------------
OneStepPieceOutcome RunOneStepOnPieces(vtkMultiProcessController* controller,
  vtkPolyData* local,
  vtkPolyData* curves,
  const OneStepPieceOptions& options,
  OneStepPieceState& state,
  const std::vector<vtkPolyData*>& outputs,
  std::string& error,
  std::vector<std::string>& warnings,
  std::string& reason)
{
  PieceStopwatch watch, total;
  PieceCosts costs;
  // The filter's own steps that need the whole surface: if any rank's settings say so, every
  // rank gathers (the settings are normally the same on every rank).
  if (!Everywhere(controller, options.NotOnPieces.empty()))
  {
    reason = options.NotOnPieces.empty() ? "another rank's settings need the whole surface"
                                         : options.NotOnPieces;
    return OneStepPieceOutcome::Gather;
  }
  // Only the Boolean changed on every rank: the labeled arrangement is reused.
  const bool reuse = Everywhere(controller, options.SameLabels && state.Labeled != nullptr);
  if (!reuse)
  {
    state.Labeled.reset();
    const OneStepPieceOutcome labeled = LabelOnPieces(
      controller, local, curves, options, state, outputs[0], costs, error, warnings, reason);
    if (labeled != OneStepPieceOutcome::Done)
    {
      return labeled;
    }
    watch.Lap();
  }
  std::size_t sent = 0, received = 0;
  std::string vectorNote;
  if (!WritePieceBoolean(controller,
        *state.Labeled,
        options.Boolean,
        outputs,
        error,
        &sent,
        &received,
        &vectorNote,
        options.ControlCurves))
  {
    return OneStepPieceOutcome::Failed;
  }
  if (!vectorNote.empty())
  {
    warnings.push_back(vectorNote); // rank 0's: why ports 2 and 3 are empty
  }
  costs.AddTime("Selection", watch.Lap());
  costs.AddTime("Total", total.Lap());
  // The decisions: the filter's two all-reduces of one number (vtkBoolSurfAlgorithm), then
  // the two above.
  costs.AddBytes("Decision", 4 * sizeof(int), 4 * sizeof(int));
  costs.AddBytes("RegionBoundary", sent, received);
  WritePieceCosts(costs, outputs[0]);
  return OneStepPieceOutcome::Done;
}

} // namespace boolsurf

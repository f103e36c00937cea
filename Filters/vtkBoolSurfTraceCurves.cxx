#include "vtkBoolSurfTraceCurves.h"

#include "vtkBoolSurfArrayNames.h"

#include "vtkBoolSurfControlCurves.h"
#include "vtkBoolSurfCurvesMessage.h"
#include "vtkBoolSurfPieceTraceStage.h"
#include "vtkBoolSurfSharedPieceTrace.h"
#include "vtkBoolSurfStageHandoff.h"
#include "vtkBoolSurfTraceStage.h"

#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

vtkStandardNewMacro(vtkBoolSurfTraceCurves);

struct vtkBoolSurfTraceCurves::Internals
{
  /// What the last failed update could not trace, one sentence each.
  std::vector<std::string> Problems;
  /// The ringed piece and the tracing kept between updates on pieces, shared with the other
  /// filters tracing on the same piece (Surface Curves).
  std::shared_ptr<boolsurf::PieceTraceState> Pieces;
};

//------------------------------------------------------------------------------
vtkBoolSurfTraceCurves::vtkBoolSurfTraceCurves()
  : Internal(new Internals)
{
  this->SetNumberOfInputPorts(2);
}

//------------------------------------------------------------------------------
vtkBoolSurfTraceCurves::~vtkBoolSurfTraceCurves() = default;

//------------------------------------------------------------------------------
bool vtkBoolSurfTraceCurves::Execute(const std::vector<vtkPolyData*>& inputs,
  const std::vector<vtkPolyData*>& outputs,
  std::string& error)
{
  vtkPolyData* surfaceInput = inputs[0];
  vtkPolyData* curvesInput = inputs[1];
  vtkPolyData* output = outputs[0];
  this->Internal->Problems.clear();
  if (!this->GetSurface(surfaceInput, error))
  {
    this->Internal->Problems.push_back(error);
    return false;
  }
  if (boolsurf::PassOnDrawingStart(curvesInput, outputs))
  {
    return true; // a drawing being started: nothing to trace yet, and no message
  }
  auto result = std::make_shared<boolsurf::TracedCurvesResult>();
  std::vector<std::string> notes;
  const bool ok = boolsurf::TraceControlCurves(this->GetSurfaceCache(),
    curvesInput,
    this->GetTraceOptions(),
    this,
    result->Curves,
    output,
    this->Internal->Problems,
    notes,
    &result->Sources);
  this->ReportWarnings(notes);
  if (!ok)
  {
    if (this->Internal->Problems.empty())
    {
      return true; // aborted: the output stays empty
    }
    error = "Cannot trace the curves:" + boolsurf::JoinLines(this->Internal->Problems);
    return false;
  }
  boolsurf::AddSiteGraphField(*this->GetSurfaceCache().GetCurrent().Mesh, output->GetFieldData());
  // The traced curves in Core form for Surface Arrangement (see vtkBoolSurfStageHandoff.h).
  result->Surface = boolsurf::SurfaceIdentity(surfaceInput);
  result->Method = this->GetTraceOptions().Method;
  // Under MPI, the curves as the pieces of a split surface need them, for Surface Arrangement
  // on each rank's piece (vtkBoolSurfCurvesMessage.h): packed here, where the traced mesh is.
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    std::string note;
    if (boolsurf::PackPieceCurvesMessage(
          this->GetSurfaceCache().GetCurrent(), result->Curves, result->PieceMessage, note))
    {
      boolsurf::AddPieceCurvesField(result->PieceMessage, output->GetFieldData());
    }
    if (!note.empty() && !result->PieceMessage.empty())
    {
      vtkWarningMacro(<< note);
    }
  }
  boolsurf::AttachStageResult<boolsurf::TracedCurvesResult>(
    output->GetPointData()->GetArray(boolsurf::names::TriangleId), std::move(result));
  return true;
}

//------------------------------------------------------------------------------
bool vtkBoolSurfTraceCurves::ExecutePiece(const std::vector<vtkPolyData*>& locals,
  const std::vector<vtkPolyData*>& outputs,
  std::string& error)
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  Internals& internal = *this->Internal;
  internal.Problems.clear();
  internal.Pieces = boolsurf::SharedPieceTraceState(locals[0], std::move(internal.Pieces));
  std::vector<std::string> notes;
  std::string reason;
  const boolsurf::PieceTraceOutcome outcome = boolsurf::TraceOnPieces(controller,
    locals[0],
    locals[1],
    this->GetTraceOptions(),
    *internal.Pieces,
    outputs[0],
    internal.Problems,
    notes,
    reason,
    this);
  this->ReportWarnings(notes);
  switch (outcome)
  {
    case boolsurf::PieceTraceOutcome::Traced:
      return true;
    case boolsurf::PieceTraceOutcome::DrawingStart:
      boolsurf::MarkDrawingStart(outputs);
      return true;
    case boolsurf::PieceTraceOutcome::Gather:
      if (controller->GetLocalProcessId() == 0)
      {
        vtkWarningMacro(
          "traced on the surface gathered to rank 0, not on each rank's piece: " << reason);
      }
      this->GatherInsteadOfPieces(); // decided alike on every rank
      return true;
    case boolsurf::PieceTraceOutcome::Failed:
      break;
  }
  error = "Cannot trace the curves:" + boolsurf::JoinLines(internal.Problems);
  return false;
}

//------------------------------------------------------------------------------
void vtkBoolSurfTraceCurves::RecordFailure(const std::string&,
  const std::vector<vtkPolyData*>& outputs)
{
  // The empty output lists every problem: a script or a downstream filter can tell why.
  vtkNew<vtkStringArray> errors;
  errors->SetName(boolsurf::names::TraceErrors);
  for (const std::string& p : this->Internal->Problems)
  {
    errors->InsertNextValue(p);
  }
  outputs[0]->GetFieldData()->AddArray(errors);
}

//------------------------------------------------------------------------------
void vtkBoolSurfTraceCurves::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

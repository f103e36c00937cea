#include "vtkBoolSurfBoolean.h"

#include "vtkBoolSurfControlCurves.h"

#include "vtkBoolSurfArrayNames.h"
#include "vtkBoolSurfBooleanStage.h"
#include "vtkBoolSurfLabelingStage.h"
#include "vtkBoolSurfPieceBoolean.h"
#include "vtkBoolSurfPieceCosts.h"
#include "vtkBoolSurfSelectionOutput.h"
#include "vtkBoolSurfStageHandoff.h"
#include "vtkBoolSurfStageSettingsDefinitions.h"

#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMultiProcessController.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkBoolSurfBoolean);

struct vtkBoolSurfBoolean::Internals
{
  std::vector<char> Selected;
  boolsurf::SelectionOutputBuffers Output;
  boolsurf::ResultPathSolver Solver;
};

//------------------------------------------------------------------------------
vtkBoolSurfBoolean::vtkBoolSurfBoolean()
  : Internal(new Internals)
{
  this->BooleanSettings.reset(new boolsurf::BooleanOptions);
  this->SetNumberOfOutputPorts(4);
}

//------------------------------------------------------------------------------
vtkBoolSurfBoolean::~vtkBoolSurfBoolean() = default;

//------------------------------------------------------------------------------
vtkBoolSurfBooleanSettingsDefinitions(vtkBoolSurfBoolean);

//------------------------------------------------------------------------------
bool vtkBoolSurfBoolean::Execute(const std::vector<vtkPolyData*>& inputs,
  const std::vector<vtkPolyData*>& outputs,
  std::string& error)
{
  vtkPolyData* input = inputs[0];
  vtkPolyData* region = outputs[0];
  vtkPolyData* boundary = outputs[1];
  vtkPolyData* controls = outputs[2];
  vtkPolyData* clipped = outputs[3];
  if (boolsurf::PassOnDrawingStart(input, outputs))
  {
    return true; // a drawing being started: no region yet, and no message
  }
  Internals& in = *this->Internal;
  // The labeled arrangement in Core form (handed over, or computed again for a file), written
  // as the one-step filter writes it.
  const auto labeled = this->GetLabeledArrangement(input, error);
  if (!labeled)
  {
    return false;
  }
  std::string text, note;
  if (!boolsurf::SelectBooleanCells(
        labeled->Labels, *this->BooleanSettings, in.Selected, text, error) ||
    !boolsurf::WriteHandedOverSelection(*labeled->Arranged,
      in.Selected,
      in.Solver,
      in.Output,
      region,
      boundary,
      controls,
      clipped,
      error,
      note))
  {
    return false;
  }
  boolsurf::AddExpressionField(region, text);
  boolsurf::AddExpressionField(boundary, text);
  // The labels table travels with the region: row ArrangementCell gives a triangle's labels.
  boolsurf::AddLabelTable(labeled->Labels, region->GetFieldData());
  if (!note.empty())
  {
    vtkWarningMacro(<< note);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkBoolSurfBoolean::ExecutePiece(const std::vector<vtkPolyData*>& locals,
  const std::vector<vtkPolyData*>& outputs,
  std::string& error)
{
  if (boolsurf::PassOnDrawingStart(locals[0], outputs))
  {
    return true; // a drawing being started (on every rank: the arrangement marked each piece)
  }
  boolsurf::PieceStopwatch watch; // this rank's time, written with the output (mpi_scale.py)
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const auto labeled = boolsurf::FindPieceLabels(locals[0], error);
  std::string vectorNote;
  if (!labeled ||
    !boolsurf::WritePieceBoolean(
      controller, *labeled, *this->BooleanSettings, outputs, error, nullptr, nullptr, &vectorNote))
  {
    return false;
  }
  boolsurf::WriteLocalStageCosts(watch.Lap(), outputs[0]);
  if (controller->GetLocalProcessId() == 0)
  {
    vtkWarningMacro("ran on each rank's piece of the surface: "
      << boolsurf::PieceBooleanPortsNote << (vectorNote.empty() ? "" : "; ") << vectorNote);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkBoolSurfBoolean::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Operation: " << this->GetOperation() << "\n";
  os << indent << "ShapeA: " << this->GetShapeA() << "\n";
  os << indent << "ShapeB: " << this->GetShapeB() << "\n";
  os << indent << "Expression: " << this->GetExpression() << "\n";
  os << indent << "FillRule: " << this->GetFillRule() << "\n";
}

#include "vtkBoolSurfBoolean.h"

#include "vtkBoolSurfControlCurves.h"

#include "vtkBoolSurfArrayNames.h"
#include "vtkBoolSurfBooleanStage.h"
#include "vtkBoolSurfLabelingStage.h"
#include "vtkBoolSurfPieceCosts.h"
#include "vtkBoolSurfPieceLabels.h"
#include "vtkBoolSurfPieceRegionBoundary.h"
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
  std::string text;
  std::vector<char> selected;
  std::shared_ptr<const boolsurf::PieceArrangementResult> arranged;
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  // The selection fails alike on every rank (the labels are replicated), so no rank is left
  // waiting in the boundary's exchange below.
  if (!boolsurf::WritePieceRegion(
        locals[0], *this->BooleanSettings, outputs[0], text, selected, arranged, error))
  {
    return false;
  }
  // Port 1: the whole region's boundary loops, chained on rank 0 from every rank's runs.
  if (!boolsurf::WritePieceRegionBoundary(controller, *arranged, selected, outputs[1], error))
  {
    outputs[0]->Initialize();
    return false;
  }
  boolsurf::AddExpressionField(outputs[1], text);
  boolsurf::WriteLocalStageCosts(watch.Lap(), outputs[0]);
  // Ports 2 and 3 (control points of the boundary and the clipped curves) need the curves'
  // control points and a geodesic solver on the whole surface: empty on pieces. Every port is
  // marked as coming from pieces so that the filters that gather refuse them.
  for (std::size_t p = 1; p < outputs.size(); ++p)
  {
    outputs[p]->GetFieldData()->AddArray(
      outputs[0]->GetFieldData()->GetAbstractArray(boolsurf::names::ArrangementOnPieces));
  }
  if (controller->GetLocalProcessId() == 0)
  {
    vtkWarningMacro("ran on each rank's piece of the surface: each rank's port 0 is its part of "
                    "the region, port 1 (the region's boundary loops) is whole on rank 0 and "
                    "empty on the others; ports 2 and 3 (the boundary's control points and the "
                    "clipped curves) are not computed on pieces (they need the control points "
                    "and geodesics on the whole surface) and stay empty");
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

#include "vtkBoolSurfBoolean.h"

#include "vtkBoolSurfControlCurves.h"

#include "vtkBoolSurfBooleanStage.h"
#include "vtkBoolSurfLabelingStage.h"
#include "vtkBoolSurfSelectionOutput.h"
#include "vtkBoolSurfStageHandoff.h"

#include <vtkInformation.h>
#include <vtkInformationVector.h>
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
  this->SetNumberOfOutputPorts(4);
}

//------------------------------------------------------------------------------
vtkBoolSurfBoolean::~vtkBoolSurfBoolean() = default;

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
  // The labeled arrangement in Core form when the stages upstream handed it over (then written
  // as the one-step filter writes it); else the labels the input's arrays hold.
  std::string notAttached; // the arrays are read then
  const auto attached = this->GetLabeledArrangement(input, notAttached);
  vtkSmartPointer<vtkPolyData> labeled = input;
  boolsurf::ArrangementFields fields;
  boolsurf::LabelingResult read;
  if (!attached)
  {
    if (!boolsurf::ReadLabels(input, labeled, fields, read, error))
    {
      return false;
    }
    this->UpdateProgress(0.5);
  }
  const boolsurf::LabelingResult& labels = attached ? attached->Labels : read;
  std::string text, note;
  if (!boolsurf::SelectRequestedCells(labels,
        boolsurf::MakeBooleanRequest(
          this->Operation, this->ShapeA, this->ShapeB, this->Expression, this->FillRule),
        in.Selected,
        text,
        error))
  {
    return false;
  }
  if (!attached)
  {
    boolsurf::WriteSelection(
      labeled, fields, in.Selected, region, boundary, controls, clipped, &note);
  }
  else if (!boolsurf::WriteHandedOverSelection(*attached->Arranged,
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
  if (attached)
  {
    // The labels table travels with the region, as WriteSelection passes the input's on.
    boolsurf::AddLabelTable(attached->Labels, region->GetFieldData());
  }
  if (!note.empty())
  {
    vtkWarningMacro(<< note);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkBoolSurfBoolean::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Operation: " << this->Operation << "\n";
  os << indent << "ShapeA: " << this->ShapeA << "\n";
  os << indent << "ShapeB: " << this->ShapeB << "\n";
  os << indent << "Expression: " << this->Expression << "\n";
  os << indent << "FillRule: " << this->FillRule << "\n";
}

#include "vtkBoolSurfBoolean.h"

#include "vtkBoolSurfControlCurves.h"

#include "vtkBoolSurfArrayNames.h"

#include "vtkBoolSurfBooleanStage.h"
#include "vtkBoolSurfLabelingStage.h"
#include "vtkBoolSurfSelectionOutput.h"
#include "vtkBoolSurfStageHandoff.h"

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkBoolSurfBoolean);

namespace
{
/// The Boolean on a labeled arrangement handed over in Core form, written as the one-step
/// filter writes it. `note` says when the control-point outputs stay empty.
bool SelectFromCore(const boolsurf::LabeledArrangementResult& labeled,
  const boolsurf::BooleanRequest& request,
  std::vector<char>& selected,
  boolsurf::SelectionOutputBuffers& buffers,
  boolsurf::ResultPathSolver& solver,
  vtkPolyData* region,
  vtkPolyData* boundary,
  vtkPolyData* controls,
  vtkPolyData* clipped,
  std::string& error,
  std::string& note)
{
  std::string text;
  if (!boolsurf::SelectRequestedCells(labeled.Labels, request, selected, text, error))
  {
    return false;
  }
  if (!boolsurf::WriteHandedOverSelection(*labeled.Arranged,
        selected,
        solver,
        buffers,
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
  boolsurf::AddLabelTable(labeled.Labels, region->GetFieldData());
  return true;
}
} // namespace

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
  std::string note, warning;
  if (boolsurf::PassOnDrawingStart(input, outputs))
  {
    return true; // a drawing being started: no region yet, and no message
  }
  // The labeled arrangement in Core form when the stages upstream handed it over: selected and
  // written as the one-step filter does.
  if (const auto labeled = boolsurf::FindLabeledArrangement(input))
  {
    Internals& in = *this->Internal;
    if (!SelectFromCore(*labeled,
          boolsurf::MakeBooleanRequest(
            this->Operation, this->ShapeA, this->ShapeB, this->Expression, this->FillRule),
          in.Selected,
          in.Output,
          in.Solver,
          region,
          boundary,
          controls,
          clipped,
          error,
          note))
    {
      return false;
    }
    if (!note.empty())
    {
      vtkWarningMacro(<< note);
    }
    return true;
  }
  boolsurf::ArrangementFields fields;
  boolsurf::LabelingResult labels;
  vtkFieldData* fd = input ? input->GetFieldData() : nullptr;
  vtkDataArray* cellLabels = fd ? fd->GetArray(boolsurf::names::CellLabels) : nullptr;
  vtkDataArray* consistent = fd ? fd->GetArray(boolsurf::names::ShapeConsistent) : nullptr;
  vtkSmartPointer<vtkPolyData> labeled = input;
  if (cellLabels && consistent)
  {
    if (!boolsurf::ReadArrangementFields(input, fields, error))
    {
      return false;
    }
    const int ns = fields.NumberOfShapes;
    if (cellLabels->GetNumberOfComponents() != ns ||
      cellLabels->GetNumberOfTuples() != fields.NumberOfCells ||
      consistent->GetNumberOfTuples() != ns)
    {
      error = "field data CellLabels (" + std::to_string(cellLabels->GetNumberOfTuples()) + " x " +
        std::to_string(cellLabels->GetNumberOfComponents()) + ") or ShapeConsistent (" +
        std::to_string(consistent->GetNumberOfTuples()) + ") does not match the arrangement's " +
        std::to_string(fields.NumberOfCells) + " cells and " + std::to_string(ns) + " shapes";
      return false;
    }
    labels.NumberOfShapes = ns;
    labels.ShapeIds = fields.ShapeIds;
    labels.Labels.resize(static_cast<size_t>(fields.NumberOfCells) * ns);
    if (auto* ints = vtkArrayDownCast<vtkIntArray>(cellLabels))
    {
      std::copy_n(ints->GetPointer(0), labels.Labels.size(), labels.Labels.data());
    }
    else
    {
      for (vtkIdType c = 0; c < cellLabels->GetNumberOfTuples(); ++c)
      {
        for (int s = 0; s < ns; ++s)
        {
          labels.Labels[c * ns + s] = static_cast<int>(cellLabels->GetComponent(c, s));
        }
      }
    }
    for (int s = 0; s < ns; ++s)
    {
      labels.ShapeConsistent.push_back(consistent->GetComponent(s, 0) != 0);
    }
  }
  else
  {
    // An arrangement without labels: label it here with the automatic zero cell.
    labeled = vtkSmartPointer<vtkPolyData>::New();
    if (!boolsurf::LabelArrangement(
          input, boolsurf::LabelingOutputOptions(), labeled, fields, labels, error, warning))
    {
      return false;
    }
  }
  this->UpdateProgress(0.5);
  const boolsurf::BooleanRequest request = boolsurf::MakeBooleanRequest(
    this->Operation, this->ShapeA, this->ShapeB, this->Expression, this->FillRule);
  if (!boolsurf::ComputeBoolean(
        labeled, fields, labels, request, region, boundary, error, controls, clipped, &note))
  {
    return false;
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

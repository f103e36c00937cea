#include "vtkBoolSurfBoolean.h"

#include "vtkBoolSurfRankGather.h"

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
  const boolsurf::ArrangementResult& arranged = *labeled.Arranged;
  std::string text;
  if (!boolsurf::SelectRequestedCells(labeled.Labels, request, selected, text, error))
  {
    return false;
  }
  const bool withControls = !arranged.Sources.empty();
  if (!boolsurf::WriteSelectedCells(arranged.Surface,
        arranged.Arrangement,
        arranged.Sources,
        selected,
        withControls ? &solver.Get(arranged.Surface.Mesh, arranged.ExactGeodesics) : nullptr,
        buffers,
        region,
        boundary,
        controls,
        clipped,
        error))
  {
    return false;
  }
  note = withControls ? "" : boolsurf::NoControlPointsNote;
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
int vtkBoolSurfBoolean::RequestData(vtkInformation* vtkNotUsed(request),
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  // Every rank takes part in the gather first (see vtkBoolSurfRankGather); only rank 0 computes.
  vtkBoolSurfRankGather gather(this, inputVector, 1);
  vtkPolyData* input = gather.Input(0);
  vtkPolyData* region = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* boundary = vtkPolyData::GetData(outputVector, 1);
  vtkPolyData* controls = vtkPolyData::GetData(outputVector, 2);
  vtkPolyData* clipped = vtkPolyData::GetData(outputVector, 3);
  // A failed update leaves empty outputs, not the previous region.
  region->Initialize();
  boundary->Initialize();
  controls->Initialize();
  clipped->Initialize();
  if (!gather.ComputesHere())
  {
    return 1; // other MPI ranks: empty outputs
  }
  std::string note;
  this->UpdateProgress(0.0);

  std::string error, warning;
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
      region->Initialize();
      boundary->Initialize();
      controls->Initialize();
      clipped->Initialize();
      vtkErrorMacro(<< error);
      return vtkBoolSurfErrorReported;
    }
    if (!note.empty())
    {
      vtkWarningMacro(<< note);
    }
    this->UpdateProgress(1.0);
    return 1;
  }
  boolsurf::ArrangementFields fields;
  boolsurf::LabelingResult labels;
  vtkFieldData* fd = input ? input->GetFieldData() : nullptr;
  vtkDataArray* cellLabels = fd ? fd->GetArray("CellLabels") : nullptr;
  vtkDataArray* consistent = fd ? fd->GetArray("ShapeConsistent") : nullptr;
  vtkSmartPointer<vtkPolyData> labeled = input;
  if (cellLabels && consistent)
  {
    if (!boolsurf::ReadArrangementFields(input, fields, error))
    {
      vtkErrorMacro(<< error);
      return vtkBoolSurfErrorReported;
    }
    const int ns = fields.NumberOfShapes;
    if (cellLabels->GetNumberOfComponents() != ns ||
      cellLabels->GetNumberOfTuples() != fields.NumberOfCells ||
      consistent->GetNumberOfTuples() != ns)
    {
      vtkErrorMacro(<< "field data CellLabels (" << cellLabels->GetNumberOfTuples() << " x "
                    << cellLabels->GetNumberOfComponents() << ") or ShapeConsistent ("
                    << consistent->GetNumberOfTuples() << ") does not match the arrangement's "
                    << fields.NumberOfCells << " cells and " << ns << " shapes");
      return vtkBoolSurfErrorReported;
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
      vtkErrorMacro(<< error);
      return vtkBoolSurfErrorReported;
    }
  }
  this->UpdateProgress(0.5);
  const boolsurf::BooleanRequest request = boolsurf::MakeBooleanRequest(
    this->Operation, this->ShapeA, this->ShapeB, this->Expression, this->FillRule);
  if (!boolsurf::ComputeBoolean(
        labeled, fields, labels, request, region, boundary, error, controls, clipped, &note))
  {
    vtkErrorMacro(<< error);
    return vtkBoolSurfErrorReported;
  }
  if (!note.empty())
  {
    vtkWarningMacro(<< note);
  }
  this->UpdateProgress(1.0);
  return 1;
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

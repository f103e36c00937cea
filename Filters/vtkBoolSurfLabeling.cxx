#include "vtkBoolSurfLabeling.h"

#include "vtkBoolSurfRankGather.h"

#include "vtkBoolSurfHomologyOutput.h"
#include "vtkBoolSurfLabelingStage.h"
#include "vtkBoolSurfStageHandoff.h"

#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkBoolSurfLabeling);

struct vtkBoolSurfLabeling::Internals
{
  /// On the arrangement's input surface, for ZeroCellPoint.
  boolsurf::SurfaceLocator Locator;
};

//------------------------------------------------------------------------------
vtkBoolSurfLabeling::vtkBoolSurfLabeling()
  : Internal(new Internals)
{
  this->SetNumberOfOutputPorts(2);
}

//------------------------------------------------------------------------------
vtkBoolSurfLabeling::~vtkBoolSurfLabeling() = default;

//------------------------------------------------------------------------------
int vtkBoolSurfLabeling::RequestData(vtkInformation* vtkNotUsed(request),
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  // Every rank takes part in the gather first (see vtkBoolSurfRankGather); only rank 0 computes.
  vtkBoolSurfRankGather gather(this, inputVector, 1);
  vtkPolyData* input = gather.Input(0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* generators = vtkPolyData::GetData(outputVector, 1);
  output->Initialize(); // a failed update leaves an empty output, not the previous one
  generators->Initialize();
  if (!gather.ComputesHere())
  {
    return 1; // other MPI ranks: empty outputs
  }
  this->UpdateProgress(0.0);
  boolsurf::ArrangementFields fields;
  boolsurf::LabelingResult labels;
  std::string error, warning;
  boolsurf::LabelingOutputOptions options;
  options.ZeroCellPoint = this->ZeroCellMode == POINT ? this->ZeroCellPoint : nullptr;
  options.ColorShape = this->ColorShape;
  options.PerTriangleLabels = this->PerTriangleLabels;
  // The arrangement in Core form when Surface Arrangement handed it over: labeled as the
  // one-step filter labels it.
  const auto arranged = boolsurf::FindStageResult<boolsurf::ArrangementResult>(
    input ? input->GetCellData()->GetArray("ArrangementCell") : nullptr);
  if (arranged)
  {
    options.Arranged = arranged.get();
    if (options.ZeroCellPoint)
    {
      options.SurfaceLocator = this->Internal->Locator.Get(arranged->Surface.Triangles);
    }
  }
  if (!boolsurf::LabelArrangement(input, options, output, fields, labels, error, warning))
  {
    vtkErrorMacro(<< error);
    return vtkBoolSurfErrorReported;
  }
  if (arranged)
  {
    auto result = std::make_shared<boolsurf::LabeledArrangementResult>();
    result->Arranged = arranged;
    result->Labels = std::move(labels);
    boolsurf::AttachStageResult<boolsurf::LabeledArrangementResult>(
      output->GetFieldData()->GetArray("CellLabels"), std::move(result));
  }
  if (!warning.empty())
  {
    vtkWarningMacro(<< warning);
  }
  // Port 1: the homology generators the arrangement found on the surface.
  boolsurf::WriteGeneratorPolylines(
    boolsurf::ReadHomologyFields(input->GetFieldData()), generators);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkBoolSurfLabeling::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ZeroCellMode: " << this->ZeroCellMode << "\n";
  os << indent << "ZeroCellPoint: " << this->ZeroCellPoint[0] << " " << this->ZeroCellPoint[1]
     << " " << this->ZeroCellPoint[2] << "\n";
  os << indent << "ColorShape: " << this->ColorShape << "\n";
  os << indent << "PerTriangleLabels: " << this->PerTriangleLabels << "\n";
}

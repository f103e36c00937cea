#include "vtkBoolSurfBSC.h"

#include "vtkBoolSurfRankGather.h"

#include "vtkBoolSurfBSCStage.h"
#include "vtkBoolSurfBooleanStage.h"

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkBoolSurfBSC);

//------------------------------------------------------------------------------
vtkBoolSurfBSC::vtkBoolSurfBSC()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(4);
}

//------------------------------------------------------------------------------
int vtkBoolSurfBSC::FillInputPortInformation(int vtkNotUsed(port), vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
int vtkBoolSurfBSC::RequestData(vtkInformation* vtkNotUsed(request),
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  // Every rank takes part in the gather first (see vtkBoolSurfRankGather); only rank 0 computes.
  vtkBoolSurfRankGather gather(this, inputVector, 2);
  vtkPolyData* input = gather.Input(0);
  vtkPolyData* samples = gather.Input(1);
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

  boolsurf::ArrangementFields fields;
  std::string error;
  if (!boolsurf::ReadArrangementFields(input, fields, error))
  {
    vtkErrorMacro(<< error);
    return vtkBoolSurfErrorReported;
  }
  std::vector<boolsurf::SampleQuery> queries;
  if (!boolsurf::ReadSampleQueries(samples, nullptr, queries, error))
  {
    vtkErrorMacro(<< error);
    return vtkBoolSurfErrorReported;
  }
  std::vector<boolsurf::PatchSnap> snaps;
  boolsurf::BscResult result;
  if (!boolsurf::SelectSampledCells(input,
        fields,
        queries,
        boolsurf::SnapDistance(input, this->SnapTolerance),
        this->MaxSearchStates,
        snaps,
        result,
        error,
        [this] { return this->CheckAbort(); }))
  {
    vtkErrorMacro(<< error);
    return vtkBoolSurfErrorReported;
  }
  this->UpdateProgress(0.5);
  boolsurf::WriteSelection(
    input, fields, result.Selected, region, boundary, controls, clipped, &note);
  if (!note.empty())
  {
    vtkWarningMacro(<< note);
  }
  boolsurf::AddSampleFields(snaps, result, region);
  boolsurf::AddSampleFields(snaps, result, boundary);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkBoolSurfBSC::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SnapTolerance: " << this->SnapTolerance << "\n";
  os << indent << "MaxSearchStates: " << this->MaxSearchStates << "\n";
}

#include "vtkBoolSurfTraceCurves.h"

#include "vtkBoolSurfRankGather.h"

#include "vtkBoolSurfStageHandoff.h"
#include "vtkBoolSurfTraceStage.h"

#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

vtkStandardNewMacro(vtkBoolSurfTraceCurves);

struct vtkBoolSurfTraceCurves::Internals
{
  boolsurf::vtkSurfaceCache Surface;
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
int vtkBoolSurfTraceCurves::FillInputPortInformation(int vtkNotUsed(port), vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
int vtkBoolSurfTraceCurves::RequestData(vtkInformation* vtkNotUsed(request),
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  // Every rank takes part in the gather first (see vtkBoolSurfRankGather); only rank 0 computes.
  vtkBoolSurfRankGather gather(this, inputVector, 2);
  vtkPolyData* surfaceInput = gather.Input(0);
  vtkPolyData* curvesInput = gather.Input(1);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize(); // a failed update leaves an empty output, not the previous one
  if (!gather.ComputesHere())
  {
    return 1; // other MPI ranks: empty outputs
  }

  std::vector<std::string> warnings, problems, notes;
  std::string error;
  if (!this->Internal->Surface.GetUsable(surfaceInput, warnings, error))
  {
    problems.push_back(error);
  }
  for (const std::string& w : warnings)
  {
    vtkWarningMacro(<< w);
  }
  auto result = std::make_shared<boolsurf::TracedCurvesResult>();
  boolsurf::TraceOptions options;
  options.Resolution = this->Resolution;
  options.ProjectionTolerance = this->ProjectionTolerance;
  options.ExactGeodesics = this->ExactGeodesics != 0;
  if (problems.empty())
  {
    boolsurf::TraceControlCurves(this->Internal->Surface,
      curvesInput,
      options,
      this,
      result->Curves,
      output,
      problems,
      notes,
      &result->Sources);
  }
  for (const std::string& n : notes)
  {
    vtkWarningMacro(<< n);
  }
  if (!problems.empty())
  {
    output->Initialize();
    vtkNew<vtkStringArray> errors;
    errors->SetName("TraceErrors");
    for (const std::string& p : problems)
    {
      errors->InsertNextValue(p);
    }
    output->GetFieldData()->AddArray(errors);
    vtkErrorMacro(<< "Cannot trace the curves:" << boolsurf::JoinLines(problems));
    return 1; // the empty output with TraceErrors is the answer
  }
  // The traced curves in Core form for Surface Arrangement (see vtkBoolSurfStageHandoff.h).
  result->Surface = boolsurf::SurfaceIdentity(surfaceInput);
  result->ExactGeodesics = options.ExactGeodesics;
  boolsurf::AttachStageResult<boolsurf::TracedCurvesResult>(
    output->GetPointData()->GetArray("TriangleId"), std::move(result));
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkBoolSurfTraceCurves::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "ExactGeodesics: " << this->ExactGeodesics << "\n";
  os << indent << "ProjectionTolerance: " << this->ProjectionTolerance << "\n";
}

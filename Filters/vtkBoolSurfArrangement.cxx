#include "vtkBoolSurfArrangement.h"

#include "Arrangement.h"
#include "vtkBoolSurfArrangementOutput.h"
#include "vtkBoolSurfSurfaceCache.h"
#include "vtkBoolSurfTracedCurves.h"

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkBoolSurfArrangement);

struct vtkBoolSurfArrangement::Internals
{
  boolsurf::vtkSurfaceCache Surface;
};

//------------------------------------------------------------------------------
vtkBoolSurfArrangement::vtkBoolSurfArrangement()
  : Internal(new Internals)
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
}

//------------------------------------------------------------------------------
vtkBoolSurfArrangement::~vtkBoolSurfArrangement() = default;

//------------------------------------------------------------------------------
vtkPolyData* vtkBoolSurfArrangement::GetPatchesOutput()
{
  return this->GetOutput(1);
}

//------------------------------------------------------------------------------
int vtkBoolSurfArrangement::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  (void)port;
  return 1;
}

//------------------------------------------------------------------------------
int vtkBoolSurfArrangement::RequestData(vtkInformation* vtkNotUsed(request),
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkPolyData* surfaceInput = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* curvesInput = vtkPolyData::GetData(inputVector[1], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* patches = vtkPolyData::GetData(outputVector, 1);

  this->UpdateProgress(0.0);
  bool rebuilt = false;
  const boolsurf::vtkSurfaceInput& surface =
    this->Internal->Surface.Get(surfaceInput, boolsurf::SurfaceCheckOptions(), rebuilt);
  for (const std::string& w : surface.Warnings)
  {
    vtkWarningMacro(<< "Surface: " << w);
  }
  if (surface.Check.HasErrors())
  {
    vtkErrorMacro(<< "The surface is unfit for BoolSurf:\n" << surface.Check.ErrorSummary());
    return 0;
  }
  std::vector<boolsurf::TracedCurve> curves;
  std::vector<std::string> problems;
  if (!boolsurf::ReadTracedCurves(curvesInput, *surface.Mesh, curves, problems))
  {
    std::string all;
    for (const std::string& p : problems)
    {
      all += "\n" + p;
    }
    vtkErrorMacro(<< "Invalid traced curves:" << all);
    return 0;
  }
  this->UpdateProgress(0.1);
  if (this->CheckAbort())
  {
    return 1;
  }

  boolsurf::ArrangementOptions options;
  options.Threads = this->NumberOfThreads;
  boolsurf::Arrangement arrangement;
  std::string error;
  if (!boolsurf::ComputeArrangement(*surface.Mesh, curves, options, arrangement, error))
  {
    vtkErrorMacro(<< "Arrangement failed: " << error);
    return 0;
  }
  this->UpdateProgress(0.8);
  if (this->CheckAbort())
  {
    return 1;
  }
  boolsurf::WriteArrangementSurface(surface, curves, arrangement, output);
  boolsurf::WriteArrangementPatches(arrangement, output, patches);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkBoolSurfArrangement::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
}

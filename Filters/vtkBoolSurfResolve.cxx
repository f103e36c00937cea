#include "vtkBoolSurfResolve.h"

#include "vtkBoolSurfRankGather.h"

#include "vtkBoolSurfResolveStage.h"
#include "vtkBoolSurfSurfaceCache.h"

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkBoolSurfResolve);

struct vtkBoolSurfResolve::Internals
{
  // The surface's adjacency, tracer and homology generators, kept while only the curves change.
  boolsurf::vtkSurfaceCache Surface;
};

//------------------------------------------------------------------------------
vtkBoolSurfResolve::vtkBoolSurfResolve()
  : Internal(new Internals)
{
  this->SetNumberOfInputPorts(2);
}

//------------------------------------------------------------------------------
vtkBoolSurfResolve::~vtkBoolSurfResolve() = default;

//------------------------------------------------------------------------------
int vtkBoolSurfResolve::FillInputPortInformation(int vtkNotUsed(port), vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
int vtkBoolSurfResolve::RequestData(vtkInformation* vtkNotUsed(request),
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  // Every rank takes part in the gather first (see vtkBoolSurfRankGather); only rank 0 computes.
  vtkBoolSurfRankGather gather(this, inputVector, 2);
  vtkPolyData* surfaceInput = gather.Input(0);
  vtkPolyData* curvesInput = gather.Input(1);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize(); // a failed update leaves an empty output
  if (!gather.ComputesHere())
  {
    return 1; // other MPI ranks: empty outputs
  }
  this->UpdateProgress(0.0);
  std::vector<std::string> warnings;
  std::string error;
  const boolsurf::vtkSurfaceInput* surface =
    this->Internal->Surface.GetUsable(surfaceInput, warnings, error);
  for (const std::string& w : warnings)
  {
    vtkWarningMacro(<< w);
  }
  if (!surface)
  {
    vtkErrorMacro(<< error);
    return vtkBoolSurfErrorReported;
  }
  if (!curvesInput)
  {
    vtkErrorMacro(<< "no control curves on input port 1");
    return vtkBoolSurfErrorReported;
  }
  boolsurf::ResolveStageOptions options;
  options.Strategy = static_cast<boolsurf::ResolveStrategy>(this->Strategy);
  options.Offset = this->Offset;
  options.Resolution = this->Resolution;
  options.ProjectionTolerance = this->ProjectionTolerance;
  if (!boolsurf::ParseShapeStrategies(this->ShapeStrategies, options.PerShape, error))
  {
    vtkErrorMacro(<< error);
    return vtkBoolSurfErrorReported;
  }
  std::vector<std::string> notes;
  const bool ok = boolsurf::ResolveControlCurves(
    this->Internal->Surface, curvesInput, options, output, notes, error);
  for (const std::string& n : notes)
  {
    vtkWarningMacro(<< n);
  }
  if (!ok)
  {
    output->Initialize();
    vtkErrorMacro(<< error);
    return vtkBoolSurfErrorReported;
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkBoolSurfResolve::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Strategy: " << this->Strategy << "\n";
  os << indent << "ShapeStrategies: " << this->ShapeStrategies << "\n";
  os << indent << "Offset: " << this->Offset << "\n";
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "ProjectionTolerance: " << this->ProjectionTolerance << "\n";
}

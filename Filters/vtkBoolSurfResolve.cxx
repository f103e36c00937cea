#include "vtkBoolSurfResolve.h"

#include "vtkBoolSurfResolveStage.h"
#include "vtkBoolSurfSurfaceCache.h"

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkBoolSurfResolve);

//------------------------------------------------------------------------------
vtkBoolSurfResolve::vtkBoolSurfResolve()
{
  this->SetNumberOfInputPorts(2);
}

//------------------------------------------------------------------------------
vtkBoolSurfResolve::~vtkBoolSurfResolve() = default;

//------------------------------------------------------------------------------
bool vtkBoolSurfResolve::Execute(const std::vector<vtkPolyData*>& inputs,
  const std::vector<vtkPolyData*>& outputs,
  std::string& error)
{
  vtkPolyData* surfaceInput = inputs[0];
  vtkPolyData* curvesInput = inputs[1];
  vtkPolyData* output = outputs[0];
  if (!this->GetSurface(surfaceInput, error))
  {
    return false;
  }
  if (!curvesInput)
  {
    error = "no control curves on input port 1";
    return false;
  }
  boolsurf::ResolveStageOptions options;
  options.Strategy = static_cast<boolsurf::ResolveStrategy>(this->Strategy);
  options.Offset = this->Offset;
  options.Trace = this->GetTraceOptions();
  if (!boolsurf::ParseShapeStrategies(this->ShapeStrategies, options.PerShape, error))
  {
    return false;
  }
  std::vector<std::string> notes;
  const bool ok = boolsurf::ResolveControlCurves(
    this->GetSurfaceCache(), curvesInput, options, output, notes, error);
  this->ReportWarnings(notes);
  return ok;
}

//------------------------------------------------------------------------------
void vtkBoolSurfResolve::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Strategy: " << this->Strategy << "\n";
  os << indent << "ShapeStrategies: " << this->ShapeStrategies << "\n";
  os << indent << "Offset: " << this->Offset << "\n";
}

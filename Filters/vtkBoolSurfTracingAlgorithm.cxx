#include "vtkBoolSurfTracingAlgorithm.h"

#include "vtkBoolSurfStageSettingsDefinitions.h"
#include "vtkBoolSurfTraceStage.h"

//------------------------------------------------------------------------------
vtkBoolSurfTracingAlgorithm::vtkBoolSurfTracingAlgorithm()
  : TraceSettings(new boolsurf::TraceOptions)
{
}

//------------------------------------------------------------------------------
vtkBoolSurfTracingAlgorithm::~vtkBoolSurfTracingAlgorithm() = default;

//------------------------------------------------------------------------------
vtkBoolSurfClampedSettingDefinition(vtkBoolSurfTracingAlgorithm,
  Resolution,
  int,
  this->TraceSettings->Resolution);
vtkBoolSurfClampedSettingDefinition(vtkBoolSurfTracingAlgorithm,
  ProjectionTolerance,
  double,
  this->TraceSettings->ProjectionTolerance);
vtkBoolSurfClampedSettingDefinition(vtkBoolSurfTracingAlgorithm,
  GeodesicMethod,
  int,
  this->TraceSettings->Method);
vtkBoolSurfThreadSettingsDefinitions(vtkBoolSurfTracingAlgorithm, this->TraceSettings->Threads);

//------------------------------------------------------------------------------
void vtkBoolSurfTracingAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Resolution: " << this->GetResolution() << "\n";
  os << indent << "GeodesicMethod: " << this->GetGeodesicMethod() << " ("
     << GetGeodesicMethodName(this->GetGeodesicMethod()) << ")\n";
  os << indent << "ProjectionTolerance: " << this->GetProjectionTolerance() << "\n";
  os << indent << "NumberOfThreads: " << this->GetNumberOfThreads() << "\n";
}

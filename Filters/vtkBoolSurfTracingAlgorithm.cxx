#include "vtkBoolSurfTracingAlgorithm.h"

#include "vtkBoolSurfTraceStage.h"

#include <algorithm>

namespace
{
/// `value` clamped to [low, high], and whether it differs from `current` (as vtkSetClampMacro
/// decides when to call Modified()).
template <typename T>
bool ClampedChange(T& current, T value, T low, T high)
{
  value = std::min(std::max(value, low), high);
  if (current == value)
  {
    return false;
  }
  current = value;
  return true;
}
} // namespace

//------------------------------------------------------------------------------
vtkBoolSurfTracingAlgorithm::vtkBoolSurfTracingAlgorithm()
  : TraceSettings(new boolsurf::TraceOptions)
{
}

//------------------------------------------------------------------------------
vtkBoolSurfTracingAlgorithm::~vtkBoolSurfTracingAlgorithm() = default;

//------------------------------------------------------------------------------
void vtkBoolSurfTracingAlgorithm::SetResolution(int resolution)
{
  if (ClampedChange(this->TraceSettings->Resolution,
        resolution,
        this->GetResolutionMinValue(),
        this->GetResolutionMaxValue()))
  {
    this->Modified();
  }
}

int vtkBoolSurfTracingAlgorithm::GetResolution()
{
  return this->TraceSettings->Resolution;
}

//------------------------------------------------------------------------------
void vtkBoolSurfTracingAlgorithm::SetProjectionTolerance(double tolerance)
{
  if (ClampedChange(this->TraceSettings->ProjectionTolerance,
        tolerance,
        this->GetProjectionToleranceMinValue(),
        this->GetProjectionToleranceMaxValue()))
  {
    this->Modified();
  }
}

double vtkBoolSurfTracingAlgorithm::GetProjectionTolerance()
{
  return this->TraceSettings->ProjectionTolerance;
}

//------------------------------------------------------------------------------
void vtkBoolSurfTracingAlgorithm::SetGeodesicMethod(int method)
{
  int current = this->GetGeodesicMethod();
  if (ClampedChange(
        current, method, this->GetGeodesicMethodMinValue(), this->GetGeodesicMethodMaxValue()))
  {
    this->TraceSettings->Method = static_cast<boolsurf::GeodesicMethod>(current);
    this->Modified();
  }
}

int vtkBoolSurfTracingAlgorithm::GetGeodesicMethod()
{
  return static_cast<int>(this->TraceSettings->Method);
}

//------------------------------------------------------------------------------
void vtkBoolSurfTracingAlgorithm::SetNumberOfThreads(int threads)
{
  if (ClampedChange(this->TraceSettings->Threads,
        threads,
        this->GetNumberOfThreadsMinValue(),
        this->GetNumberOfThreadsMaxValue()))
  {
    this->Modified();
  }
}

int vtkBoolSurfTracingAlgorithm::GetNumberOfThreads()
{
  return this->TraceSettings->Threads;
}

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

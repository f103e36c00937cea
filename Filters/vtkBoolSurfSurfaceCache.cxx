#include "vtkBoolSurfSurfaceCache.h"

#include "Geodesic/CurveTracer.h"

#include <vtkPolyData.h>
#include <vtkStaticCellLocator.h>

namespace boolsurf
{

vtkSurfaceCache::vtkSurfaceCache() = default;
vtkSurfaceCache::~vtkSurfaceCache() = default;

//------------------------------------------------------------------------------
const vtkSurfaceInput& vtkSurfaceCache::Get(vtkPolyData* input,
  const SurfaceCheckOptions& options,
  bool& rebuilt)
{
  const vtkMTimeType time = input ? input->GetMTime() : 0;
  rebuilt = !this->Surface.Mesh || input != this->Input || time != this->InputTime ||
    options.DegenerateTolerance != this->Tolerance;
  if (rebuilt)
  {
    ConvertSurface(input, this->Surface, options);
    this->Input = input;
    this->InputTime = time;
    this->Tolerance = options.DegenerateTolerance;
    this->Locator = nullptr;
    this->Tracer.reset();
  }
  return this->Surface;
}

//------------------------------------------------------------------------------
const vtkSurfaceInput* vtkSurfaceCache::GetUsable(vtkPolyData* input,
  std::vector<std::string>& warnings,
  std::string& error)
{
  bool rebuilt = false;
  const vtkSurfaceInput& surface = this->Get(input, SurfaceCheckOptions(), rebuilt);
  for (const std::string& w : surface.Warnings)
  {
    warnings.push_back("Surface: " + w);
  }
  if (surface.Check.HasErrors())
  {
    error = "The surface is unfit for BoolSurf:\n" + surface.Check.ErrorSummary();
    return nullptr;
  }
  return &surface;
}

//------------------------------------------------------------------------------
vtkStaticCellLocator* vtkSurfaceCache::GetLocator()
{
  if (!this->Locator)
  {
    this->Locator = vtkSmartPointer<vtkStaticCellLocator>::New();
    this->Locator->SetDataSet(this->Surface.Triangles);
    this->Locator->BuildLocator();
  }
  return this->Locator;
}

//------------------------------------------------------------------------------
CurveTracer& vtkSurfaceCache::GetTracer()
{
  if (!this->Tracer)
  {
    this->Tracer = std::make_unique<CurveTracer>(*this->Surface.Mesh);
  }
  return *this->Tracer;
}

} // namespace boolsurf

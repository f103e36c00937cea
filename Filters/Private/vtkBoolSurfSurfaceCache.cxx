#include "vtkBoolSurfSurfaceCache.h"

#include "Homology/GeneratorShortening.h"
#include "Homology/HomologyBasis.h"

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

//------------------------------------------------------------------------------
const HomologyBasis* vtkSurfaceCache::GetHomology(std::string& error)
{
  const TriangleMesh* mesh = this->Surface.Mesh.get();
  if (!mesh || !this->Surface.Topology)
  {
    error = "no surface to compute homology generators on";
    return nullptr;
  }
  if (!this->Homology || this->Homology->GetMeshSerial() != mesh->GetSerial())
  {
    this->Homology = std::make_unique<HomologyBasis>();
    this->HomologyError.clear();
    this->ShortGenerators.clear();
    this->HasShortGenerators = false;
    if (!this->Homology->Compute(
          *mesh, *this->Surface.Topology, HomologyOptions(), this->HomologyError))
    {
      // Keep the failed basis (its serial marks the mesh) so the error is not recomputed.
      this->HomologyError = "homology generators: " + this->HomologyError;
    }
  }
  if (!this->HomologyError.empty())
  {
    error = this->HomologyError;
    return nullptr;
  }
  return this->Homology.get();
}

//------------------------------------------------------------------------------
const std::vector<TracedCurve>* vtkSurfaceCache::GetShortenedGenerators()
{
  std::string error;
  const HomologyBasis* basis = this->GetHomology(error);
  if (!basis || basis->GetNumberOfGenerators() == 0)
  {
    return nullptr;
  }
  if (!this->HasShortGenerators)
  {
    this->ShortGenerators.assign(basis->GetNumberOfGenerators(), TracedCurve());
    for (int g = 0; g < basis->GetNumberOfGenerators(); ++g)
    {
      if (!ShortenGenerator(
            *this->Surface.Mesh, *basis, g, this->GetTracer(), this->ShortGenerators[g]))
      {
        this->ShortGenerators[g] = TracedCurve();
      }
    }
    this->HasShortGenerators = true;
  }
  return &this->ShortGenerators;
}

} // namespace boolsurf

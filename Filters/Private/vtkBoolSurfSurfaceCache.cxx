#include "vtkBoolSurfSurfaceCache.h"

#include "Homology/GeneratorShortening.h"
#include "Homology/HomologyBasis.h"

#include "Geodesic/CurveTracer.h"
#include "Mesh/ClosestTriangleGrid.h"
#include "Offset/OffsetRegionOfCells.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStaticCellLocator.h>

#include <cstdint>
#include <map>
#include <mutex>
#include <thread>
#include <tuple>

namespace boolsurf
{
namespace
{

/// What a converted surface was made from: the input object and its modification time (as
/// each cache checks), its point and polygon arrays and sizes (so that an address reused by
/// another object cannot be mistaken for it), and the conversion's tolerance.
struct SurfaceKey
{
  const void* Input = nullptr;
  vtkMTimeType Time = 0;
  const void* Points = nullptr;
  const void* Polys = nullptr;
  vtkIdType NumberOfPoints = 0, NumberOfCells = 0;
  double Tolerance = 0;

  SurfaceKey(vtkPolyData* input, double tolerance)
    : Input(input)
    , Time(input ? input->GetMTime() : 0)
    , Points(input && input->GetPoints() ? input->GetPoints()->GetData() : nullptr)
    , Polys(input ? input->GetPolys() : nullptr)
    , NumberOfPoints(input ? input->GetNumberOfPoints() : 0)
    , NumberOfCells(input ? input->GetNumberOfCells() : 0)
    , Tolerance(tolerance)
  {
  }
  bool operator<(const SurfaceKey& o) const
  {
    return std::tie(Input, Time, Points, Polys, NumberOfPoints, NumberOfCells, Tolerance) <
      std::tie(o.Input, o.Time, o.Points, o.Polys, o.NumberOfPoints, o.NumberOfCells, o.Tolerance);
  }
};

/// Converted surfaces in use by some cache, by what they were made from. Entries are weak: a
/// surface lives as long as a cache holds it, and an entry whose surface died is dropped on the
/// next lookup. Filters update on any thread of a pipeline, hence the mutex.
std::mutex& SharedSurfacesMutex()
{
  static std::mutex mutex;
  return mutex;
}

std::map<SurfaceKey, std::weak_ptr<const vtkSurfaceInput>>& SharedSurfaces()
{
  static std::map<SurfaceKey, std::weak_ptr<const vtkSurfaceInput>> surfaces;
  return surfaces;
}

std::shared_ptr<const vtkSurfaceInput> ConvertedSurface(vtkPolyData* input,
  const SurfaceCheckOptions& options)
{
  const SurfaceKey key(input, options.DegenerateTolerance);
  {
    std::lock_guard<std::mutex> lock(SharedSurfacesMutex());
    auto& all = SharedSurfaces();
    for (auto it = all.begin(); it != all.end();)
    {
      it = it->second.expired() ? all.erase(it) : std::next(it);
    }
    auto found = all.find(key);
    if (found != all.end())
    {
      if (auto surface = found->second.lock())
      {
        return surface;
      }
    }
  }
  auto surface = std::make_shared<vtkSurfaceInput>();
  ConvertSurface(input, *surface, options); // outside the lock: it may take a second
  std::lock_guard<std::mutex> lock(SharedSurfacesMutex());
  SharedSurfaces()[key] = surface;
  return surface;
}

/// The tracers in use on each converted surface, per thread: filters on one surface share the
/// tracer of the thread they update on (a tracer is used by one thread at a time; VTK's
/// pipelines update a chain's filters on one thread). Entries are weak, as SharedSurfaces'; a
/// tracer lives as long as a cache holds it, and every cache holding it holds its surface.
struct TracerKey
{
  const vtkSurfaceInput* Surface = nullptr;
  std::uint64_t MeshSerial = 0;
  std::thread::id Thread;
  bool operator<(const TracerKey& o) const
  {
    return std::tie(Surface, MeshSerial, Thread) < std::tie(o.Surface, o.MeshSerial, o.Thread);
  }
};

std::map<TracerKey, std::weak_ptr<CurveTracer>>& SharedTracers()
{
  static std::map<TracerKey, std::weak_ptr<CurveTracer>> tracers;
  return tracers;
}

std::shared_ptr<CurveTracer> SharedTracer(const vtkSurfaceInput& surface)
{
  const TracerKey key{ &surface, surface.Mesh->GetSerial(), std::this_thread::get_id() };
  std::lock_guard<std::mutex> lock(SharedSurfacesMutex());
  auto& all = SharedTracers();
  for (auto it = all.begin(); it != all.end();)
  {
    it = it->second.expired() ? all.erase(it) : std::next(it);
  }
  if (auto found = all.find(key); found != all.end())
  {
    if (auto tracer = found->second.lock())
    {
      return tracer;
    }
  }
  // The solver's triangle components are the topology's, shared.
  auto tracer = std::make_shared<CurveTracer>(*surface.Mesh,
    surface.Topology ? std::make_shared<TriangleComponents>(surface.Topology) : nullptr);
  all[key] = tracer;
  return tracer;
}

} // namespace

vtkSurfaceCache::vtkSurfaceCache()
  : Surface(std::make_shared<vtkSurfaceInput>())
{
}

vtkSurfaceCache::~vtkSurfaceCache() = default;

//------------------------------------------------------------------------------
const vtkSurfaceInput& vtkSurfaceCache::Get(vtkPolyData* input,
  const SurfaceCheckOptions& options,
  bool& rebuilt)
{
  const vtkMTimeType time = input ? input->GetMTime() : 0;
  rebuilt = !this->Surface->Mesh || input != this->Input || time != this->InputTime ||
    options.DegenerateTolerance != this->Tolerance;
  if (rebuilt)
  {
    // What was built on the old surface goes first: the tracer refers to its mesh.
    this->Locator = nullptr;
    this->Closest.reset();
    this->Tracer.reset();
    this->Offset.reset();
    this->Surface = ConvertedSurface(input, options);
    this->Input = input;
    this->InputTime = time;
    this->Tolerance = options.DegenerateTolerance;
  }
  return *this->Surface;
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
    this->Locator->SetDataSet(this->Surface->Triangles);
    this->Locator->BuildLocator();
  }
  return this->Locator;
}

//------------------------------------------------------------------------------
const ClosestTriangleGrid& vtkSurfaceCache::GetClosestTriangles()
{
  if (!this->Closest)
  {
    this->Closest = std::make_unique<ClosestTriangleGrid>(*this->Surface->Mesh);
  }
  return *this->Closest;
}

//------------------------------------------------------------------------------
OffsetWorkspace& vtkSurfaceCache::GetOffsetWorkspace()
{
  if (!this->Offset)
  {
    this->Offset = std::make_unique<OffsetWorkspace>(*this->Surface->Mesh);
  }
  return *this->Offset;
}

//------------------------------------------------------------------------------
CurveTracer& vtkSurfaceCache::GetTracer()
{
  if (!this->Tracer || this->TracerThread != std::this_thread::get_id())
  {
    this->Tracer = SharedTracer(*this->Surface);
    this->TracerThread = std::this_thread::get_id();
  }
  return *this->Tracer;
}

//------------------------------------------------------------------------------
const HomologyBasis* vtkSurfaceCache::GetHomology(std::string& error)
{
  const TriangleMesh* mesh = this->Surface->Mesh.get();
  if (!mesh || !this->Surface->Topology)
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
          *mesh, *this->Surface->Topology, HomologyOptions(), this->HomologyError))
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
    // Always with the default method, whatever the tracer was last used for: the loops are
    // computed once per surface and must not depend on which filter asked first.
    GeodesicPathSolver& solver = this->GetTracer().GetPathSolver();
    const GeodesicPathOptions saved = solver.GetOptions();
    GeodesicPathOptions bounded = saved;
    bounded.Method = GeodesicMethod::Bounded;
    solver.SetOptions(bounded);
    this->ShortGenerators.assign(basis->GetNumberOfGenerators(), TracedCurve());
    for (int g = 0; g < basis->GetNumberOfGenerators(); ++g)
    {
      if (!ShortenGenerator(
            *this->Surface->Mesh, *basis, g, this->GetTracer(), this->ShortGenerators[g]))
      {
        this->ShortGenerators[g] = TracedCurve();
      }
    }
    solver.SetOptions(saved);
    this->HasShortGenerators = true;
  }
  return &this->ShortGenerators;
}

} // namespace boolsurf

// Per-filter cache of the converted input surface (a private header of the module).
//
// Building the triangle mesh, its adjacency (the dual graph of adjacencies) and topology is
// the one cost that grows with the mesh; while only the curves or the filter's properties
// change, the surface input keeps its identity and modification time, and every stage
// reuses what it built before, so edits cost time proportional to the curves. The converted
// surface itself (immutable) is shared by every filter whose input is the same unmodified
// surface, as the stages of a chain are: one copy of the mesh in memory, converted once, and
// the mesh a stage reads is the one the stage before it just read (still in the CPU's caches).
#ifndef vtkBoolSurfSurfaceCache_h
#define vtkBoolSurfSurfaceCache_h

#include "Geodesic/TracedCurve.h"
#include "vtkBoolSurfSurfaceAdapter.h"

#include <vtkSmartPointer.h>
#include <vtkType.h>

#include <memory>
#include <thread>

class vtkStaticCellLocator;

namespace boolsurf
{

class ClosestTriangleGrid;
class CurveTracer;
class HomologyBasis;
struct OffsetWorkspace;

class vtkSurfaceCache
{
public:
  vtkSurfaceCache();
  ~vtkSurfaceCache();

  /// The converted surface for `input`, rebuilt only when the input object, its modification
  /// time or the options changed. `rebuilt` tells which happened.
  const vtkSurfaceInput& Get(vtkPolyData* input, const SurfaceCheckOptions& options, bool& rebuilt);

  /// Get() for the stages that need a valid surface: conversion notes go to `warnings`; when
  /// the surface is unfit, returns null with every problem in `error`.
  const vtkSurfaceInput* GetUsable(vtkPolyData* input,
    std::vector<std::string>& warnings,
    std::string& error);

  /// The result of the last Get().
  const vtkSurfaceInput& GetCurrent() const { return *this->Surface; }

  /// Closest-cell locator on the triangles of the last Get() (built on first use).
  vtkStaticCellLocator* GetLocator();

  /// Closest point of the mesh of the last Get() to a point of space (built on first use):
  /// projecting control points and centers given by coordinates, at every edit.
  const ClosestTriangleGrid& GetClosestTriangles();

  /// Curve tracer on the mesh of the last Get() (built on first use; its geodesic search
  /// state is reused by every path). Shared by every cache of the same converted surface on
  /// the same thread: Surface Curves traces its display port, then Trace Surface Curves or
  /// the one-step filter traces the same curves and recalls them from the tracer's memory
  /// instead of tracing them again, and the search states exist once. Each user sets the
  /// method and resolution it traces with (the memory keys curves by every setting).
  CurveTracer& GetTracer();

  /// What offsets reuse on the mesh of the last Get() (distance searches, the arrangement of the
  /// offset shapes), built on first use.
  OffsetWorkspace& GetOffsetWorkspace();

  /// Homology generators of the mesh of the last Get(), computed on first use and kept while
  /// the surface is the same (null with the reason in `error` when they cannot be computed).
  const HomologyBasis* GetHomology(std::string& error);

  /// Per generator of GetHomology(), its locally shortest loop for display (empty Points when
  /// it could not be shortened within its class); computed on first use. Null when there are
  /// no generators.
  const std::vector<TracedCurve>* GetShortenedGenerators();

private:
  std::unique_ptr<HomologyBasis> Homology;
  std::vector<TracedCurve> ShortGenerators;
  bool HasShortGenerators = false;
  std::string HomologyError;
  vtkPolyData* Input = nullptr; // identity only, never dereferenced
  vtkMTimeType InputTime = 0;
  double Tolerance = -1;
  /// Shared with the other caches of the same surface (see the .cxx); never null.
  std::shared_ptr<const vtkSurfaceInput> Surface;
  vtkSmartPointer<vtkStaticCellLocator> Locator;
  std::unique_ptr<ClosestTriangleGrid> Closest;
  std::shared_ptr<CurveTracer> Tracer; ///< shared (see GetTracer)
  std::thread::id TracerThread;
  std::unique_ptr<OffsetWorkspace> Offset;
};

} // namespace boolsurf

#endif

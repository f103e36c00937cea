// The resolution of inconsistent shapes on VTK data, shared by vtkBoolSurfResolve and the
// one-step vtkBoolSurf filter (a private header of the module).
#ifndef vtkBoolSurfResolveStage_h
#define vtkBoolSurfResolveStage_h

#include "Homology/ShapeResolution.h"
#include "vtkBoolSurfSurfaceCache.h"
#include "vtkBoolSurfTraceStage.h"

#include <map>
#include <string>
#include <vector>

class vtkPolyData;

namespace boolsurf
{

struct ResolveStageOptions
{
  ResolveStrategy Strategy = ResolveStrategy::DuplicateReversed; ///< for every shape...
  std::map<int, ResolveStrategy> PerShape;                       ///< ...but these
  double Offset = 0;                                             ///< DuplicateReversed; 0: auto
  /// How the curves are traced to find their homology classes (Threads is not used).
  TraceOptions Trace;
};

/// Parses "3:RemoveCurves, S5=AddGenerators; 7:1" (ShapeId, then a strategy name or number)
/// into `out`. False with a message naming the entry that cannot be read.
bool ParseShapeStrategies(const std::string& text,
  std::map<int, ResolveStrategy>& out,
  std::string& error);

/// Reads the control curves of `curves` (the input of TraceSurfaceCurves) on the cached surface,
/// resolves every shape with generators in excess and writes the control curves to `output`:
/// one polyline per curve (closed ones repeat their first point), point data TriangleId and
/// Barycentric, cell data ShapeId, CurveType, Closed, `Resolution` (ResolutionAction),
/// `ResolutionSource` (input curve id, or generator id for added generators),
/// `ResolutionReason` (text), field data `RemovedCurves`, `TreatedShapes`, `ResolutionNotes`.
/// False with the problems (curve and point ids named) in `error`.
bool ResolveControlCurves(vtkSurfaceCache& cache,
  vtkPolyData* curves,
  const ResolveStageOptions& options,
  vtkPolyData* output,
  std::vector<std::string>& notes,
  std::string& error);

} // namespace boolsurf

#endif

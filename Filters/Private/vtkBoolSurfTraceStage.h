// The tracing stage on VTK data, shared by vtkBoolSurfTraceCurves and the one-step vtkBoolSurf
// filter (a private header of the module).
#ifndef vtkBoolSurfTraceStage_h
#define vtkBoolSurfTraceStage_h

#include "Geodesic/CurveTracer.h"
#include "Geodesic/TraceOptions.h"
#include "Selection/BoundaryControlPoints.h"
#include "vtkBoolSurfControlCurves.h"
#include "vtkBoolSurfSurfaceCache.h"

#include <string>
#include <vector>

class vtkAlgorithm;
class vtkFieldData;
class vtkPolyData;

namespace boolsurf
{

/// Traces every curve of `controlCurves` on the cached surface. On success fills `traced`
/// (for the arrangement) and, when `output` is not null, writes the traced polylines. On
/// failure returns false with every problem in `problems` (curve and point ids named).
/// `sources` (may be null) receives each curve's control points and the curve parameter of
/// each traced point, for results given back as control points.
/// `progress` (may be null) receives progress updates in [0, 1] and is checked for aborts.
/// `controls` (may be null) receives the control curves as read.
bool TraceControlCurves(vtkSurfaceCache& cache,
  vtkPolyData* controlCurves,
  const TraceOptions& options,
  vtkAlgorithm* progress,
  std::vector<TracedCurve>& traced,
  vtkPolyData* output,
  std::vector<std::string>& problems,
  std::vector<std::string>& notes,
  std::vector<CurveSource>* sources = nullptr,
  std::vector<InputControlCurve>* controls = nullptr);

/// The tracing half of TraceControlCurves, for curves already read (or held, as Surface Curves
/// holds its drawing): `problems` may already hold the reading's problems, which fail it too.
bool TraceInputCurves(vtkSurfaceCache& cache,
  const std::vector<InputControlCurve>& controls,
  const TraceOptions& options,
  vtkAlgorithm* progress,
  std::vector<TracedCurve>& traced,
  vtkPolyData* output,
  std::vector<std::string>& problems,
  std::vector<CurveSource>* sources = nullptr);

/// The traced polylines of `traces`, traced from `controls`, written into `output` as Trace
/// Surface Curves writes them. `mesh` null (tracing on pieces, where no rank holds the
/// surface): every trace carries its written forms (CurveTrace::Positions and Written, a
/// control point's in its own triangle) and only their count is read of Curve.Points.
void WriteTracedCurves(const TriangleMesh* mesh,
  const std::vector<InputControlCurve>& controls,
  const std::vector<CurveTrace>& traces,
  vtkPolyData* output);

/// ReadControlCurves on the cached surface: control points projected with its locator, no
/// farther than options.ProjectionTolerance times its bounding-box diagonal.
void ReadSurfaceControlCurves(vtkSurfaceCache& cache,
  vtkPolyData* controlCurves,
  const TraceOptions& options,
  std::vector<InputControlCurve>& controls,
  std::vector<std::string>& problems,
  std::vector<std::string>& notes);

/// Field array "GeodesicSiteGraph" (components Sites, BuildMilliseconds, MemoryMB,
/// BuildNumber): the per-surface structure of the Bounded geodesic method, once a far leg has
/// built it for `mesh`; nothing before. BuildNumber changes only when the graph is rebuilt
/// (the surface changed), never when only the curves do.
void AddSiteGraphField(const TriangleMesh& mesh, vtkFieldData* fieldData);

/// How the user knows traced point `point` of `curves[curve]`: "curve 3 (input CurveId 7) of
/// shape 1, between its control points 4 and 5 (traced point 21)", from the control points and
/// parameters in `sources` (as TraceControlCurves fills them; without them only the curve is
/// named). For messages of later stages that refuse a point.
std::string DescribeCurvePoint(const std::vector<TracedCurve>& curves,
  const std::vector<CurveSource>& sources,
  int curve,
  int point);

} // namespace boolsurf

#endif

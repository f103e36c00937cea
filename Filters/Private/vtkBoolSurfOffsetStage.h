// Geodesic offsets on VTK data, shared by vtkBoolSurfOffset ("Offset Shapes") and the one-step
// vtkBoolSurf filter's OffsetShape option (a private header of the module).
#ifndef vtkBoolSurfOffsetStage_h
#define vtkBoolSurfOffsetStage_h

#include "Geodesic/GeodesicPath.h"
#include "Offset/GeodesicOffset.h"
#include "vtkBoolSurfSurfaceCache.h"
#include "vtkBoolSurfTraceStage.h"

#include <string>
#include <vector>

class vtkPolyData;

namespace boolsurf
{

struct OffsetStageOptions
{
  double Distance = 0.0;
  /// What is offset: this Boolean expression over the shapes (e.g. "S0 | S2 - S1") when not
  /// empty, else the union of `Shapes`, else of every shape.
  std::string Expression;
  std::vector<int> Shapes;
  int FillRule = 0;
  /// Bands around every curve of those shapes (closed ones too) instead of their region.
  bool Bands = false;
  OffsetEndStyle Ends = OffsetEndStyle::Round;
  int OutputResolution = 0; ///< points on the offset curve inside each crossed triangle
  int OutputShapeId = -1;   ///< -1: one above the largest input ShapeId
  bool KeepInputCurves = true;
  /// With KeepInputCurves: leave out the curves of the offset shapes (the offset replaces
  /// them; the one-step filter's OffsetShape).
  bool ReplaceShapes = false;
  /// Tracing of the input curves, as in Trace Surface Curves (its Threads: the arrangement's
  /// too).
  TraceOptions Trace;
};

/// Reads and traces the control curves of `curves` (the input of Trace Surface Curves; without
/// a ShapeId array all its curves are one shape, so a Boolean's or BSC's Boundary output is
/// offset as the region it bounds) on the cached surface, offsets the requested region (or bands)
/// by Distance and writes control curves to `output` in the same form: the kept input curves, then
/// the offset loops as geodesic polygons of exact surface points (point data
/// TriangleId/Barycentric; cell data ShapeId, CurveType, Closed, OffsetCurve = 1 for offset loops,
/// 0 for input curves), field data OffsetDistance, OffsetShapeId, OffsetExpression and
/// OffsetStatistics. False with a named error: unknown shape id, malformed expression, inconsistent
/// shape, a negative distance larger than the shape, a non-finite distance.
bool OffsetControlCurves(vtkSurfaceCache& cache,
  vtkPolyData* curves,
  const OffsetStageOptions& options,
  vtkPolyData* output,
  std::vector<std::string>& notes,
  std::string& error);

} // namespace boolsurf

#endif

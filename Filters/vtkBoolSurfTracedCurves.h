// Reading of traced curves (the output of vtkBoolSurfTraceCurves, or any polylines with
// `TriangleId`/`Barycentric` point data) into Core's TracedCurve (a private header).
#ifndef vtkBoolSurfTracedCurves_h
#define vtkBoolSurfTracedCurves_h

#include "TracedCurve.h"

#include <string>
#include <vector>

class vtkPolyData;

namespace boolsurf
{

/// One TracedCurve per line/polygon cell. Cell data `ShapeId` (default: cell id), `CurveId`
/// (default: cell id) and `Closed` (default: polygon cells and polylines whose last point id
/// repeats the first). Returns false with messages naming the curve and point ids.
bool ReadTracedCurves(vtkPolyData* curves,
  const TriangleMesh& mesh,
  std::vector<TracedCurve>& out,
  std::vector<std::string>& problems);

} // namespace boolsurf

#endif

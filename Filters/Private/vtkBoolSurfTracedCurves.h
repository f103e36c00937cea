// Reading of traced curves (the output of vtkBoolSurfTraceCurves, or any polylines with
// `TriangleId`/`Barycentric` point data) into Core's TracedCurve (a private header).
#ifndef vtkBoolSurfTracedCurves_h
#define vtkBoolSurfTracedCurves_h

#include "Geodesic/TracedCurve.h"

#include <vtkType.h>

#include <functional>
#include <string>
#include <vector>

class vtkPolyData;

namespace boolsurf
{

/// Calls `visit` for every line and polygon cell of `curves` (the cells that are curves), in
/// cell-id order, with the cell's vtkPolyData id and point ids; `polygon` tells the two apart.
void ForEachCurveCell(vtkPolyData* curves,
  const std::function<void(vtkIdType cellId, vtkIdType n, const vtkIdType* ids, bool polygon)>&
    visit);

/// One TracedCurve per line/polygon cell. Cell data `ShapeId` (default: cell id), `CurveId`
/// (default: cell id) and `Closed` (default: polygon cells and polylines whose last point id
/// repeats the first). Returns false with messages naming the curve and point ids.
bool ReadTracedCurves(vtkPolyData* curves,
  const TriangleMesh& mesh,
  std::vector<TracedCurve>& out,
  std::vector<std::string>& problems);

} // namespace boolsurf

#endif

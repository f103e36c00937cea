// Reading of the "control polygons" input of vtkBoolSurfTraceCurves (a private header of the
// module): one polyline or polygon cell per curve, cell data `ShapeId` and `CurveType`,
// points either projected onto the surface or given exactly as `TriangleId`/`Barycentric`
// point data.
#ifndef vtkBoolSurfControlCurves_h
#define vtkBoolSurfControlCurves_h

#include "Geodesic/CurveTracer.h" // for CurveType
#include "Mesh/ClosestTriangleGrid.h"
#include "Mesh/SurfacePoint.h"

#include <functional>
#include <string>
#include <vector>

class vtkPolyData;

namespace boolsurf
{

struct ControlCurve
{
  int CurveId = -1; ///< cell id in the curves input
  /// The input's own cell data `CurveId` for this cell (a scene's polygon index), for messages;
  /// -1 when the input has none.
  long long InputCurveId = -1;
  int ShapeId = 0;
  CurveType Type = CurveType::GeodesicPolygon;
  bool Closed = false;
  std::vector<SurfacePoint> Points; ///< the closing point of a closed curve is not repeated
  std::vector<long long> PointIds;  ///< input point id of each control point
};

struct ControlCurveOptions
{
  /// Largest allowed distance from a control point to the surface, absolute.
  double MaximumDistance = 0;
};

/// Reads every line and polygon cell of `curves` (vertex cells and strips are ignored with a
/// note in `notes`). Each problem met (named by curve id and point id) is appended to
/// `problems`; the curve it concerns is left out of `out`. `closest` gives the closest-point
/// grid of `mesh`; it is asked for only when a control point must be projected, so curves
/// given exactly never build one.
void ReadControlCurves(vtkPolyData* curves,
  const std::function<const ClosestTriangleGrid&()>& closest,
  const TriangleMesh& mesh,
  const ControlCurveOptions& options,
  std::vector<ControlCurve>& out,
  std::vector<std::string>& problems,
  std::vector<std::string>& notes);

} // namespace boolsurf

#endif

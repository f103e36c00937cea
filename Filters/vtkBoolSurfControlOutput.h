// Results given back as control curves (a private header of the module): the sub-curves of
// Core's BoundaryControlPoints written as polydata in the control-curves format that
// vtkBoolSurfTraceCurves reads, so they can be traced again, saved as a scene or edited.
#ifndef vtkBoolSurfControlOutput_h
#define vtkBoolSurfControlOutput_h

#include "Selection/BoundaryControlPoints.h"

#include <functional>
#include <vector>

class vtkPolyData;

namespace boolsurf
{

/// One polyline per sub-curve (a whole closed curve repeats its first point), point data
/// TriangleId and Barycentric (exact surface points) and 3D points; cell data ShapeId (0 for
/// boundary pieces, which together bound one region; the source shape for clipped pieces),
/// CurveType, Closed, SourceCurveId, SourceShapeId, Reversed, ParameterRange (the source
/// curve's parameters, segment index + fraction) and `groupName` (BoundaryLoop or
/// ClippedPiece) holding each sub-curve's Group.
void WriteControlSubCurves(const std::function<Vec3(const SurfacePoint&)>& position,
  const std::vector<ControlSubCurve>& curves,
  const char* groupName,
  bool boundary,
  vtkPolyData* output);

} // namespace boolsurf

#endif

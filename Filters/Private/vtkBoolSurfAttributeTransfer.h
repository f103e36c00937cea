// Carries the input surface's own point and cell arrays onto a refined surface (a private
// header of the module): cell data is copied from each refined triangle's source triangle,
// point data is interpolated with each refined point's barycentric coordinates in its source
// triangle. Users keep their scalars (curvature, thickness, labels, ...) through BoolSurf.
#ifndef vtkBoolSurfAttributeTransfer_h
#define vtkBoolSurfAttributeTransfer_h

#include "Mesh/SurfacePoint.h"

#include <vtkType.h>

#include <array>
#include <functional>
#include <vector>

class vtkPolyData;

namespace boolsurf
{

/// `source` is the triangulated input surface (cell ids = mesh triangle ids); `target` gets
/// its point data (numberOfPoints tuples, point p interpolated at pointSurface(p)) and cell
/// data (one tuple per entry of sourceTriangle). Arrays whose names are in `skip` are not
/// carried (names BoolSurf writes). pointSurface is called only when the source has arrays to
/// carry.
void TransferSurfaceAttributes(vtkPolyData* source,
  const TriangleMesh& mesh,
  vtkIdType numberOfPoints,
  const std::function<SurfacePoint(vtkIdType)>& pointSurface,
  const std::vector<int>& sourceTriangle,
  vtkPolyData* target);

} // namespace boolsurf

#endif

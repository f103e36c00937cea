// What Surface Arrangement writes on its refined surface so that the arrangement can be
// computed again where no Core result travels with the data (a file, a deep copy): the writer
// side of vtkBoolSurfArrangementRebuild.h (a private header of the module).
//
// The refined surface's first points are the mesh's vertices, in order, and every mesh
// triangle the curves leave whole keeps its corners (refined triangle t is mesh triangle t):
// the writer adds only the corners of the triangles the curves cross (and of unusable ones,
// left out of the refined surface) and the traced curves, O(curves + crossed triangles) per
// edit.
#ifndef vtkBoolSurfArrangementRebuildWriter_h
#define vtkBoolSurfArrangementRebuildWriter_h

#include "Arrangement/Arrangement.h"
#include "Geodesic/GeodesicPath.h"
#include "Selection/BoundaryControlPoints.h"

#include <vector>

class vtkFieldData;

namespace boolsurf
{

/// Field data names::Arranged* of port 0 (vtkBoolSurfArrayNames.h): what
/// RebuildArrangement needs besides the refined surface's own arrays.
void WriteRebuildFields(const TriangleMesh& mesh,
  const Arrangement& arrangement,
  const std::vector<TracedCurve>& curves,
  const std::vector<CurveSource>& sources,
  GeodesicMethod method,
  vtkFieldData* fd);

} // namespace boolsurf

#endif

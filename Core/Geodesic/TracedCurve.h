// A curve traced on a triangle mesh: the hand-off between the tracing stage and the
// arrangement.
//
// The tracing stage emits one polyline per input curve whose vertices are canonical surface
// points (a mesh vertex, a point on a mesh edge, or a point strictly inside a triangle), with a
// vertex wherever the curve crosses a mesh edge. So every segment between consecutive points
// lies inside one triangle (possibly along one of its edges), and the arrangement never has to
// search the mesh.
#ifndef boolsurf_TracedCurve_h
#define boolsurf_TracedCurve_h

#include "Mesh/SurfacePoint.h"

#include <vector>

namespace boolsurf
{

struct TracedCurve
{
  /// Consecutive points always share at least one triangle. A closed curve does not repeat its
  /// first point at the end.
  std::vector<CanonicalPoint> Points;
  /// Closed curves bound cells; open curves are refined into the mesh (and split where they
  /// cross other curves) but do not separate cells.
  bool Closed = true;
  int ShapeId = 0; ///< >= 0
  int CurveId = 0; ///< index of the curve in the user's input, reported back in patches
};

} // namespace boolsurf

#endif

// How a traced curve's points are written into output arrays (triangle + barycentric), decided
// in one place: by Trace Surface Curves, by the tracer's memory of traced curves (so that an
// edit that keeps a curve writes it by copying) and by any writer of curve points.
#ifndef boolsurf_WrittenCurvePoints_h
#define boolsurf_WrittenCurvePoints_h

#include "Geodesic/TracedCurve.h"

#include <cstddef>

namespace boolsurf
{

struct CurveTrace;

/// Point i of `curve` as output arrays write it: canonically (WriteSurfacePoint), in `preferred`
/// when that triangle holds the point (a control point's own triangle), else in a triangle it
/// shares with the next point of the curve (the previous one at an open curve's end), so a
/// reader finds consecutive points in a common triangle.
SurfacePoint WrittenCurvePoint(const TriangleMesh& mesh,
  const TracedCurve& curve,
  std::size_t i,
  int preferred = -1);

/// Fills trace.Positions and trace.Written for every point of trace.Curve (WrittenCurvePoint
/// with no preferred triangle: a writer that knows a control point's own triangle writes that
/// point again).
void ComputeWrittenForms(const TriangleMesh& mesh, CurveTrace& trace);

} // namespace boolsurf

#endif

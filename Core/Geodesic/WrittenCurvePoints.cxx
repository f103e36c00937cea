#include "Geodesic/WrittenCurvePoints.h"

#include "Geodesic/CurveTracer.h"

namespace boolsurf
{

//------------------------------------------------------------------------------
SurfacePoint WrittenCurvePoint(const TriangleMesh& mesh,
  const TracedCurve& curve,
  std::size_t i,
  int preferred)
{
  const CanonicalPoint& p = curve.Points[i];
  const std::size_t n = curve.Points.size();
  // A face point has one form; the others go where their neighbour is, unless the caller
  // names a triangle that holds them.
  if (p.Location != PointLocation::Face && n > 1 &&
    !(preferred >= 0 && TriangleContains(mesh, p, preferred)))
  {
    const std::size_t next = i + 1 < n ? i + 1 : (curve.Closed ? 0 : i - 1);
    preferred = SharedTriangle(mesh, p, curve.Points[next]);
  }
  return WriteSurfacePoint(mesh, p, preferred);
}

//------------------------------------------------------------------------------
void ComputeWrittenForms(const TriangleMesh& mesh, CurveTrace& trace)
{
  const std::size_t n = trace.Curve.Points.size();
  trace.Positions.resize(n);
  trace.Written.resize(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    trace.Positions[i] = PositionOf(mesh, trace.Curve.Points[i]);
    trace.Written[i] = WrittenCurvePoint(mesh, trace.Curve, i);
  }
}

} // namespace boolsurf

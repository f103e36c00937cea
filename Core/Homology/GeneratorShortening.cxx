#include "Homology/GeneratorShortening.h"

#include <algorithm>

namespace boolsurf
{

//------------------------------------------------------------------------------
double TracedLength(const TriangleMesh& mesh, const TracedCurve& curve)
{
  const size_t n = curve.Points.size();
  double length = 0;
  for (size_t i = 0; i + (curve.Closed ? 0 : 1) < n; ++i)
  {
    length +=
      Distance(PositionOf(mesh, curve.Points[i]), PositionOf(mesh, curve.Points[(i + 1) % n]));
  }
  return length;
}

//------------------------------------------------------------------------------
bool ShortenGenerator(const TriangleMesh& mesh,
  const HomologyBasis& basis,
  int g,
  CurveTracer& tracer,
  TracedCurve& out,
  int passes)
{
  const HomologyGenerator& gen = basis.GetGenerator(g);
  const int n = static_cast<int>(gen.Points.size());
  if (n < 3)
  {
    return false;
  }
  // Corners a few triangles apart along the loop: the shortest path between two of them stays
  // near the loop.
  const int corners = std::max(3, std::min(n, n / 6));
  std::vector<SurfacePoint> control;
  for (int k = 0; k < corners; ++k)
  {
    control.push_back(ToSurfacePoint(mesh, gen.Points[static_cast<size_t>(k) * n / corners]));
  }
  std::vector<int> unit(basis.GetNumberOfGenerators(), 0), h;
  unit[g] = 1;
  std::string error;
  CurveTrace trace;
  TracedCurve best;
  for (int pass = 0; pass <= passes; ++pass)
  {
    if (!tracer.Trace(control, CurveType::GeodesicPolygon, true, trace, error))
    {
      break;
    }
    trace.DropRepeatedClosingPoint();
    if (!basis.ClassOf(trace.Curve, h, error) || h != unit)
    {
      break; // left the class: keep the last good loop
    }
    best = trace.Curve;
    // Next corners: the middle traced point of each side.
    std::vector<SurfacePoint> next;
    const size_t m = trace.Curve.Points.size();
    for (int side = 0; side < static_cast<int>(control.size()); ++side)
    {
      size_t first = m, last = 0;
      for (size_t i = 0; i < m; ++i)
      {
        if (trace.Segment[i] == side)
        {
          first = std::min(first, i);
          last = std::max(last, i);
        }
      }
      if (first < m)
      {
        next.push_back(ToSurfacePoint(mesh, trace.Curve.Points[(first + last + 1) / 2 % m]));
      }
    }
    if (next.size() < 3)
    {
      break;
    }
    control = next;
  }
  if (best.Points.empty())
  {
    return false;
  }
  out = best;
  out.Closed = true;
  return true;
}

} // namespace boolsurf

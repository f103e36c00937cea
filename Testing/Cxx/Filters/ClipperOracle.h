// Clipper (libpolyclipping-dev) as the independent 2D oracle of the flat-mesh tests: control
// polygons in Clipper's integer coordinates, and areas of its results.
#ifndef ClipperOracle_h
#define ClipperOracle_h

#include "FilterTestUtils.h"

#include <polyclipping/clipper.hpp>

#include <cmath>
#include <random>

namespace testutils
{

// Polygon vertices lie on a dyadic grid so Clipper's integer input is exact; 2^40 keeps its
// rounded intersection points within ~1e-12 of the true ones.
constexpr double ClipperScale = 1099511627776.0; // 2^40

inline ClipperLib::IntPoint ToClipper(double x, double y)
{
  return { static_cast<ClipperLib::cInt>(std::llround(x * ClipperScale)),
    static_cast<ClipperLib::cInt>(std::llround(y * ClipperScale)) };
}

inline ClipperLib::Path ToClipper(const ControlPolygon& p)
{
  ClipperLib::Path path;
  for (const auto& x : p.Points)
  {
    path.push_back(ToClipper(x[0], x[1]));
  }
  return path;
}

inline double ClipperArea(const ClipperLib::Paths& paths)
{
  double area = 0;
  for (const auto& p : paths)
  {
    area += ClipperLib::Area(p);
  }
  return area / (ClipperScale * ClipperScale);
}

/// Area of `op` between two polygons (non-zero fill).
inline double ClipperResultArea(const ControlPolygon& a,
  const ControlPolygon& b,
  ClipperLib::ClipType op)
{
  ClipperLib::Clipper clipper;
  clipper.AddPath(ToClipper(a), ClipperLib::ptSubject, true);
  clipper.AddPath(ToClipper(b), ClipperLib::ptClip, true);
  ClipperLib::Paths solution;
  clipper.Execute(op, solution, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  return ClipperArea(solution);
}

/// A random polygon of 3 to 7 vertices (self-intersecting as it comes) on the dyadic grid of
/// [0.05, 0.95]^2 in 1/4096 steps, so that Clipper's integer input is exact.
template <class Rng>
ControlPolygon RandomGridPolygon(Rng& rng, int shape, bool closed = true)
{
  std::uniform_int_distribution<int> count(3, 7);
  std::uniform_int_distribution<int> grid(205, 3891);
  ControlPolygon p;
  p.ShapeId = shape;
  p.Closed = closed;
  const int n = count(rng);
  for (int i = 0; i < n; ++i)
  {
    p.Points.push_back({ grid(rng) / 4096.0, grid(rng) / 4096.0, 0.0 });
  }
  return p;
}

/// True when (x, y) is strictly inside polygon p.
inline bool InsidePolygon(const ControlPolygon& p, double x, double y)
{
  return ClipperLib::PointInPolygon(ToClipper(x, y), ToClipper(p)) == 1;
}

} // namespace testutils

#endif

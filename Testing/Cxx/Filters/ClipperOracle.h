// Clipper (libpolyclipping-dev) as the independent 2D oracle of the flat-mesh tests: control
// polygons in Clipper's integer coordinates, and areas of its results.
#ifndef ClipperOracle_h
#define ClipperOracle_h

#include "FilterTestUtils.h"

#include <polyclipping/clipper.hpp>

#include <cmath>

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

/// True when (x, y) is strictly inside polygon p.
inline bool InsidePolygon(const ControlPolygon& p, double x, double y)
{
  return ClipperLib::PointInPolygon(ToClipper(x, y), ToClipper(p)) == 1;
}

} // namespace testutils

#endif

// The planar truth for drawings of integer polygons: exact areas of Boolean combinations of
// winding numbers, computed without any mesh, arrangement or Clipper. The oracle of the tests
// of degenerate drawings on flat meshes (where a geodesic polygon is the polygon itself).
#ifndef boolsurf_PlanarWinding_h
#define boolsurf_PlanarWinding_h

#include <algorithm>
#include <array>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace boolsurf
{
namespace testing
{

/// A closed polygon with integer vertices, of one shape.
struct LatticePolygon
{
  int Shape = 0;
  std::vector<std::array<long long, 2>> Points;
};

/// Exact planar area of {p : inside(winding numbers of the shapes at p)}, by vertical slabs:
/// between consecutive x coordinates of polygon vertices and crossings no side starts, ends or
/// crosses another, so the selected length of a vertical line is linear in x and the slab's
/// area is that length at the slab's middle times its width. Independent of the arrangement
/// and of Clipper (which, on overlapping edges, is sometimes wrong); exact up to rounding.
template <class Inside>
double SweepArea(const std::vector<LatticePolygon>& polygons, int numberOfShapes, Inside inside)
{
  struct Side
  {
    double X0, Y0, X1, Y1;
    int Shape;
  };
  std::vector<Side> sides;
  std::vector<double> xs;
  for (const auto& p : polygons)
  {
    const size_t n = p.Points.size();
    for (size_t i = 0; i < n; ++i)
    {
      const auto &a = p.Points[i], &b = p.Points[(i + 1) % n];
      xs.push_back(static_cast<double>(a[0]));
      if (a[0] != b[0])
        sides.push_back({ double(a[0]), double(a[1]), double(b[0]), double(b[1]), p.Shape });
    }
  }
  for (size_t i = 0; i < sides.size(); ++i)
  {
    for (size_t j = i + 1; j < sides.size(); ++j)
    {
      const Side &s = sides[i], &r = sides[j];
      const double dx1 = s.X1 - s.X0, dy1 = s.Y1 - s.Y0, dx2 = r.X1 - r.X0, dy2 = r.Y1 - r.Y0;
      const double den = dx1 * dy2 - dy1 * dx2;
      if (den == 0)
        continue;
      const double t = ((r.X0 - s.X0) * dy2 - (r.Y0 - s.Y0) * dx2) / den;
      const double u = ((r.X0 - s.X0) * dy1 - (r.Y0 - s.Y0) * dx1) / den;
      if (t > 0 && t < 1 && u > 0 && u < 1)
        xs.push_back(s.X0 + t * dx1);
    }
  }
  std::sort(xs.begin(), xs.end());
  double area = 0;
  std::vector<std::pair<double, const Side*>> hits;
  std::vector<int> winding(numberOfShapes);
  for (size_t k = 0; k + 1 < xs.size(); ++k)
  {
    const double x0 = xs[k], x1 = xs[k + 1];
    if (x1 - x0 <= 0)
      continue;
    const double xm = 0.5 * (x0 + x1);
    hits.clear();
    for (const Side& s : sides)
    {
      if ((s.X0 < xm && xm < s.X1) || (s.X1 < xm && xm < s.X0))
        hits.emplace_back(s.Y0 + (xm - s.X0) / (s.X1 - s.X0) * (s.Y1 - s.Y0), &s);
    }
    std::sort(
      hits.begin(), hits.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    // Going up across a side that runs left -> right enters its left side: +1.
    std::fill(winding.begin(), winding.end(), 0);
    double length = 0;
    for (size_t h = 0; h < hits.size(); ++h)
    {
      const Side& s = *hits[h].second;
      if (s.Shape >= 0 && s.Shape < numberOfShapes)
        winding[s.Shape] += s.X1 > s.X0 ? 1 : -1;
      if (h + 1 < hits.size() && inside(winding))
        length += hits[h + 1].first - hits[h].first;
    }
    area += length * (x1 - x0);
  }
  return area;
}

/// A random closed polygon on the lattice [0, n]^2, with the degeneracies drawn on purpose:
/// repeated points, spikes, runs copied (maybe reversed) from polygons drawn before.
inline std::vector<std::array<long long, 2>> LatticePolygonPoints(std::mt19937& rng,
  int n,
  const std::vector<LatticePolygon>& before)
{
  std::uniform_int_distribution<int> coord(0, n), count(3, 7), pattern(0, 9);
  std::vector<std::array<long long, 2>> pts;
  const int k = count(rng);
  for (int i = 0; i < k; ++i)
  {
    const std::array<long long, 2> p{ coord(rng), coord(rng) };
    pts.push_back(p);
    switch (pattern(rng))
    {
      case 0: // repeated point
        pts.push_back(p);
        break;
      case 1: // spike out and back
      {
        const std::array<long long, 2> q{ coord(rng), coord(rng) };
        pts.push_back(q);
        pts.push_back(p);
        break;
      }
      case 2: // a run of an earlier polygon, forwards or backwards (shared / overlapping edges)
        if (!before.empty())
        {
          const auto& other = before[rng() % before.size()].Points;
          const size_t start = rng() % other.size(), len = 2 + rng() % 2;
          const bool reverse = rng() % 2;
          for (size_t j = 0; j < len; ++j)
          {
            const size_t idx =
              reverse ? (start + other.size() * 4 - j) % other.size() : (start + j) % other.size();
            pts.push_back(other[idx]);
          }
        }
        break;
      default:
        break;
    }
  }
  return pts;
}

/// Two or three random lattice polygons, alternately of shapes 0 and 1.
inline std::vector<LatticePolygon> RandomLatticeDrawing(std::mt19937& rng, int n)
{
  std::vector<LatticePolygon> drawing;
  const int polygons = 2 + static_cast<int>(rng() % 2);
  for (int p = 0; p < polygons; ++p)
    drawing.push_back({ p % 2, LatticePolygonPoints(rng, n, drawing) });
  return drawing;
}

/// One drawing of the degenerate-curves issue: a single polygon of shape 0, its non-zero
/// area as the issue quotes it (two decimals), and the square [Lo, Hi]^2 to draw it on, with
/// the lattice step of a mesh aligned with it.
struct DegenerateCase
{
  const char* Name;
  std::vector<std::array<long long, 2>> Points;
  double Area;
  double Lo, Hi, Step;
};

/// The issue's small cases: a self-crossing polygon with a vertex on its own segment, a vertex
/// on its own edge, a keyhole (outer square and hole joined by a doubled bridge), a spike out
/// and back inside a square.
inline std::vector<DegenerateCase> DegenerateIssueCases()
{
  return {
    { "vertex on its own segment (self-crossing)",
      { { 390, 200 },
        { 10, 510 },
        { 360, 460 },
        { 780, 490 },
        { 20, 90 },
        { 360, 400 },
        { 720, 320 },
        { 500, 470 } },
      95942.65,
      0,
      800,
      10 },
    { "vertex on its own edge",
      { { 0, 0 }, { 20, 0 }, { 20, 10 }, { 10, 0 }, { 0, 10 } },
      100,
      -2,
      22,
      1 },
    { "keyhole",
      { { 0, 0 },
        { 20, 0 },
        { 20, 20 },
        { 0, 20 },
        { 0, 10 },
        { 5, 10 },
        { 5, 15 },
        { 15, 15 },
        { 15, 5 },
        { 5, 5 },
        { 5, 10 },
        { 0, 10 } },
      300,
      -2,
      22,
      1 },
    { "spike out and back",
      { { 0, 0 }, { 10, 0 }, { 10, 10 }, { 5, 5 }, { 10, 10 }, { 0, 10 } },
      100,
      -2,
      12,
      1 },
  };
}

/// "S0: (0,0) (1,0) ...; S1: ..." for failure messages.
inline std::string DescribeDrawing(const std::vector<LatticePolygon>& drawing)
{
  std::string text;
  for (const auto& p : drawing)
  {
    text += "S" + std::to_string(p.Shape) + ":";
    for (const auto& x : p.Points)
      text += " (" + std::to_string(x[0]) + "," + std::to_string(x[1]) + ")";
    text += "; ";
  }
  return text;
}

} // namespace testing
} // namespace boolsurf

#endif

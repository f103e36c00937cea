#include "RefinementChecks.h"

#include "Arrangement/Predicates.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <utility>

namespace boolsurf
{
namespace testing
{

std::array<mpq_class, 2> ExactCoordinates(const LocalArrangement& arr, int i)
{
  const LocalPoint& p = arr.Points[i];
  if (p.Crossing < 0)
  {
    return { mpq_class(p.P.x), mpq_class(p.P.y) };
  }
  const SegmentCrossing& c = arr.Crossings[p.Crossing];
  const mpq_class p0x(c.P0.x), p0y(c.P0.y);
  const mpq_class dx = mpq_class(c.P1.x) - p0x, dy = mpq_class(c.P1.y) - p0y;
  const mpq_class ex = mpq_class(c.Q1.x) - mpq_class(c.Q0.x);
  const mpq_class ey = mpq_class(c.Q1.y) - mpq_class(c.Q0.y);
  const mpq_class fx = mpq_class(c.Q0.x) - p0x, fy = mpq_class(c.Q0.y) - p0y;
  const mpq_class t = (fx * ey - fy * ex) / (dx * ey - dy * ex);
  return { p0x + t * dx, p0y + t * dy };
}

int Orientation(const std::array<mpq_class, 2>& a,
  const std::array<mpq_class, 2>& b,
  const std::array<mpq_class, 2>& c)
{
  const mpq_class d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  return sgn(d);
}

Vec2 RandomTrianglePoint(std::mt19937& rng, double margin, double scale)
{
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double u = unit(rng), v = unit(rng);
  if (u + v > 1)
  {
    u = 1 - u;
    v = 1 - v;
  }
  return { margin + scale * u, margin + scale * v };
}

double DistanceToSegment(Vec2 a, Vec2 b, Vec2 q)
{
  const Vec2 d = b - a;
  const double len2 = d.x * d.x + d.y * d.y;
  double t = len2 > 0 ? ((q.x - a.x) * d.x + (q.y - a.y) * d.y) / len2 : 0.0;
  t = std::min(1.0, std::max(0.0, t));
  return Length(a + t * d - q);
}

void ExpectValidRefinement(const LocalArrangement& before, const LocalArrangement& after)
{
  const auto p = [&after](int i) { return after.Points[i].P; };
  double area = 0;
  std::map<std::pair<int, int>, int> directed;
  for (const std::array<int, 3>& t : after.Triangles)
  {
    ASSERT_GT(Orientation(ExactCoordinates(after, t[0]),
                ExactCoordinates(after, t[1]),
                ExactCoordinates(after, t[2])),
      0);
    area += 0.5 * Orient2d(p(t[0]), p(t[1]), p(t[2]));
    for (int j = 0; j < 3; ++j)
    {
      const int uses = ++directed[std::make_pair(t[j], t[(j + 1) % 3])];
      ASSERT_EQ(uses, 1) << t[j] << " " << t[(j + 1) % 3];
    }
  }
  EXPECT_NEAR(area, 0.5, 1e-12);
  std::set<std::pair<int, int>> boundary;
  for (std::size_t i = 0; i < after.Boundary.size(); ++i)
  {
    boundary.insert({ after.Boundary[i], after.Boundary[(i + 1) % after.Boundary.size()] });
  }
  for (const auto& [edge, count] : directed)
  {
    const bool twin = directed.count(std::make_pair(edge.second, edge.first)) > 0;
    EXPECT_TRUE(twin != (boundary.count(edge) > 0)) << edge.first << " " << edge.second;
  }
  ASSERT_EQ(after.Chains.size(), before.Chains.size());
  for (std::size_t c = 0; c < before.Chains.size(); ++c)
  {
    const std::vector<int>& drawn = before.Chains[c];
    const std::vector<int>& path = after.Chains[c];
    ASSERT_FALSE(path.empty());
    EXPECT_EQ(path.front(), after.Alias[drawn.front()]) << "chain " << c;
    EXPECT_EQ(path.back(), after.Alias[drawn.back()]) << "chain " << c;
    for (std::size_t i = 0; i + 1 < path.size(); ++i)
    {
      EXPECT_TRUE(directed.count(std::make_pair(path[i], path[i + 1])) > 0 ||
        directed.count(std::make_pair(path[i + 1], path[i])) > 0)
        << "chain " << c << " piece " << path[i] << " -> " << path[i + 1] << " is no edge";
    }
    for (const int q : path)
    {
      double nearest = 1.0;
      for (std::size_t i = 0; i + 1 < drawn.size(); ++i)
      {
        nearest = std::min(nearest,
          DistanceToSegment(before.Points[drawn[i]].P, before.Points[drawn[i + 1]].P, p(q)));
      }
      EXPECT_LT(nearest, 1e-9) << "chain " << c << " point " << q;
    }
  }
}

} // namespace testing
} // namespace boolsurf

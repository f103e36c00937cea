// A mesh triangle crowded with curve pieces: the randomized SVG experiment's one refusal
// (siggraph-logo-simple xor chrome on 3torus_200k, triangle 46612: "constraint insertion does
// not converge") as stage 2 left it, and random crowded triangles. The refinement must answer
// with a valid triangulation in which every piece runs along edges where it was drawn.
#include "Arrangement/PieceSplitting.h"
#include "Arrangement/Predicates.h"
#include "Arrangement/TriangleRefinement.h"
#include "Support/SourceTree.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <utility>

using namespace boolsurf;

namespace
{

std::string FixturePath()
{
  return (
    boolsurf::testing::SourceTree() / "Testing/Data/Arrangement/CrowdedTriangle3torus200k.txt")
    .string();
}

// The fixture: points (u, v as hexadecimal doubles, refined-surface id, where), the boundary,
// and the chains (closed flag, count, point ids), as stage 2 (IntersectTriangleSegments) left
// them.
bool ReadFixture(const std::string& path, LocalArrangement& arr)
{
  std::ifstream in(path);
  std::string word;
  std::size_t n = 0;
  if (!(in >> word >> arr.Triangle >> word >> n))
  {
    return false;
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    std::string u, v;
    LocalPoint p;
    in >> u >> v >> p.Global >> p.Where;
    p.P = { std::strtod(u.c_str(), nullptr), std::strtod(v.c_str(), nullptr) };
    arr.Points.push_back(p);
  }
  in >> word >> n;
  arr.Boundary.resize(n);
  for (int& b : arr.Boundary)
  {
    in >> b;
  }
  in >> word >> n;
  for (std::size_t c = 0; c < n; ++c)
  {
    int closed = 0;
    std::size_t k = 0;
    in >> closed >> k;
    std::vector<int> chain(k);
    for (int& id : chain)
    {
      in >> id;
    }
    arr.Chains.push_back(chain);
    arr.ChainClosed.push_back(static_cast<char>(closed));
  }
  return static_cast<bool>(in);
}

double DistanceToSegment(Vec2 a, Vec2 b, Vec2 q)
{
  const Vec2 d = b - a;
  const double len2 = d.x * d.x + d.y * d.y;
  double t = len2 > 0 ? ((q.x - a.x) * d.x + (q.y - a.y) * d.y) / len2 : 0.0;
  t = std::min(1.0, std::max(0.0, t));
  return Length(a + t * d - q);
}

// The refined triangle is a triangulation of the unit triangle (counter-clockwise triangles
// whose areas sum to 1/2, every edge used once each way inside and once along the boundary),
// and every chain became a path of triangulation edges from its first to its last point, never
// farther than rounding from the pieces it was drawn as.
void ExpectValidRefinement(const LocalArrangement& before, const LocalArrangement& after)
{
  const auto p = [&after](int i) { return after.Points[i].P; };
  double area = 0;
  std::map<std::pair<int, int>, int> directed;
  for (const std::array<int, 3>& t : after.Triangles)
  {
    ASSERT_GT(Orient2dSign(p(t[0]), p(t[1]), p(t[2])), 0);
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

} // namespace

// The randomized SVG experiment's refusal: refined now, by splitting the pieces at their
// crossings once the incremental insertion gives up.
TEST(CrowdedTriangle, RandomSvgRefusalIsRefined)
{
  LocalArrangement arr;
  ASSERT_TRUE(ReadFixture(FixturePath(), arr)) << FixturePath();
  ASSERT_EQ(arr.Points.size(), 118u);
  ASSERT_EQ(arr.Chains.size(), 143u);
  const LocalArrangement before = arr;
  ASSERT_TRUE(RefineTriangle(arr)) << arr.Error;
  ExpectValidRefinement(before, arr);
}

// Splitting leaves no two pieces crossing and no point strictly inside a piece (exact
// predicates), on random crowded triangles: hundreds of pieces between random points, with
// shared end points, pieces through other pieces' ends, and overlapping collinear pieces.
TEST(CrowdedTriangle, SplitPiecesNeverCross)
{
  std::mt19937 rng(46612);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 12; ++trial)
  {
    LocalArrangement arr;
    arr.Points = { { { 0, 0 }, 0, 3 }, { { 1, 0 }, 1, 4 }, { { 0, 1 }, 2, 5 } };
    arr.Boundary = { 0, 1, 2 };
    const auto inside = [&]
    {
      double u = unit(rng), v = unit(rng);
      if (u + v > 1)
      {
        u = 1 - u;
        v = 1 - v;
      }
      arr.Points.push_back({ { 0.05 + 0.8 * u, 0.05 + 0.8 * v }, -1, -1 }); // x + y <= 0.9
      return static_cast<int>(arr.Points.size()) - 1;
    };
    const int pieces = 40 + 5 * trial; // up to about a thousand crossings
    for (int k = 0; k < pieces; ++k)
    {
      const int a = k % 7 == 0 && arr.Points.size() > 3
        ? 3 + static_cast<int>(unit(rng) * (arr.Points.size() - 3))
        : inside();
      const int b = inside();
      if (k % 11 == 0)
      {
        // A piece through the middle of another: exactly collinear in doubles it rarely is,
        // so use its end and midpoint on an axis-aligned line instead.
        const Vec2 pa = arr.Points[a].P;
        arr.Points.push_back({ { pa.x + 0.01, pa.y }, -1, -1 });
        arr.Points.push_back({ { pa.x + 0.02, pa.y }, -1, -1 });
        const int m = static_cast<int>(arr.Points.size()) - 2;
        arr.Chains.push_back({ a, m + 1 });
        arr.Chains.push_back({ m, m + 1 });
        arr.ChainClosed.push_back(1);
        arr.ChainClosed.push_back(0);
      }
      arr.Chains.push_back({ a, b });
      arr.ChainClosed.push_back(static_cast<char>(k % 2));
    }
    const LocalArrangement before = arr;
    std::string problem;
    ASSERT_TRUE(SplitPiecesAtCrossings(arr, 1e-12, problem)) << problem;
    EXPECT_GT(arr.Points.size(), before.Points.size()); // crossings became points
    std::vector<std::array<int, 2>> segments;
    for (const std::vector<int>& chain : arr.Chains)
    {
      for (std::size_t i = 0; i + 1 < chain.size(); ++i)
      {
        segments.push_back({ chain[i], chain[i + 1] });
      }
    }
    const auto p = [&arr](int i) { return arr.Points[i].P; };
    for (std::size_t i = 0; i < segments.size(); ++i)
    {
      const Vec2 a = p(segments[i][0]), b = p(segments[i][1]);
      for (std::size_t q = 3; q < arr.Points.size(); ++q)
      {
        const Vec2 x = p(static_cast<int>(q));
        const bool strictlyInside = Orient2dSign(a, b, x) == 0 &&
          ((a.x != b.x) ? (std::min(a.x, b.x) < x.x && x.x < std::max(a.x, b.x))
                        : (std::min(a.y, b.y) < x.y && x.y < std::max(a.y, b.y)));
        ASSERT_FALSE(strictlyInside) << "trial " << trial << ": point " << q << " inside a piece";
      }
      for (std::size_t j = i + 1; j < segments.size(); ++j)
      {
        const Vec2 c = p(segments[j][0]), d = p(segments[j][1]);
        const int o1 = Orient2dSign(a, b, c), o2 = Orient2dSign(a, b, d);
        const int o3 = Orient2dSign(c, d, a), o4 = Orient2dSign(c, d, b);
        const bool proper = o1 * o2 < 0 && o3 * o4 < 0;
        ASSERT_FALSE(proper) << "trial " << trial << ": pieces " << i << " and " << j << " cross";
      }
    }
    // And the triangulation of the split pieces is a valid refinement of the drawing.
    LocalArrangement refined = arr;
    ASSERT_TRUE(RefineTriangle(refined)) << refined.Error;
    ExpectValidRefinement(before, refined);
  }
}

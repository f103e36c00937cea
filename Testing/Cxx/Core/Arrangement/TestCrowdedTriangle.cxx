// A mesh triangle crowded with curve pieces: the randomized SVG experiment's one refusal
// (siggraph-logo-simple xor chrome on 3torus_200k, triangle 46612: "constraint insertion does
// not converge", when crossings were rounded) and random crowded triangles. Stage 2 must cut
// the segments at exact crossings (checked against rationals computed here, independently of
// the arrangement's filtered predicates) and the refinement must answer with a valid
// triangulation in which every piece runs along edges where it was drawn.
#include "Arrangement/ExactCrossings.h"
#include "Arrangement/Predicates.h"
#include "Arrangement/SegmentIntersection.h"
#include "Arrangement/TriangleRefinement.h"
#include "RefinementChecks.h"
#include "Support/SourceTree.h"

#include <gmpxx.h>
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
using boolsurf::testing::ExactCoordinates;
using boolsurf::testing::ExpectValidRefinement;
using boolsurf::testing::Orientation;
using boolsurf::testing::RandomTrianglePoint;

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

/// The fixture's drawing as segments: each chain reduced to its first and last point (stage 2's
/// input), the rounded crossings the old stage 2 added dropped and the points renumbered.
LocalArrangement SegmentsOf(const LocalArrangement& cut)
{
  std::vector<int> used(cut.Points.size(), 0);
  for (const int b : cut.Boundary)
  {
    used[b] = 1;
  }
  for (const std::vector<int>& chain : cut.Chains)
  {
    used[chain.front()] = used[chain.back()] = 1;
  }
  LocalArrangement out;
  out.Triangle = cut.Triangle;
  std::vector<int> id(cut.Points.size(), -1);
  for (std::size_t i = 0; i < cut.Points.size(); ++i)
  {
    if (used[i])
    {
      id[i] = static_cast<int>(out.Points.size());
      out.Points.push_back(cut.Points[i]);
    }
  }
  for (const int b : cut.Boundary)
  {
    out.Boundary.push_back(id[b]);
  }
  for (std::size_t c = 0; c < cut.Chains.size(); ++c)
  {
    out.Chains.push_back({ id[cut.Chains[c].front()], id[cut.Chains[c].back()] });
    out.ChainClosed.push_back(cut.ChainClosed[c]);
  }
  return out;
}

bool StrictlyInside(const std::array<mpq_class, 2>& a,
  const std::array<mpq_class, 2>& b,
  const std::array<mpq_class, 2>& q)
{
  const int axis = a[0] != b[0] ? 0 : 1;
  return (a[axis] < q[axis] && q[axis] < b[axis]) || (b[axis] < q[axis] && q[axis] < a[axis]);
}

/// Stage 2's output against exact rationals: every chain runs from its segment's first to its
/// last point through points exactly on the segment, strictly in order; no two points are
/// equal; no two pieces cross; no point lies strictly inside a piece; and every pair of
/// segments that crosses properly has a common point in both chains.
void ExpectExactCuts(const LocalArrangement& segments, const LocalArrangement& cut)
{
  const int n = static_cast<int>(cut.Points.size());
  std::vector<std::array<mpq_class, 2>> x(n);
  for (int i = 0; i < n; ++i)
  {
    x[i] = ExactCoordinates(cut, i);
  }
  std::set<std::pair<mpq_class, mpq_class>> distinct;
  for (int i = 0; i < n; ++i)
  {
    distinct.insert({ x[i][0], x[i][1] });
  }
  ASSERT_EQ(static_cast<int>(distinct.size()), n) << "two points of the cut are equal";
  ASSERT_EQ(cut.Chains.size(), segments.Chains.size());
  std::vector<std::array<int, 3>> pieces; // end points, chain
  for (std::size_t c = 0; c < cut.Chains.size(); ++c)
  {
    const std::vector<int>& chain = cut.Chains[c];
    const int a = segments.Chains[c].front(), b = segments.Chains[c].back();
    ASSERT_EQ(chain.front(), a);
    ASSERT_EQ(chain.back(), b);
    for (std::size_t k = 0; k < chain.size(); ++k)
    {
      ASSERT_EQ(Orientation(x[a], x[b], x[chain[k]]), 0) << "chain " << c << " point " << k;
      if (k + 1 < chain.size())
      {
        ASSERT_TRUE(StrictlyInside(x[chain[k]], x[b], x[chain[k + 1]]) || chain[k + 1] == b)
          << "chain " << c << " out of order at " << k;
        pieces.push_back({ chain[k], chain[k + 1], static_cast<int>(c) });
      }
    }
  }
  // Rational tests only where rounded bounding boxes (grown far beyond rounding) meet.
  const auto near = [&cut](const std::array<int, 3>& piece, Vec2 lo, Vec2 hi)
  {
    const Vec2 a = cut.Points[piece[0]].P, b = cut.Points[piece[1]].P;
    const double m = 1e-9;
    return std::min(a.x, b.x) - m <= hi.x && lo.x <= std::max(a.x, b.x) + m &&
      std::min(a.y, b.y) - m <= hi.y && lo.y <= std::max(a.y, b.y) + m;
  };
  for (std::size_t i = 0; i < pieces.size(); ++i)
  {
    const auto &a = x[pieces[i][0]], &b = x[pieces[i][1]];
    for (int q = 0; q < n; ++q)
    {
      if (!near(pieces[i], cut.Points[q].P, cut.Points[q].P))
      {
        continue;
      }
      ASSERT_FALSE(q != pieces[i][0] && q != pieces[i][1] && Orientation(a, b, x[q]) == 0 &&
        StrictlyInside(a, b, x[q]))
        << "point " << q << " (crossing " << cut.Points[q].Crossing << ") inside piece " << i
        << " of chain " << pieces[i][2];
    }
    for (std::size_t j = i + 1; j < pieces.size(); ++j)
    {
      const Vec2 c2 = cut.Points[pieces[j][0]].P, d2 = cut.Points[pieces[j][1]].P;
      if (!near(pieces[i],
            { std::min(c2.x, d2.x), std::min(c2.y, d2.y) },
            { std::max(c2.x, d2.x), std::max(c2.y, d2.y) }))
      {
        continue;
      }
      const auto &c = x[pieces[j][0]], &d = x[pieces[j][1]];
      const bool proper = Orientation(a, b, c) * Orientation(a, b, d) < 0 &&
        Orientation(c, d, a) * Orientation(c, d, b) < 0;
      ASSERT_FALSE(proper) << "pieces of chains " << pieces[i][2] << " and " << pieces[j][2]
                           << " cross";
    }
  }
}

} // namespace

// The randomized SVG experiment's refusal, from its segments: exact cuts, then a valid
// refinement.
TEST(CrowdedTriangle, RandomSvgRefusalIsRefined)
{
  LocalArrangement fixture;
  ASSERT_TRUE(ReadFixture(FixturePath(), fixture)) << FixturePath();
  ASSERT_EQ(fixture.Points.size(), 118u);
  ASSERT_EQ(fixture.Chains.size(), 143u);
  const LocalArrangement segments = SegmentsOf(fixture);
  LocalArrangement arr = segments;
  CutSegmentsAtIntersections(arr, 0.0);
  ASSERT_GT(arr.Crossings.size(), 0u);
  ExpectExactCuts(segments, arr);
  const LocalArrangement cut = arr;
  ASSERT_TRUE(RefineTriangle(arr)) << arr.Error;
  ExpectValidRefinement(cut, arr);
}

namespace
{

/// A random crowded triangle: `pieces` segments between random points, with shared end points,
/// pieces through other pieces' ends, overlapping collinear pieces, and, when `lattice` is
/// set, all points on a coarse lattice so that many crossings coincide exactly.
LocalArrangement RandomSegments(std::mt19937& rng, int pieces, bool lattice)
{
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  LocalArrangement arr;
  arr.Points = { { { 0, 0 }, 0, 3 }, { { 1, 0 }, 1, 4 }, { { 0, 1 }, 2, 5 } };
  arr.Boundary = { 0, 1, 2 };
  std::map<std::pair<double, double>, int> ids;
  const auto point = [&](Vec2 p)
  {
    const auto found = ids.emplace(std::make_pair(p.x, p.y), static_cast<int>(arr.Points.size()));
    if (found.second)
    {
      arr.Points.push_back({ p, -1, -1 });
    }
    return found.first->second;
  };
  const auto inside = [&]
  {
    Vec2 p = RandomTrianglePoint(rng, 0.05, 0.8); // x + y <= 0.9
    if (lattice)
    {
      p = { std::round(p.x * 16) / 16, std::round(p.y * 16) / 16 };
      p = { std::max(p.x, 0.0625), std::max(p.y, 0.0625) };
    }
    return point(p);
  };
  for (int k = 0; k < pieces; ++k)
  {
    const int a = k % 7 == 0 && arr.Points.size() > 3
      ? 3 + static_cast<int>(unit(rng) * (arr.Points.size() - 3))
      : inside();
    int b = inside();
    if (b == a)
    {
      continue;
    }
    if (k % 11 == 0)
    {
      // A piece through the middle of another, on an axis-aligned line.
      const Vec2 pa = arr.Points[a].P;
      const int m = point({ pa.x + 1.0 / 128, pa.y }), e = point({ pa.x + 2.0 / 128, pa.y });
      arr.Chains.push_back({ a, e });
      arr.Chains.push_back({ m, e });
      arr.ChainClosed.push_back(1);
      arr.ChainClosed.push_back(0);
    }
    arr.Chains.push_back({ a, b });
    arr.ChainClosed.push_back(static_cast<char>(k % 2));
  }
  return SegmentsOf(arr); // without points drawn and then not used (stage 2 has none)
}

} // namespace

// Random crowded triangles, in general position and on a lattice (where three or more pieces
// through one crossing are common): stage 2's cuts are exact, and the refinement is valid.
TEST(CrowdedTriangle, ExactCutsOnRandomCrowdedTriangles)
{
  std::mt19937 rng(46612);
  for (int trial = 0; trial < 12; ++trial)
  {
    const bool lattice = trial % 2 == 1;
    const LocalArrangement segments = RandomSegments(rng, 40 + 5 * trial, lattice);
    LocalArrangement arr = segments;
    CutSegmentsAtIntersections(arr, 0.0);
    EXPECT_GT(arr.Crossings.size(), 0u) << "trial " << trial;
    ExpectExactCuts(segments, arr);
    const LocalArrangement cut = arr;
    ASSERT_TRUE(RefineTriangle(arr)) << "trial " << trial << ": " << arr.Error;
    ExpectValidRefinement(cut, arr);
  }
}

// Three lines through one point exactly: one crossing shared by all three (not three crossings
// a rounding apart); three lines nearly through one point: exactly cut, three crossings and a
// tiny triangle between them, still a valid refinement; with near points merged (the
// default), one point.
TEST(CrowdedTriangle, ConcurrentCrossingsAreOnePoint)
{
  for (const double shift : { 0.0, 1e-15 })
  {
    LocalArrangement arr;
    arr.Points = { { { 0, 0 }, 0, 3 }, { { 1, 0 }, 1, 4 }, { { 0, 1 }, 2, 5 } };
    arr.Boundary = { 0, 1, 2 };
    // Lines through (0.3, 0.2) (+ shift for the third), end points exact in doubles.
    const std::vector<std::array<Vec2, 2>> lines = { { Vec2{ 0.1, 0.2 }, Vec2{ 0.5, 0.2 } },
      { Vec2{ 0.3, 0.1 }, Vec2{ 0.3, 0.4 } },
      { Vec2{ 0.2, 0.1 + shift }, Vec2{ 0.4, 0.3 + shift } } };
    for (const auto& l : lines)
    {
      const int a = static_cast<int>(arr.Points.size());
      arr.Points.push_back({ l[0], -1, -1 });
      arr.Points.push_back({ l[1], -1, -1 });
      arr.Chains.push_back({ a, a + 1 });
      arr.ChainClosed.push_back(1);
    }
    const LocalArrangement segments = arr;
    CutSegmentsAtIntersections(arr, 0.0);
    ExpectExactCuts(segments, arr);
    // 0.1 + 0.2 is not 0.3 in doubles, so "exactly" is decided on the doubles given: the
    // third line passes through the first two's crossing iff the rationals say so.
    LocalArrangement firstTwo = segments;
    firstTwo.Crossings.push_back({ lines[0][0], lines[0][1], lines[1][0], lines[1][1] });
    firstTwo.Points.push_back({ {}, -1, -1, 0 });
    const auto x = ExactCoordinates(firstTwo, static_cast<int>(firstTwo.Points.size()) - 1);
    const bool concurrent = Orientation({ mpq_class(lines[2][0].x), mpq_class(lines[2][0].y) },
                              { mpq_class(lines[2][1].x), mpq_class(lines[2][1].y) },
                              x) == 0;
    EXPECT_EQ(arr.Crossings.size(), concurrent ? 1u : 3u) << "shift " << shift;
    const LocalArrangement cut = arr;
    ASSERT_TRUE(RefineTriangle(arr)) << arr.Error;
    ExpectValidRefinement(cut, arr);
    LocalArrangement merged = segments;
    CutSegmentsAtIntersections(merged);
    // One point shared by the three chains: the crossing itself when they are concurrent,
    // else an explicit point at its rounded position (it stands for points it is only near).
    ASSERT_EQ(merged.Points.size(), segments.Points.size() + 1) << "shift " << shift;
    EXPECT_EQ(merged.Crossings.size(), concurrent ? 1u : 0u) << "shift " << shift;
    for (const std::vector<int>& chain : merged.Chains)
    {
      ASSERT_EQ(chain.size(), 3u);
      EXPECT_EQ(chain[1], static_cast<int>(segments.Points.size()));
    }
    ASSERT_TRUE(RefineTriangle(merged)) << merged.Error;
  }
}

namespace
{

std::array<mpq_class, 2> RationalPoint(const ExactPoint& p)
{
  LocalArrangement one;
  one.Points.push_back({ p.P, -1, -1, p.Crossing ? 0 : -1 });
  if (p.Crossing)
  {
    one.Crossings.push_back(*p.Crossing);
  }
  return ExactCoordinates(one, 0);
}

} // namespace

// The predicates against rationals computed here, on crossings of lines between points of a
// dyadic lattice (exactly concurrent and collinear configurations: the exact zeros) and of the
// same points moved by one ulp (near-degenerate: the double-double and integer stages), with
// cached and uncached crossings.
TEST(ExactCrossings, PredicatesAgreeWithRationals)
{
  std::mt19937 rng(2028);
  std::uniform_int_distribution<int> coord(1, 7);
  const auto latticePoint = [&](bool nudge)
  {
    Vec2 p{ coord(rng) / 16.0, coord(rng) / 16.0 };
    if (nudge && rng() % 2)
    {
      p.x = std::nextafter(p.x, 1.0);
    }
    return p;
  };
  std::vector<SegmentCrossing> crossings;
  while (crossings.size() < 60)
  {
    const bool nudge = crossings.size() % 3 == 2;
    const Vec2 p0 = latticePoint(nudge), p1 = latticePoint(nudge);
    const Vec2 q0 = latticePoint(nudge), q1 = latticePoint(nudge);
    if (Orient2dSign(p0, p1, q0) * Orient2dSign(p0, p1, q1) >= 0 ||
      Orient2dSign(q0, q1, p0) * Orient2dSign(q0, q1, p1) >= 0)
    {
      continue; // not a proper crossing
    }
    crossings.push_back(crossings.size() % 2 ? MakeSegmentCrossing(p0, p1, q0, q1)
                                             : SegmentCrossing{ p0, p1, q0, q1 });
  }
  std::vector<ExactPoint> points;
  for (const SegmentCrossing& c : crossings)
  {
    points.push_back({ RoundedCrossing(c), &c });
    points.push_back({ c.P0, nullptr }); // explicit points on the crossing's lines
  }
  std::vector<std::array<mpq_class, 2>> exact;
  for (const ExactPoint& p : points)
  {
    exact.push_back(RationalPoint(p));
  }
  const long long fallbacksBefore = ExactFallbackCount();
  int zeros = 0, checked = 0;
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    for (std::size_t j = 0; j < points.size(); j += 3)
    {
      for (int axis = 0; axis < 2; ++axis)
      {
        const int expected = sgn(exact[i][axis] - exact[j][axis]);
        ASSERT_EQ(ExactCompare(points[i], points[j], axis), expected) << i << " " << j;
      }
      for (std::size_t k = 0; k < points.size(); k += 7)
      {
        const int expected = Orientation(exact[i], exact[j], exact[k]);
        ASSERT_EQ(ExactOrient(points[i], points[j], points[k]), expected)
          << i << " " << j << " " << k;
        zeros += expected == 0;
        ++checked;
      }
    }
  }
  EXPECT_GT(zeros, checked / 100) << "the configurations must include exact zeros";
  EXPECT_GT(ExactFallbackCount(), fallbacksBefore) << "and reach the exact stage";
}

// A segment of no length (a curve drawn through one point twice) is a point: it cuts the
// segments it lies strictly inside and no other, in an ordinary triangle (pairs of segments)
// and in a crowded one (pairs of lines), where it was once taken for collinear with every
// segment whose x-range holds it.
TEST(CrowdedTriangle, PointSegmentsCutOnlyWhatTheyLieOn)
{
  for (const int filler : { 0, 80 })
  {
    LocalArrangement arr;
    arr.Points = { { { 0, 0 }, 0, 3 }, { { 1, 0 }, 1, 4 }, { { 0, 1 }, 2, 5 } };
    arr.Boundary = { 0, 1, 2 };
    const auto add = [&arr](Vec2 p)
    {
      arr.Points.push_back({ p, -1, -1 });
      return static_cast<int>(arr.Points.size()) - 1;
    };
    const int a = add({ 0.1, 0.2 }), b = add({ 0.5, 0.2 });  // the segment it lies on
    const int c = add({ 0.1, 0.4 }), d = add({ 0.5, 0.45 }); // one above it, not through it
    const int on = add({ 0.3, 0.2 }), off = add({ 0.3, 0.3 });
    arr.Chains = { { a, b }, { c, d }, { on, on }, { off, off } };
    arr.ChainClosed = { 1, 1, 0, 0 };
    for (int k = 0; k < filler; ++k)
    {
      // Short vertical segments far to the right: they make the triangle crowded and meet
      // nothing above.
      const double x = 0.6 + 0.003 * k;
      arr.Chains.push_back({ add({ x, 0.01 }), add({ x, 0.02 }) });
      arr.ChainClosed.push_back(0);
    }
    CutSegmentsAtIntersections(arr, 0.0);
    EXPECT_EQ(arr.Chains[0], (std::vector<int>{ a, on, b })) << "filler " << filler;
    EXPECT_EQ(arr.Chains[1], (std::vector<int>{ c, d })) << "filler " << filler;
    EXPECT_TRUE(arr.Crossings.empty()) << "filler " << filler;
  }
}

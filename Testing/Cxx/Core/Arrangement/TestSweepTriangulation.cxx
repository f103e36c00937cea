// The sweep that triangulates a crossed mesh triangle (SweepTriangulation.h): every kind of
// planar subdivision stage 2 can hand it (holes inside holes, dangling pieces, isolated points,
// vertical pieces, pieces from corners and along the boundary, equal points, repeated pieces)
// is triangulated with every piece as an edge and Euler's count of triangles; random ones, cut
// exactly by stage 2, too; and inputs that break stage 2's guarantee (pieces crossing without a
// point, a point inside a piece, overlapping pieces, a point outside) are refused with an error
// that names the points involved, never a crash or a wrong triangulation.
#include "Arrangement/SegmentIntersection.h"
#include "Arrangement/TriangleRefinement.h"
#include "RefinementChecks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace boolsurf;
using boolsurf::testing::ExpectValidRefinement;
using boolsurf::testing::RandomTrianglePoint;

namespace
{

/// The unit triangle with `edgePoints` on its sides (corners 0..2, then the points of local
/// edges 0, 1, 2 in edge order), as stage 2 lays out a local arrangement.
LocalArrangement UnitTriangle(const std::vector<std::vector<double>>& edgeParameters)
{
  LocalArrangement arr;
  arr.Triangle = 7;
  arr.Points = { { { 0, 0 }, 0, 3 }, { { 1, 0 }, 1, 4 }, { { 0, 1 }, 2, 5 } };
  const Vec2 corner[3] = { { 0, 0 }, { 1, 0 }, { 0, 1 } };
  std::vector<std::vector<int>> onEdge(3);
  for (int k = 0; k < 3; ++k)
  {
    for (const double t : edgeParameters[k])
    {
      const Vec2 a = corner[k], b = corner[(k + 1) % 3];
      onEdge[k].push_back(static_cast<int>(arr.Points.size()));
      arr.Points.push_back({ { a.x + t * (b.x - a.x), a.y + t * (b.y - a.y) }, -1, k });
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    arr.Boundary.push_back(k);
    arr.Boundary.insert(arr.Boundary.end(), onEdge[k].begin(), onEdge[k].end());
  }
  return arr;
}

int AddPoint(LocalArrangement& arr, Vec2 p)
{
  arr.Points.push_back({ p, -1, -1 });
  return static_cast<int>(arr.Points.size()) - 1;
}

void AddChain(LocalArrangement& arr, std::vector<int> chain, bool closed)
{
  arr.Chains.push_back(std::move(chain));
  arr.ChainClosed.push_back(closed ? 1 : 0);
}

/// Euler's count for a triangulated polygon: 2 n - b - 2 triangles for n vertices, b of them on
/// the boundary.
int EulerTriangles(const LocalArrangement& arr)
{
  int vertices = 0;
  for (std::size_t i = 0; i < arr.Points.size(); ++i)
  {
    vertices += arr.Alias[i] == static_cast<int>(i) ? 1 : 0;
  }
  return 2 * vertices - static_cast<int>(arr.Boundary.size()) - 2;
}

} // namespace

// One triangle holding every feature at once.
TEST(SweepTriangulation, HolesDanglingPiecesIsolatedPointsAndVerticals)
{
  // Edge 0 (y = 0) has points at x = 0.25 and 0.5; edge 1 one at (0.75, 0.25); edge 2 (x = 0,
  // from the top down) one at (0, 0.5).
  LocalArrangement arr = UnitTriangle({ { 0.25, 0.5 }, { 0.25 }, { 0.5 } });
  const int e0a = 3, e0b = 4, e1 = 5, e2 = 6;
  // A square with a square inside it, and a point inside both.
  const std::vector<Vec2> outer = { { 0.2, 0.2 }, { 0.4, 0.2 }, { 0.4, 0.4 }, { 0.2, 0.4 } };
  const std::vector<Vec2> inner = {
    { 0.25, 0.25 }, { 0.35, 0.25 }, { 0.35, 0.35 }, { 0.25, 0.35 }
  };
  for (const std::vector<Vec2>* square : { &outer, &inner })
  {
    std::vector<int> chain;
    for (const Vec2 p : *square)
    {
      chain.push_back(AddPoint(arr, p));
    }
    chain.push_back(chain.front());
    AddChain(arr, chain, true);
  }
  AddPoint(arr, { 0.3, 0.3 });
  AddPoint(arr, { 0.1, 0.6 });
  // The outer square's bottom side drawn again, as an open curve.
  AddChain(arr, { 9, 10 }, false);
  // A dangling piece, a vertical curve of two pieces, a vertical piece alone.
  AddChain(arr, { AddPoint(arr, { 0.05, 0.05 }), AddPoint(arr, { 0.15, 0.1 }) }, false);
  AddChain(arr,
    { AddPoint(arr, { 0.1, 0.2 }), AddPoint(arr, { 0.1, 0.3 }), AddPoint(arr, { 0.1, 0.4 }) },
    true);
  AddChain(arr, { AddPoint(arr, { 0.6, 0.05 }), AddPoint(arr, { 0.6, 0.3 }) }, true);
  // From an edge point inwards, from a corner to the edge point of another side, along the
  // bottom side from its first edge point to corner 1 (through the second edge point), and the
  // edge point of edge 2 to a point inside the outer square's corner region.
  AddChain(arr, { e0b, AddPoint(arr, { 0.45, 0.1 }) }, true);
  AddChain(arr, { 1, AddPoint(arr, { 0.7, 0.2 }), e1 }, true);
  AddChain(arr, { e0a, 1 }, true);
  AddChain(arr, { e2, AddPoint(arr, { 0.15, 0.45 }) }, false);
  // Two curve points at one place, each on its own piece.
  const int twinA = AddPoint(arr, { 0.7, 0.1 }), twinB = AddPoint(arr, { 0.7, 0.1 });
  AddChain(arr, { twinA, AddPoint(arr, { 0.8, 0.05 }) }, true);
  AddChain(arr, { twinB, AddPoint(arr, { 0.65, 0.2 }) }, true);
  const LocalArrangement before = arr;

  ASSERT_TRUE(RefineTriangle(arr)) << arr.Error;
  ExpectValidRefinement(before, arr);
  EXPECT_EQ(static_cast<int>(arr.Triangles.size()), EulerTriangles(arr));
  EXPECT_EQ(arr.Alias[twinB], twinA);
  EXPECT_EQ(arr.Chains[arr.Chains.size() - 4], (std::vector<int>{ e0a, e0b, 1 }));
  int interior = 0;
  for (const LocalPoint& p : arr.Points)
  {
    interior += p.Where < 0 ? 1 : 0;
  }
  EXPECT_EQ(arr.NumberOfNewPoints, interior - 1); // all but the twin
  // The inner square's sides and the outer square's are blocked; the vertical piece alone too.
  int blocked = 0;
  for (const unsigned char mask : arr.Blocked)
  {
    blocked += (mask & 1) + ((mask >> 1) & 1) + ((mask >> 2) & 1);
  }
  EXPECT_GT(blocked, 2 * 8);
}

// Random drawings on a lattice (vertical, horizontal and concurrent pieces are common) and in
// general position, with isolated points, cut exactly by stage 2, and again with near points
// merged (the arrangement's first pass): the sweep triangulates every exact cut, and each
// merged cut either validly or with an error (the arrangement then cuts exactly).
TEST(SweepTriangulation, RandomPlanarSubdivisions)
{
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 60; ++trial)
  {
    const bool lattice = trial % 2 == 0;
    LocalArrangement arr = UnitTriangle({ { 0.5 }, { 0.5 }, { 0.5 } });
    const auto inside = [&]
    {
      Vec2 p = RandomTrianglePoint(rng, 0.02, 0.85); // x + y <= 0.89
      if (lattice)
      {
        p = { std::floor(p.x * 8) / 8 + 1.0 / 32, std::floor(p.y * 8) / 8 + 1.0 / 32 };
      }
      return p;
    };
    const int pieces = 3 + trial;
    for (int k = 0; k < pieces; ++k)
    {
      const int a = k % 9 == 0 ? static_cast<int>(unit(rng) * 6) : AddPoint(arr, inside());
      const int b = AddPoint(arr, inside());
      if (arr.Points[a].P.x == arr.Points[b].P.x && arr.Points[a].P.y == arr.Points[b].P.y)
      {
        continue;
      }
      AddChain(arr, { a, b }, k % 3 != 0);
    }
    for (const bool exact : { true, false })
    {
      LocalArrangement cut = arr;
      CutSegmentsAtIntersections(cut, exact ? 0.0 : NearPointDistance);
      for (int k = 0; k < 3; ++k)
      {
        // Isolated points, off the lattice and off every piece.
        AddPoint(cut, { 0.03 + 0.3 * unit(rng), 0.03 + 0.3 * unit(rng) });
      }
      const LocalArrangement before = cut;
      const bool refined = RefineTriangle(cut);
      if (exact)
      {
        ASSERT_TRUE(refined) << "trial " << trial << ": " << cut.Error;
      }
      if (refined)
      {
        ExpectValidRefinement(before, cut);
        EXPECT_EQ(static_cast<int>(cut.Triangles.size()), EulerTriangles(cut)) << "trial " << trial;
      }
      else
      {
        EXPECT_EQ(cut.Error.rfind("triangle 7: ", 0), 0u) << cut.Error;
      }
    }
  }
}

// Inputs that break stage 2's guarantee are refused, naming the points involved.
TEST(SweepTriangulation, InconsistentInputIsNamed)
{
  struct Case
  {
    const char* What;
    std::vector<std::pair<Vec2, Vec2>> Pieces;
    const char* Expected;
  };
  const std::vector<Case> cases = {
    { "two pieces crossing without a crossing point",
      { { { 0.2, 0.2 }, { 0.6, 0.3 } }, { { 0.3, 0.1 }, { 0.4, 0.5 } } },
      "cross" },
    { "a point inside a piece",
      { { { 0.2, 0.2 }, { 0.6, 0.2 } }, { { 0.4, 0.2 }, { 0.4, 0.4 } } },
      "lies inside curve piece 3-4" },
    { "overlapping pieces",
      { { { 0.2, 0.2 }, { 0.6, 0.2 } }, { { 0.3, 0.2 }, { 0.5, 0.2 } } },
      "lies inside curve piece 3-4" },
    { "pieces overlapping from one point",
      { { { 0.2, 0.2 }, { 0.6, 0.2 } }, { { 0.2, 0.2 }, { 0.5, 0.2 } } },
      "overlap" },
    { "a point outside the triangle",
      { { { 0.2, 0.2 }, { 0.8, 0.8 } } },
      "point 4 lies outside the triangle" },
  };
  for (const Case& c : cases)
  {
    LocalArrangement arr = UnitTriangle({ {}, {}, {} });
    for (const auto& [a, b] : c.Pieces)
    {
      AddChain(arr, { AddPoint(arr, a), AddPoint(arr, b) }, true);
    }
    EXPECT_FALSE(RefineTriangle(arr)) << c.What;
    EXPECT_EQ(arr.Error.rfind("triangle 7: ", 0), 0u) << c.What << ": " << arr.Error;
    EXPECT_NE(arr.Error.find(c.Expected), std::string::npos) << c.What << ": " << arr.Error;
    EXPECT_TRUE(arr.Triangles.empty() || !arr.Error.empty());
  }
}

// Level sets of fields given per corner of the refined surface (Winding/WindingLevelSet.h), on
// flat meshes where the answer is planar geometry: a closed polygon with 1 inside is its own
// level set, a linear field gives a straight line closed along the boundary, a field with a
// jump follows the curve where the jump straddles the threshold, and the enclosed areas are
// checked against polygon clipping done here without any mesh.
#include "Winding/WindingLevelSet.h"

#include "Arrangement/Arrangement.h"
#include "Mesh/ProceduralMeshes.h"
#include "Support/SyntheticCurves.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <vector>

using namespace boolsurf;

namespace
{

constexpr double Pi = 3.14159265358979323846;

using Polygon = std::vector<Vec2>;

/// A regular polygon of n straight legs (counter-clockwise unless `clockwise`).
Polygon CirclePolygon(Vec2 center, double radius, int n, bool clockwise = false)
{
  Polygon p;
  for (int i = 0; i < n; ++i)
  {
    const double a = 2.0 * Pi * (clockwise ? -i : i) / n + 0.1;
    p.push_back({ center.x + radius * std::cos(a), center.y + radius * std::sin(a) });
  }
  return p;
}

Polygon Rectangle(double x0, double y0, double x1, double y1)
{
  return { { x0, y0 }, { x1, y0 }, { x1, y1 }, { x0, y1 } };
}

double ShoelaceArea(const Polygon& p)
{
  double area = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
  {
    area += Cross(p[i], p[(i + 1) % p.size()]);
  }
  return 0.5 * area;
}

/// The part of polygon p with x >= x0 (Sutherland-Hodgman against one vertical line).
Polygon ClipRightOf(const Polygon& p, double x0)
{
  Polygon out;
  for (std::size_t i = 0; i < p.size(); ++i)
  {
    const Vec2 a = p[i], b = p[(i + 1) % p.size()];
    const bool inA = a.x >= x0, inB = b.x >= x0;
    if (inA)
    {
      out.push_back(a);
    }
    if (inA != inB)
    {
      const double s = (x0 - a.x) / (b.x - a.x);
      out.push_back({ x0, a.y + s * (b.y - a.y) });
    }
  }
  return out;
}

bool Inside(const Polygon& p, Vec2 x)
{
  bool inside = false;
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++)
  {
    if ((p[i].y > x.y) != (p[j].y > x.y) &&
      x.x < (p[j].x - p[i].x) * (x.y - p[i].y) / (p[j].y - p[i].y) + p[i].x)
    {
      inside = !inside;
    }
  }
  return inside;
}

/// A flat irregular square [0, 1]^2, the polygons traced on it as closed curves, and their
/// arrangement.
struct FlatScene
{
  TriangleMesh Mesh;
  std::vector<Polygon> Polygons;
  std::vector<TracedCurve> Curves;
  Arrangement Arr;
  std::vector<int> JumpTriangles;

  /// `jitter` 0: the regular grid, whose vertices fall on round coordinates.
  FlatScene(int cells, std::vector<Polygon> polygons, double jitter = 0.4)
    : Polygons(std::move(polygons))
  {
    const MeshData d = MakeFlatSquare(cells, 1.0, jitter, 5);
    this->Mesh = TriangleMesh(d.Positions, d.Triangles);
    FlatPolygonTracer tracer(this->Mesh);
    for (std::size_t i = 0; i < this->Polygons.size(); ++i)
    {
      TracedCurve c;
      EXPECT_TRUE(tracer.Trace(this->Polygons[i], true, 0, static_cast<int>(i), c));
      this->Curves.push_back(c);
    }
    ArrangementOptions options;
    options.Threads = 1;
    std::string error;
    EXPECT_TRUE(ComputeArrangement(this->Mesh, this->Curves, options, this->Arr, error)) << error;
    this->JumpTriangles = this->TrianglesTouchingCurves();
  }

  /// Refined triangles with a corner on a curve: where a field that is constant per cell can
  /// jump.
  std::vector<int> TrianglesTouchingCurves() const
  {
    std::vector<char> onCurve(this->Arr.GetNumberOfPoints(), 0);
    for (const auto& points : this->Arr.CurvePoints)
    {
      for (int p : points)
      {
        onCurve[p] = 1;
      }
    }
    std::vector<int> touching;
    for (int r = 0; r < this->Arr.GetNumberOfTriangles(); ++r)
    {
      const Triangle t = this->Arr.GetTriangle(this->Mesh, r);
      if (t[0] >= 0 && (onCurve[t[0]] || onCurve[t[1]] || onCurve[t[2]]))
      {
        touching.push_back(r);
      }
    }
    return touching;
  }

  Vec3 Corner(int r, int k) const
  {
    return this->Arr.GetPosition(this->Mesh, this->Arr.GetTriangle(this->Mesh, r)[k]);
  }
  Vec2 Centroid(int r) const
  {
    const Vec3 g = (1.0 / 3.0) * (this->Corner(r, 0) + this->Corner(r, 1) + this->Corner(r, 2));
    return { g.x, g.y };
  }
  /// Number of polygons whose inside holds refined triangle r.
  int Depth(int r) const
  {
    int depth = 0;
    for (const Polygon& p : this->Polygons)
    {
      depth += Inside(p, this->Centroid(r)) ? 1 : 0;
    }
    return depth;
  }

  LevelSetInput Input(double threshold, std::function<double(int, int)> value) const
  {
    LevelSetInput in;
    in.Threshold = threshold;
    in.CornerValue = std::move(value);
    in.JumpTriangles = &this->JumpTriangles;
    return in;
  }

  std::vector<LevelSetLoop> Extract(const LevelSetInput& in) const
  {
    std::vector<LevelSetLoop> loops;
    std::string error;
    EXPECT_TRUE(ExtractLevelSet(this->Mesh, this->Arr, in, loops, error)) << error;
    return loops;
  }
};

Polygon PlanarLoop(const TriangleMesh& mesh, const LevelSetLoop& loop)
{
  Polygon p;
  for (const CanonicalPoint& c : loop.Points)
  {
    const Vec3 x = PositionOf(mesh, c);
    p.push_back({ x.x, x.y });
  }
  return p;
}

double TotalArea(const TriangleMesh& mesh, const std::vector<LevelSetLoop>& loops)
{
  double area = 0;
  for (const LevelSetLoop& loop : loops)
  {
    area += ShoelaceArea(PlanarLoop(mesh, loop));
  }
  return area;
}

/// Every loop is a valid closed TracedCurve: valid points, no consecutive repeats, consecutive
/// points in a common triangle, written forms that read back to the points, and the length.
void ExpectValidLoops(const TriangleMesh& mesh, const std::vector<LevelSetLoop>& loops)
{
  for (std::size_t l = 0; l < loops.size(); ++l)
  {
    const LevelSetLoop& loop = loops[l];
    const int n = static_cast<int>(loop.Points.size());
    ASSERT_GE(n, 3) << "loop " << l;
    ASSERT_EQ(loop.SurfacePoints.size(), loop.Points.size());
    double length = 0;
    for (int i = 0; i < n; ++i)
    {
      const CanonicalPoint &a = loop.Points[i], &b = loop.Points[(i + 1) % n];
      std::string problem;
      EXPECT_TRUE(CheckCanonicalPoint(mesh, a, problem)) << problem;
      EXPECT_FALSE(a == b) << "loop " << l << " repeats point " << i;
      EXPECT_GE(SharedTriangle(mesh, a, b), 0)
        << "loop " << l << ": " << Describe(a) << " and " << Describe(b) << " share no triangle";
      // Bit for bit except on an edge whose second vertex is corner 0 of both its triangles,
      // where WriteSurfacePoint can only give the parameter as 1 - (the other weight).
      const CanonicalPoint read = LocateSurfacePoint(mesh, loop.SurfacePoints[i]);
      EXPECT_TRUE(read.Location == a.Location && read.Id == a.Id) << Describe(a);
      EXPECT_NEAR(read.T, a.T, 1e-15) << Describe(a);
      EXPECT_TRUE(read.U == a.U && read.V == a.V) << Describe(a);
      length += Length(PositionOf(mesh, b) - PositionOf(mesh, a));
    }
    EXPECT_NEAR(loop.Length, length, 1e-12);
  }
}

/// Whether `loop` is `points` up to a rotation of the start.
bool SameCycle(const std::vector<CanonicalPoint>& loop, const std::vector<CanonicalPoint>& points)
{
  if (loop.size() != points.size() || loop.empty())
  {
    return false;
  }
  const auto start = std::find(points.begin(), points.end(), loop.front());
  if (start == points.end())
  {
    return false;
  }
  const std::size_t offset = static_cast<std::size_t>(start - points.begin());
  for (std::size_t i = 0; i < loop.size(); ++i)
  {
    if (!(loop[i] == points[(offset + i) % points.size()]))
    {
      return false;
    }
  }
  return true;
}

} // namespace

TEST(WindingLevelSet, ClosedPolygonIsItsOwnLevelSet)
{
  for (const bool clockwise : { false, true })
  {
    SCOPED_TRACE(clockwise ? "clockwise" : "counter-clockwise");
    const FlatScene scene(12, { CirclePolygon({ 0.5, 0.47 }, 0.31, 24, clockwise) });
    std::vector<int> depth(scene.Arr.GetNumberOfTriangles());
    for (int r = 0; r < scene.Arr.GetNumberOfTriangles(); ++r)
    {
      depth[r] = scene.Depth(r);
    }
    const auto loops = scene.Extract(scene.Input(0.5, [&](int r, int) { return depth[r]; }));
    ASSERT_EQ(loops.size(), 1u);
    ExpectValidLoops(scene.Mesh, loops);

    // The curve on the refined surface, counter-clockwise: the level set with 1 on its left.
    std::vector<CanonicalPoint> curve;
    double curveLength = 0;
    const std::vector<int>& ids = scene.Arr.CurvePoints[0];
    for (std::size_t i = 0; i < ids.size(); ++i)
    {
      curve.push_back(scene.Arr.GetPointOnMesh(ids[i]));
      curveLength += Length(scene.Arr.GetPosition(scene.Mesh, ids[(i + 1) % ids.size()]) -
        scene.Arr.GetPosition(scene.Mesh, ids[i]));
    }
    if (clockwise)
    {
      std::reverse(curve.begin(), curve.end());
    }
    EXPECT_TRUE(SameCycle(loops[0].Points, curve));
    EXPECT_NEAR(loops[0].Length, curveLength, 1e-12);
    EXPECT_GT(TotalArea(scene.Mesh, loops), 0.0);
  }
}

TEST(WindingLevelSet, LinearFieldIsAStraightLineClosedAlongTheBoundary)
{
  const double t = 0.37;
  // Without curves, and with a curve across the line whose triangles are listed as jump
  // triangles although the field does not jump there.
  for (const bool withCurve : { false, true })
  {
    SCOPED_TRACE(withCurve ? "with a curve" : "without curves");
    std::vector<Polygon> polygons;
    if (withCurve)
    {
      polygons.push_back(CirclePolygon({ 0.4, 0.5 }, 0.2, 16));
    }
    const FlatScene scene(16, polygons);
    const auto loops =
      scene.Extract(scene.Input(t, [&](int r, int k) { return scene.Corner(r, k).x; }));
    ASSERT_EQ(loops.size(), 1u);
    ExpectValidLoops(scene.Mesh, loops);
    EXPECT_NEAR(TotalArea(scene.Mesh, loops), 1.0 - t, 1e-12);
    EXPECT_NEAR(loops[0].Length, 1.0 + 2.0 * (1.0 - t) + 1.0, 1e-12);
    for (const CanonicalPoint& c : loops[0].Points)
    {
      const Vec3 x = PositionOf(scene.Mesh, c);
      const bool onLine = std::abs(x.x - t) < 1e-12;
      const bool onBoundary = x.x == 1.0 || x.y == 0.0 || x.y == 1.0;
      EXPECT_TRUE(onLine || (onBoundary && x.x > t)) << Describe(c);
    }
  }
}

TEST(WindingLevelSet, JumpFieldFollowsTheCurveWhereTheJumpStraddles)
{
  const Polygon circle = CirclePolygon({ 0.5, 0.5 }, 0.3, 32);
  const FlatScene scene(14, { circle });
  std::vector<int> depth(scene.Arr.GetNumberOfTriangles());
  for (int r = 0; r < scene.Arr.GetNumberOfTriangles(); ++r)
  {
    depth[r] = scene.Depth(r);
  }
  auto value = [&](int r, int k) { return scene.Corner(r, k).x + depth[r]; };
  const Polygon square = Rectangle(0, 0, 1, 1);
  const double circleArea = ShoelaceArea(circle);
  struct Case
  {
    double Threshold;
    std::size_t Loops;
    double Area; // of {x + inside >= threshold}: inside parts with x >= t - 1, outside x >= t
  };
  const Case cases[] = {
    // Inside only: the iso line x = 0.3 closed by the curve's arc on its right.
    { 1.3, 1, ShoelaceArea(ClipRightOf(circle, 0.3)) },
    // The strip x >= 0.75 outside and the whole disc inside: they overlap into one region,
    // bounded by the iso line, the boundary and the curve.
    { 0.75, 1, circleArea + 0.25 - ShoelaceArea(ClipRightOf(circle, 0.75)) },
    // The strip x >= 0.9 and the disc, apart.
    { 0.9, 2, circleArea + ShoelaceArea(ClipRightOf(square, 0.9)) },
  };
  for (const Case& c : cases)
  {
    SCOPED_TRACE("threshold " + std::to_string(c.Threshold));
    const auto loops = scene.Extract(scene.Input(c.Threshold, value));
    ASSERT_EQ(loops.size(), c.Loops);
    ExpectValidLoops(scene.Mesh, loops);
    EXPECT_NEAR(TotalArea(scene.Mesh, loops), c.Area, 1e-12);
    for (const LevelSetLoop& loop : loops)
    {
      EXPECT_GT(ShoelaceArea(PlanarLoop(scene.Mesh, loop)), 0.0);
    }
    // Partly the curve (its refined points), partly the iso line.
    int curvePoints = 0, isoPoints = 0;
    for (const LevelSetLoop& loop : loops)
    {
      for (const CanonicalPoint& p : loop.Points)
      {
        const Vec3 x = PositionOf(scene.Mesh, p);
        isoPoints += std::abs(x.x - (c.Threshold > 1 ? c.Threshold - 1 : c.Threshold)) < 1e-12;
        for (int id : scene.Arr.CurvePoints[0])
        {
          if (scene.Arr.GetPointOnMesh(id) == p)
          {
            ++curvePoints;
            break;
          }
        }
      }
    }
    EXPECT_GT(curvePoints, 3);
    EXPECT_GT(isoPoints, 3);
  }
}

TEST(WindingLevelSet, DisjointAndNestedRegionsGiveOrientedLoops)
{
  {
    SCOPED_TRACE("two disjoint squares");
    const FlatScene scene(
      10, { Rectangle(0.12, 0.15, 0.41, 0.8), Rectangle(0.55, 0.2, 0.9, 0.62) });
    const auto loops = scene.Extract(
      scene.Input(0.5, [&](int r, int) { return static_cast<double>(scene.Depth(r)); }));
    ASSERT_EQ(loops.size(), 2u);
    ExpectValidLoops(scene.Mesh, loops);
    std::vector<double> areas;
    for (const LevelSetLoop& loop : loops)
    {
      areas.push_back(ShoelaceArea(PlanarLoop(scene.Mesh, loop)));
    }
    std::sort(areas.begin(), areas.end());
    EXPECT_NEAR(areas[0], 0.35 * 0.42, 1e-12);
    EXPECT_NEAR(areas[1], 0.29 * 0.65, 1e-12);
  }
  const Polygon outer = Rectangle(0.1, 0.12, 0.88, 0.9),
                inner = CirclePolygon({ 0.5, 0.5 }, 0.2, 20);
  const FlatScene scene(12, { outer, inner });
  std::vector<int> depth(scene.Arr.GetNumberOfTriangles());
  for (int r = 0; r < scene.Arr.GetNumberOfTriangles(); ++r)
  {
    depth[r] = scene.Depth(r);
  }
  {
    SCOPED_TRACE("nested: 0, 1, 2");
    const auto value = [&](int r, int) { return static_cast<double>(depth[r]); };
    for (const double t : { 0.5, 1.5 })
    {
      const auto loops = scene.Extract(scene.Input(t, value));
      ASSERT_EQ(loops.size(), 1u);
      ExpectValidLoops(scene.Mesh, loops);
      EXPECT_NEAR(TotalArea(scene.Mesh, loops), ShoelaceArea(t < 1 ? outer : inner), 1e-12);
    }
  }
  {
    SCOPED_TRACE("annulus: 0, 1, 0");
    const auto loops =
      scene.Extract(scene.Input(0.5, [&](int r, int) { return depth[r] == 1 ? 1.0 : 0.0; }));
    ASSERT_EQ(loops.size(), 2u);
    ExpectValidLoops(scene.Mesh, loops);
    std::vector<double> areas;
    for (const LevelSetLoop& loop : loops)
    {
      areas.push_back(ShoelaceArea(PlanarLoop(scene.Mesh, loop)));
    }
    std::sort(areas.begin(), areas.end());
    EXPECT_NEAR(areas[0], -ShoelaceArea(inner), 1e-12); // the hole, clockwise
    EXPECT_NEAR(areas[1], ShoelaceArea(outer), 1e-12);
  }
}

TEST(WindingLevelSet, ValuesAtTheThresholdCloseWithoutSpikes)
{
  // On the regular 8 x 8 grid, w = x equals 3/8 on a whole column of vertices and 1 on the
  // right side: corner values at the threshold count as above.
  const FlatScene grid(8, {}, 0.0);
  const auto x = [&](int r, int k) { return grid.Corner(r, k).x; };
  struct Case
  {
    double Threshold;
    std::size_t Loops;
    double Area;
  };
  // 0: the whole square, bounded by the boundary; 1: the right side only, a region of no width
  // (its loop up the boundary and back down the iso points collapses).
  for (const Case& c : { Case{ 0.375, 1, 0.625 }, Case{ 0.0, 1, 1.0 }, Case{ 1.0, 0, 0.0 } })
  {
    SCOPED_TRACE("threshold " + std::to_string(c.Threshold));
    const auto loops = grid.Extract(grid.Input(c.Threshold, x));
    ASSERT_EQ(loops.size(), c.Loops);
    ExpectValidLoops(grid.Mesh, loops);
    EXPECT_NEAR(TotalArea(grid.Mesh, loops), c.Area, 1e-15);
  }
  {
    SCOPED_TRACE("a constant field at the threshold: all above");
    const auto loops = grid.Extract(grid.Input(0.5, [](int, int) { return 0.5; }));
    ASSERT_EQ(loops.size(), 1u);
    ExpectValidLoops(grid.Mesh, loops);
    EXPECT_NEAR(TotalArea(grid.Mesh, loops), 1.0, 1e-15);
    EXPECT_NEAR(loops[0].Length, 4.0, 1e-14);
  }
  {
    // Two squares of the checkerboard touching at a corner: 2 in and 2 out there, paired in
    // a fixed order; either way the loops bound both squares.
    const FlatScene touching(
      8, { Rectangle(0.25, 0.25, 0.5, 0.5), Rectangle(0.5, 0.5, 0.75, 0.75) }, 0.0);
    const auto loops = touching.Extract(
      touching.Input(0.5, [&](int r, int) { return static_cast<double>(touching.Depth(r)); }));
    ASSERT_GE(loops.size(), 1u);
    ExpectValidLoops(touching.Mesh, loops);
    EXPECT_NEAR(TotalArea(touching.Mesh, loops), 2 * 0.0625, 1e-15);
    std::size_t points = 0;
    for (const LevelSetLoop& loop : loops)
    {
      points += loop.Points.size();
    }
    EXPECT_EQ(points, 16u); // 8 grid points around each square, the shared corner in both
  }
}

TEST(WindingLevelSet, CurveAlongTheBoundaryBoundsItsRegion)
{
  // A rectangle whose left, bottom and top sides run along the mesh's boundary, 1 inside: on
  // those sides only one triangle carries the region, and the boundary closes it.
  const Polygon half = Rectangle(0.0, 0.0, 0.45, 1.0);
  const FlatScene scene(10, { half });
  const auto loops = scene.Extract(
    scene.Input(0.5, [&](int r, int) { return static_cast<double>(scene.Depth(r)); }));
  ASSERT_EQ(loops.size(), 1u);
  ExpectValidLoops(scene.Mesh, loops);
  EXPECT_NEAR(TotalArea(scene.Mesh, loops), 0.45, 1e-12);
  EXPECT_NEAR(loops[0].Length, 2.9, 1e-12);
}

TEST(WindingLevelSet, NonFiniteValueNamesTheTriangle)
{
  const FlatScene scene(6, { CirclePolygon({ 0.5, 0.5 }, 0.3, 12) });
  const int bad = scene.Arr.GetNumberOfTriangles() - 2; // a piece of a refined triangle
  for (const double nonFinite :
    { std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity() })
  {
    const LevelSetInput in = scene.Input(
      0.5, [&](int r, int k) { return r == bad && k == 1 ? nonFinite : scene.Corner(r, k).x; });
    std::vector<LevelSetLoop> loops;
    std::string error;
    EXPECT_FALSE(ExtractLevelSet(scene.Mesh, scene.Arr, in, loops, error));
    EXPECT_NE(error.find("refined triangle " + std::to_string(bad) + " "), std::string::npos)
      << error;
    EXPECT_TRUE(loops.empty());
  }
}

TEST(WindingLevelSet, ValuesThatJumpWhereNoJumpIsListedAreRefused)
{
  // A field constant per cell, but no jump triangles listed: the segments along the curve are
  // missing and the iso-free triangles cannot close.
  const FlatScene scene(8, { CirclePolygon({ 0.5, 0.5 }, 0.3, 12) });
  LevelSetInput in =
    scene.Input(0.5, [&](int r, int k) { return scene.Corner(r, k).x + scene.Depth(r); });
  in.Threshold = 1.4; // the iso line x = 0.4 inside the disc ends on the curve
  in.JumpTriangles = nullptr;
  std::vector<LevelSetLoop> loops;
  std::string error;
  EXPECT_FALSE(ExtractLevelSet(scene.Mesh, scene.Arr, in, loops, error));
  EXPECT_NE(error.find("refined triangle"), std::string::npos) << error;
}

TEST(WindingLevelSet, LoopChainsBackIntoAnArrangement)
{
  // The level set of a jump field (iso line and curve arc) as a control curve of its own.
  const Polygon circle = CirclePolygon({ 0.5, 0.5 }, 0.3, 32);
  const FlatScene scene(14, { circle });
  std::vector<int> depth(scene.Arr.GetNumberOfTriangles());
  for (int r = 0; r < scene.Arr.GetNumberOfTriangles(); ++r)
  {
    depth[r] = scene.Depth(r);
  }
  const auto loops =
    scene.Extract(scene.Input(1.3, [&](int r, int k) { return scene.Corner(r, k).x + depth[r]; }));
  ASSERT_EQ(loops.size(), 1u);
  TracedCurve curve;
  curve.Points = loops[0].Points;
  curve.Closed = true;
  Arrangement arr;
  ArrangementOptions options;
  options.Threads = 1;
  std::string error;
  ASSERT_TRUE(ComputeArrangement(scene.Mesh, { curve }, options, arr, error)) << error;
  EXPECT_EQ(arr.NumberOfCells, 2);
  // One of the two cells is the region the loop encloses.
  std::vector<double> cellArea(arr.NumberOfCells, 0.0);
  for (int r = 0; r < arr.GetNumberOfTriangles(); ++r)
  {
    const Triangle t = arr.GetTriangle(scene.Mesh, r);
    const Vec3 a = arr.GetPosition(scene.Mesh, t[0]), b = arr.GetPosition(scene.Mesh, t[1]),
               c = arr.GetPosition(scene.Mesh, t[2]);
    cellArea[arr.CellOfTriangle(r)] +=
      0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  }
  const double enclosed = ShoelaceArea(PlanarLoop(scene.Mesh, loops[0]));
  EXPECT_NEAR(
    std::min(std::abs(cellArea[0] - enclosed), std::abs(cellArea[1] - enclosed)), 0.0, 1e-12);
}

TEST(WindingLevelSet, HeightOnASphereIsOneCircleAroundTheCap)
{
  // A closed surface: no boundary, the iso line only. Seen from above (+z, the outward normal
  // of the cap), the cap {z >= 0.2} is on the loop's left: counter-clockwise in the xy plane.
  const MeshData d = MakeIcosphere(4);
  const TriangleMesh mesh(d.Positions, d.Triangles);
  Arrangement arr;
  ArrangementOptions options;
  options.Threads = 1;
  std::string error;
  ASSERT_TRUE(ComputeArrangement(mesh, {}, options, arr, error)) << error;
  LevelSetInput in;
  in.Threshold = 0.2;
  in.CornerValue = [&](int r, int k)
  { return arr.GetPosition(mesh, arr.GetTriangle(mesh, r)[k]).z; };
  std::vector<LevelSetLoop> loops;
  ASSERT_TRUE(ExtractLevelSet(mesh, arr, in, loops, error)) << error;
  ASSERT_EQ(loops.size(), 1u);
  ExpectValidLoops(mesh, loops);
  for (const CanonicalPoint& c : loops[0].Points)
  {
    EXPECT_NEAR(PositionOf(mesh, c).z, 0.2, 1e-12);
  }
  EXPECT_GT(ShoelaceArea(PlanarLoop(mesh, loops[0])), 0.0);
  // The circle of radius sqrt(1 - 0.2^2), a little shorter as a polygon inscribed in it.
  const double circle = 2.0 * Pi * std::sqrt(1.0 - 0.04);
  EXPECT_LT(loops[0].Length, circle);
  EXPECT_GT(loops[0].Length, 0.99 * circle);
}

TEST(WindingLevelSet, DISABLED_TimingOnAMillionTriangles)
{
  // Run with --gtest_also_run_disabled_tests: the scan over about 1M refined triangles.
  // Corner values read from an array, as the winding stage hands them over.
  const FlatScene scene(708, { CirclePolygon({ 0.5, 0.5 }, 0.3, 64) });
  std::vector<double> values(3 * static_cast<std::size_t>(scene.Arr.GetNumberOfTriangles()));
  for (int r = 0; r < scene.Arr.GetNumberOfTriangles(); ++r)
  {
    const int depth = scene.Depth(r);
    for (int k = 0; k < 3; ++k)
    {
      values[3 * r + k] = scene.Corner(r, k).x + depth;
    }
  }
  const LevelSetInput in = scene.Input(1.3, [&](int r, int k) { return values[3 * r + k]; });
  std::vector<LevelSetLoop> loops;
  std::string error;
  double best = 1e9;
  for (int run = 0; run < 5; ++run)
  {
    const auto start = std::chrono::steady_clock::now();
    ASSERT_TRUE(ExtractLevelSet(scene.Mesh, scene.Arr, in, loops, error)) << error;
    best = std::min(best,
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  ASSERT_EQ(loops.size(), 1u);
  std::printf("%d refined triangles, %zu loop points: %.2f ms\n",
    scene.Arr.GetNumberOfTriangles(),
    loops[0].Points.size(),
    best);
}

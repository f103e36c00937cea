// The control curve's one validity check: every point a usable surface point inside its
// triangle up to Core's one tolerance, two distinct points, a count its type can trace; and
// the rule that an open curve whose ends meet is closed.
#include "Curves/ControlCurve.h"
#include "Mesh/ProceduralMeshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace
{
using namespace boolsurf;

TriangleMesh Square()
{
  const MeshData data = MakeFlatSquare(2);
  return TriangleMesh(data.Positions, data.Triangles);
}

ControlCurve Polygon(std::vector<SurfacePoint> points, bool closed = true)
{
  ControlCurve c;
  c.Type = CurveType::GeodesicPolygon;
  c.Closed = closed;
  c.Points = std::move(points);
  return c;
}

TEST(ControlCurve, ValidCurvesPass)
{
  const TriangleMesh mesh = Square();
  std::string problem;
  EXPECT_TRUE(CheckControlCurve(mesh, Polygon({ { 0, 0.2, 0.2 }, { 3, 0.3, 0.3 } }), problem))
    << problem;
  ControlCurve bezier = Polygon({ { 0, 0.2, 0.2 }, { 1, 0.2, 0.2 }, { 2, 0.2, 0.2 } });
  bezier.Type = CurveType::CubicBezier;
  EXPECT_TRUE(CheckControlCurve(mesh, bezier, problem)) << problem;
  bezier.Closed = false;
  bezier.Points.push_back({ 3, 0.2, 0.2 });
  EXPECT_TRUE(CheckControlCurve(mesh, bezier, problem)) << problem;
}

TEST(ControlCurve, PointsInsideTheirTriangleUpToTheOneTolerance)
{
  const TriangleMesh mesh = Square();
  std::string problem;
  const double in = 0.5 * InsideTriangleTolerance, out = 2 * InsideTriangleTolerance;
  EXPECT_TRUE(CheckControlCurve(mesh, Polygon({ { 0, -in, 0.5 }, { 3, 0.5, 0.5 + in } }), problem))
    << problem;
  for (const SurfacePoint& bad : { SurfacePoint{ 0, -out, 0.5 },
         SurfacePoint{ 0, 0.5, -out },
         SurfacePoint{ 0, 0.5, 0.5 + out } })
  {
    EXPECT_FALSE(CheckControlCurve(mesh, Polygon({ { 3, 0.2, 0.2 }, bad }), problem));
    EXPECT_NE(problem.find("control point 1: barycentric coordinates"), std::string::npos)
      << problem;
    EXPECT_NE(problem.find("lie outside triangle 0"), std::string::npos) << problem;
  }
  EXPECT_TRUE(IsInsideTriangle(0, 1));
  EXPECT_FALSE(IsInsideTriangle(std::nan(""), 0.5));
  EXPECT_FALSE(IsInsideTriangle(0.5, std::numeric_limits<double>::infinity()));
}

TEST(ControlCurve, UnusablePointsAreNamed)
{
  const TriangleMesh mesh = Square();
  std::string problem;
  EXPECT_FALSE(CheckControlCurve(mesh, Polygon({ { 0, 0.2, 0.2 }, { 99, 0.2, 0.2 } }), problem));
  EXPECT_NE(problem.find("control point 1: triangle id 99 is out of range"), std::string::npos)
    << problem;
  EXPECT_FALSE(CheckControlCurve(mesh, Polygon({ { -1, 0.2, 0.2 }, { 1, 0.2, 0.2 } }), problem));
  EXPECT_NE(problem.find("control point 0: triangle id -1"), std::string::npos) << problem;
}

TEST(ControlCurve, TwoDistinctPointsAreNeeded)
{
  const TriangleMesh mesh = Square();
  std::string problem;
  EXPECT_FALSE(CheckControlCurve(mesh, Polygon({ { 0, 0.2, 0.2 } }), problem));
  EXPECT_NE(
    problem.find("1 control point(s): a curve needs two distinct points"), std::string::npos)
    << problem;
  EXPECT_FALSE(CheckControlCurve(mesh, Polygon({ { 0, 0.2, 0.2 }, { 0, 0.2, 0.2 } }), problem));
  EXPECT_NE(problem.find("all at the same surface point"), std::string::npos) << problem;
  EXPECT_FALSE(HasDistinctPoints(Polygon({})));
  EXPECT_TRUE(HasDistinctPoints(Polygon({ { 0, 0.2, 0.2 }, { 0, 0.2, 0.3 } })));
}

TEST(ControlCurve, BezierCountsFollowClosedness)
{
  const TriangleMesh mesh = Square();
  std::string problem;
  ControlCurve c = Polygon(
    { { 0, 0.2, 0.2 }, { 1, 0.2, 0.2 }, { 2, 0.2, 0.2 }, { 3, 0.2, 0.2 }, { 4, 0.2, 0.2 } }, false);
  c.Type = CurveType::CubicBezier;
  EXPECT_FALSE(CheckControlCurve(mesh, c, problem));
  EXPECT_EQ(problem,
    "an open cubic Bezier spline needs 3n+1 control points (anchor, handle, handle, anchor, "
    "...); it has 5: 2 more complete it");
  c.Closed = true;
  EXPECT_FALSE(CheckControlCurve(mesh, c, problem));
  EXPECT_EQ(problem,
    "a closed cubic Bezier spline needs 3n control points (anchor, handle, handle, anchor, "
    "...); it has 5: 1 more completes it");
  EXPECT_EQ(WhatCurveNeeds(false, true, 1), "a geodesic polygon needs 2 control points; it has 1");
  EXPECT_EQ(WhatCurveNeeds(true, true, 6), "");
  EXPECT_EQ(WhatCurveNeeds(true, false, 7), "");
}

TEST(ControlCurve, OpenCurveWhoseEndsMeetIsClosed)
{
  ControlCurve c = Polygon({ { 0, 0.2, 0.2 }, { 1, 0.2, 0.2 }, { 0, 0.2, 0.2 } }, false);
  EXPECT_TRUE(CloseWhereEndsMeet(c));
  EXPECT_TRUE(c.Closed);
  EXPECT_EQ(c.Points.size(), 2u);
  // Already closed, too short, or ends a bit apart: unchanged.
  EXPECT_FALSE(CloseWhereEndsMeet(c));
  ControlCurve two = Polygon({ { 0, 0.2, 0.2 }, { 0, 0.2, 0.2 } }, false);
  EXPECT_FALSE(CloseWhereEndsMeet(two));
  ControlCurve apart =
    Polygon({ { 0, 0.2, 0.2 }, { 1, 0.2, 0.2 }, { 0, 0.2, 0.2 + 1e-15 } }, false);
  EXPECT_FALSE(CloseWhereEndsMeet(apart));
  EXPECT_FALSE(apart.Closed);
}

} // namespace

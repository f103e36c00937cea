// A scene's points on a surface without VTK: on the mesh its faces index ((1-u-v) p0 + u p1 +
// v p2 after clamping), and a screen-space scene's polylines scaled into [0.1, 0.9]^2, turned
// counter-clockwise and located on the flat grid MakeFlatSquare (exactly the grid the scene
// reader has always made).
#include "Scene/SceneJson.h"
#include "Scene/ScenePlacement.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

using namespace boolsurf;

namespace
{
SceneModel Parse(const std::string& text)
{
  std::istringstream in(text);
  SceneModel scene;
  std::string error;
  EXPECT_TRUE(ParseSceneJson(in, scene, error)) << error;
  return scene;
}

/// Twice the signed area of a polygon's points (x, y), counter-clockwise positive.
double Area2(const SceneModel& scene, const ScenePolygon& polygon)
{
  double area2 = 0;
  for (std::size_t k = 0; k < polygon.Points.size(); ++k)
  {
    const Vec3& p = scene.Points[polygon.Points[k]].Position;
    const Vec3& q = scene.Points[polygon.Points[(k + 1) % polygon.Points.size()]].Position;
    area2 += p.x * q.y - q.x * p.y;
  }
  return area2;
}
} // namespace

TEST(ScenePlacement, PointsAtTheirBarycentricPositionAfterClamping)
{
  MeshData mesh;
  mesh.Positions = { { 0, 0, 0 }, { 2, 0, 0 }, { 0, 4, 1 }, { 2, 4, 3 } };
  mesh.Triangles = { { 0, 1, 2 }, { 3, 2, 1 } };
  SceneModel s = Parse(R"({"model": "m.ply", "points": [{"face": 0, "uv": [0.25, 0.5]},
    {"face": 1, "uv": [-5e-7, 0.5]}, {"face": 1, "uv": [0.6000004, 0.4]}],
    "polygons": [[0, 1, 2]]})");
  std::string error;
  ASSERT_TRUE(PlaceScenePoints(s, mesh, "m.ply", error)) << error;
  EXPECT_EQ(s.Points[0].Position.x, 0.25 * 2);
  EXPECT_EQ(s.Points[0].Position.y, 0.5 * 4);
  EXPECT_EQ(s.Points[0].Position.z, 0.5 * 1);
  // u = -5e-7 is within the tolerance: clamped to 0, the point is on edge (p0, p2).
  EXPECT_EQ(s.Points[1].U, 0.0);
  EXPECT_EQ(s.Points[1].V, 0.5);
  EXPECT_EQ(s.Points[1].Position.x, 0.5 * 2 + 0.5 * 2);
  EXPECT_EQ(s.Points[1].Position.y, 0.5 * 4 + 0.5 * 0);
  EXPECT_EQ(s.Points[1].Position.z, 0.5 * 3);
  // u + v a little over 1: scaled back onto edge (p1, p2).
  EXPECT_LE(s.Points[2].U + s.Points[2].V, 1.0);
  EXPECT_NEAR(s.Points[2].U, 0.6, 1e-6);

  // A face beyond the mesh is an error quoting it as written.
  SceneModel far = Parse(R"({"model": "m.ply", "points": [{"face": 2.0, "uv": [0.1, 0.1]}],
    "polygons": [[0, 0]]})");
  EXPECT_FALSE(PlaceScenePoints(far, mesh, "dir/m.ply", error))
    << "face 2 of a 2-triangle mesh placed";
  EXPECT_EQ(error,
    "'points'[0].face = 2.0 is out of range: mesh dir/m.ply has 2 "
    "triangles");
}

// MakeFlatSquare(n) is the grid the reader made: vertex (i, j) at exactly (i / n, j / n),
// quad (i, j) split into (p00, p10, p11), (p00, p11, p01).
TEST(ScenePlacement, FlatSquareIsTheScreenSpaceGrid)
{
  for (int n : { 1, 3, 7, 10, 64 })
  {
    const MeshData grid = MakeFlatSquare(n);
    ASSERT_EQ(grid.Positions.size(), static_cast<std::size_t>((n + 1) * (n + 1)));
    ASSERT_EQ(grid.Triangles.size(), static_cast<std::size_t>(2 * n * n));
    for (int j = 0; j <= n; ++j)
    {
      for (int i = 0; i <= n; ++i)
      {
        const Vec3& p = grid.Positions[j * (n + 1) + i];
        ASSERT_EQ(p.x, double(i) / n) << n << " " << i << " " << j;
        ASSERT_EQ(p.y, double(j) / n) << n << " " << i << " " << j;
        ASSERT_EQ(p.z, 0.0);
      }
    }
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const int q = j * n + i, a = j * (n + 1) + i;
        EXPECT_EQ(grid.Triangles[2 * q], (std::array<int, 3>{ a, a + 1, a + n + 2 }));
        EXPECT_EQ(grid.Triangles[2 * q + 1], (std::array<int, 3>{ a, a + n + 2, a + n + 1 }));
      }
    }
  }
}

TEST(ScenePlacement, FlatSquarePointLandsOnItsTriangle)
{
  const int n = 4;
  const MeshData grid = MakeFlatSquare(n);
  // (0.3, 0.6): quad (1, 2), above its diagonal: triangle 2 (2 * 4 + 1) + 1 = 19.
  const SurfacePoint p = FlatSquarePoint(n, 0.3, 0.6);
  EXPECT_EQ(p.Triangle, 19);
  EXPECT_EQ(grid.Triangles[19], (std::array<int, 3>{ 11, 17, 16 }));
  EXPECT_NEAR(p.U, 0.2, 1e-15);
  EXPECT_NEAR(p.V, 0.2, 1e-15);
  // Below the diagonal: the first triangle of the quad.
  EXPECT_EQ(FlatSquarePoint(n, 0.6, 0.3).Triangle, 2 * (1 * 4 + 2));
  // The far corner and points outside the square are clamped onto it.
  const SurfacePoint corner = FlatSquarePoint(n, 1.0, 1.0);
  EXPECT_EQ(corner.Triangle, 2 * 15);
  EXPECT_EQ(corner.U, 0.0);
  EXPECT_EQ(corner.V, 1.0);
  EXPECT_EQ(FlatSquarePoint(n, -3, 0.1).Triangle, FlatSquarePoint(n, 0, 0.1).Triangle);

  // Anywhere: (u, v) in the triangle and reproducing the point.
  for (int k = 0; k <= 200; ++k)
  {
    const double x = std::fmod(0.6180339887 * k, 1.0), y = std::fmod(0.4142135623 * k * k, 1.0);
    const SurfacePoint s = FlatSquarePoint(n, x, y);
    ASSERT_GE(s.Triangle, 0);
    ASSERT_LT(s.Triangle, 2 * n * n);
    EXPECT_GE(s.U, 0);
    EXPECT_GE(s.V, 0);
    EXPECT_LE(s.U + s.V, 1 + 1e-15);
    const std::array<int, 3>& t = grid.Triangles[s.Triangle];
    const Vec3 &p0 = grid.Positions[t[0]], &p1 = grid.Positions[t[1]], &p2 = grid.Positions[t[2]];
    EXPECT_NEAR((1 - s.U - s.V) * p0.x + s.U * p1.x + s.V * p2.x, x, 1e-15) << k;
    EXPECT_NEAR((1 - s.U - s.V) * p0.y + s.U * p1.y + s.V * p2.y, y, 1e-15) << k;
  }
}

TEST(ScenePlacement, ScreenSpaceNormalisedOrientedAndOnTheGrid)
{
  // A square listed (0,0) (10,0) (10,10) (0,10) in screen coordinates (y down): clockwise
  // once y points up. And an open polyline inside it.
  SceneModel s = Parse(R"({"screenspace": true,
    "polygons": [[], [[0, 0], [10, 0], [10, 10], [0, 10]], [[2, 2], [8, 3]]],
    "are_closed": [true, true, false]})");
  MeshData grid;
  std::string error;
  ASSERT_TRUE(PlaceScreenSpaceScene(s, 8, grid, error)) << error;
  EXPECT_EQ(grid.Triangles.size(), 2u * 8 * 8);
  ASSERT_EQ(s.Points.size(), 6u);
  ASSERT_EQ(s.Polygons.size(), 2u);
  EXPECT_EQ(s.Polygons[0].Points, (std::vector<int>{ 0, 1, 2, 3 }));
  EXPECT_EQ(s.Polygons[1].Points, (std::vector<int>{ 4, 5 }));
  ASSERT_FALSE(s.Notes.empty());
  EXPECT_EQ(
    s.Notes.back(), "screen-space scene: its polylines were placed on a flat grid on [0,1]^2");

  // The square is the whole extent: it fills [0.1, 0.9]^2 exactly.
  double lo[2] = { 1, 1 }, hi[2] = { 0, 0 };
  for (const ScenePoint& p : s.Points)
  {
    lo[0] = std::min(lo[0], p.Position.x);
    lo[1] = std::min(lo[1], p.Position.y);
    hi[0] = std::max(hi[0], p.Position.x);
    hi[1] = std::max(hi[1], p.Position.y);
    EXPECT_EQ(p.Position.z, 0.0);
  }
  EXPECT_NEAR(lo[0], 0.1, 1e-15);
  EXPECT_NEAR(lo[1], 0.1, 1e-15);
  EXPECT_NEAR(hi[0], 0.9, 1e-15);
  EXPECT_NEAR(hi[1], 0.9, 1e-15);
  // Turned counter-clockwise (reversed: its first point is the file's last, (0, 10), which is
  // at the bottom left once y points up).
  EXPECT_GT(Area2(s, s.Polygons[0]), 0);
  EXPECT_NEAR(s.Points[0].Position.x, 0.1, 1e-15);
  EXPECT_NEAR(s.Points[0].Position.y, 0.1, 1e-15);
  // The open polyline keeps its order: (2, 2) then (8, 3), y flipped (lower on screen).
  EXPECT_NEAR(s.Points[4].Position.x, 0.1 + 0.08 * 2, 1e-15);
  EXPECT_NEAR(s.Points[4].Position.y, 0.9 - 0.08 * 2, 1e-15);
  EXPECT_NEAR(s.Points[5].Position.y, 0.9 - 0.08 * 3, 1e-15);

  // Every point on the grid: its (face, u, v) reproduces its position.
  for (const ScenePoint& p : s.Points)
  {
    const std::array<int, 3>& t = grid.Triangles[static_cast<std::size_t>(p.Face)];
    const Vec3 &p0 = grid.Positions[t[0]], &p1 = grid.Positions[t[1]], &p2 = grid.Positions[t[2]];
    EXPECT_GE(p.U, 0);
    EXPECT_GE(p.V, 0);
    EXPECT_LE(p.U + p.V, 1 + 1e-15);
    EXPECT_NEAR((1 - p.U - p.V) * p0.x + p.U * p1.x + p.V * p2.x, p.Position.x, 1e-15);
    EXPECT_NEAR((1 - p.U - p.V) * p0.y + p.U * p1.y + p.V * p2.y, p.Position.y, 1e-15);
  }
}

TEST(ScenePlacement, ScreenSpaceKeepsTheAspectRatioAndCentres)
{
  // 40 wide, 10 high: x spans [0.1, 0.9], y the middle 0.2 of it around 0.5.
  SceneModel s = Parse(R"({"screenspace": true, "polygons": [[[100, 5], [140, 5], [140, 15]]]})");
  MeshData grid;
  std::string error;
  ASSERT_TRUE(PlaceScreenSpaceScene(s, 4, grid, error)) << error;
  double ylo = 1, yhi = 0, xlo = 1, xhi = 0;
  for (const ScenePoint& p : s.Points)
  {
    xlo = std::min(xlo, p.Position.x);
    xhi = std::max(xhi, p.Position.x);
    ylo = std::min(ylo, p.Position.y);
    yhi = std::max(yhi, p.Position.y);
  }
  EXPECT_NEAR(xlo, 0.1, 1e-14);
  EXPECT_NEAR(xhi, 0.9, 1e-14);
  EXPECT_NEAR(ylo, 0.4, 1e-14);
  EXPECT_NEAR(yhi, 0.6, 1e-14);
  // (100,5) (140,5) (140,15) on screen turns clockwise once y points up: reversed.
  EXPECT_GT(Area2(s, s.Polygons[0]), 0);
  EXPECT_NEAR(s.Points[0].Position.x, 0.9, 1e-14); // (140, 15) first
  EXPECT_NEAR(s.Points[0].Position.y, 0.4, 1e-14);
}

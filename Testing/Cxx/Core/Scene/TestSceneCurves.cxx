// A placed scene's polygons as Core's control curves: one per polygon, in its order, with its
// index, shape, type and closedness, and each point's face and (u, v) exactly; a point two
// polygons name is a point of each.
#include "Scene/SceneCurves.h"
#include "Scene/SceneJson.h"
#include "Scene/ScenePlacement.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

using namespace boolsurf;

TEST(SceneCurves, OneCurvePerPolygonWithItsPointsExactly)
{
  MeshData mesh;
  mesh.Positions = { { 0, 0, 0 }, { 2, 0, 0 }, { 0, 4, 1 }, { 2, 4, 3 } };
  mesh.Triangles = { { 0, 1, 2 }, { 3, 2, 1 } };
  std::istringstream in(R"({"model": "m.ply",
    "points": [{"face": 0, "uv": [0.25, 0.5]}, {"face": 1, "uv": [0.1, 0.3]},
               {"face": 1, "uv": [-5e-7, 0.5]}],
    "polygons": [[], [0, 1, 2], [2, 1]], "are_closed": [true, true, false],
    "shapes": [[], [2], [1]]})");
  SceneModel scene;
  std::string error;
  ASSERT_TRUE(ParseSceneJson(in, scene, error)) << error;
  ASSERT_TRUE(PlaceScenePoints(scene, mesh, "m.ply", error)) << error;

  const std::vector<ControlCurve> curves = SceneControlCurves(scene);
  ASSERT_EQ(curves.size(), 2u); // the empty polygon 0 is no curve
  EXPECT_EQ(curves[0].CurveId, 1);
  EXPECT_EQ(curves[0].ShapeId, 2);
  EXPECT_TRUE(curves[0].Closed);
  EXPECT_EQ(curves[0].Type, CurveType::GeodesicPolygon);
  EXPECT_EQ(curves[1].CurveId, 2);
  EXPECT_EQ(curves[1].ShapeId, 1);
  EXPECT_FALSE(curves[1].Closed);
  ASSERT_EQ(curves[0].Points.size(), 3u);
  ASSERT_EQ(curves[1].Points.size(), 2u);
  // Scene point 2, clamped by the placement, in both curves.
  for (const SurfacePoint& p : { curves[0].Points[2], curves[1].Points[0] })
  {
    EXPECT_EQ(p.Triangle, 1);
    EXPECT_EQ(p.U, scene.Points[2].U);
    EXPECT_EQ(p.V, 0.5);
  }
  EXPECT_EQ(curves[0].Points[0].Triangle, 0);
  EXPECT_EQ(curves[0].Points[0].U, 0.25);
  EXPECT_EQ(curves[0].Points[0].V, 0.5);
}

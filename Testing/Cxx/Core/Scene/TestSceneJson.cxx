// Scene files read into Core's SceneModel without VTK: the model of a surface scene, the
// messages for bad files (values quoted as written in the file), the order in which a file's
// problems are found, and scenes written back (EmitSceneJson) and read again.
#include "Scene/SceneJson.h"
#include "Scene/ScenePlacement.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

using namespace boolsurf;

namespace
{
SceneModel Parse(const std::string& text, const SceneParseOptions& options = {})
{
  std::istringstream in(text);
  SceneModel scene;
  std::string error;
  EXPECT_TRUE(ParseSceneJson(in, scene, error, options)) << error;
  return scene;
}

/// The message of parsing `text` ("" when it reads).
std::string ErrorOf(const std::string& text, const SceneParseOptions& options = {})
{
  std::istringstream in(text);
  SceneModel scene;
  std::string error;
  return ParseSceneJson(in, scene, error, options) ? "" : error;
}

const char* Scene = R"({
  "model": "./data/models/quads.ply",
  "points": [ {"face": 0, "uv": [0.25, 0.25]}, {"face": 1, "uv": [5E-1, 0.25]},
              {"face": 2, "uv": [0.2, 0.3]},   {"face": 3, "uv": [0.1, -1e-7]},
              {"face": 2.0, "uv": [0, 1]} ],
  "polygons": [ [], [0, 1, 2], [2, 3, 4], [3], [1, 4] ],
  "are_closed": [true, true, false, true, 1],
  "curve_types": [0, 0, 1, 0, 0],
  "shapes": [ [0], [1, 2] ],
  "operations": [ {"a": 1, "b": 3, "type": 2} ]
})";
} // namespace

TEST(SceneJson, SurfaceSceneIntoTheModel)
{
  const SceneModel s = Parse(Scene);
  EXPECT_FALSE(s.ScreenSpace);
  EXPECT_EQ(s.Model, "./data/models/quads.ply");
  ASSERT_EQ(s.Points.size(), 5u);
  EXPECT_EQ(s.Points[1].Face, 1);
  EXPECT_EQ(s.Points[1].U, 0.5);
  EXPECT_EQ(s.Points[1].V, 0.25);
  EXPECT_EQ(s.Points[1].UVText, "[5E-1,0.25]"); // as written
  EXPECT_EQ(s.Points[3].V, -1e-7);              // within the tolerance: kept until placed
  EXPECT_EQ(s.Points[4].Face, 2);
  EXPECT_EQ(s.Points[4].FaceText, "2.0");
  EXPECT_EQ(s.Points[4].UVText, "[0,1]");

  // Polygons 0 (empty) and 3 (one point) are not curves; the others keep the file's index.
  ASSERT_EQ(s.Polygons.size(), 3u);
  EXPECT_EQ(s.NumberOfPolygons, 5);
  EXPECT_EQ(s.Polygons[0].Index, 1);
  EXPECT_EQ(s.Polygons[1].Index, 2);
  EXPECT_EQ(s.Polygons[2].Index, 4);
  EXPECT_EQ(s.Polygons[0].Points, (std::vector<int>{ 0, 1, 2 }));
  EXPECT_EQ(s.Polygons[1].Points, (std::vector<int>{ 2, 3, 4 }));
  EXPECT_TRUE(s.Polygons[0].Closed);
  EXPECT_FALSE(s.Polygons[1].Closed);
  EXPECT_TRUE(s.Polygons[2].Closed); // `1` reads as true
  EXPECT_EQ(s.Polygons[1].CurveType, 1);
  EXPECT_EQ(s.Polygons[2].CurveType, 0);
  // Polygons 1 and 2 are shape 1; polygon 4 is in no shape: a new one after the file's two.
  EXPECT_EQ(s.NumberOfShapes, 2);
  EXPECT_EQ(s.Polygons[0].Shape, 1);
  EXPECT_EQ(s.Polygons[1].Shape, 1);
  EXPECT_EQ(s.Polygons[2].Shape, 2);

  ASSERT_TRUE(s.Operations.has_value());
  ASSERT_EQ(s.Operations->size(), 1u);
  EXPECT_EQ((*s.Operations)[0].A, 1);
  EXPECT_EQ((*s.Operations)[0].B, 3);
  EXPECT_EQ((*s.Operations)[0].Type, 2);
  ASSERT_EQ(s.Notes.size(), 1u);
  EXPECT_EQ(s.Notes[0], "'polygons'[3] has a single point (3): skipped, a curve needs at least 2");
}

TEST(SceneJson, DefaultsOneShapePerPolygonAllClosedNoOperations)
{
  const SceneModel s = Parse(R"({"model": "m.ply", "points": [{"face": 0, "uv": [0.1, 0.1]},
    {"face": 3, "uv": [0.1, 0.1]}], "polygons": [[], [0, 1], [1, 0]]})");
  ASSERT_EQ(s.Polygons.size(), 2u);
  EXPECT_EQ(s.NumberOfShapes, 3);
  EXPECT_EQ(s.Polygons[0].Shape, 1);
  EXPECT_EQ(s.Polygons[1].Shape, 2);
  EXPECT_TRUE(s.Polygons[0].Closed && s.Polygons[1].Closed);
  EXPECT_FALSE(s.Operations.has_value());
  EXPECT_TRUE(s.Notes.empty());
  // An empty list of operations is kept as one (written back as such).
  EXPECT_TRUE(Parse(R"({"model": "m.ply", "points": [{"face": 0, "uv": [0.1, 0.1]}],
    "polygons": [[0, 0]], "operations": []})")
                .Operations->empty());
}

TEST(SceneJson, MessagesQuoteValuesAsWritten)
{
  const std::string points = R"("points": [{"face": 0, "uv": [0.1, 0.1]},
    {"face": 1, "uv": [0.1, 0.1]}], "polygons": [[], [0, 1]])";
  struct Case
  {
    std::string Text, Message;
  };
  const std::vector<Case> cases = {
    { R"({"model": "m.ply", "points": [{"face": 1e20, "uv": [0.1, 0.1]}], "polygons": []})",
      "'points'[0].face is 1e20, not an integer in [0, 2147483647]" },
    { R"({"model": "m.ply", )" + points + R"(, "operations": [{"a": 1e300, "b": 1, "type": 0}]})",
      "'operations'[0].a is 1e300, not an integer in [0, 2147483647]" },
    { R"({"model": "m.ply", )" + points +
        R"(, "operations": [{"a": 4294967297, "b": 1, "type": 0}]})",
      "'operations'[0].a is 4294967297, not an integer in [0, 2147483647]" },
    { R"({"model": "m.ply", "points": [{"face": 0, "uv": [2.5E-1, 0.25, 0.2500]}],
          "polygons": [[0, 0]]})",
      "'points'[0].uv is [2.5E-1,0.25,0.2500], not two numbers [u, v]" },
    { R"({"model": "m.ply", "points": [{"face": 0, "uv": [0.7, 0.40]}], "polygons": [[0, 0]]})",
      "'points'[0].uv = [0.7,0.40] is outside the triangle (needs u >= 0, v >= 0, u + v <= 1)" },
    { R"({"model": "m.ply", )" + points + R"(, "curve_types": [0, 2.0]})",
      "'curve_types'[1] is 2.0: 0 geodesic polygon, 1 cubic Bezier spline" },
    { R"({"model": "m.ply", )" + points + R"(, "operations": [{"a": 1, "b": 0, "type": 4E0}]})",
      "'operations'[0].type is 4E0: 0 union, 1 difference, 2 intersection, 3 symmetric "
      "difference" },
    { R"({"model": "m.ply", )" + points + R"(, "shapes": [[1], [1.0]]})",
      "'shapes'[1][0]: polygon 1 is already in shape 0" },
    { R"({"model": "m.ply", )" + points + R"(, "shapes": [[0], [5]]})",
      "'shapes'[1][0] names polygon 5, but the scene has 2 polygons" },
    { R"({"model": "m.ply", "points": [{"face": 0, "uv": [0.1, 0.1]}],
          "polygons": [[], [0, 7.0]]})",
      "'polygons'[1][1] names point 7.0, but the scene has 1 points" },
    { R"({"model": 12.50, )" + points + "}", "'model' is 12.50, not a file name" },
    { R"({"model": "m.ply", )" + points + R"(, "are_closed": [true, "yes"]})",
      "'are_closed'[1] is \"yes\", not a bool" },
    { R"({"points": [], "polygons": [[0, 1]]})",
      "the scene (and MeshFileName is not set) has no key 'model'" },
    { R"({"model": "m.ply", "polygons": [[0, 1]]})", "the scene has no key 'points'" },
    { R"({"model": "m.ply", "points": [{"uv": [0.1, 0.1]}], "polygons": [[0, 0]]})",
      "'points'[0] has no key 'face'" },
    { R"({"model": "m.ply", "points": [{"face": 0, "uv": [0.1, 0.1]}], "polygons": [[], [0]]})",
      "'polygons' are all empty: the scene has no curve" },
    { "[1, 2]", "the top level is not a JSON object" },
  };
  for (const Case& c : cases)
  {
    EXPECT_EQ(ErrorOf(c.Text), c.Message) << c.Text;
  }
  EXPECT_EQ(ErrorOf(R"({"model": "m.ply", "points": [)").rfind("bad JSON: ", 0), 0u);
  // Nested 100 deep: described, not printed (nor recursed into). Deeper than
  // MaxSceneNestingDepth is refused before (TestSceneDeepNesting).
  const std::string deep = std::string(100, '[') + "1" + std::string(100, ']');
  EXPECT_EQ(ErrorOf(R"({"model": "m.ply", )" + points + R"(, "are_closed": [)" + deep + "]}"),
    "'are_closed'[0] is an array of 1 item(s), not a bool");
}

TEST(SceneJson, ModelIgnoredWhenTheCallerNamesTheMesh)
{
  SceneParseOptions options;
  options.ReadModel = false;
  const SceneModel s = Parse(R"({"model": 3, "points": [{"face": 0, "uv": [0.1, 0.1]}],
    "polygons": [[0, 0]]})",
    options);
  EXPECT_EQ(s.Model, "");
  EXPECT_EQ(s.Polygons.size(), 1u);
}

// FindMesh is called once the curves are checked and before the points are: a file's
// problems are found in one order (curves, mesh, each point's face then uv, operations).
TEST(SceneJson, FaceOutOfRangeAndTheOrderOfChecks)
{
  int calls = 0;
  SceneParseOptions options;
  options.FindMesh = [&](const SceneModel& scene, SceneMeshInfo& mesh, std::string&)
  {
    ++calls;
    EXPECT_EQ(scene.Model, "m.ply");
    EXPECT_TRUE(scene.Points.empty());
    mesh = SceneMeshInfo{ 4, "meshes/m.ply" };
    return true;
  };
  // Point 1's face (written 1E2) is out of range; point 2's uv is bad too: the face comes first.
  const std::string text = R"({"model": "m.ply", "points": [{"face": 3, "uv": [0.1, 0.1]},
    {"face": 1E2, "uv": [0.1, 0.1]}, {"face": 0, "uv": [0.9, 0.9]}],
    "polygons": [[], [0, 1, 2]], "operations": [{"a": 0}]})";
  EXPECT_EQ(ErrorOf(text, options),
    "'points'[1].face = 1E2 is out of range: mesh meshes/m.ply has 4 triangles");
  EXPECT_EQ(calls, 1);
  // Without a mesh, the uv; then, after the points, the operations.
  EXPECT_EQ(ErrorOf(text),
    "'points'[2].uv = [0.9,0.9] is outside the triangle (needs u >= 0, v >= 0, u + v <= 1)");
  EXPECT_EQ(ErrorOf(R"({"model": "m.ply", "points": [{"face": 3, "uv": [0.1, 0.1]}],
    "polygons": [[0, 0]], "operations": [{"a": 0}]})"),
    "'operations'[0] has no key 'b'");
  // A bad polygon is found before the mesh is looked for; the mesh's error propagates.
  calls = 0;
  EXPECT_EQ(ErrorOf(R"({"model": "m.ply", "points": [], "polygons": [[0, 1]]})", options),
    "'polygons'[0][0] names point 0, but the scene has 0 points");
  EXPECT_EQ(calls, 0);
  options.FindMesh = [](const SceneModel&, SceneMeshInfo&, std::string& error)
  {
    error = "no mesh";
    return false;
  };
  EXPECT_EQ(ErrorOf(text, options), "no mesh");

  // Checked later on the parsed model, with the same message.
  const SceneModel s = Parse(R"({"model": "m.ply", "points": [{"face": 3, "uv": [0.1, 0.1]},
    {"face": 1E2, "uv": [0.1, 0.1]}], "polygons": [[0, 1]]})");
  std::string error;
  EXPECT_FALSE(CheckSceneFaces(s, 4, "meshes/m.ply", error)) << "face 100 of 4 triangles accepted";
  EXPECT_EQ(error,
    "'points'[1].face = 1E2 is out of range: mesh meshes/m.ply has 4 "
    "triangles");
  EXPECT_TRUE(CheckSceneFaces(s, 101, "meshes/m.ply", error));
}

TEST(SceneJson, LooksLikeScene)
{
  std::istringstream scene(R"({"polygons": []})"), other(R"({"basis": []})"), bad("{"), array("[]");
  EXPECT_TRUE(LooksLikeSceneJson(scene));
  EXPECT_FALSE(LooksLikeSceneJson(other));
  EXPECT_FALSE(LooksLikeSceneJson(bad));
  EXPECT_FALSE(LooksLikeSceneJson(array));
}

TEST(SceneJson, EmittedAsTheWriterAlwaysHas)
{
  SceneModel s;
  s.Model = "m.ply";
  s.Points = { ScenePoint{ 3, 0.25, 0.5, "", "", {} }, ScenePoint{ 0, 0.1, 0.2, "", "", {} } };
  ScenePolygon p;
  p.Index = 1;
  p.Points = { 0, 1 };
  p.Closed = false;
  p.Shape = 0;
  s.Polygons.push_back(p);
  // Keys sorted; polygon 0 empty (and closed); no curve_types without a Bezier curve.
  EXPECT_EQ(EmitSceneJson(s, -1),
    R"({"are_closed":[true,false],"model":"m.ply","points":[{"face":3,"uv":[0.25,0.5]},)"
    R"({"face":0,"uv":[0.1,0.2]}],"polygons":[[],[0,1]],"shapes":[[1]]})"
    "\n");
  s.Polygons[0].CurveType = 1;
  s.Operations = std::vector<SceneOperation>{};
  const std::string text = EmitSceneJson(s, 1);
  EXPECT_NE(text.find("\"curve_types\": [\n  0,\n  1\n ]"), std::string::npos) << text;
  EXPECT_NE(text.find("\"operations\": []"), std::string::npos) << text;
}

TEST(SceneJson, EmitThenParseGivesTheSameModel)
{
  SceneModel s = Parse(Scene);
  // Values a decimal rendering would round.
  s.Points[2].U = 0.1 + 0.2;
  s.Points[2].V = 1.0 / 3.0;
  s.NumberOfPolygons = 7; // trailing empty polygons are kept
  s.NumberOfShapes = 4;   // so are empty shapes
  const SceneModel back = Parse(EmitSceneJson(s));
  EXPECT_EQ(back.Model, s.Model);
  ASSERT_EQ(back.Points.size(), s.Points.size());
  for (std::size_t k = 0; k < s.Points.size(); ++k)
  {
    EXPECT_EQ(back.Points[k].Face, s.Points[k].Face) << k;
    EXPECT_EQ(back.Points[k].U, s.Points[k].U) << k; // bit for bit
    EXPECT_EQ(back.Points[k].V, s.Points[k].V) << k;
  }
  EXPECT_EQ(back.NumberOfPolygons, 7);
  EXPECT_EQ(back.NumberOfShapes, 4);
  ASSERT_EQ(back.Polygons.size(), s.Polygons.size());
  for (std::size_t i = 0; i < s.Polygons.size(); ++i)
  {
    EXPECT_EQ(back.Polygons[i].Index, s.Polygons[i].Index);
    EXPECT_EQ(back.Polygons[i].Points, s.Polygons[i].Points);
    EXPECT_EQ(back.Polygons[i].Closed, s.Polygons[i].Closed);
    EXPECT_EQ(back.Polygons[i].CurveType, s.Polygons[i].CurveType);
    // The curve in no shape was given shape 2: it is written in shape 2.
    EXPECT_EQ(back.Polygons[i].Shape, s.Polygons[i].Shape);
  }
  ASSERT_TRUE(back.Operations.has_value());
  ASSERT_EQ(back.Operations->size(), 1u);
  EXPECT_EQ((*back.Operations)[0].Type, 2);
  // Emitting again gives the same text.
  EXPECT_EQ(EmitSceneJson(back), EmitSceneJson(s));
}

TEST(SceneJson, ScreenSpaceRoundTrip)
{
  const SceneModel s = Parse(R"({"screenspace": true, "polygons": [[], [[0.1, 2], [3, 4.5]],
    [[1, 1], [2, 1], [2, 2]]], "are_closed": [true, false, true], "shapes": [[2], [1]]})");
  ASSERT_TRUE(s.ScreenSpace);
  ASSERT_EQ(s.Polygons.size(), 2u);
  EXPECT_EQ(s.Polygons[0].Polyline.size(), 2u);
  EXPECT_EQ(s.Polygons[0].Polyline[0].x, 0.1);
  EXPECT_EQ(s.Polygons[0].Polyline[1].y, 4.5); // as written: y still grows downwards
  EXPECT_FALSE(s.Polygons[0].Closed);
  EXPECT_EQ(s.Polygons[0].Shape, 1);
  EXPECT_EQ(s.Polygons[1].Shape, 0);
  EXPECT_TRUE(s.Points.empty()); // until placed
  const SceneModel back = Parse(EmitSceneJson(s));
  ASSERT_TRUE(back.ScreenSpace);
  ASSERT_EQ(back.Polygons.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i)
  {
    ASSERT_EQ(back.Polygons[i].Polyline.size(), s.Polygons[i].Polyline.size());
    for (std::size_t k = 0; k < s.Polygons[i].Polyline.size(); ++k)
    {
      EXPECT_EQ(back.Polygons[i].Polyline[k].x, s.Polygons[i].Polyline[k].x);
      EXPECT_EQ(back.Polygons[i].Polyline[k].y, s.Polygons[i].Polyline[k].y);
    }
    EXPECT_EQ(back.Polygons[i].Closed, s.Polygons[i].Closed);
    EXPECT_EQ(back.Polygons[i].Shape, s.Polygons[i].Shape);
  }
}

TEST(SceneJson, ScreenSpaceErrors)
{
  // All points the same is found before a one-point polyline.
  EXPECT_EQ(ErrorOf(R"({"screenspace": true, "polygons": [[[1, 1]], [[1, 1], [1, 1]]]})"),
    "'polygons' hold no two distinct points");
  EXPECT_EQ(ErrorOf(R"({"screenspace": true, "polygons": [[[0, 0], [1, 1]], [], [[5, 5]]]})"),
    "'polygons'[2] has a single point; a curve needs at least 2");
  EXPECT_EQ(ErrorOf(R"({"screenspace": true, "polygons": [[[0, 0], [1E0]]]})"),
    "'polygons'[0][1] is [1E0], not an [x, y] point");
  EXPECT_EQ(ErrorOf(R"({"screenspace": true, "polygons": [[[0, 0], [1, 1]], 3]})"),
    "'polygons'[1] is not a list of [x, y] points");
  EXPECT_EQ(ErrorOf(R"({"screenspace": true, "polygons": [[[0, 0], [1, 1]]],
    "operations": [{"a": 0, "b": 0, "type": -1}]})"),
    "'operations'[0].type is -1, not an integer in [0, 2147483647]");
}

// Scene files nested 10^6 deep (arrays, objects, both mixed, split over lines) are refused
// with a named error (nesting too deep, the limit, the line, column and top-level key), never
// a stack overflow; brackets inside strings do not count, and the limit itself is accepted.
// A scene nested 10^5 deep in 'points' used to crash: the ordered object copied its deep
// value, recursively, when it grew to hold 'polygons'.
#include "Scene/SceneJson.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

using namespace boolsurf;

namespace
{
constexpr int Levels = 1000000;

/// The message of parsing `text` ("" when it reads).
std::string ErrorOf(const std::string& text)
{
  std::istringstream in(text);
  SceneModel scene;
  std::string error;
  return ParseSceneJson(in, scene, error) ? "" : error;
}

bool LooksLikeScene(const std::string& text)
{
  std::istringstream in(text);
  return LooksLikeSceneJson(in);
}

std::string Repeat(const std::string& s, int n)
{
  std::string out;
  out.reserve(s.size() * n);
  for (int i = 0; i < n; ++i)
  {
    out += s;
  }
  return out;
}

const std::string Limit = std::to_string(MaxSceneNestingDepth);
const std::string Beyond = std::to_string(MaxSceneNestingDepth + 1);
} // namespace

TEST(SceneDeepNesting, ArraysInPoints)
{
  const std::string head = R"({"model": "mesh.ply", "points": )";
  const std::string text =
    head + std::string(Levels, '[') + std::string(Levels, ']') + R"(, "polygons": []})";
  // The top-level object is level 1: the 257th level is the 256th '['.
  const std::string column = std::to_string(head.size() + MaxSceneNestingDepth);
  EXPECT_EQ(ErrorOf(text),
    "nesting too deep: an array at line 1, column " + column + " (in 'points') is " + Beyond +
      " levels deep; scene files may nest arrays and objects at most " + Limit + " levels");
  // Recognized as a scene (the reader is chosen, and reports the error above).
  EXPECT_TRUE(LooksLikeScene(text));
}

TEST(SceneDeepNesting, Objects)
{
  const std::string text = Repeat(R"({"a":)", Levels) + "0" + std::string(Levels, '}');
  const std::string column = std::to_string(1 + 5 * MaxSceneNestingDepth);
  EXPECT_EQ(ErrorOf(text),
    "nesting too deep: an object at line 1, column " + column + " (in 'a') is " + Beyond +
      " levels deep; scene files may nest arrays and objects at most " + Limit + " levels");
  EXPECT_FALSE(LooksLikeScene(text)); // no 'polygons'
}

TEST(SceneDeepNesting, ArraysAndObjectsMixedOverLines)
{
  // Level k (k >= 2) on line k + 1: even levels arrays, odd levels objects.
  std::string text = "{\"model\": \"mesh.ply\", \"polygons\": [],\n\"points\":\n";
  for (int level = 2; level <= Levels; ++level)
  {
    text += level % 2 == 0 ? "[\n" : "{\"p\":\n";
  }
  text += "0";
  for (int level = Levels; level >= 2; --level)
  {
    text += level % 2 == 0 ? "]" : "}";
  }
  text += "}";
  EXPECT_EQ(ErrorOf(text),
    "nesting too deep: an object at line " + std::to_string(MaxSceneNestingDepth + 2) +
      ", column 1 (in 'points') is " + Beyond +
      " levels deep; scene files may nest arrays and objects at most " + Limit + " levels");
  EXPECT_TRUE(LooksLikeScene(text));
}

TEST(SceneDeepNesting, UnclosedAndTopLevelArrays)
{
  EXPECT_EQ(ErrorOf(std::string(Levels, '[')),
    "nesting too deep: an array at line 1, column " + Beyond + " is " + Beyond +
      " levels deep; scene files may nest arrays and objects at most " + Limit + " levels");
  EXPECT_FALSE(LooksLikeScene(std::string(Levels, '[') + std::string(Levels, ']')));
  EXPECT_FALSE(LooksLikeScene(std::string(Levels, '{')));
}

TEST(SceneDeepNesting, BracketsInStringsDoNotCount)
{
  // A model name of 10^6 brackets (and escaped quotes) is a string, not nesting.
  const std::string name = "\\\"" + std::string(Levels, '[') + "\\\"" + std::string(Levels, '{');
  std::istringstream in(R"({"model": ")" + name + R"(", "points": [{"face": 0, "uv": [0.1, 0.1]},
    {"face": 0, "uv": [0.2, 0.1]}], "polygons": [[0, 1]]})");
  SceneModel scene;
  std::string error;
  ASSERT_TRUE(ParseSceneJson(in, scene, error)) << error;
  EXPECT_EQ(scene.Model.size(), 2u + 2u * Levels);
  EXPECT_EQ(scene.Polygons.size(), 1u);
}

TEST(SceneDeepNesting, TheLimitItselfIsRead)
{
  // 'points' holding arrays up to level 256 exactly: read, then refused for what it holds.
  const int arrays = MaxSceneNestingDepth - 1;
  const std::string text = R"({"model": "mesh.ply", "polygons": [[0, 0]], "points": [)" +
    std::string(arrays - 1, '[') + std::string(arrays - 1, ']') + "]}";
  EXPECT_EQ(
    ErrorOf(text), "'points'[0] is an array of 1 item(s), not {\"face\": f, \"uv\": [u, v]}");
}

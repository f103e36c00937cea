// Where a scene's mesh is looked for (paths only, no mesh read): the override beside the scene,
// the scene's `model` below its ancestors, the renamed copies of the shared collection, the
// search path and `meshes` folders.
#include "Scene/SceneMeshLookup.h"
#include "Scene/SceneModel.h"

#include "Support/ScratchDirectory.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace boolsurf;
namespace fs = std::filesystem;

namespace
{
/// A scratch folder per test process, removed at exit.
fs::path Scratch()
{
  static const boolsurf::testing::ScratchDirectory dir(
    "boolsurf-scene-lookup-", { "repo/scenes", "repo/meshes", "other" });
  return dir.Path;
}

/// FindSceneMesh's mesh (empty, and a failure, when it finds none).
fs::path Found(const fs::path& scene,
  const std::string& override,
  const std::string& model,
  const std::string& searchPath)
{
  fs::path mesh;
  std::string error;
  EXPECT_TRUE(FindSceneMesh(scene, override, model, searchPath, mesh, error)) << error;
  return mesh;
}
} // namespace

TEST(SceneMeshLookup, PathsAndSearchPath)
{
  EXPECT_EQ(NormalizeModelPath(".\\data\\models\\x.ply"), "data/models/x.ply");
  EXPECT_EQ(NormalizeModelPath("././a/./b.ply"), "a/./b.ply");
  EXPECT_EQ(SplitSearchPath("a;b::c;"), (std::vector<std::string>{ "a", "b", "c" }));
  EXPECT_TRUE(SplitSearchPath("").empty());
  EXPECT_EQ(RenamedSceneMeshes().at("bunny.ply"), "bunny_boolsurf.ply");
  // An override is looked for beside the scene, then as given; nothing else.
  EXPECT_EQ(SceneMeshCandidates("dir/scene.json", "m.ply", "ignored.ply", "x"),
    (std::vector<fs::path>{ "dir/m.ply", "m.ply" }));
  EXPECT_EQ(SceneMeshCandidates("dir/scene.json", "/abs/m.ply", "", ""),
    (std::vector<fs::path>{ "/abs/m.ply" }));
}

TEST(SceneMeshLookup, FindsTheRenamedCopyBesideAnAncestor)
{
  const fs::path scene = Scratch() / "repo" / "scenes" / "s.json";
  std::ofstream(Scratch() / "repo" / "meshes" / "bunny_boolsurf.ply") << "ply\n";
  EXPECT_EQ(Found(scene, "", ".\\data\\bunny.ply", ""),
    (Scratch() / "repo" / "meshes" / "bunny_boolsurf.ply").lexically_normal());
  // The model below an ancestor comes first, then the search path.
  fs::create_directories(Scratch() / "repo" / "data");
  std::ofstream(Scratch() / "repo" / "data" / "bunny.ply") << "ply\n";
  EXPECT_EQ(Found(scene, "", "./data/bunny.ply", ""),
    (Scratch() / "repo" / "data" / "bunny.ply").lexically_normal());
  std::ofstream(Scratch() / "other" / "cube.ply") << "ply\n";
  EXPECT_EQ(Found(scene, "", "data/cube.ply", "/nonexistent:" + Scratch().string() + "/other"),
    (Scratch() / "other" / "cube.ply").lexically_normal());

  fs::path mesh;
  std::string message;
  EXPECT_FALSE(FindSceneMesh(scene, "", "./data/nowhere.ply", "", mesh, message))
    << "a mesh that is nowhere was found";
  EXPECT_EQ(message.rfind("mesh './data/nowhere.ply' not found (set MeshFileName or "
                          "MeshSearchPath); looked for:\n  ",
              0),
    0u)
    << message;
  EXPECT_NE(message.find((Scratch() / "repo" / "scenes" / "data" / "nowhere.ply").string()),
    std::string::npos)
    << message;
}

// The reference scenes of the original BoolSurf code whose meshes are in the shared
// collection, for benchmarks: the scene -> mesh table is read from the collection's README.
#ifndef SharedScenes_h
#define SharedScenes_h

#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace benchutil
{

struct SceneFile
{
  std::string Scene; ///< path relative to boolsurf-scenes/
  std::string Mesh;  ///< file name in meshes/
};

/// Scenes marked "mesh available" in boolsurf-scenes/README.md.
inline std::vector<SceneFile> AvailableScenes(const std::string& dataDir)
{
  std::vector<SceneFile> scenes;
  std::ifstream readme(dataDir + "/boolsurf-scenes/README.md");
  const std::regex row(R"(^\| `([^`]+\.json)` \|[^|]*\| `\.\./meshes/([^`]+)` \|.*mesh available)");
  std::string line;
  std::smatch m;
  while (std::getline(readme, line))
  {
    if (std::regex_search(line, m, row))
    {
      scenes.push_back({ m[1], m[2] });
    }
  }
  return scenes;
}

} // namespace benchutil

#endif

// Where a scene's mesh file is: the scene's `model` is a path relative to the BoolSurf
// repository root, and the shared mesh collection holds some meshes under other names.
// Paths only (std::filesystem); reading the mesh is the caller's business.
#ifndef boolsurf_SceneMeshLookup_h
#define boolsurf_SceneMeshLookup_h

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace boolsurf
{

/// The renamed copies of the shared mesh collection (boolsurf-scenes/README.md, "Scene → mesh
/// map"): scene base name → file name in ../meshes.
const std::map<std::string, std::string>& RenamedSceneMeshes();

/// `model` with '\' turned into '/' and leading "./" removed.
std::string NormalizeModelPath(std::string model);

/// The folders of a search path separated by ';' or ':' (empty ones dropped).
std::vector<std::string> SplitSearchPath(const std::string& path);

/// Every place the mesh may be, in order, duplicates removed: `override` (when not empty)
/// relative to the scene's folder, then as given; else `model` relative to each ancestor
/// folder of the scene file (and as given when absolute), its base name (and renamed copy) in
/// the scene's folder, in the folders of `searchPath` and in a `meshes` folder beside any
/// ancestor.
std::vector<std::filesystem::path> SceneMeshCandidates(const std::filesystem::path& sceneFile,
  const std::string& override,
  const std::string& model,
  const std::string& searchPath);

/// The first candidate that is a file, in `mesh`; false, with a message naming the mesh and the
/// places looked at (at most 12), when there is none.
bool FindSceneMesh(const std::filesystem::path& sceneFile,
  const std::string& override,
  const std::string& model,
  const std::string& searchPath,
  std::filesystem::path& mesh,
  std::string& error);

} // namespace boolsurf

#endif

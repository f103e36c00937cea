#include "Scene/SceneMeshLookup.h"

#include <algorithm>

namespace boolsurf
{
namespace fs = std::filesystem;

//------------------------------------------------------------------------------
const std::map<std::string, std::string>& RenamedSceneMeshes()
{
  static const std::map<std::string, std::string> names = {
    { "eight200k-remeshed.ply", "eight_200k.ply" },
    { "3Torus_200k.ply", "3torus_200k.ply" },
    { "bunny.ply", "bunny_boolsurf.ply" },
    { "cow_notsolowpoly.ply", "spot.ply" },
  };
  return names;
}

//------------------------------------------------------------------------------
std::string NormalizeModelPath(std::string model)
{
  std::replace(model.begin(), model.end(), '\\', '/');
  while (model.rfind("./", 0) == 0)
  {
    model.erase(0, 2);
  }
  return model;
}

//------------------------------------------------------------------------------
std::vector<std::string> SplitSearchPath(const std::string& path)
{
  std::vector<std::string> dirs;
  std::string current;
  for (char c : path)
  {
    if (c == ';' || c == ':')
    {
      if (!current.empty())
      {
        dirs.push_back(current);
      }
      current.clear();
    }
    else
    {
      current += c;
    }
  }
  if (!current.empty())
  {
    dirs.push_back(current);
  }
  return dirs;
}

//------------------------------------------------------------------------------
std::vector<fs::path> SceneMeshCandidates(const fs::path& sceneFile,
  const std::string& override,
  const std::string& model,
  const std::string& searchPath)
{
  std::vector<fs::path> out;
  auto add = [&](const fs::path& p)
  {
    const fs::path q = p.lexically_normal();
    if (std::find(out.begin(), out.end(), q) == out.end())
    {
      out.push_back(q);
    }
  };
  const fs::path sceneDir =
    sceneFile.parent_path().empty() ? fs::path(".") : sceneFile.parent_path();
  if (!override.empty())
  {
    const fs::path o(override);
    if (o.is_relative())
    {
      add(sceneDir / o);
    }
    add(o);
    return out;
  }
  const fs::path rel(NormalizeModelPath(model));
  const std::string base = rel.filename().string();
  std::vector<std::string> names = { base };
  auto renamed = RenamedSceneMeshes().find(base);
  if (renamed != RenamedSceneMeshes().end())
  {
    names.push_back(renamed->second);
  }
  // The scene's folder and its ancestors (BoolSurf's paths are relative to its repository
  // root, which is an ancestor of the scene file in the original layout).
  std::vector<fs::path> ancestors;
  fs::path abs = fs::absolute(sceneDir).lexically_normal();
  for (fs::path a = abs;; a = a.parent_path())
  {
    ancestors.push_back(a);
    if (a == a.parent_path() || ancestors.size() > 8)
    {
      break;
    }
  }
  if (rel.is_absolute())
  {
    add(rel);
  }
  for (const fs::path& a : ancestors)
  {
    add(a / rel);
  }
  for (const std::string& n : names)
  {
    add(sceneDir / n);
  }
  for (const std::string& dir : SplitSearchPath(searchPath))
  {
    add(fs::path(dir) / rel);
    for (const std::string& n : names)
    {
      add(fs::path(dir) / n);
    }
  }
  for (const fs::path& a : ancestors)
  {
    for (const std::string& n : names)
    {
      add(a / "meshes" / n);
    }
  }
  return out;
}

//------------------------------------------------------------------------------
bool FindSceneMesh(const fs::path& sceneFile,
  const std::string& override,
  const std::string& model,
  const std::string& searchPath,
  fs::path& mesh,
  std::string& error)
{
  const std::vector<fs::path> candidates =
    SceneMeshCandidates(sceneFile, override, model, searchPath);
  for (const fs::path& c : candidates)
  {
    std::error_code ec;
    if (fs::is_regular_file(c, ec))
    {
      mesh = c;
      return true;
    }
  }
  std::string tried;
  for (std::size_t k = 0; k < candidates.size() && k < 12; ++k)
  {
    tried += "\n  " + candidates[k].string();
  }
  if (candidates.size() > 12)
  {
    tried += "\n  ... (" + std::to_string(candidates.size() - 12) + " more)";
  }
  error = "mesh '" + (override.empty() ? model : override) +
    "' not found (set MeshFileName or MeshSearchPath); looked for:" + tried;
  return false;
}

} // namespace boolsurf

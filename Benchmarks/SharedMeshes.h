// Meshes of the shared collection for the Core benchmarks, read once per process: a benchmark
// measures what it builds from a mesh, not the file.
#ifndef SharedMeshes_h
#define SharedMeshes_h

#include "Mesh/PlyReader.h"

#include <map>
#include <string>

namespace benchutil
{

/// meshes/`name` of the shared collection (BOOLSURF_SHARED_DATA_DIR), or null with the reason
/// in `error`.
inline const boolsurf::MeshData* LoadSharedMesh(const std::string& name, std::string& error)
{
  static std::map<std::string, boolsurf::MeshData> cache;
  auto it = cache.find(name);
  if (it == cache.end())
  {
    boolsurf::MeshData data;
    if (!boolsurf::ReadPly(std::string(BOOLSURF_SHARED_DATA_DIR) + "/meshes/" + name, data, error))
    {
      return nullptr;
    }
    it = cache.emplace(name, std::move(data)).first;
  }
  return &it->second;
}

} // namespace benchutil

#endif

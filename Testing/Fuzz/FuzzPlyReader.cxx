// libFuzzer target: the checked PLY reader (Core/Mesh/PlyReader) on arbitrary file contents.
// Every input must give a mesh or an error message; a mesh must only hold triangles whose
// vertex indices exist, and an error must say something.
#include "FuzzSupport.h"
#include "Mesh/PlyReader.h"

#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace boolsurf;
  const std::string path = fuzz::ScratchFolder() + "/input.ply";
  fuzz::WriteFile(path, data, size);

  MeshData mesh;
  std::string error;
  if (!ReadPly(path, mesh, error))
  {
    BOOLSURF_FUZZ_CHECK(!error.empty(), "a failed read must say why");
    return 0;
  }
  BOOLSURF_FUZZ_CHECK(error.empty(), error);
  const long long vertices = static_cast<long long>(mesh.Positions.size());
  for (std::size_t t = 0; t < mesh.Triangles.size(); ++t)
  {
    for (int v : mesh.Triangles[t])
    {
      BOOLSURF_FUZZ_CHECK(v >= 0 && v < vertices,
        "triangle " + std::to_string(t) + " uses vertex " + std::to_string(v) + " of " +
          std::to_string(vertices));
    }
  }
  // The file's vertices must all have been read from it: at least 12 bytes each in binary,
  // 6 characters ("0 0 0\n") in ascii, so never more vertices than bytes.
  BOOLSURF_FUZZ_CHECK(vertices <= static_cast<long long>(size), std::to_string(vertices));
  return 0;
}

#include "FuzzSupport.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdlib.h> // mkdtemp

namespace boolsurf
{
namespace fuzz
{

const std::string& ScratchFolder()
{
  // Never freed: the folder is removed at exit, after static objects are destroyed.
  static const std::string* folder = []
  {
    const char* tmp = std::getenv("TMPDIR");
    auto* pattern =
      new std::string(std::string(tmp && *tmp ? tmp : "/tmp") + "/boolsurf-fuzz-XXXXXX");
    if (!mkdtemp(&(*pattern)[0]))
    {
      std::perror("mkdtemp");
      std::abort();
    }
    std::atexit(
      []
      {
        std::error_code ignored;
        std::filesystem::remove_all(ScratchFolder(), ignored);
      });
    return pattern;
  }();
  return *folder;
}

void WriteFile(const std::string& path, const void* data, std::size_t size)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  if (!out)
  {
    std::fprintf(stderr, "cannot write %s\n", path.c_str());
    std::abort();
  }
}

} // namespace fuzz
} // namespace boolsurf

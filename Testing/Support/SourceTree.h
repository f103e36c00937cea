// Where the project's sources are, for tests that read files shipped in the repository
// (Testing/Data, Data/): BOOLSURF_SOURCE_DIR when set (ctest sets it), else found from this
// header's own path, which also works at test discovery and when a test is run by hand.
#ifndef boolsurf_SourceTree_h
#define boolsurf_SourceTree_h

#include <cstdlib>
#include <filesystem>

namespace boolsurf
{
namespace testing
{

inline std::filesystem::path SourceTree()
{
  if (const char* dir = std::getenv("BOOLSURF_SOURCE_DIR"))
  {
    return dir;
  }
  // Testing/Support/SourceTree.h -> the source tree (normalized first: the compiler names the
  // header through its include directory, Testing/Support/..).
  return std::filesystem::path(__FILE__)
    .lexically_normal()
    .parent_path()
    .parent_path()
    .parent_path();
}

} // namespace testing
} // namespace boolsurf

#endif

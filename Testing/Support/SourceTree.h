// Where the project's sources are, for tests that read files shipped in the repository
// (Testing/Data, Data/): BOOLSURF_SOURCE_DIR when set (the Python tests get it from ctest),
// else the tree the tests were configured from (BOOLSURF_TEST_SOURCE_DIR, compiled in), else
// found from this header's own path.
#ifndef boolsurf_SourceTree_h
#define boolsurf_SourceTree_h

#include "Support/SourceTreeDir.h" // BOOLSURF_TEST_SOURCE_DIR, written when configured

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
#ifdef BOOLSURF_TEST_SOURCE_DIR
  return BOOLSURF_TEST_SOURCE_DIR;
#else
  // Testing/Support/SourceTree.h -> the source tree (normalized first: the compiler names the
  // header through its include directory, Testing/Support/..).
  return std::filesystem::path(__FILE__)
    .lexically_normal()
    .parent_path()
    .parent_path()
    .parent_path();
#endif
}

} // namespace testing
} // namespace boolsurf

#endif

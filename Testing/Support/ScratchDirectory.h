// A scratch folder for one test process, removed when the process exits, so test runs leave
// nothing in the system's temporary folder. BOOLSURF_KEEP_TEST_OUTPUT=1 keeps it.
#ifndef boolsurf_ScratchDirectory_h
#define boolsurf_ScratchDirectory_h

#include <cstdlib>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <system_error>

#include <unistd.h>

namespace boolsurf
{
namespace testing
{

class ScratchDirectory
{
public:
  /// <temp>/<prefix><pid>, with the given subfolders: unique per process, as ctest runs each
  /// test in its own process.
  explicit ScratchDirectory(const std::string& prefix,
    std::initializer_list<std::filesystem::path> subfolders = {})
    : Path(std::filesystem::temp_directory_path() / (prefix + std::to_string(getpid())))
  {
    std::filesystem::create_directories(this->Path);
    for (const std::filesystem::path& sub : subfolders)
    {
      std::filesystem::create_directories(this->Path / sub);
    }
  }
  ~ScratchDirectory()
  {
    if (!std::getenv("BOOLSURF_KEEP_TEST_OUTPUT"))
    {
      std::error_code ignored;
      std::filesystem::remove_all(this->Path, ignored);
    }
  }
  ScratchDirectory(const ScratchDirectory&) = delete;
  ScratchDirectory& operator=(const ScratchDirectory&) = delete;

  const std::filesystem::path Path;
};

} // namespace testing
} // namespace boolsurf

#endif

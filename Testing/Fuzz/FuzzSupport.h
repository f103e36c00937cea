// Helpers shared by the libFuzzer targets: a failed invariant aborts (so libFuzzer reports the
// input), fuzz bytes are decoded by a reader that yields zeros once they run out, and inputs
// that the code under test reads from files are written to a private temporary folder.
#ifndef boolsurf_FuzzSupport_h
#define boolsurf_FuzzSupport_h

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace boolsurf
{
namespace fuzz
{

/// A violated invariant: prints what and where, then aborts (a finding for libFuzzer).
[[noreturn]] inline void Fail(const char* what,
  const char* file,
  int line,
  const std::string& detail)
{
  std::fprintf(stderr, "%s:%d: invariant violated: %s %s\n", file, line, what, detail.c_str());
  std::abort();
}

#define BOOLSURF_FUZZ_CHECK(condition, detail)                                                     \
  do                                                                                               \
  {                                                                                                \
    if (!(condition))                                                                              \
    {                                                                                              \
      ::boolsurf::fuzz::Fail(#condition, __FILE__, __LINE__, (detail));                            \
    }                                                                                              \
  } while (0)

/// Reads the fuzz input front to back; past its end every read gives 0.
class ByteReader
{
public:
  ByteReader(const std::uint8_t* data, std::size_t size)
    : Data(data)
    , Size(size)
  {
  }
  std::uint8_t Byte() { return this->Position < this->Size ? this->Data[this->Position++] : 0; }
  std::uint16_t U16()
  {
    const std::uint16_t lo = this->Byte();
    return static_cast<std::uint16_t>(lo | (this->Byte() << 8));
  }
  std::uint32_t U32()
  {
    const std::uint32_t lo = this->U16();
    return lo | (static_cast<std::uint32_t>(this->U16()) << 16);
  }
  /// The bytes not read yet, as text.
  std::string Rest()
  {
    std::string s(
      reinterpret_cast<const char*>(this->Data + this->Position), this->Size - this->Position);
    this->Position = this->Size;
    return s;
  }
  bool AtEnd() const { return this->Position >= this->Size; }

private:
  const std::uint8_t* Data;
  std::size_t Size;
  std::size_t Position = 0;
};

/// A folder of its own under TMPDIR (or /tmp), made on first use and kept for the process.
const std::string& ScratchFolder();

/// Writes `size` bytes to `path` (replacing it); aborts when the file cannot be written, which
/// is a problem of the machine, not of the input.
void WriteFile(const std::string& path, const void* data, std::size_t size);

} // namespace fuzz
} // namespace boolsurf

#endif

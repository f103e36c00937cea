// Buffers that an arrangement rewrites on every edit of the curves.
#ifndef boolsurf_EditBuffers_h
#define boolsurf_EditBuffers_h

#include <cstddef>

namespace boolsurf
{

/// The capacity to allocate for `n` elements of a buffer that is rewritten on every edit: an
/// eighth more. An edit moves the curves by a few triangles, so these buffers (points, refined
/// triangles, their cells: a million entries on a 1M-triangle mesh) change size by a few entries
/// from one edit to the next; left to std::vector, the first edit that adds one entry doubles
/// the buffer, a copy and tens of megabytes of fresh pages (about 30 ms on igea_1m) in the middle
/// of a drag, and again in each result a pipeline keeps.
inline std::size_t EditCapacity(std::size_t n)
{
  return n + n / 8;
}

/// Resizes `v` to `n` elements; a reallocation leaves EditCapacity(n) of room.
template <class Vector>
void ResizeForEdits(Vector& v, std::size_t n)
{
  if (n > v.capacity())
  {
    v.reserve(EditCapacity(n));
  }
  v.resize(n);
}

} // namespace boolsurf

#endif

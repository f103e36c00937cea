// Buffers that an arrangement rewrites on every edit of the curves.
#ifndef boolsurf_EditBuffers_h
#define boolsurf_EditBuffers_h

#include "Mesh/ZeroPageArray.h"

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

/// Resizes a zero-page buffer whose contents need not survive the call (scratch, or entries the
/// caller rewrites before reading them) to `n` elements. Growing past the capacity takes a
/// fresh block of EditCapacity(n) zero entries instead of copying the old ones: a copy would
/// write every page of the new block (on 4.3M triangles, 17 MB and 8 ms in one edit, measured).
/// Within the capacity, the entries keep their values (ZeroPageAllocator).
template <class T>
void ResizeDiscardingForEdits(ZeroPageVector<T>& v, std::size_t n)
{
  if (n > v.capacity())
  {
    ZeroPageVector<T> fresh;
    fresh.reserve(EditCapacity(n));
    v.swap(fresh);
  }
  v.resize(n);
}

} // namespace boolsurf

#endif

// Sorting the id lists of an edit (triangles touched by curves: thousands of ids in the range
// of the mesh's triangles). std::sort spends about 50 ns an id on such a list (unpredictable
// branches); an LSD radix sort with 11-bit digits makes three linear passes instead.
#ifndef boolsurf_SortedIds_h
#define boolsurf_SortedIds_h

#include <algorithm>
#include <array>
#include <vector>

namespace boolsurf
{

/// Sorts non-negative ids ascending and removes repeats (same result as std::sort followed by
/// std::unique). Lists too short to amortize the digit counts use std::sort.
inline void SortUniqueIds(std::vector<int>& ids)
{
  constexpr int DigitBits = 11;
  constexpr int Buckets = 1 << DigitBits;
  if (ids.size() < 1024)
  {
    std::sort(ids.begin(), ids.end());
  }
  else
  {
    const int largest = *std::max_element(ids.begin(), ids.end());
    std::vector<int> other(ids.size());
    for (int shift = 0; shift < 31 && (largest >> shift) > 0; shift += DigitBits)
    {
      std::array<int, Buckets + 1> start{};
      for (int id : ids)
      {
        ++start[((id >> shift) & (Buckets - 1)) + 1];
      }
      for (int b = 0; b < Buckets; ++b)
      {
        start[b + 1] += start[b];
      }
      for (int id : ids)
      {
        other[start[(id >> shift) & (Buckets - 1)]++] = id;
      }
      ids.swap(other);
    }
  }
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
}

} // namespace boolsurf

#endif

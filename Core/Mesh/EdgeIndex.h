// A hash map from an edge key (two 32-bit point ids packed in 64 bits, or any 64-bit id) to an
// int. It lives in Mesh, below the stages, because two of them use it: the arrangement's large
// local triangulations of crowded triangles and the geodesic strips (triangle -> position in
// the strip). Open addressing with linear probing in one flat array, so a lookup touches one
// or two cache lines where std::unordered_map follows a pointer to a separately allocated node
// (on 100k-point triangles the node map's misses were a third of the refinement). Erasing
// shifts the following entries back (no tombstones), so a map that sees as many erasures as
// insertions, as a triangulation's half-edges do, never degrades.
#ifndef boolsurf_EdgeIndex_h
#define boolsurf_EdgeIndex_h

#include <cstddef>
#include <cstdint>
#include <vector>

namespace boolsurf
{

/// The key of the edge between points a and b, whichever way round.
inline std::uint64_t UndirectedPointPair(int a, int b)
{
  const std::uint32_t lo = static_cast<std::uint32_t>(a < b ? a : b);
  const std::uint32_t hi = static_cast<std::uint32_t>(a < b ? b : a);
  return (static_cast<std::uint64_t>(lo) << 32) | hi;
}

/// The key of the edge from point a to point b.
inline std::uint64_t DirectedPointPair(int a, int b)
{
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
    static_cast<std::uint32_t>(b);
}

class EdgeIndex
{
public:
  using Key = std::uint64_t;

  /// Empties the map, keeping room for about `expected` entries without growing.
  void Reset(std::size_t expected)
  {
    std::size_t capacity = 16;
    int bits = 4;
    while (capacity < 2 * expected)
    {
      capacity *= 2;
      ++bits;
    }
    this->Slots.assign(capacity, Slot{ Empty, 0 });
    this->Mask = capacity - 1;
    this->Shift = 64 - bits;
    this->Count = 0;
  }

  /// The value stored for `key`, or -1.
  int Find(Key key) const
  {
    if (this->Slots.empty())
    {
      return -1;
    }
    for (std::size_t i = this->Home(key);; i = (i + 1) & this->Mask)
    {
      const Slot& s = this->Slots[i];
      if (s.K == key)
      {
        return s.V;
      }
      if (s.K == Empty)
      {
        return -1;
      }
    }
  }

  bool Contains(Key key) const { return this->Find(key) >= 0; }

  /// Stores `value` (>= 0) for `key`, replacing any value it had.
  void Set(Key key, int value)
  {
    if (2 * (this->Count + 1) > this->Slots.size())
    {
      this->Grow();
    }
    std::size_t i = this->Home(key);
    for (; this->Slots[i].K != Empty; i = (i + 1) & this->Mask)
    {
      if (this->Slots[i].K == key)
      {
        this->Slots[i].V = value;
        return;
      }
    }
    this->Slots[i] = Slot{ key, value };
    ++this->Count;
  }

  /// Removes `key`; returns whether it was there.
  bool Erase(Key key)
  {
    if (this->Slots.empty())
    {
      return false;
    }
    std::size_t i = this->Home(key);
    for (;; i = (i + 1) & this->Mask)
    {
      if (this->Slots[i].K == Empty)
      {
        return false;
      }
      if (this->Slots[i].K == key)
      {
        break;
      }
    }
    // Backward shift: move up every later entry of the run that may live at the hole.
    for (std::size_t j = (i + 1) & this->Mask; this->Slots[j].K != Empty; j = (j + 1) & this->Mask)
    {
      const std::size_t home = this->Home(this->Slots[j].K);
      // The entry at j may move to i when its home is not cyclically in (i, j].
      const bool between = i <= j ? (i < home && home <= j) : (i < home || home <= j);
      if (!between)
      {
        this->Slots[i] = this->Slots[j];
        i = j;
      }
    }
    this->Slots[i] = Slot{ Empty, 0 };
    --this->Count;
    return true;
  }

  std::size_t Size() const { return this->Count; }

private:
  static constexpr Key Empty = ~Key(0); // no pair of non-negative 32-bit ids packs to this
  struct Slot
  {
    Key K;
    int V;
  };

  std::size_t Home(Key key) const
  {
    // Fibonacci hashing (the top bits of the product): packed ids are far from uniform.
    return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> this->Shift);
  }

  void Grow()
  {
    std::vector<Slot> old;
    old.swap(this->Slots);
    this->Reset(old.size()); // twice the entries' room: capacity doubles
    for (const Slot& s : old)
    {
      if (s.K != Empty)
      {
        this->Set(s.K, s.V);
      }
    }
  }

  std::vector<Slot> Slots; ///< empty until the first Reset or Set
  std::size_t Mask = 0;
  int Shift = 64;
  std::size_t Count = 0;
};

} // namespace boolsurf

#endif

// A mesh-sized array of per-search state that costs memory only where a search writes.
#ifndef boolsurf_ZeroPageArray_h
#define boolsurf_ZeroPageArray_h

#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>
#include <type_traits>

namespace boolsurf
{

/// Fixed-size array of a trivial type, zeroed, whose block comes from calloc: for large sizes
/// the C library maps fresh zero pages that the system supplies on first touch, instead of
/// writing zeros through the whole block as std::vector(n, 0) does. A search state indexed by
/// vertex or triangle, of which one search touches a small part (a short geodesic on a
/// million-triangle mesh touches a few hundred entries), then costs memory and page faults
/// for that part only. Readers must not rely on any value but zero before their own writes.
template <class T>
class ZeroPageArray
{
  static_assert(std::is_trivially_copyable<T>::value && std::is_trivially_destructible<T>::value,
    "ZeroPageArray holds plain values");

public:
  /// n zeroed entries (the previous block is released).
  void Reset(std::size_t n)
  {
    this->Data.reset();
    this->Size = 0;
    if (n == 0)
    {
      return;
    }
    T* block = static_cast<T*>(std::calloc(n, sizeof(T)));
    if (!block)
    {
      throw std::bad_alloc();
    }
    this->Data.reset(block);
    this->Size = n;
  }
  /// Every entry back to zero (touches the whole block).
  void Zero()
  {
    for (std::size_t i = 0; i < this->Size; ++i)
    {
      this->Data.get()[i] = T{};
    }
  }

  std::size_t size() const { return this->Size; }
  T& operator[](std::size_t i) { return this->Data.get()[i]; }
  const T& operator[](std::size_t i) const { return this->Data.get()[i]; }

private:
  struct Free
  {
    void operator()(T* p) const { std::free(p); }
  };
  std::unique_ptr<T, Free> Data;
  std::size_t Size = 0;
};

} // namespace boolsurf

#endif

// Mesh-sized arrays that cost memory only where they are written.
#ifndef boolsurf_ZeroPageArray_h
#define boolsurf_ZeroPageArray_h

#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

#if defined(__unix__) || defined(__APPLE__)
#include <sys/mman.h>
#endif

namespace boolsurf
{

/// Zeroed blocks whose pages the system supplies on first touch. Blocks of a megabyte or more
/// are mapped directly: calloc maps fresh pages only above the C library's mmap threshold,
/// which grows to 32 MB once such a block is freed, and below it writes zeros through the block
/// (a mesh-sized buffer on a million-triangle mesh is 4-20 MB).
struct ZeroPages
{
  static constexpr std::size_t MappedBytes = std::size_t(1) << 20;

  static void* Allocate(std::size_t bytes)
  {
#if defined(__unix__) || defined(__APPLE__)
    if (bytes >= MappedBytes)
    {
      void* block =
        mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
      if (block == MAP_FAILED)
      {
        throw std::bad_alloc();
      }
      return block;
    }
#endif
    void* block = std::calloc(bytes > 0 ? bytes : 1, 1);
    if (!block)
    {
      throw std::bad_alloc();
    }
    return block;
  }

  static void Free(void* block, std::size_t bytes)
  {
    if (!block)
    {
      return;
    }
#if defined(__unix__) || defined(__APPLE__)
    if (bytes >= MappedBytes)
    {
      munmap(block, bytes);
      return;
    }
#endif
    (void)bytes;
    std::free(block);
  }
};

/// Fixed-size array of a trivial type, zeroed, from calloc: a search state indexed by vertex or
/// triangle, of which one search touches a small part (a short geodesic on a million-triangle
/// mesh touches a few hundred entries). Where calloc maps fresh pages it costs memory and page
/// faults for that part only; where it reuses freed memory it writes the zeros up front. Not
/// ZeroPages: there every first touch of a page is a fault, about 45 us more per short leg
/// through Trace Surface Curves on igea_1m (0.56 -> 0.61 ms, measured), where searches run
/// many times over the same arrays. Readers must not rely on any value but zero before their
/// own writes.
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

/// Allocator of std::vector buffers in zero pages whose resize() writes nothing: the entries a
/// resize adds are zero in a fresh block and keep their last value where a shrunk vector grows
/// back. For mesh-sized scratch and result buffers of which an edit writes a small part (the
/// cells of the triangles curves touch, marks on curve points): a resize over a whole mesh
/// writes no page, so their memory is what is written. Readers must not read an entry before
/// writing it unless its zero (or kept) value is what they want. resize(n, value), assign() and
/// growing past the capacity (a copy) still write.
template <class T>
struct ZeroPageAllocator
{
  static_assert(std::is_trivially_copyable<T>::value && std::is_trivially_destructible<T>::value,
    "ZeroPageAllocator holds plain values");
  using value_type = T;

  ZeroPageAllocator() = default;
  template <class U>
  ZeroPageAllocator(const ZeroPageAllocator<U>&) noexcept
  {
  }

  T* allocate(std::size_t n) { return static_cast<T*>(ZeroPages::Allocate(n * sizeof(T))); }
  void deallocate(T* block, std::size_t n) noexcept { ZeroPages::Free(block, n * sizeof(T)); }

  /// resize(n) default-initializes: no write.
  template <class U>
  void construct(U* p) noexcept
  {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args)
  {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }

  template <class U>
  bool operator==(const ZeroPageAllocator<U>&) const noexcept
  {
    return true;
  }
  template <class U>
  bool operator!=(const ZeroPageAllocator<U>&) const noexcept
  {
    return false;
  }
};

/// A std::vector in zero pages (ZeroPageAllocator).
template <class T>
using ZeroPageVector = std::vector<T, ZeroPageAllocator<T>>;

/// `v` as `n` zero entries in a fresh block (its old block released), no page written: for
/// mesh-sized buffers of which a few entries are ever written (per-mesh buffers each edit
/// writes and then clears a few entries of, mostly-zero topology arrays).
template <class T>
void AssignFreshZeroPages(ZeroPageVector<T>& v, std::size_t n)
{
  ZeroPageVector<T> fresh;
  fresh.resize(n);
  v.swap(fresh);
}

} // namespace boolsurf

#endif

// Lock-free union-find whose sets keep their lowest member as root.
#ifndef boolsurf_ConcurrentUnionFind_h
#define boolsurf_ConcurrentUnionFind_h

#include <atomic>
#include <utility>

namespace boolsurf
{

/// Root of x's set in a parent array shared by threads. A parent is never above its child, so
/// the root of a set is its lowest member; path halving only ever stores ancestors, so
/// concurrent finds and unions stay correct.
inline int FindSet(std::atomic<int>* parent, int x)
{
  for (;;)
  {
    const int p = parent[x].load(std::memory_order_relaxed);
    if (p == x)
    {
      return x;
    }
    const int g = parent[p].load(std::memory_order_relaxed);
    if (g != p)
    {
      parent[x].store(g, std::memory_order_relaxed);
    }
    x = g;
  }
}

/// Joins the sets of a and b by linking the higher root below the lower one (CAS, retried when
/// another thread linked it first), so every set's root is its lowest member whatever the
/// order of the unions: a numbering by roots does not depend on the thread count.
inline void UniteSets(std::atomic<int>* parent, int a, int b)
{
  for (;;)
  {
    a = FindSet(parent, a);
    b = FindSet(parent, b);
    if (a == b)
    {
      return;
    }
    if (a < b)
    {
      std::swap(a, b);
    }
    int expected = a;
    if (parent[a].compare_exchange_strong(expected, b, std::memory_order_acq_rel))
    {
      return;
    }
  }
}

} // namespace boolsurf

#endif

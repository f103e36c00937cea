#include "Mesh/TriangleComponents.h"

#include <atomic>
#include <memory>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace boolsurf
{

namespace
{
constexpr int BlockSize = 1 << 14;

/// Root of x's set. Roots only ever get a parent of lower id, so a concurrent reader sees a
/// chain that ends at the current root or at one that is being linked (Unite retries).
int FindRoot(const std::atomic<int>* parent, int x)
{
  int p = parent[x].load(std::memory_order_relaxed);
  while (p != x)
  {
    x = p;
    p = parent[x].load(std::memory_order_relaxed);
  }
  return x;
}

/// FindRoot that also halves the path (x's parent becomes its grandparent, an ancestor all
/// the same, so a lost race only skips a shortcut).
int FindRootHalving(std::atomic<int>* parent, int x)
{
  int p = parent[x].load(std::memory_order_relaxed);
  while (p != x)
  {
    const int grandparent = parent[p].load(std::memory_order_relaxed);
    if (grandparent != p)
    {
      parent[x].compare_exchange_weak(p, grandparent, std::memory_order_relaxed);
    }
    x = grandparent;
    p = parent[x].load(std::memory_order_relaxed);
  }
  return x;
}

/// Links the sets of a and b, the higher root below the lower one, so that every set's root
/// is its lowest triangle whatever order the links are made in.
void Unite(std::atomic<int>* parent, int a, int b)
{
  for (;;)
  {
    a = FindRootHalving(parent, a);
    b = FindRootHalving(parent, b);
    if (a == b)
    {
      return;
    }
    if (a < b)
    {
      std::swap(a, b);
    }
    int expected = a; // a is still a root: hang it below b
    if (parent[a].compare_exchange_weak(expected, b, std::memory_order_relaxed))
    {
      return;
    }
  }
}
} // namespace

//------------------------------------------------------------------------------
// A parallel union-find over the manifold edges (each linked once, from its lower triangle):
// a set's root is its lowest triangle, so numbering the roots in increasing order gives the
// components the ids a breadth-first pass from the lowest unassigned triangle would, on any
// number of threads.
TriangleComponents::TriangleComponents(const TriangleMesh& mesh)
{
  const int nt = mesh.GetNumberOfTriangles();
  this->Component.assign(nt, -1);
  if (nt == 0)
  {
    return;
  }
  const std::unique_ptr<std::atomic<int>[]> parent(new std::atomic<int>[nt]);
  const tbb::blocked_range<int> all(0, nt, BlockSize);
  tbb::parallel_for(all,
    [&](const tbb::blocked_range<int>& range)
    {
      for (int t = range.begin(); t != range.end(); ++t)
      {
        parent[t].store(t, std::memory_order_relaxed);
      }
    });
  tbb::parallel_for(all,
    [&](const tbb::blocked_range<int>& range)
    {
      for (int t = range.begin(); t != range.end(); ++t)
      {
        for (int k = 0; mesh.IsUsable(t) && k < 3; ++k)
        {
          const int n = mesh.GetNeighbor(t, k);
          if (n > t)
          {
            Unite(parent.get(), t, n);
          }
        }
      }
    });
  // Roots first (their ids in increasing order), then every triangle takes its root's id.
  for (int t = 0; t < nt; ++t)
  {
    if (mesh.IsUsable(t) && parent[t].load(std::memory_order_relaxed) == t)
    {
      this->Component[t] = this->NumberOfComponents++;
    }
  }
  tbb::parallel_for(all,
    [&](const tbb::blocked_range<int>& range)
    {
      for (int t = range.begin(); t != range.end(); ++t)
      {
        const int root = FindRoot(parent.get(), t);
        if (mesh.IsUsable(t) && root != t) // roots were numbered above (and are read here)
        {
          this->Component[t] = this->Component[root];
        }
      }
    });
}

} // namespace boolsurf

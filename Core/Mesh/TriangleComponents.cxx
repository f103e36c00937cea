#include "Mesh/TriangleComponents.h"

#include "Mesh/ConcurrentUnionFind.h"
#include "Mesh/MeshTopology.h"

#include <atomic>
#include <memory>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace boolsurf
{

namespace
{
constexpr int BlockSize = 1 << 14;
} // namespace

//------------------------------------------------------------------------------
TriangleComponents::TriangleComponents(std::shared_ptr<const MeshTopology> topology)
  : Owner(topology)
  , Component(topology->TriangleComponent.data())
  , NumberOfComponents(topology->GetNumberOfComponents())
{
}

//------------------------------------------------------------------------------
// A parallel union-find over the manifold edges (each linked once, from its lower triangle;
// Mesh/ConcurrentUnionFind): a set's root is its lowest triangle, so numbering the roots in
// increasing order gives the components the ids a breadth-first pass from the lowest
// unassigned triangle would, on any number of threads.
TriangleComponents::TriangleComponents(const TriangleMesh& mesh)
{
  const int nt = mesh.GetNumberOfTriangles();
  auto owned = std::make_shared<std::vector<int>>(nt, -1);
  this->Owner = owned;
  int* component = owned->data();
  this->Component = component;
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
            UniteSets(parent.get(), t, n);
          }
        }
      }
    });
  // Roots first (their ids in increasing order), then every triangle takes its root's id.
  for (int t = 0; t < nt; ++t)
  {
    if (mesh.IsUsable(t) && parent[t].load(std::memory_order_relaxed) == t)
    {
      component[t] = this->NumberOfComponents++;
    }
  }
  tbb::parallel_for(all,
    [&](const tbb::blocked_range<int>& range)
    {
      for (int t = range.begin(); t != range.end(); ++t)
      {
        const int root = FindSet(parent.get(), t);
        if (mesh.IsUsable(t) && root != t) // roots were numbered above (and are read here)
        {
          component[t] = component[root];
        }
      }
    });
}

} // namespace boolsurf

#include "Geodesic/SiteCells.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <functional>
#include <limits>
#include <memory>
#include <queue>
#include <utility>

namespace boolsurf
{
namespace
{
constexpr double Unreached = std::numeric_limits<double>::infinity();

/// Frontier vertices (or vertices) per parallel task.
constexpr std::size_t Grain = 512;

void GrowSerial(const TriangleMesh& mesh,
  const std::vector<int>& offsets,
  const std::vector<int>& neighbors,
  const std::vector<int>& sites,
  SiteCells& out)
{
  const int nv = mesh.GetNumberOfVertices();
  out.Cell.assign(nv, -1);
  out.Parent.assign(nv, -1);
  out.SiteDistance.assign(nv, Unreached);
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap;
  for (int s = 0; s < static_cast<int>(sites.size()); ++s)
  {
    const int v = sites[s];
    out.Cell[v] = s;
    out.SiteDistance[v] = 0.0;
    heap.push({ 0.0, v });
  }
  while (!heap.empty())
  {
    const auto [d, u] = heap.top();
    heap.pop();
    if (d > out.SiteDistance[u])
    {
      continue;
    }
    const Vec3& pu = mesh.GetPosition(u);
    for (int i = offsets[u]; i < offsets[u + 1]; ++i)
    {
      const int w = neighbors[i];
      const double dw = d + Distance(pu, mesh.GetPosition(w));
      if (dw < out.SiteDistance[w])
      {
        out.SiteDistance[w] = dw;
        out.Parent[w] = u;
        out.Cell[w] = out.Cell[u];
        heap.push({ dw, w });
      }
    }
  }
}

/// The distances, by rounds of relaxations from the vertices that improved in the round before
/// (an atomic minimum per vertex), until none improves.
void RelaxDistances(const TriangleMesh& mesh,
  const std::vector<int>& offsets,
  const std::vector<int>& neighbors,
  const std::vector<int>& sites,
  std::vector<double>& distance)
{
  const int nv = mesh.GetNumberOfVertices();
  const std::unique_ptr<std::atomic<double>[]> d(new std::atomic<double>[nv]);
  const std::unique_ptr<std::atomic<int>[]> queued(new std::atomic<int>[nv]);
  tbb::parallel_for(tbb::blocked_range<int>(0, nv, 4096),
    [&](const tbb::blocked_range<int>& r)
    {
      for (int v = r.begin(); v < r.end(); ++v)
      {
        d[v].store(Unreached, std::memory_order_relaxed);
        queued[v].store(0, std::memory_order_relaxed);
      }
    });
  std::vector<int> frontier(sites.begin(), sites.end());
  for (int v : sites)
  {
    d[v].store(0.0, std::memory_order_relaxed);
  }
  tbb::enumerable_thread_specific<std::vector<int>> improved;
  for (int round = 1; !frontier.empty(); ++round)
  {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, frontier.size(), Grain),
      [&](const tbb::blocked_range<std::size_t>& r)
      {
        std::vector<int>& next = improved.local();
        for (std::size_t i = r.begin(); i < r.end(); ++i)
        {
          const int u = frontier[i];
          const double du = d[u].load(std::memory_order_relaxed);
          const Vec3& pu = mesh.GetPosition(u);
          for (int k = offsets[u]; k < offsets[u + 1]; ++k)
          {
            const int w = neighbors[k];
            const double dw = du + Distance(pu, mesh.GetPosition(w));
            double current = d[w].load(std::memory_order_relaxed);
            while (
              dw < current && !d[w].compare_exchange_weak(current, dw, std::memory_order_relaxed))
            {
            }
            // Lowered here (current was above dw): relax from w next round, listed once.
            if (dw < current && queued[w].exchange(round, std::memory_order_relaxed) != round)
            {
              next.push_back(w);
            }
          }
        }
      });
    frontier.clear();
    for (std::vector<int>& next : improved)
    {
      frontier.insert(frontier.end(), next.begin(), next.end());
      next.clear();
    }
  }
  distance.resize(nv);
  for (int v = 0; v < nv; ++v)
  {
    distance[v] = d[v].load(std::memory_order_relaxed);
  }
}

/// Each vertex's parent as Dijkstra picks it (see SiteCells.h), then its cell up the parents.
/// False when an edge does not raise the distance it relaxes from (Dijkstra's settling order
/// is then not (d, id)) or a vertex has no parent: the caller searches serially instead.
bool ChooseParents(const TriangleMesh& mesh,
  const std::vector<int>& offsets,
  const std::vector<int>& neighbors,
  const std::vector<int>& sites,
  SiteCells& out)
{
  const int nv = mesh.GetNumberOfVertices();
  out.Cell.assign(nv, -1);
  out.Parent.assign(nv, -1);
  for (int s = 0; s < static_cast<int>(sites.size()); ++s)
  {
    out.Cell[sites[s]] = s;
  }
  std::atomic<bool> serialOrder{ true };
  const std::vector<double>& d = out.SiteDistance;
  tbb::parallel_for(tbb::blocked_range<int>(0, nv, 4096),
    [&](const tbb::blocked_range<int>& r)
    {
      for (int w = r.begin(); w < r.end(); ++w)
      {
        if (!(d[w] < Unreached))
        {
          continue;
        }
        const Vec3& pw = mesh.GetPosition(w);
        int best = -1;
        for (int k = offsets[w]; k < offsets[w + 1]; ++k)
        {
          const int u = neighbors[k];
          const double sum = d[u] + Distance(mesh.GetPosition(u), pw);
          if (sum == d[u])
          {
            serialOrder.store(false, std::memory_order_relaxed);
          }
          if (sum == d[w] && (best < 0 || d[u] < d[best] || (d[u] == d[best] && u < best)))
          {
            best = u;
          }
        }
        if (out.Cell[w] < 0) // not a site
        {
          if (best < 0)
          {
            serialOrder.store(false, std::memory_order_relaxed);
          }
          out.Parent[w] = best;
        }
      }
    });
  if (!serialOrder.load())
  {
    return false;
  }
  // Distances strictly fall along parents, so every chain ends at a site.
  tbb::parallel_for(tbb::blocked_range<int>(0, nv, 4096),
    [&](const tbb::blocked_range<int>& r)
    {
      for (int w = r.begin(); w < r.end(); ++w)
      {
        if (out.Parent[w] < 0)
        {
          continue; // a site, or unreached
        }
        int v = w;
        while (out.Parent[v] >= 0)
        {
          v = out.Parent[v];
        }
        out.Cell[w] = out.Cell[v];
      }
    });
  return true;
}
} // namespace

//------------------------------------------------------------------------------
bool GrowSiteCells(const TriangleMesh& mesh,
  const std::vector<int>& offsets,
  const std::vector<int>& neighbors,
  const std::vector<int>& sites,
  bool parallel,
  SiteCells& out)
{
  if (parallel)
  {
    RelaxDistances(mesh, offsets, neighbors, sites, out.SiteDistance);
    if (ChooseParents(mesh, offsets, neighbors, sites, out))
    {
      return true;
    }
  }
  GrowSerial(mesh, offsets, neighbors, sites, out);
  return false;
}

} // namespace boolsurf

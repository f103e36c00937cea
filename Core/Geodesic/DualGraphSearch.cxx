#include "Geodesic/DualGraphSearch.h"

#include <algorithm>
#include <functional>
#include <limits>

namespace boolsurf
{

//------------------------------------------------------------------------------
DualGraphSearch::DualGraphSearch(const TriangleMesh& mesh)
  : Mesh(mesh)
{
  const int nt = mesh.GetNumberOfTriangles();
  this->Centroids.resize(nt);
  this->Nodes.resize(nt);
  for (int t = 0; t < nt; ++t)
  {
    if (mesh.IsUsable(t))
    {
      this->Centroids[t] = (1.0 / 3.0) *
        (mesh.GetCornerPosition(t, 0) + mesh.GetCornerPosition(t, 1) +
          mesh.GetCornerPosition(t, 2));
    }
  }
}

//------------------------------------------------------------------------------
void DualGraphSearch::NextGeneration()
{
  if (this->Generation == std::numeric_limits<std::uint32_t>::max())
  {
    // Once every 4 billion searches the stamps wrap: clear them so no stale entry matches.
    for (Node& n : this->Nodes)
    {
      n.Visited = n.Closed = n.Target = 0;
    }
    this->Generation = 0;
  }
  ++this->Generation;
}

//------------------------------------------------------------------------------
bool DualGraphSearch::FindStrip(const std::vector<int>& sources,
  const Vec3& from,
  const std::vector<int>& targets,
  const Vec3& to,
  std::vector<int>& strip)
{
  strip.clear();
  this->LastExpanded = 0;
  this->NextGeneration();
  const std::uint32_t gen = this->Generation;
  const std::greater<std::pair<double, int>> later;
  const double w = this->HeuristicWeight;
  this->Heap.clear();

  for (int t : targets)
  {
    this->Nodes[t].Target = gen;
  }
  for (int t : sources)
  {
    Node& n = this->Nodes[t];
    const double cost = Distance(from, this->Centroids[t]);
    if (n.Visited == gen && n.Cost <= cost)
    {
      continue;
    }
    n.Visited = gen;
    n.Cost = cost;
    n.Parent = -1;
    this->Heap.emplace_back(cost + w * Distance(this->Centroids[t], to), t);
    std::push_heap(this->Heap.begin(), this->Heap.end(), later);
  }

  int reached = -1;
  while (!this->Heap.empty())
  {
    std::pop_heap(this->Heap.begin(), this->Heap.end(), later);
    const int t = this->Heap.back().second;
    this->Heap.pop_back();
    Node& node = this->Nodes[t];
    if (node.Closed == gen)
    {
      continue; // a stale duplicate: the triangle was settled with a lower cost
    }
    node.Closed = gen;
    ++this->LastExpanded;
    if (node.Target == gen)
    {
      // The estimate of a target's centroid-to-end leg is exact, and the bound is consistent,
      // so the first target settled closes the cheapest chain.
      reached = t;
      break;
    }
    const Vec3& c = this->Centroids[t];
    for (int k = 0; k < 3; ++k)
    {
      const int m = this->Mesh.GetNeighbor(t, k);
      if (m < 0)
      {
        continue;
      }
      Node& next = this->Nodes[m];
      if (next.Closed == gen)
      {
        continue;
      }
      const double cost = node.Cost + Distance(c, this->Centroids[m]);
      if (next.Visited == gen && next.Cost <= cost)
      {
        continue;
      }
      next.Visited = gen;
      next.Cost = cost;
      next.Parent = t;
      this->Heap.emplace_back(cost + w * Distance(this->Centroids[m], to), m);
      std::push_heap(this->Heap.begin(), this->Heap.end(), later);
    }
  }
  if (reached < 0)
  {
    return false;
  }
  for (int t = reached; t >= 0; t = this->Nodes[t].Parent)
  {
    strip.push_back(t);
  }
  std::reverse(strip.begin(), strip.end());
  return true;
}

} // namespace boolsurf

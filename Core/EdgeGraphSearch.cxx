#include "EdgeGraphSearch.h"

#include <algorithm>
#include <functional>
#include <limits>

namespace boolsurf
{

//------------------------------------------------------------------------------
EdgeGraphSearch::EdgeGraphSearch(const TriangleMesh& mesh)
  : Mesh(mesh)
{
  const int nv = mesh.GetNumberOfVertices();
  // Morton order of the vertex positions (21 bits per axis in the bounding box).
  std::vector<std::pair<std::uint64_t, int>> keys(nv);
  Vec3 lo{ 0, 0, 0 }, hi{ 0, 0, 0 };
  if (nv > 0)
  {
    lo = hi = mesh.GetPosition(0);
  }
  for (const Vec3& p : mesh.GetPositions())
  {
    lo = { std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z) };
    hi = { std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z) };
  }
  auto spread = [](std::uint64_t x)
  {
    x &= 0x1fffff;
    x = (x | x << 32) & 0x1f00000000ffffULL;
    x = (x | x << 16) & 0x1f0000ff0000ffULL;
    x = (x | x << 8) & 0x100f00f00f00f00fULL;
    x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
    x = (x | x << 2) & 0x1249249249249249ULL;
    return x;
  };
  auto quantize = [](double v, double a, double b)
  {
    const double s = b > a ? (v - a) / (b - a) : 0.0;
    return static_cast<std::uint64_t>(std::min(std::max(s, 0.0), 1.0) * 2097151.0);
  };
  for (int v = 0; v < nv; ++v)
  {
    const Vec3& p = mesh.GetPosition(v);
    keys[v] = { spread(quantize(p.x, lo.x, hi.x)) | spread(quantize(p.y, lo.y, hi.y)) << 1 |
        spread(quantize(p.z, lo.z, hi.z)) << 2,
      v };
  }
  std::sort(keys.begin(), keys.end());
  this->Internal.resize(nv);
  this->External.resize(nv);
  for (int i = 0; i < nv; ++i)
  {
    this->External[i] = keys[i].second;
    this->Internal[keys[i].second] = i;
  }

  this->Offsets.assign(nv + 1, 0);
  this->Nodes.resize(nv);
  // Each vertex lists the other two corners of every usable triangle around it, deduplicated
  // (an interior edge is seen from both of its triangles).
  std::vector<int> row;
  for (int i = 0; i < nv; ++i)
  {
    const int v = this->External[i];
    row.clear();
    for (int corner : mesh.GetVertexCorners(v))
    {
      const int t = corner / 3, k = corner % 3;
      if (!mesh.IsUsable(t))
      {
        continue;
      }
      const Triangle& tri = mesh.GetTriangle(t);
      row.push_back(tri[(k + 1) % 3]);
      row.push_back(tri[(k + 2) % 3]);
    }
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    const Vec3& p = mesh.GetPosition(v);
    this->Nodes[i].Position = p;
    this->Nodes[i].Seen = 0;
    for (int w : row)
    {
      this->Neighbors.push_back(this->Internal[w]);
      this->EdgeCosts.push_back(Distance(p, mesh.GetPosition(w)));
    }
    this->Offsets[i + 1] = static_cast<int>(this->Neighbors.size());
  }
}

//------------------------------------------------------------------------------
void EdgeGraphSearch::NextGeneration()
{
  if (this->Generation == std::numeric_limits<std::uint32_t>::max())
  {
    for (Node& n : this->Nodes)
    {
      n.Seen = 0;
    }
    this->Generation = 0;
  }
  ++this->Generation;
}

//------------------------------------------------------------------------------
// Bidirectional A* with the average potential p(v) = (|v - to| - |v - from|) / 2: the forward
// search orders vertices by g_f(v) + p(v), the backward one by g_b(v) - p(v). Both are
// Dijkstra searches on consistently reduced arc lengths, so the classic bidirectional stopping
// rule applies: once the two smallest keys add up to at least the best complete path seen
// (mu), no shorter path exists. With the virtual start and end nodes the offsets cancel
// (p(from) = -p(to)), which is why the rule reads minF + minB >= mu.
double EdgeGraphSearch::FindPath(const std::vector<Terminal>& sources,
  const Vec3& from,
  const std::vector<Terminal>& targets,
  const Vec3& to,
  std::vector<int>& vertices)
{
  vertices.clear();
  this->LastSettled = 0;
  this->NextGeneration();
  const std::uint32_t gen = this->Generation;
  const std::greater<std::pair<double, int>> later;
  auto potential = [&](const Node& n)
  { return 0.5 * (Distance(n.Position, to) - Distance(n.Position, from)); };
  auto node = [&](int v) -> Node&
  {
    Node& n = this->Nodes[v];
    if (n.Seen != gen)
    {
      n.Seen = gen;
      n.SeenMask = n.ClosedMask = 0;
    }
    return n;
  };

  double mu = std::numeric_limits<double>::infinity();
  int meetA = -1, meetB = -1; // best path: forward chain to meetA, arc, backward chain from meetB
  for (int side = 0; side < 2; ++side)
  {
    std::vector<std::pair<double, int>>& heap = this->Heaps[side];
    heap.clear();
    const double sign = side == 0 ? 1.0 : -1.0;
    const int other = 1 - side;
    for (const Terminal& terminal : side == 0 ? sources : targets)
    {
      const int v = this->Internal[terminal.Vertex];
      Node& n = node(v);
      if ((n.SeenMask & (1 << side)) && n.Cost[side] <= terminal.Cost)
      {
        continue;
      }
      n.SeenMask |= 1 << side;
      n.Cost[side] = terminal.Cost;
      n.Parent[side] = -1;
      heap.emplace_back(terminal.Cost + sign * potential(n), v);
      std::push_heap(heap.begin(), heap.end(), later);
      if ((n.SeenMask & (1 << other)) && n.Cost[0] + n.Cost[1] < mu)
      {
        mu = n.Cost[0] + n.Cost[1];
        meetA = meetB = v;
      }
    }
  }

  for (;;)
  {
    // Drop stale tops (vertices already settled on that side) so the bounds are tight.
    for (int side = 0; side < 2; ++side)
    {
      std::vector<std::pair<double, int>>& heap = this->Heaps[side];
      while (!heap.empty() && (this->Nodes[heap.front().second].ClosedMask & (1 << side)))
      {
        std::pop_heap(heap.begin(), heap.end(), later);
        heap.pop_back();
      }
    }
    if (this->Heaps[0].empty() || this->Heaps[1].empty())
    {
      break; // one side exhausted its component: mu (if finite) is final
    }
    const double minF = this->Heaps[0].front().first, minB = this->Heaps[1].front().first;
    if (minF + minB >= mu)
    {
      break;
    }
    const int side = minF <= minB ? 0 : 1;
    const int other = 1 - side;
    const double sign = side == 0 ? 1.0 : -1.0;
    std::vector<std::pair<double, int>>& heap = this->Heaps[side];
    std::pop_heap(heap.begin(), heap.end(), later);
    const int u = heap.back().second;
    heap.pop_back();
    Node& nu = this->Nodes[u];
    nu.ClosedMask |= 1 << side;
    ++this->LastSettled;
    const double gu = nu.Cost[side];
    for (int i = this->Offsets[u], end = this->Offsets[u + 1]; i < end; ++i)
    {
      const int w = this->Neighbors[i];
      const double g = gu + this->EdgeCosts[i];
      Node& nw = node(w);
      if (nw.SeenMask & (1 << other))
      {
        const double total = g + nw.Cost[other];
        if (total < mu)
        {
          mu = total;
          meetA = side == 0 ? u : w;
          meetB = side == 0 ? w : u;
        }
      }
      if ((nw.ClosedMask & (1 << side)) || ((nw.SeenMask & (1 << side)) && nw.Cost[side] <= g))
      {
        continue;
      }
      nw.SeenMask |= 1 << side;
      nw.Cost[side] = g;
      nw.Parent[side] = u;
      heap.emplace_back(g + sign * potential(nw), w);
      std::push_heap(heap.begin(), heap.end(), later);
    }
  }
  if (meetA < 0)
  {
    return -1.0;
  }
  // Parents only ever move to cheaper chains, so both chains stay valid and no longer than mu.
  // The bound on their length guards against cycles through zero-length edges.
  const int limit = this->Mesh.GetNumberOfVertices();
  for (int v = meetA; v >= 0 && static_cast<int>(vertices.size()) <= limit;
       v = this->Nodes[v].Parent[0])
  {
    vertices.push_back(v);
  }
  std::reverse(vertices.begin(), vertices.end());
  for (int v = meetB == meetA ? this->Nodes[meetB].Parent[1] : meetB;
       v >= 0 && static_cast<int>(vertices.size()) <= 2 * limit;
       v = this->Nodes[v].Parent[1])
  {
    vertices.push_back(v);
  }
  if (static_cast<int>(vertices.size()) > 2 * limit)
  {
    vertices.clear();
    return -1.0;
  }
  for (int& v : vertices)
  {
    v = this->External[v];
  }
  return mu;
}

} // namespace boolsurf

#include "Mesh/MeshTopology.h"

#include "Mesh/PerMeshRegistry.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <deque>

namespace boolsurf
{
namespace
{

// Breadth-first over edge neighbours; also decides orientability by propagating a flip flag
// (a misoriented neighbour pair flips it) and watching for a contradiction.
void ComputeComponents(const TriangleMesh& mesh, MeshTopology& topo)
{
  const int nt = mesh.GetNumberOfTriangles();
  // Zero pages: component 0, most surfaces' only one, is never written, so the array costs
  // memory where a surface has other components or unusable triangles only (17 MB at 4.3M
  // triangles). Bits and a queue that drops what it has visited (a breadth-first front is a
  // small part of a surface) for the rest: a byte per triangle and a queue of every triangle
  // were 21 MB more.
  AssignFreshZeroPages(topo.TriangleComponent, nt);
  std::vector<bool> reached(nt, false), flip(nt, false);
  std::deque<int> queue;
  for (int seed = 0; seed < nt; ++seed)
  {
    if (!mesh.IsUsable(seed))
    {
      topo.TriangleComponent[seed] = -1;
      continue;
    }
    if (reached[seed])
    {
      continue;
    }
    const int c = static_cast<int>(topo.Components.size());
    topo.Components.emplace_back();
    ComponentTopology& comp = topo.Components.back();
    queue.clear();
    queue.push_back(seed);
    reached[seed] = true;
    if (c != 0)
    {
      topo.TriangleComponent[seed] = c;
    }
    while (!queue.empty())
    {
      const int t = queue.front();
      queue.pop_front();
      ++comp.Triangles;
      for (int k = 0; k < 3; ++k)
      {
        const int n = mesh.GetNeighbor(t, k);
        if (n < 0)
        {
          continue;
        }
        // Proper neighbours run the shared edge in opposite directions.
        const Triangle& tri = mesh.GetTriangle(t);
        const Triangle& ntri = mesh.GetTriangle(n);
        const bool same = ntri[mesh.GetNeighborEdge(t, k)] == tri[k];
        const bool nflip = flip[t] != same;
        if (!reached[n])
        {
          reached[n] = true;
          if (c != 0)
          {
            topo.TriangleComponent[n] = c;
          }
          flip[n] = nflip;
          queue.push_back(n);
        }
        else if (flip[n] != nflip)
        {
          comp.Orientable = false;
        }
      }
    }
  }
}

// Groups the corners at each vertex into fans (connected through edges at that vertex) and
// counts one vertex per fan in the fan's component. Vertices are independent: fixed blocks of
// them run in parallel, and their results are merged in vertex order.
void ComputeFans(const TriangleMesh& mesh, MeshTopology& topo)
{
  const int nv = mesh.GetNumberOfVertices();
  const int blockSize = 1 << 14;
  const int blocks = (nv + blockSize - 1) / blockSize;
  // Per block: the component of each fan (one entry per fan), the non-manifold vertices.
  std::vector<std::vector<std::pair<int, int>>> fanComponents(blocks);
  std::vector<std::vector<int>> nonManifold(blocks);
  tbb::parallel_for(0,
    blocks,
    [&](int b)
    {
      std::vector<int> parent;
      auto find = [&](int i)
      {
        while (parent[i] != i)
        {
          parent[i] = parent[parent[i]];
          i = parent[i];
        }
        return i;
      };
      const int end = std::min(nv, (b + 1) * blockSize);
      for (int v = b * blockSize; v < end; ++v)
      {
        const IntRange corners = mesh.GetVertexCorners(v);
        const int d = corners.size();
        if (d == 0)
        {
          continue;
        }
        // Corners are listed in increasing order, hence by increasing triangle: the corner of
        // a neighbouring triangle is found by binary search.
        auto cornerOf = [&](int triangle)
        {
          const int* at = std::lower_bound(corners.begin(), corners.end(), 3 * triangle);
          return at != corners.end() && *at / 3 == triangle ? static_cast<int>(at - corners.begin())
                                                            : -1;
        };
        parent.resize(d);
        for (int i = 0; i < d; ++i)
        {
          parent[i] = i;
        }
        int fans = d;
        for (int i = 0; i < d; ++i)
        {
          const int t = corners[i] / 3, j = corners[i] % 3;
          for (int k : { j, (j + 2) % 3 }) // the two edges of t at v
          {
            const int n = mesh.GetNeighbor(t, k);
            const int m = n < 0 ? -1 : cornerOf(n);
            if (m < 0)
            {
              continue;
            }
            const int x = find(i), y = find(m);
            if (x != y)
            {
              parent[x] = y;
              --fans;
            }
          }
        }
        for (int i = 0; i < d; ++i)
        {
          if (find(i) == i) // one root per fan: credit the fan's component with a vertex
          {
            // Runs of (component, fans): consecutive vertices are mostly in one component,
            // so a block keeps a few runs instead of an entry per fan (8.6 MB at 4.3M).
            std::vector<std::pair<int, int>>& runs = fanComponents[b];
            const int c = topo.TriangleComponent[corners[i] / 3];
            if (runs.empty() || runs.back().first != c)
            {
              runs.emplace_back(c, 0);
            }
            ++runs.back().second;
          }
        }
        if (fans > 1)
        {
          nonManifold[b].push_back(v);
        }
      }
    });
  for (int b = 0; b < blocks; ++b)
  {
    for (const std::pair<int, int>& run : fanComponents[b])
    {
      topo.Components[run.first].Vertices += run.second;
    }
    topo.NonManifoldVertices.insert(
      topo.NonManifoldVertices.end(), nonManifold[b].begin(), nonManifold[b].end());
  }
}

void ComputeBoundaryLoops(const TriangleMesh& mesh, MeshTopology& topo)
{
  const int nt = mesh.GetNumberOfTriangles();
  // Zero pages, loop + 1 written at boundary vertices only (Get/SetVertexBoundaryLoop).
  AssignFreshZeroPages(topo.VertexBoundaryLoopPlusOne, mesh.GetNumberOfVertices());
  std::vector<bool> visited(3 * static_cast<size_t>(nt), false); // bits: 13 MB as bytes at 4.3M
  auto isBoundary = [&](int h)
  {
    const int e = mesh.GetEdgeId(h / 3, h % 3);
    return e >= 0 && mesh.GetEdgeValence(e) == 1;
  };
  // Fallback for broken rotations: any unvisited boundary half-edge leaving vertex b.
  auto anyOutgoing = [&](int b)
  {
    for (int c : mesh.GetVertexCorners(b))
    {
      if (isBoundary(c) && !visited[c])
      {
        return c;
      }
    }
    return -1;
  };
  for (int h0 = 0; h0 < 3 * nt; ++h0)
  {
    if (visited[h0] || !mesh.IsUsable(h0 / 3) || !isBoundary(h0))
    {
      continue;
    }
    BoundaryLoop loop;
    loop.Component = topo.TriangleComponent[h0 / 3];
    const int id = static_cast<int>(topo.BoundaryLoops.size());
    for (int h = h0; h >= 0 && !visited[h];)
    {
      visited[h] = 1;
      const Triangle& tri = mesh.GetTriangle(h / 3);
      const int a = tri[h % 3], b = tri[(h % 3 + 1) % 3];
      loop.Vertices.push_back(a);
      loop.HalfEdges.push_back(h);
      loop.Length += Distance(mesh.GetPosition(a), mesh.GetPosition(b));
      if (topo.GetVertexBoundaryLoop(a) < 0)
      {
        topo.VertexBoundaryLoopPlusOne[a] = id + 1;
      }
      int next = NextBoundaryHalfEdge(mesh, h);
      if (next < 0 || visited[next])
      {
        next = next == h0 ? next : anyOutgoing(b);
      }
      if (next == h0 || next < 0)
      {
        break;
      }
      h = next;
    }
    topo.BoundaryLoops.push_back(std::move(loop));
  }
}

} // namespace

//------------------------------------------------------------------------------
// Rotates around b inside the fan of h's triangle until the outgoing edge has no neighbour.
int NextBoundaryHalfEdge(const TriangleMesh& mesh, int h)
{
  int t = h / 3;
  int out = (h % 3 + 1) % 3; // local edge leaving b in t
  const int b = mesh.GetTriangle(t)[out];
  const int limit = mesh.GetVertexCorners(b).size() + 1;
  for (int step = 0; step < limit; ++step)
  {
    const int n = mesh.GetNeighbor(t, out);
    if (n < 0)
    {
      return mesh.GetEdgeValence(mesh.GetEdgeId(t, out)) == 1 ? 3 * t + out : -1;
    }
    const int m = mesh.GetNeighborEdge(t, out);
    const Triangle& ntri = mesh.GetTriangle(n);
    if (ntri[(m + 1) % 3] != b)
    {
      return -1; // misoriented neighbour: the rotation is undefined
    }
    t = n;
    out = (m + 1) % 3;
  }
  return -1;
}

//------------------------------------------------------------------------------
int MeshTopology::GetEulerCharacteristic() const
{
  int chi = 0;
  for (const ComponentTopology& c : this->Components)
  {
    chi += c.EulerCharacteristic;
  }
  return chi;
}

//------------------------------------------------------------------------------
MeshTopology MeshTopology::Compute(const TriangleMesh& mesh)
{
  MeshTopology topo;
  ComputeComponents(mesh, topo);
  ComputeFans(mesh, topo);
  ComputeBoundaryLoops(mesh, topo);

  for (int e = 0; e < mesh.GetNumberOfEdges(); ++e)
  {
    ++topo.Components[topo.TriangleComponent[mesh.GetEdgeHalfEdge(e) / 3]].Edges;
  }
  for (const BoundaryLoop& loop : topo.BoundaryLoops)
  {
    ++topo.Components[loop.Component].BoundaryLoops;
  }
  for (ComponentTopology& c : topo.Components)
  {
    c.EulerCharacteristic = c.Vertices - c.Edges + c.Triangles;
    c.Genus = c.Orientable ? (2 - c.BoundaryLoops - c.EulerCharacteristic) / 2 : -1;
  }
  return topo;
}

//------------------------------------------------------------------------------
namespace
{
// Weak references: a topology lives as long as the surface's converter holds it. A mesh's
// serial number is never reused, so any topology registered under it is that mesh's.
PerMeshRegistry<const MeshTopology> sharedTopologies;
} // namespace

void MeshTopology::Share(const TriangleMesh& mesh,
  const std::shared_ptr<const MeshTopology>& topology)
{
  sharedTopologies.Get(
    mesh, [&] { return topology; }, [](const MeshTopology&) { return true; });
}

std::shared_ptr<const MeshTopology> MeshTopology::FindShared(const TriangleMesh& mesh)
{
  return sharedTopologies.Find(mesh, [](const MeshTopology&) { return true; });
}

} // namespace boolsurf

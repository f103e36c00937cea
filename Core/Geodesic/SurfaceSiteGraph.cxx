#include "Geodesic/SurfaceSiteGraph.h"

#include "Geodesic/SiteCells.h"

#include "Mesh/MeshTopology.h"
#include "Mesh/PerMeshRegistry.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <random>

#include <tbb/collaborative_call_once.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/task_arena.h>

namespace boolsurf
{

namespace
{
/// The sorted, distinct neighbours of vertex v over the edges of usable triangles, into `row`.
void VertexRow(const TriangleMesh& mesh, int v, std::vector<int>& row)
{
  row.clear();
  for (int corner : mesh.GetVertexCorners(v))
  {
    const int t = corner / 3, k = corner % 3;
    if (mesh.IsUsable(t))
    {
      const Triangle& tri = mesh.GetTriangle(t);
      row.push_back(tri[(k + 1) % 3]);
      row.push_back(tri[(k + 2) % 3]);
    }
  }
  std::sort(row.begin(), row.end());
  row.erase(std::unique(row.begin(), row.end()), row.end());
}

/// Meshes below this many vertices build their graph on one thread (waking others costs more).
constexpr int ParallelVertices = 50000;

/// body(i) for i in [0, n), each index writing only its own slots, in chunks of at least
/// `grain`, on the threads of the arena the build runs in (not a new arena, as ParallelRange
/// makes): a tracing task that waits for the graph (collaborative_call_once in Get) can then
/// take part in its loops, and a filter held to one thread builds it on one.
template <class Body>
void ForEachIndex(bool parallel, int n, const Body& body, int grain)
{
  if (!parallel)
  {
    for (int i = 0; i < n; ++i)
    {
      body(i);
    }
    return;
  }
  tbb::parallel_for(tbb::blocked_range<int>(0, n, grain),
    [&](const tbb::blocked_range<int>& range)
    {
      for (int i = range.begin(); i != range.end(); ++i)
      {
        body(i);
      }
    });
}

/// Vertex adjacency over the edges of usable triangles (compressed rows, mesh ids). Each row
/// is made once, into its block's buffer (fixed blocks of vertices), then the buffers are
/// copied into place: the same rows on any number of threads, at half the cost of making
/// every row twice (once to count, once to write).
void BuildAdjacency(const TriangleMesh& mesh,
  std::vector<int>& offsets,
  std::vector<int>& neighbors)
{
  constexpr int BlockVertices = 4096;
  const int nv = mesh.GetNumberOfVertices();
  const bool parallel = nv >= ParallelVertices;
  const int blocks = (nv + BlockVertices - 1) / BlockVertices;
  offsets.assign(nv + 1, 0);
  std::vector<std::vector<int>> rows(blocks);
  ForEachIndex(
    parallel,
    blocks,
    [&](int block)
    {
      const int first = block * BlockVertices, last = std::min(nv, first + BlockVertices);
      std::vector<int> row;
      for (int v = first; v < last; ++v)
      {
        VertexRow(mesh, v, row);
        offsets[v + 1] = static_cast<int>(row.size());
        rows[block].insert(rows[block].end(), row.begin(), row.end());
      }
    },
    1);
  for (int v = 0; v < nv; ++v)
  {
    offsets[v + 1] += offsets[v];
  }
  neighbors.resize(offsets[nv]);
  ForEachIndex(
    parallel,
    blocks,
    [&](int block)
    {
      std::copy(
        rows[block].begin(), rows[block].end(), neighbors.begin() + offsets[block * BlockVertices]);
      std::vector<int>().swap(rows[block]);
    },
    1);
}
} // namespace

//------------------------------------------------------------------------------
SurfaceSiteGraph::SurfaceSiteGraph(const TriangleMesh& mesh, int hops)
  : Mesh(mesh)
  , MeshSerial(mesh.GetSerial())
{
  const auto begin = std::chrono::steady_clock::now();
  // The topology (whether every component is a sphere) does not depend on the sites: the
  // surface's converter has usually computed it already (MeshTopology::Share); else it is
  // computed on another thread while the sites, cells and arcs are built.
  const auto sites = [&]
  {
    std::vector<int> offsets, neighbors;
    BuildAdjacency(mesh, offsets, neighbors);
    this->ChooseSites(
      offsets, neighbors, hops > 0 ? hops : DefaultHops(mesh.GetNumberOfVertices()));
    this->GrowCells(offsets, neighbors);
    this->BuildArcs(offsets, neighbors);
    this->ComputeSiteNormals();
  };
  const auto allSpheresOf = [](const MeshTopology& t)
  {
    return std::all_of(t.Components.begin(),
      t.Components.end(),
      [](const ComponentTopology& c)
      { return c.BoundaryLoops == 0 && c.EulerCharacteristic == 2; });
  };
  bool allSpheres = false;
  const auto topology = [&] { allSpheres = allSpheresOf(MeshTopology::Compute(mesh)); };
  if (const std::shared_ptr<const MeshTopology> shared = MeshTopology::FindShared(mesh))
  {
    allSpheres = allSpheresOf(*shared);
    sites();
  }
  else if (mesh.GetNumberOfVertices() >= ParallelVertices)
  {
    tbb::parallel_invoke(sites, topology);
  }
  else
  {
    sites();
    topology();
  }
  this->AllSpheres = allSpheres;
  this->BuildSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  static std::atomic<std::uint64_t> builds{ 0 };
  this->BuildNumber = ++builds;
}

//------------------------------------------------------------------------------
int SurfaceSiteGraph::DefaultHops(int vertices)
{
  const int hops = static_cast<int>(std::lround(std::sqrt(static_cast<double>(vertices)) / 80.0));
  return std::min(8, std::max(1, hops));
}

//------------------------------------------------------------------------------
namespace
{
// A surface's graph and the flag that builds it once. The registry hands out the slot under its
// lock (at once); the build runs outside it, in tbb::collaborative_call_once: the threads that
// ask for the graph while it is being built (tracing tasks whose legs need a route) work on
// its parallel loops instead of sleeping on a lock, and the build is isolated, so its thread
// never picks up an outer tracing task that would ask for the same graph again.
struct GraphSlot
{
  const TriangleMesh* Mesh = nullptr;
  tbb::collaborative_once_flag Once;
  std::unique_ptr<const SurfaceSiteGraph> Graph;
  std::atomic<bool> Built{ false };
};

// Weak references: a graph lives as long as a solver on its mesh holds it (the pointers handed
// out share the ownership of the slot).
PerMeshRegistry<GraphSlot> registry;

bool IsSlotOf(const GraphSlot& slot, const TriangleMesh& mesh)
{
  return slot.Mesh == &mesh;
}
} // namespace

std::shared_ptr<const SurfaceSiteGraph> SurfaceSiteGraph::Find(const TriangleMesh& mesh)
{
  const std::shared_ptr<GraphSlot> slot =
    registry.Find(mesh, [&](const GraphSlot& s) { return IsSlotOf(s, mesh); });
  if (!slot || !slot->Built.load(std::memory_order_acquire))
  {
    return nullptr;
  }
  return std::shared_ptr<const SurfaceSiteGraph>(slot, slot->Graph.get());
}

std::shared_ptr<const SurfaceSiteGraph> SurfaceSiteGraph::Get(const TriangleMesh& mesh)
{
  const std::shared_ptr<GraphSlot> slot = registry.Get(
    mesh,
    [&]
    {
      auto made = std::make_shared<GraphSlot>();
      made->Mesh = &mesh;
      return made;
    },
    [&](const GraphSlot& s) { return IsSlotOf(s, mesh); });
  tbb::collaborative_call_once(slot->Once,
    [&]
    {
      slot->Graph = std::make_unique<const SurfaceSiteGraph>(mesh);
      slot->Built.store(true, std::memory_order_release);
    });
  return std::shared_ptr<const SurfaceSiteGraph>(slot, slot->Graph.get());
}

//------------------------------------------------------------------------------
// Greedy maximal set of vertices pairwise more than `hops` edges apart: visit vertices in a
// fixed pseudo-random order; an unclaimed one becomes a site and claims its `hops`-ball
// (breadth-first). The order only spreads the sites; any order gives the covering property.
void SurfaceSiteGraph::ChooseSites(const std::vector<int>& offsets,
  const std::vector<int>& neighbors,
  int hops)
{
  const int nv = this->Mesh.GetNumberOfVertices();
  std::vector<int> order(nv);
  for (int v = 0; v < nv; ++v)
  {
    order[v] = v;
  }
  std::mt19937 rng(20221206u);
  std::shuffle(order.begin(), order.end(), rng);
  std::vector<int> claimed(nv, -1); // hop distance to the claiming site, -1: unclaimed
  std::vector<int> frontier, next;
  for (int v : order)
  {
    if (claimed[v] >= 0 || offsets[v] == offsets[v + 1])
    {
      continue; // claimed, or on no usable triangle
    }
    this->Sites.push_back(v);
    claimed[v] = 0;
    frontier.assign(1, v);
    for (int h = 1; h <= hops && !frontier.empty(); ++h)
    {
      next.clear();
      for (int u : frontier)
      {
        for (int i = offsets[u]; i < offsets[u + 1]; ++i)
        {
          const int w = neighbors[i];
          // Re-claim a vertex a nearer site reaches in fewer hops: keeps balls of later sites
          // from stopping at earlier ones' far edges (only the covering property matters).
          if (claimed[w] < 0 || claimed[w] > h)
          {
            claimed[w] = h;
            next.push_back(w);
          }
        }
      }
      frontier.swap(next);
    }
  }
}

//------------------------------------------------------------------------------
void SurfaceSiteGraph::GrowCells(const std::vector<int>& offsets, const std::vector<int>& neighbors)
{
  // On a large mesh, on the other threads too (the same cells: SiteCells.h), unless this
  // thread is held to one (a global_control, a one-slot arena).
  const bool parallel = this->Mesh.GetNumberOfVertices() >= ParallelVertices &&
    tbb::this_task_arena::max_concurrency() > 1 &&
    tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism) > 1;
  SiteCells cells;
  GrowSiteCells(this->Mesh, offsets, neighbors, this->Sites, parallel, cells);
  this->Cell = std::move(cells.Cell);
  this->Parent = std::move(cells.Parent);
  this->SiteDistance = std::move(cells.SiteDistance);
}

//------------------------------------------------------------------------------
void SurfaceSiteGraph::BuildArcs(const std::vector<int>& offsets, const std::vector<int>& neighbors)
{
  struct Candidate
  {
    int A, B;
    double Length;
    int U, V;
    bool operator<(const Candidate& o) const
    {
      return A != o.A ? A < o.A : B != o.B ? B < o.B : Length < o.Length;
    }
  };
  // The edges between cells, in vertex order (counted per vertex, then written in parallel:
  // the same list as one thread makes, so the sort below keeps the same first edge per run).
  const int nv = this->Mesh.GetNumberOfVertices();
  const bool parallel = nv >= ParallelVertices;
  const auto crosses = [&](int u, int i)
  {
    const int a = this->Cell[u], b = this->Cell[neighbors[i]];
    return a >= 0 && b >= 0 && b != a;
  };
  std::vector<int> first(nv + 1, 0);
  ForEachIndex(
    parallel,
    nv,
    [&](int u)
    {
      int count = 0;
      for (int i = offsets[u]; i < offsets[u + 1]; ++i)
      {
        count += crosses(u, i) ? 1 : 0;
      }
      first[u + 1] = count;
    },
    4096);
  for (int u = 0; u < nv; ++u)
  {
    first[u + 1] += first[u];
  }
  std::vector<Candidate> candidates(first[nv]);
  ForEachIndex(
    parallel,
    nv,
    [&](int u)
    {
      int k = first[u];
      for (int i = offsets[u]; i < offsets[u + 1]; ++i)
      {
        if (crosses(u, i))
        {
          const int w = neighbors[i];
          candidates[k++] = { this->Cell[u],
            this->Cell[w],
            this->SiteDistance[u] + Distance(this->Mesh.GetPosition(u), this->Mesh.GetPosition(w)) +
              this->SiteDistance[w],
            u,
            w };
        }
      }
    },
    4096);
  std::sort(candidates.begin(), candidates.end());
  const int ns = static_cast<int>(this->Sites.size());
  this->ArcOffsets.assign(ns + 1, 0);
  for (std::size_t i = 0; i < candidates.size(); ++i)
  {
    const Candidate& c = candidates[i];
    if (i > 0 && candidates[i - 1].A == c.A && candidates[i - 1].B == c.B)
    {
      continue; // the shortest edge between two cells is the first of its run
    }
    this->ArcTarget.push_back(c.B);
    this->ArcLength.push_back(
      Distance(this->Mesh.GetPosition(this->Sites[c.A]), this->Mesh.GetPosition(this->Sites[c.B])));
    this->ArcFrom.push_back(c.U);
    this->ArcTo.push_back(c.V);
    ++this->ArcOffsets[c.A + 1];
  }
  for (int s = 0; s < ns; ++s)
  {
    this->ArcOffsets[s + 1] += this->ArcOffsets[s];
  }
}

//------------------------------------------------------------------------------
void SurfaceSiteGraph::ComputeSiteNormals()
{
  const TriangleMesh& mesh = this->Mesh;
  this->SiteNormal.assign(this->Sites.size(), Vec3{ 0, 0, 0 });
  for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    if (!mesh.IsUsable(t))
    {
      continue;
    }
    const Triangle& tri = mesh.GetTriangle(t);
    const Vec3& p0 = mesh.GetPosition(tri[0]);
    const Vec3 n = Cross(mesh.GetPosition(tri[1]) - p0, mesh.GetPosition(tri[2]) - p0);
    for (int k = 0; k < 3; ++k)
    {
      const int s = this->Cell[tri[k]];
      if (s >= 0)
      {
        this->SiteNormal[s] = this->SiteNormal[s] + n;
      }
    }
  }
  for (Vec3& n : this->SiteNormal)
  {
    const double length = Length(n);
    n = length > 0.0 ? (1.0 / length) * n : Vec3{ 0, 0, 0 };
  }
}

//------------------------------------------------------------------------------
double SurfaceSiteGraph::TwoArcLength(int a, int m, int b) const
{
  const Vec3& pm = this->Mesh.GetPosition(this->Sites[m]);
  const Vec3 u = this->Mesh.GetPosition(this->Sites[a]) - pm;
  const Vec3 v = this->Mesh.GetPosition(this->Sites[b]) - pm;
  const Vec3& n = this->SiteNormal[m];
  const Vec3 pu = u - Dot(u, n) * n, pv = v - Dot(v, n) * n;
  const double lu = Length(u), lv = Length(v), lpu = Length(pu), lpv = Length(pv);
  if (!(lpu > 0.0 && lpv > 0.0))
  {
    return lu + lv;
  }
  const double c = std::max(-1.0, std::min(1.0, Dot(pu, pv) / (lpu * lpv)));
  const double unfolded = std::sqrt(std::max(0.0, lu * lu + lv * lv - 2.0 * lu * lv * c));
  return std::max(unfolded, Length(u - v));
}

//------------------------------------------------------------------------------
std::size_t SurfaceSiteGraph::GetMemory() const
{
  return this->Sites.size() * sizeof(int) + this->Cell.size() * sizeof(int) +
    this->Parent.size() * sizeof(int) + this->SiteDistance.size() * sizeof(double) +
    this->ArcOffsets.size() * sizeof(int) +
    this->ArcTarget.size() * (3 * sizeof(int) + sizeof(double)) +
    this->SiteNormal.size() * sizeof(Vec3);
}

//------------------------------------------------------------------------------
void SurfaceSiteGraph::FlagNeighbourhood(int s, std::vector<char>& flags) const
{
  flags[s] = 1;
  for (int a = this->ArcOffsets[s]; a < this->ArcOffsets[s + 1]; ++a)
  {
    flags[this->ArcTarget[a]] = 1;
  }
}

//------------------------------------------------------------------------------
void SurfaceSiteGraph::FlagWithin(const std::vector<int>& seeds,
  double radius,
  std::vector<char>& flags) const
{
  std::vector<double> distance(this->Sites.size(), std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap;
  for (const int s : seeds)
  {
    distance[s] = 0.0;
    heap.push({ 0.0, s });
  }
  while (!heap.empty())
  {
    const auto [d, s] = heap.top();
    heap.pop();
    if (d > distance[s])
    {
      continue;
    }
    flags[s] = 1;
    for (int a = this->ArcOffsets[s]; a < this->ArcOffsets[s + 1]; ++a)
    {
      const int w = this->ArcTarget[a];
      const double dw = d + this->ArcLength[a];
      if (dw <= radius && dw < distance[w])
      {
        distance[w] = dw;
        heap.push({ dw, w });
      }
    }
  }
}

//------------------------------------------------------------------------------
void SurfaceSiteGraph::AppendChain(int v, bool down, std::vector<int>& out) const
{
  const std::size_t first = out.size();
  for (int u = v; u >= 0; u = this->Parent[u])
  {
    out.push_back(u);
  }
  if (down)
  {
    std::reverse(out.begin() + static_cast<std::ptrdiff_t>(first), out.end());
  }
}

namespace
{
//------------------------------------------------------------------------------
// FindRoute's per-site arrays sized for `ns` sites, and a new generation of their stamps.
void ResetSiteStamps(int ns, SurfaceSiteGraph::Scratch& scratch)
{
  if (scratch.Stamp.size() != static_cast<std::size_t>(ns))
  {
    scratch.Cost.assign(ns, 0.0);
    scratch.Parent.assign(ns, -1);
    scratch.ArcIn.assign(ns, -1);
    scratch.Source.assign(ns, -1);
    scratch.SecondArc.assign(ns, -1);
    scratch.Stamp.assign(ns, 0u);
    scratch.Generation = 0;
  }
  if (++scratch.Generation == 0)
  {
    std::fill(scratch.Stamp.begin(), scratch.Stamp.end(), 0u);
    scratch.Generation = 1;
  }
}

//------------------------------------------------------------------------------
// Cut loops of a mesh-edge path on `nv` vertices (a chain down a cell may retrace the chain
// that came up it): keep the first visit of a vertex and drop what lay between its visits.
// Mesh-sized, stamped.
void CutLoops(std::size_t nv, SurfaceSiteGraph::Scratch& scratch, std::vector<int>& vertices)
{
  if (scratch.Position.size() != nv)
  {
    scratch.Position.assign(nv, 0);
    scratch.PositionStamp.assign(nv, 0u);
    scratch.PositionGeneration = 0;
  }
  if (++scratch.PositionGeneration == 0)
  {
    std::fill(scratch.PositionStamp.begin(), scratch.PositionStamp.end(), 0u);
    scratch.PositionGeneration = 1;
  }
  std::size_t kept = 0;
  for (std::size_t i = 0; i < vertices.size(); ++i)
  {
    const int v = vertices[i];
    if (scratch.PositionStamp[v] == scratch.PositionGeneration)
    {
      const int at = scratch.Position[v];
      if (at < static_cast<int>(kept) && vertices[at] == v)
      {
        kept = static_cast<std::size_t>(at) + 1;
        continue;
      }
    }
    scratch.PositionStamp[v] = scratch.PositionGeneration;
    scratch.Position[v] = static_cast<int>(kept);
    vertices[kept++] = v;
  }
  vertices.resize(kept);
}
} // namespace

//------------------------------------------------------------------------------
double SurfaceSiteGraph::FindRoute(const std::vector<EdgeGraphSearch::Terminal>& sources,
  const Vec3& from,
  const std::vector<EdgeGraphSearch::Terminal>& targets,
  const Vec3& to,
  const std::vector<char>& avoid,
  Scratch& scratch,
  std::vector<int>& vertices) const
{
  (void)from;
  vertices.clear();
  const int ns = static_cast<int>(this->Sites.size());
  ResetSiteStamps(ns, scratch);
  const std::uint32_t generation = scratch.Generation;
  auto seen = [&](int s) { return scratch.Stamp[s] == generation; };
  auto bound = [&](int s) { return Distance(this->Mesh.GetPosition(this->Sites[s]), to); };

  // Terminal costs: reaching the end from a target cell's site (down its parents to the
  // corner, then the straight segment to the end point).
  std::vector<std::pair<int, double>> exits; // (site, cost), best target corner per site
  std::vector<int> exitCorner;
  for (const EdgeGraphSearch::Terminal& t : targets)
  {
    const int s = this->Cell[t.Vertex];
    if (s < 0)
    {
      continue;
    }
    const double cost = this->SiteDistance[t.Vertex] + t.Cost;
    auto it = std::find_if(
      exits.begin(), exits.end(), [&](const std::pair<int, double>& e) { return e.first == s; });
    if (it == exits.end())
    {
      exits.emplace_back(s, cost);
      exitCorner.push_back(t.Vertex);
    }
    else if (cost < it->second)
    {
      it->second = cost;
      exitCorner[it - exits.begin()] = t.Vertex;
    }
  }
  auto exitOf = [&](int s) -> int
  {
    for (std::size_t i = 0; i < exits.size(); ++i)
    {
      if (exits[i].first == s)
      {
        return static_cast<int>(i);
      }
    }
    return -1;
  };

  std::vector<std::pair<double, int>>& heap = scratch.Heap;
  heap.clear();
  auto push = [&](double key, int s)
  {
    heap.emplace_back(key, s);
    std::push_heap(heap.begin(), heap.end(), std::greater<>());
  };
  for (const EdgeGraphSearch::Terminal& t : sources)
  {
    const int s = this->Cell[t.Vertex];
    if (s < 0)
    {
      continue;
    }
    const double cost = t.Cost + this->SiteDistance[t.Vertex];
    if (!seen(s) || cost < scratch.Cost[s])
    {
      scratch.Stamp[s] = generation;
      scratch.Cost[s] = cost;
      scratch.Parent[s] = -1;
      scratch.ArcIn[s] = -1;
      scratch.SecondArc[s] = -1;
      scratch.Source[s] = t.Vertex;
      push(cost + bound(s), s);
    }
  }
  double best = std::numeric_limits<double>::infinity();
  int bestSite = -1;
  while (!heap.empty())
  {
    std::pop_heap(heap.begin(), heap.end(), std::greater<>());
    // Not a structured binding: the step lambdas below capture the site (C++17 forbids
    // capturing bindings, and clang, which builds the fuzz targets, enforces it).
    const double key = heap.back().first;
    const int s = heap.back().second;
    heap.pop_back();
    if (key >= best)
    {
      break;
    }
    if (key > scratch.Cost[s] + bound(s))
    {
      continue; // stale entry
    }
    const int e = exitOf(s);
    if (e >= 0 && scratch.Cost[s] + exits[e].second < best)
    {
      best = scratch.Cost[s] + exits[e].second;
      bestSite = s;
    }
    auto relax = [&](int w, double cost, int arc, int second)
    {
      if (!seen(w) || cost < scratch.Cost[w])
      {
        scratch.Stamp[w] = generation;
        scratch.Cost[w] = cost;
        scratch.Parent[w] = s;
        scratch.ArcIn[w] = arc;
        scratch.SecondArc[w] = second;
        scratch.Source[w] = -1;
        push(cost + bound(w), w);
      }
    };
    auto blocked = [&](int w) { return !avoid.empty() && avoid[w] && exitOf(w) < 0; };
    for (int a = this->ArcOffsets[s]; a < this->ArcOffsets[s + 1]; ++a)
    {
      const int m = this->ArcTarget[a];
      if (blocked(m))
      {
        continue;
      }
      relax(m, scratch.Cost[s] + this->ArcLength[a], a, -1);
      // Steps over two arcs: a route of single arcs turns only where the cells meet (about
      // every 60 degrees) and zigzags 5-7 % longer than the geodesic it stands for; two-arc
      // steps unfolded at the middle site cut that to about 1 % (see the header).
      for (int b = this->ArcOffsets[m]; b < this->ArcOffsets[m + 1]; ++b)
      {
        const int w = this->ArcTarget[b];
        if (w != s && !blocked(w))
        {
          relax(w, scratch.Cost[s] + this->TwoArcLength(s, m, w), a, b);
        }
      }
    }
  }
  if (bestSite < 0)
  {
    return -1.0;
  }

  // Sites of the route, start to end.
  scratch.Sites.clear();
  scratch.Arcs.clear();
  for (int s = bestSite; s >= 0; s = scratch.Parent[s])
  {
    if (scratch.SecondArc[s] >= 0)
    {
      scratch.Sites.push_back(s);
      scratch.Arcs.push_back(scratch.SecondArc[s]);
      const int m = this->ArcTarget[scratch.ArcIn[s]];
      scratch.Sites.push_back(m);
      scratch.Arcs.push_back(scratch.ArcIn[s]);
    }
    else
    {
      scratch.Sites.push_back(s);
      scratch.Arcs.push_back(scratch.ArcIn[s]);
    }
  }
  std::reverse(scratch.Sites.begin(), scratch.Sites.end());
  std::reverse(scratch.Arcs.begin(), scratch.Arcs.end());
  // Mesh-edge path: up from the start corner to the first site, then each arc's edge path
  // (down to u in the arc's cell, across to v, up to the next site), then down to the end
  // corner.
  const int first = scratch.Sites.front();
  this->AppendChain(scratch.Source[first], false, vertices);
  for (std::size_t i = 1; i < scratch.Sites.size(); ++i)
  {
    const int a = scratch.Arcs[i];
    vertices.pop_back(); // the site itself, appended again as the chain's top
    this->AppendChain(this->ArcFrom[a], true, vertices);
    this->AppendChain(this->ArcTo[a], false, vertices);
  }
  vertices.pop_back();
  this->AppendChain(exitCorner[exitOf(bestSite)], true, vertices);

  CutLoops(static_cast<std::size_t>(this->Mesh.GetNumberOfVertices()), scratch, vertices);
  return best;
}

} // namespace boolsurf

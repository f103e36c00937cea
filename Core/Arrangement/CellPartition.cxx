#include "Arrangement/CellPartition.h"

#include "Arrangement/EditBuffers.h"
#include "Mesh/ConcurrentUnionFind.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <memory>
#include <numeric>

namespace boolsurf
{

//------------------------------------------------------------------------------
int RefinedSurfaceView::FindDirected(int t, int a, int b) const
{
  auto holds = [&](int r)
  {
    const Triangle v = this->Corners(r);
    return (v[0] == a && v[1] == b) || (v[1] == a && v[2] == b) || (v[2] == a && v[0] == b);
  };
  const int s = this->SlotOf(t);
  if (s < 0)
  {
    return holds(t) ? t : -1; // an unusable triangle's entry holds no point
  }
  const int first = (*this->PieceOffset)[s], last = (*this->PieceOffset)[s + 1];
  if (this->CrowdedHalfEdges && 1 + last - first > CrowdedSize)
  {
    return (*this->CrowdedHalfEdges)[s].Find(DirectedPointPair(a, b));
  }
  if (holds(t))
  {
    return t;
  }
  for (int r = first; r < last; ++r)
  {
    if (holds(r))
    {
      return r;
    }
  }
  return -1;
}

//------------------------------------------------------------------------------
int RefinedSurfaceView::Neighbor(int r, int j, bool& blocked) const
{
  const TriangleMesh& mesh = *this->Mesh;
  // r is never a hole (the flood fill walks usable triangles), and an unrefined triangle's
  // corners are the mesh's: the common case reads one triangle, as when they were copied.
  const int t = this->Layout->GetSourceOfPiece(r);
  const bool refined = (*this->Refined)[t] & RefinedBit;
  const Triangle v = refined ? this->Corners(r) : mesh.GetTriangle(t);
  const int x = v[j], y = v[(j + 1) % 3];
  int k = j; // an unrefined triangle's edge j is the mesh edge j
  blocked = false;
  if (!refined)
  {
    // The common case, kept short: an unrefined triangle next to an unrefined triangle.
    const int n = mesh.GetNeighbor(t, j);
    if (n < 0)
    {
      return -1;
    }
    blocked = this->IsMeshSubEdgeBlocked(t, j, x, y);
    return ((*this->Refined)[n] & RefinedBit) ? this->FindDirected(n, y, x) : n;
  }
  else
  {
    const int across = (*this->PieceAcross)[this->PieceAcrossIndex(r, this->SlotOf(t))][j];
    if (across >= 0 || across == AcrossNothing)
    {
      blocked = ((*this->Blocked)[r] >> j) & 1;
      return across >= 0 ? across : -1;
    }
    k = -1 - across;
  }
  const int n = mesh.GetNeighbor(t, k);
  if (n < 0)
  {
    return -1;
  }
  blocked = this->IsMeshSubEdgeBlocked(t, k, x, y);
  return this->FindDirected(n, y, x);
}

//------------------------------------------------------------------------------
namespace
{
// Plain union-find whose roots are the lowest members (single-threaded use).
inline int FindRoot(int* parent, int x)
{
  while (parent[x] != x)
  {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

// Cuts the usable items 0 .. count - 1 into connected groups of at most `size`, each grown
// breadth-first (forEachNeighbor(i, visit) calls visit(n) for each usable neighbour n of i)
// from the lowest item not yet in a group. Seeds come in increasing order, so every item below
// a seed is already in a group: a group's seed is its lowest member and groups are ordered by
// lowest member. groupOf: per item (-1: unusable); members of group g:
// members[offset[g] .. offset[g + 1]), ascending.
template <class Usable, class ForEachNeighbor>
void GrowGroups(int count,
  int size,
  const Usable& usable,
  const ForEachNeighbor& forEachNeighbor,
  std::vector<int>& groupOf,
  std::vector<int>& offset,
  std::vector<int>& members)
{
  groupOf.assign(count, -1);
  offset.assign(1, 0);
  members.clear();
  members.reserve(count);
  for (int seed = 0; seed < count; ++seed)
  {
    if (!usable(seed) || groupOf[seed] >= 0)
    {
      continue;
    }
    const int g = static_cast<int>(offset.size()) - 1;
    const size_t start = members.size();
    const auto full = [&] { return static_cast<int>(members.size() - start) >= size; };
    groupOf[seed] = g;
    members.push_back(seed);
    for (size_t head = start; head < members.size() && !full(); ++head)
    {
      forEachNeighbor(members[head],
        [&](int n)
        {
          if (!full() && groupOf[n] < 0)
          {
            groupOf[n] = g;
            members.push_back(n);
          }
        });
    }
    std::sort(members.begin() + start, members.end());
    offset.push_back(static_cast<int>(members.size()));
  }
}
} // namespace

//------------------------------------------------------------------------------
void BuildMeshTiles(const TriangleMesh& mesh, int size, MeshTiles& tiles, int groupSize)
{
  const int nt = mesh.GetNumberOfTriangles();
  tiles.MeshSerial = mesh.GetSerial();
  GrowGroups(
    nt,
    size,
    [&](int t) { return mesh.IsUsable(t); },
    [&](int t, const auto& visit)
    {
      for (int j = 0; j < 3; ++j)
      {
        const int n = mesh.GetNeighbor(t, j);
        if (n >= 0 && mesh.IsUsable(n))
        {
          visit(n);
        }
      }
    },
    tiles.TileOfTriangle,
    tiles.Offset,
    tiles.Members);
  // Tile pairs (a < b) sharing an edge, distinct, in order: gathered tile by tile, so that
  // only the distinct pairs are kept (a list of every edge between tiles, sorted, was 10-20 MB
  // of the first update at 4.3M triangles).
  std::vector<std::pair<int, int>> adjacent;
  std::vector<int> above; // the tiles above tile a next to it
  for (int a = 0; a < tiles.GetNumberOfTiles(); ++a)
  {
    above.clear();
    for (int m = tiles.Offset[a]; m < tiles.Offset[a + 1]; ++m)
    {
      const int t = tiles.Members[m];
      for (int j = 0; j < 3; ++j)
      {
        const int n = mesh.GetNeighbor(t, j);
        const int b = n < 0 ? -1 : tiles.TileOfTriangle[n];
        if (b > a)
        {
          above.push_back(b);
        }
      }
    }
    std::sort(above.begin(), above.end());
    above.erase(std::unique(above.begin(), above.end()), above.end());
    for (int b : above)
    {
      adjacent.emplace_back(a, b);
    }
  }
  BuildTileGroups(adjacent, groupSize, tiles);
}

//------------------------------------------------------------------------------
namespace
{
// GrowGroups over items 0 .. count - 1 (all usable) joined by `pairs` (a < b, distinct).
void GrowGroupsOverPairs(int count,
  const std::vector<std::pair<int, int>>& pairs,
  int size,
  std::vector<int>& groupOf,
  std::vector<int>& offset,
  std::vector<int>& members)
{
  std::vector<int> degree(static_cast<size_t>(count) + 1, 0);
  for (const std::pair<int, int>& ab : pairs)
  {
    ++degree[ab.first + 1];
    ++degree[ab.second + 1];
  }
  for (int k = 0; k < count; ++k)
  {
    degree[k + 1] += degree[k];
  }
  std::vector<int> neighbors(degree[count]);
  {
    std::vector<int> cursor(degree.begin(), degree.end() - 1);
    for (const std::pair<int, int>& ab : pairs)
    {
      neighbors[cursor[ab.first]++] = ab.second;
      neighbors[cursor[ab.second]++] = ab.first;
    }
  }
  GrowGroups(
    count,
    size,
    [](int) { return true; },
    [&](int k, const auto& visit)
    {
      for (int i = degree[k]; i < degree[k + 1]; ++i)
      {
        visit(neighbors[i]);
      }
    },
    groupOf,
    offset,
    members);
}

// Splits tile arcs by the part (group or block) of their tiles: the arcs inside part p go to
// inner[innerOffset[p] ..) in their order, the others to `across`.
template <class PartOfTile>
void SplitArcs(int parts,
  const std::vector<std::pair<int, int>>& arcs,
  const PartOfTile& partOf,
  std::vector<int>& innerOffset,
  std::vector<std::pair<int, int>>& inner,
  std::vector<std::pair<int, int>>& across)
{
  innerOffset.assign(static_cast<size_t>(parts) + 1, 0);
  across.clear();
  for (const std::pair<int, int>& ab : arcs)
  {
    const int p = partOf(ab.first);
    if (p == partOf(ab.second))
    {
      ++innerOffset[p + 1];
    }
    else
    {
      across.push_back(ab);
    }
  }
  for (int p = 0; p < parts; ++p)
  {
    innerOffset[p + 1] += innerOffset[p];
  }
  inner.resize(innerOffset[parts]);
  std::vector<int> cursor(innerOffset.begin(), innerOffset.end() - 1);
  for (const std::pair<int, int>& ab : arcs)
  {
    const int p = partOf(ab.first);
    if (p == partOf(ab.second))
    {
      inner[cursor[p]++] = ab;
    }
  }
}

// `root` (per tile, flattened) with `arcs` united into it, every root the lowest tile of its
// set (the lowest triangle too: tiles are ordered by lowest member), flattened again.
void UniteArcsIntoRoots(const std::vector<std::pair<int, int>>& arcs, std::vector<int>& root)
{
  int* r = root.data();
  for (const std::pair<int, int>& ab : arcs)
  {
    const int a = FindRoot(r, ab.first), b = FindRoot(r, ab.second);
    if (a != b)
    {
      r[std::max(a, b)] = std::min(a, b);
    }
  }
  for (size_t k = 0; k < root.size(); ++k)
  {
    r[k] = FindRoot(r, static_cast<int>(k));
  }
}
} // namespace

//------------------------------------------------------------------------------
void BuildTileGroups(const std::vector<std::pair<int, int>>& adjacent,
  int groupSize,
  MeshTiles& tiles)
{
  const int count = tiles.GetNumberOfTiles();
  tiles.FirstMember.resize(count);
  for (int k = 0; k < count; ++k)
  {
    tiles.FirstMember[k] = tiles.Members[tiles.Offset[k]];
  }
  // Groups of tiles, grown over tile adjacency like the tiles over triangles.
  GrowGroupsOverPairs(
    count, adjacent, groupSize, tiles.GroupOf, tiles.GroupOffset, tiles.GroupTiles);
  const int groups = tiles.GetNumberOfGroups();
  std::vector<std::pair<int, int>> crossGroupArcs;
  SplitArcs(
    groups,
    adjacent,
    [&](int k) { return tiles.GroupOf[k]; },
    tiles.GroupArcOffset,
    tiles.GroupArcs,
    crossGroupArcs);
  // Each group's components with every tile clean, rooted at their lowest tile, the state the
  // flood fill of an edit starts from in groups it does not touch.
  tiles.GroupRoot.resize(count);
  std::iota(tiles.GroupRoot.begin(), tiles.GroupRoot.end(), 0);
  UniteArcsIntoRoots(tiles.GroupArcs, tiles.GroupRoot);

  // Blocks of groups, the same way one level up, grown over the groups joined by an arc.
  std::vector<std::pair<int, int>> groupPairs;
  groupPairs.reserve(crossGroupArcs.size());
  for (const std::pair<int, int>& ab : crossGroupArcs)
  {
    const int a = tiles.GroupOf[ab.first], b = tiles.GroupOf[ab.second];
    groupPairs.emplace_back(std::min(a, b), std::max(a, b));
  }
  std::sort(groupPairs.begin(), groupPairs.end());
  groupPairs.erase(std::unique(groupPairs.begin(), groupPairs.end()), groupPairs.end());
  GrowGroupsOverPairs(
    groups, groupPairs, groupSize, tiles.BlockOf, tiles.BlockOffset, tiles.BlockGroups);
  SplitArcs(
    tiles.GetNumberOfBlocks(),
    crossGroupArcs,
    [&](int k) { return tiles.BlockOf[tiles.GroupOf[k]]; },
    tiles.BlockArcOffset,
    tiles.BlockArcs,
    tiles.CrossBlockArcs);
  tiles.BlockRoot = tiles.GroupRoot;
  UniteArcsIntoRoots(tiles.BlockArcs, tiles.BlockRoot);
}

namespace
{
// The whole refined surface as one union-find, in parallel over fixed blocks of source
// triangles (used when curves touch most tiles: then tiles save nothing and this scales with
// threads). Same sets, roots and numbering as the tiled flood fill.
int FloodFillAllTriangles(const RefinedSurfaceView& surface,
  ZeroPageVector<int>& cellOfTriangle,
  std::vector<int>* cellFirstTriangle,
  TileFloodBuffers& scratch)
{
  const TriangleMesh& mesh = *surface.Mesh;
  const int count = surface.GetNumberOfTriangles();
  const int nt = mesh.GetNumberOfTriangles();
  const auto source = [&](int r) { return surface.SourceOf(r); };
  const char* state = surface.Refined->data();
  const Triangle* meshTriangles = mesh.GetTriangles().data();
  if (scratch.AtomicCapacity < static_cast<size_t>(count))
  {
    scratch.AtomicCapacity = EditCapacity(count);
    scratch.AtomicParent.reset(new std::atomic<int>[scratch.AtomicCapacity]);
  }
  std::atomic<int>* parent = scratch.AtomicParent.get();
  ResizeDiscardingForEdits(cellOfTriangle, count); // every entry is written below
  const int grain = 4096;
  tbb::parallel_for(tbb::blocked_range<int>(0, count, grain),
    [&](const tbb::blocked_range<int>& range)
    {
      for (int r = range.begin(); r != range.end(); ++r)
      {
        parent[r].store(r, std::memory_order_relaxed);
      }
    });

  // Phase 1, per fixed block of source triangles (independent of the thread count): arcs with
  // both ends in the block are united with plain loads and stores, since no other thread
  // touches the block's nodes; arcs leaving the block are kept for phase 2. Every arc is
  // united from at least one side: arcs between unrefined triangles from the lower one, arcs
  // touching a refined triangle from each refined side. With one thread, all arcs are united
  // in phase 1 (the same sets, without atomic instructions).
  const bool serial = tbb::this_task_arena::max_concurrency() == 1;
  const int sourceBlock = 1 << 16;
  const int sourceBlocks = (nt + sourceBlock - 1) / sourceBlock;
  std::vector<std::vector<std::pair<int, int>>>& crossing = scratch.Crossing;
  crossing.resize(sourceBlocks);
  for (auto& arcs : crossing)
  {
    arcs.clear();
  }
  tbb::parallel_for(0,
    sourceBlocks,
    [&](int b)
    {
      const int t0 = b * sourceBlock, t1 = std::min(nt, t0 + sourceBlock);
      std::vector<std::pair<int, int>>& out = crossing[b];
      // The block's nodes: its own mesh triangles and the pieces appended for them.
      auto inBlock = [&](int y)
      {
        const int t = surface.Layout->GetSourceOfPiece(y);
        return t >= t0 && t < t1;
      };
      auto unite = [&](int x, int y)
      {
        if (!serial && !inBlock(y))
        {
          out.emplace_back(x, y);
          return;
        }
        x = FindSet(parent, x);
        y = FindSet(parent, y);
        if (x != y)
        {
          parent[std::max(x, y)].store(std::min(x, y), std::memory_order_relaxed);
        }
      };
      for (int t = t0; t < t1; ++t)
      {
        if (!mesh.IsUsable(t))
        {
          continue;
        }
        const char st = state[t];
        if (st == 0)
        {
          // Fast path: an unrefined triangle without curves on its edges.
          for (int j = 0; j < 3; ++j)
          {
            const int n = mesh.GetNeighbor(t, j);
            if (n > t && !(state[n] & RefinedSurfaceView::RefinedBit))
            {
              unite(t, n);
            }
          }
        }
        else if (!(st & RefinedSurfaceView::RefinedBit))
        {
          const Triangle& tri = meshTriangles[t];
          for (int j = 0; j < 3; ++j)
          {
            const int n = mesh.GetNeighbor(t, j);
            if (n <= t || (state[n] & RefinedSurfaceView::RefinedBit))
            {
              continue;
            }
            if (surface.IsMeshSubEdgeBlocked(t, j, tri[j], tri[(j + 1) % 3]))
            {
              continue;
            }
            unite(t, n);
          }
        }
        else
        {
          surface.ForEachOpenArcOfPieces(t, unite);
        }
      }
    });
  // Phase 2: arcs between blocks, by lock-free unions.
  tbb::parallel_for(0,
    sourceBlocks,
    [&](int b)
    {
      for (const std::pair<int, int>& arc : crossing[b])
      {
        UniteSets(parent, arc.first, arc.second);
      }
    });

  // Number the roots (the lowest triangle of each cell) in order: per fixed block, count, scan,
  // then number; then every triangle takes its root's number.
  const int blockSize = 1 << 16;
  const int blocks = (count + blockSize - 1) / blockSize;
  std::vector<int>& blockRoots = scratch.BlockRoots;
  blockRoots.assign(blocks + 1, 0);
  tbb::parallel_for(0,
    blocks,
    [&](int b)
    {
      const int end = std::min(count, (b + 1) * blockSize);
      int roots = 0;
      for (int r = b * blockSize; r < end; ++r)
      {
        const int root = FindSet(parent, r);
        parent[r].store(root, std::memory_order_relaxed);
        roots += root == r && source(r) >= 0; // not an unusable triangle's empty entry
      }
      blockRoots[b + 1] = roots;
    });
  for (int b = 0; b < blocks; ++b)
  {
    blockRoots[b + 1] += blockRoots[b];
  }
  if (cellFirstTriangle)
  {
    cellFirstTriangle->resize(blockRoots[blocks]);
  }
  tbb::parallel_for(0,
    blocks,
    [&](int b)
    {
      const int end = std::min(count, (b + 1) * blockSize);
      int next = blockRoots[b];
      for (int r = b * blockSize; r < end; ++r)
      {
        if (source(r) < 0)
        {
          cellOfTriangle[r] = -1;
        }
        else if (parent[r].load(std::memory_order_relaxed) == r)
        {
          if (cellFirstTriangle)
          {
            (*cellFirstTriangle)[next] = r;
          }
          cellOfTriangle[r] = next++;
        }
      }
    });
  tbb::parallel_for(tbb::blocked_range<int>(0, count, grain),
    [&](const tbb::blocked_range<int>& range)
    {
      for (int r = range.begin(); r != range.end(); ++r)
      {
        const int root = parent[r].load(std::memory_order_relaxed);
        if (root != r)
        {
          cellOfTriangle[r] = cellOfTriangle[root];
        }
      }
    });
  return blockRoots[blocks];
}

//------------------------------------------------------------------------------
// Union-find over compact nodes (clean tiles first, then the refined triangles of dirty tiles),
// so that the tile-level work stays in cache: indexing it by refined triangle scattered one
// cache miss per tile over a million-entry array. Each root keeps the lowest refined triangle of
// its set (Key), which orders the cells.
inline void UniteByKey(int* parent, const int* key, int a, int b)
{
  a = FindRoot(parent, a);
  b = FindRoot(parent, b);
  if (a != b)
  {
    if (key[a] < key[b])
    {
      parent[b] = a;
    }
    else
    {
      parent[a] = b;
    }
  }
}

// FloodFillTiles: the arcs between clean tiles united. Tile nodes start from their blocks'
// precomputed components (roots are the lowest tiles, so the lowest keys: tiles are ordered by
// lowest member). A block with a dirty tile starts from its groups' components instead, a
// group with a dirty tile from single tiles, and each unites its own arcs between clean tiles.
// Then the arcs between blocks: what an edit pays for the tile graph is those and the touched
// groups and blocks, not every arc of it. The dirty tiles' nodes start as single sets.
void UniteCleanTiles(const MeshTiles& tiles,
  const char* dirty,
  int nodes,
  int* parent,
  const int* keys,
  TileFloodBuffers& buffers)
{
  const int numberOfTiles = tiles.GetNumberOfTiles();
  const std::vector<int>& dirtyTiles = buffers.DirtyTiles;
  std::copy(tiles.BlockRoot.begin(), tiles.BlockRoot.end(), parent);
  for (int i = numberOfTiles; i < nodes; ++i)
  {
    parent[i] = i;
  }
  const auto markParts = [](int part, std::vector<char>& marked, std::vector<int>& list)
  {
    if (!marked[part])
    {
      marked[part] = 1;
      list.push_back(part);
    }
  };
  std::vector<char>& dirtyGroup = buffers.DirtyGroup;
  std::vector<char>& dirtyBlock = buffers.DirtyBlock;
  if (static_cast<int>(dirtyGroup.size()) != tiles.GetNumberOfGroups() ||
    static_cast<int>(dirtyBlock.size()) != tiles.GetNumberOfBlocks())
  {
    dirtyGroup.assign(tiles.GetNumberOfGroups(), 0);
    dirtyBlock.assign(tiles.GetNumberOfBlocks(), 0);
  }
  std::vector<int>& dirtyGroups = buffers.DirtyGroups;
  std::vector<int>& dirtyBlocks = buffers.DirtyBlocks;
  dirtyGroups.clear();
  dirtyBlocks.clear();
  for (int k : dirtyTiles)
  {
    markParts(tiles.GroupOf[k], dirtyGroup, dirtyGroups);
    markParts(tiles.BlockOf[tiles.GroupOf[k]], dirtyBlock, dirtyBlocks);
  }
  for (int b : dirtyBlocks)
  {
    for (int i = tiles.BlockOffset[b]; i < tiles.BlockOffset[b + 1]; ++i)
    {
      const int g = tiles.BlockGroups[i];
      for (int j = tiles.GroupOffset[g]; j < tiles.GroupOffset[g + 1]; ++j)
      {
        const int k = tiles.GroupTiles[j];
        parent[k] = dirtyGroup[g] ? k : tiles.GroupRoot[k];
      }
    }
  }
  const auto uniteClean = [&](const std::pair<int, int>* begin, const std::pair<int, int>* end)
  {
    for (const std::pair<int, int>* ab = begin; ab != end; ++ab)
    {
      if (!dirty[ab->first] && !dirty[ab->second])
      {
        UniteByKey(parent, keys, ab->first, ab->second);
      }
    }
  };
  for (int g : dirtyGroups)
  {
    const std::pair<int, int>* arcs = tiles.GroupArcs.data();
    uniteClean(arcs + tiles.GroupArcOffset[g], arcs + tiles.GroupArcOffset[g + 1]);
    dirtyGroup[g] = 0;
  }
  for (int b : dirtyBlocks)
  {
    const std::pair<int, int>* arcs = tiles.BlockArcs.data();
    uniteClean(arcs + tiles.BlockArcOffset[b], arcs + tiles.BlockArcOffset[b + 1]);
    dirtyBlock[b] = 0;
  }
  uniteClean(
    tiles.CrossBlockArcs.data(), tiles.CrossBlockArcs.data() + tiles.CrossBlockArcs.size());
}

// FloodFillTiles, once every arc is united: the roots (each holds its set's lowest refined
// triangle) numbered as cells in increasing order of it; the number of cells.
int NumberCellsOfRoots(const MeshTiles& tiles,
  const char* dirty,
  int count,
  int nodes,
  int* parent,
  const int* keys,
  ZeroPageVector<int>& looseCell,
  std::vector<int>* cellFirstTriangle,
  TileFloodBuffers& buffers)
{
  const int numberOfTiles = tiles.GetNumberOfTiles();
  std::vector<int>& cellOfRoot = buffers.CellOfRoot;
  cellOfRoot.resize(nodes);
  std::vector<int> roots;
  auto collect = [&](int i)
  {
    parent[i] = FindRoot(parent, i);
    if (parent[i] == i)
    {
      roots.push_back(i);
    }
  };
  for (int k = 0; k < numberOfTiles; ++k)
  {
    if (!dirty[k])
    {
      collect(k);
    }
  }
  for (int i = numberOfTiles; i < nodes; ++i)
  {
    collect(i);
  }
  std::sort(roots.begin(), roots.end(), [&](int a, int b) { return keys[a] < keys[b]; });
  for (size_t c = 0; c < roots.size(); ++c)
  {
    cellOfRoot[roots[c]] = static_cast<int>(c);
  }
  if (cellFirstTriangle)
  {
    cellFirstTriangle->resize(roots.size());
    for (size_t c = 0; c < roots.size(); ++c)
    {
      (*cellFirstTriangle)[c] = keys[roots[c]];
    }
  }
  // Each clean tile's cell (in TileNode), then the triangles of the dirty tiles: nothing is
  // written for the triangles of clean tiles (TriangleCellLookup reads their tile's cell).
  // Every parent is now a root, so these are independent writes, in parallel; the dirty tiles'
  // nodes keep their cells (NodeCell) for listing the cells' contents.
  ResizeDiscardingForEdits(looseCell, count); // the entries read are written below
  int* cell = looseCell.data();
  std::vector<int>& nodeCell = buffers.NodeCell;
  nodeCell.resize(nodes);
  std::vector<int>& tileCell = buffers.TileNode;
  constexpr int grain = 1 << 14;
  tbb::parallel_for(tbb::blocked_range<int>(0, nodes, grain),
    [&](const tbb::blocked_range<int>& range)
    {
      for (int i = range.begin(); i != range.end(); ++i)
      {
        if (i < numberOfTiles)
        {
          tileCell[i] = dirty[i] ? -1 : cellOfRoot[parent[i]];
        }
        else
        {
          nodeCell[i] = cell[keys[i]] = cellOfRoot[parent[i]];
        }
      }
    });
  return static_cast<int>(roots.size());
}

// Dirty tiles per parallel task of FloodFillTiles (about 64 triangles each).
constexpr int DirtyTileGrain = 16;

int FloodFillTiles(const RefinedSurfaceView& surface,
  const MeshTiles& tiles,
  ZeroPageVector<int>& looseCell,
  std::vector<int>* cellFirstTriangle,
  TileFloodBuffers& buffers)
{
  const TriangleMesh& mesh = *surface.Mesh;
  const int count = surface.GetNumberOfTriangles();
  const char* state = surface.Refined->data();
  const int* tileOf = tiles.TileOfTriangle.data();
  const int numberOfTiles = tiles.GetNumberOfTiles();
  const char* dirty = buffers.Dirty.data();
  const std::vector<int>& dirtyTiles = buffers.DirtyTiles;
  // Node of each refined triangle of a dirty tile (entries of other triangles are stale).
  ZeroPageVector<int>& nodeOfTriangle = buffers.NodeOfTriangle;
  ResizeDiscardingForEdits(nodeOfTriangle, count);
  // Nodes: tile k is node k (used only when clean), then the dirty tiles' refined triangles.
  std::vector<int>& key = buffers.NodeKey;
  // A tile's key is its lowest triangle (unrefined: refined index = mesh index).
  key.assign(tiles.FirstMember.begin(), tiles.FirstMember.end());
  // The dirty tiles' nodes, numbered tile after tile (first node of dirty tile d: firstNode[d]);
  // tiles are independent, so blocks of them run in parallel, here and for the arcs below.
  const int dirtyCount = static_cast<int>(dirtyTiles.size());
  // Holds each dirty tile's piece count at d + 1 (FloodFillCellsByTiles counted them).
  std::vector<int>& firstNode = buffers.DirtyTileFirstNode;
  // body(d, dirty tile, block) for each dirty tile d; block b holds d in
  // [b * DirtyTileGrain, (b + 1) * DirtyTileGrain) and runs on one thread.
  const int blocks = (dirtyCount + DirtyTileGrain - 1) / DirtyTileGrain;
  const auto forDirtyTiles = [&](auto&& body)
  {
    tbb::parallel_for(0,
      blocks,
      [&](int block)
      {
        const int end = std::min(dirtyCount, (block + 1) * DirtyTileGrain);
        for (int d = block * DirtyTileGrain; d < end; ++d)
        {
          body(d, dirtyTiles[d], block);
        }
      });
  };
  firstNode[0] = numberOfTiles;
  for (int d = 0; d < dirtyCount; ++d)
  {
    firstNode[d + 1] += firstNode[d];
  }
  key.resize(firstNode[dirtyCount]);
  forDirtyTiles(
    [&](int d, int k, int)
    {
      int node = firstNode[d];
      for (int i = tiles.Offset[k]; i < tiles.Offset[k + 1]; ++i)
      {
        surface.ForEachPiece(tiles.Members[i],
          [&](int r)
          {
            nodeOfTriangle[r] = node;
            key[node++] = r;
          });
      }
    });
  const int nodes = static_cast<int>(key.size());
  std::vector<int>& parentOfNode = buffers.NodeParent;
  parentOfNode.resize(nodes);
  int* parent = parentOfNode.data();
  const int* keys = key.data();
  auto nodeOf = [&](int r)
  {
    const int k = tileOf[surface.Layout->GetSourceOfPiece(r)]; // a node is never a hole
    return dirty[k] ? nodeOfTriangle[r] : k;
  };

  UniteCleanTiles(tiles, dirty, nodes, parent, keys, buffers);
  // Arcs from the triangles of dirty tiles, as in FloodFillAllTriangles; an arc between two
  // unrefined triangles of dirty tiles is united from the lower one, an arc into a clean tile from
  // the dirty side, an arc touching a refined triangle from each refined side. An arc inside one
  // dirty tile joins nodes of that tile only, so the tiles are united in parallel; an arc to
  // another tile is kept and united afterwards (sets keep their lowest key as root, so the
  // order of the unions does not change the result).
  std::vector<std::vector<std::pair<int, int>>>& crossing = buffers.TileCrossing;
  if (static_cast<int>(crossing.size()) < blocks)
  {
    crossing.resize(blocks);
  }
  forDirtyTiles(
    [&](int d, int k, int block)
    {
      std::vector<std::pair<int, int>>& across = crossing[block];
      if (d % DirtyTileGrain == 0)
      {
        across.clear();
      }
      const int first = firstNode[d], end = firstNode[d + 1];
      const auto unite = [&](int a, int b)
      {
        if (b >= first && b < end)
        {
          UniteByKey(parent, keys, a, b);
        }
        else
        {
          across.emplace_back(a, b);
        }
      };
      for (int i = tiles.Offset[k]; i < tiles.Offset[k + 1]; ++i)
      {
        const int t = tiles.Members[i];
        const char st = state[t];
        if (!(st & RefinedSurfaceView::RefinedBit))
        {
          const Triangle& tri = mesh.GetTriangle(t);
          for (int j = 0; j < 3; ++j)
          {
            const int n = mesh.GetNeighbor(t, j);
            if (n < 0 || (state[n] & RefinedSurfaceView::RefinedBit))
            {
              continue;
            }
            const int kn = tileOf[n];
            const bool cleanNeighbor = !dirty[kn];
            if (!cleanNeighbor && n <= t)
            {
              continue;
            }
            if (st != 0 && surface.IsMeshSubEdgeBlocked(t, j, tri[j], tri[(j + 1) % 3]))
            {
              continue;
            }
            unite(nodeOfTriangle[t], cleanNeighbor ? kn : nodeOfTriangle[n]);
          }
          continue;
        }
        surface.ForEachOpenArcOfPieces(
          t, [&](int r, int n) { unite(nodeOfTriangle[r], nodeOf(n)); });
      }
    });
  for (int block = 0; block < blocks; ++block)
  {
    for (const std::pair<int, int>& ab : crossing[block])
    {
      UniteByKey(parent, keys, ab.first, ab.second);
    }
  }

  return NumberCellsOfRoots(
    tiles, dirty, count, nodes, parent, keys, looseCell, cellFirstTriangle, buffers);
}

// Groups items by cell, stably (a counting sort): items of cell c end up in
// out[offsets[c] .. offsets[c + 1]). forEach(f) must call f(cell, item) for every item, in the
// same order each time (it is called twice: count, then place).
template <class ForEach>
void GroupByCell(int cells,
  const ForEach& forEach,
  std::vector<int>& offsets,
  std::vector<int>& out)
{
  offsets.assign(cells + 1, 0);
  forEach([&](int cell, int) { ++offsets[cell + 1]; });
  for (int c = 0; c < cells; ++c)
  {
    offsets[c + 1] += offsets[c];
  }
  out.resize(offsets[cells]);
  std::vector<int> cursor(offsets.begin(), offsets.end() - 1);
  forEach([&](int cell, int item) { out[cursor[cell]++] = item; });
}

//------------------------------------------------------------------------------
// Each cell's clean tiles (in tile order) and loose triangles (those of dirty tiles, in tile
// order). buffers.TileNode holds the cell of each clean tile, -1 for dirty ones. `byNodes`:
// the tiled flood fill ran, so the loose triangles are its nodes after the tiles' (NodeKey),
// already in that order, with their cells in NodeCell: two passes over those arrays instead
// of enumerating the dirty tiles' pieces twice.
void ListCellContents(const MeshTiles& tiles,
  const RefinedSurfaceView& surface,
  const ZeroPageVector<int>& looseCell,
  int cells,
  const TileFloodBuffers& buffers,
  bool byNodes,
  CellContents& contents)
{
  const std::vector<int>& tileNode = buffers.TileNode;
  GroupByCell(
    cells,
    [&](const auto& f)
    {
      for (int k = 0; k < tiles.GetNumberOfTiles(); ++k)
      {
        if (tileNode[k] >= 0)
        {
          f(tileNode[k], k);
        }
      }
    },
    contents.TileOffset,
    contents.Tiles);
  if (byNodes)
  {
    const int first = tiles.GetNumberOfTiles(), nodes = static_cast<int>(buffers.NodeKey.size());
    GroupByCell(
      cells,
      [&](const auto& f)
      {
        for (int i = first; i < nodes; ++i)
        {
          f(buffers.NodeCell[i], buffers.NodeKey[i]);
        }
      },
      contents.TriangleOffset,
      contents.Triangles);
    return;
  }
  GroupByCell(
    cells,
    [&](const auto& f)
    {
      for (int k : buffers.DirtyTiles)
      {
        for (int i = tiles.Offset[k]; i < tiles.Offset[k + 1]; ++i)
        {
          surface.ForEachPiece(tiles.Members[i], [&](int r) { f(looseCell[r], r); });
        }
      }
    },
    contents.TriangleOffset,
    contents.Triangles);
}
} // namespace

//------------------------------------------------------------------------------
int FloodFillCellsByTiles(const RefinedSurfaceView& surface,
  const MeshTiles& tiles,
  const std::vector<int>& changedTriangles,
  std::vector<int>& tileCell,
  ZeroPageVector<int>& looseCell,
  std::vector<int>* cellFirstTriangle,
  TileFloodBuffers& buffers,
  CellContents* contents)
{
  const int count = surface.GetNumberOfTriangles();
  const int* tileOf = tiles.TileOfTriangle.data();
  const int numberOfTiles = tiles.GetNumberOfTiles();
  if (static_cast<int>(buffers.Dirty.size()) != numberOfTiles)
  {
    buffers.Dirty.assign(numberOfTiles, 0);
  }
  char* dirty = buffers.Dirty.data();
  std::vector<int>& dirtyTiles = buffers.DirtyTiles;
  dirtyTiles.clear();
  for (int t : changedTriangles)
  {
    const int k = tileOf[t];
    if (k >= 0 && !dirty[k])
    {
      dirty[k] = 1;
      dirtyTiles.push_back(k);
    }
  }
  std::sort(dirtyTiles.begin(), dirtyTiles.end());
  // Where curves touch most of the surface, tiles save little and their triangle-level part is
  // sequential: flood the whole surface in parallel instead (same result). Measured on 1M
  // triangles, the tiled fill wins up to about a quarter of the triangles touched with two
  // threads (and beyond with one); a flat square with a third touched floods in 24 ms on two
  // threads this way against 36 ms tiled.
  // Pieces per dirty tile (at d + 1, for FloodFillTiles's node numbering), in parallel.
  const int dirtyCount = static_cast<int>(dirtyTiles.size());
  std::vector<int>& pieces = buffers.DirtyTileFirstNode;
  pieces.assign(static_cast<size_t>(dirtyCount) + 1, 0);
  tbb::parallel_for(tbb::blocked_range<int>(0, dirtyCount, DirtyTileGrain),
    [&](const tbb::blocked_range<int>& range)
    {
      for (int d = range.begin(); d != range.end(); ++d)
      {
        const int k = dirtyTiles[d];
        int n = 0;
        for (int i = tiles.Offset[k]; i < tiles.Offset[k + 1]; ++i)
        {
          n += surface.CountPieces(tiles.Members[i]);
        }
        pieces[d + 1] = n;
      }
    });
  long long touched = 0;
  for (int d = 0; d < dirtyCount; ++d)
  {
    touched += pieces[d + 1];
  }
  const int threads = tbb::this_task_arena::max_concurrency();
  std::vector<int>& tileNode = buffers.TileNode;
  tileNode.resize(numberOfTiles);
  int cellCount = 0;
  bool tiled = false;
  if (buffers.Method == FloodFillMethod::Triangles ||
    (buffers.Method == FloodFillMethod::Automatic && touched * 2 * threads > count))
  {
    cellCount = FloodFillAllTriangles(surface, looseCell, cellFirstTriangle, buffers);
    for (int k = 0; k < numberOfTiles; ++k)
    {
      tileNode[k] = dirty[k] ? -1 : looseCell[tiles.FirstMember[k]];
    }
  }
  else
  {
    cellCount = FloodFillTiles(surface, tiles, looseCell, cellFirstTriangle, buffers);
    tiled = true;
  }
  tileCell.assign(tileNode.begin(), tileNode.end());
  if (contents)
  {
    ListCellContents(tiles, surface, looseCell, cellCount, buffers, tiled, *contents);
  }
  for (int k : dirtyTiles)
  {
    dirty[k] = 0;
  }
  return cellCount;
}

//------------------------------------------------------------------------------
int BuildPatchesAndCellGraph(const RefinedSurfaceView& surface,
  const std::vector<TracedCurve>& curves,
  const std::vector<RefinedCurve>& refinedCurves,
  const std::vector<Vec3>& curvePositions,
  const std::vector<SurfacePoint>& curvePointSurface,
  const TriangleCellLookup& cellOfTriangle,
  std::vector<ArrangementPatch>& patches,
  std::vector<CellGraphArc>& arcs,
  PatchGraphBuffers* buffers)
{
  const TriangleMesh& mesh = *surface.Mesh;
  const int nv = mesh.GetNumberOfVertices();
  const std::size_t numberOfPoints = nv + curvePositions.size();
  const auto position = [&](int p)
  { return p < nv ? mesh.GetPosition(p) : curvePositions[p - nv]; };
  patches.clear();
  arcs.clear();

  // Per-point marks, zero between calls; only curve points are ever marked, so they are reset
  // at the end instead of filling arrays over every refined point on each edit.
  PatchGraphBuffers localBuffers;
  PatchGraphBuffers& marks = buffers ? *buffers : localBuffers;
  if (marks.Visits.size() < numberOfPoints)
  {
    // Zero pages, or entries reset at the end of the last call.
    ResizeDiscardingForEdits(marks.Visits, numberOfPoints);
    ResizeDiscardingForEdits(marks.IsEnd, numberOfPoints);
  }
  // Visits per point over all curves: a point visited twice is where curves meet (crossing,
  // touching, overlap end, or a curve meeting itself).
  ZeroPageVector<int>& visits = marks.Visits;
  for (size_t ci = 0; ci < refinedCurves.size(); ++ci)
  {
    const std::vector<int>& pts = refinedCurves[ci].Points;
    const int n = static_cast<int>(pts.size());
    for (int p : pts)
    {
      ++visits[p];
    }
    // A curve that turns back on itself (the tip of a spike, the end of a keyhole bridge, a
    // zero-area A -> B -> A) leaves its tip along the sub-edge it came by: the tip is a meeting
    // point too, so the way out and the way back are separate patches on one place, whose
    // label changes cancel.
    const bool cyclic = curves[ci].Closed;
    for (int i = cyclic ? 0 : 1; i < (cyclic ? n : n - 1) && n >= (cyclic ? 2 : 3); ++i)
    {
      if (pts[(i + n - 1) % n] == pts[(i + 1) % n])
      {
        ++visits[pts[i]];
      }
    }
  }
  ZeroPageVector<char>& isEnd = marks.IsEnd;
  int graphVertices = 0;
  auto markEnd = [&](int p)
  {
    if (!isEnd[p])
    {
      isEnd[p] = 1;
      ++graphVertices;
    }
  };

  // Cells on the left and right of sub-edge p -> q.
  auto sides = [&](int p, int q, int source, int& left, int& right)
  {
    int candidates[2] = { source, -1 };
    if (source < 0)
    {
      const int e = -source - 1;
      const int h = mesh.GetEdgeHalfEdge(e);
      candidates[0] = h / 3;
      candidates[1] = mesh.GetNeighbor(h / 3, h % 3);
    }
    left = right = -1;
    for (int t : candidates)
    {
      if (t < 0)
      {
        continue;
      }
      const int l = surface.FindDirected(t, p, q);
      const int r = surface.FindDirected(t, q, p);
      if (l >= 0)
        left = cellOfTriangle(l);
      if (r >= 0)
        right = cellOfTriangle(r);
    }
  };

  // The mesh half-edge under a sub-edge that runs along an open boundary of the surface (a mesh
  // edge with a triangle on one side only), else -1. Beyond it lies no cell: the patch's sides
  // there are one cell and nothing, unlike anywhere else on the curve.
  const auto boundaryHalfEdge = [&](int source)
  {
    if (source >= 0)
    {
      return -1;
    }
    const int h = mesh.GetEdgeHalfEdge(-source - 1);
    return mesh.GetTwin(h) < 0 ? h : -1;
  };

  for (size_t ci = 0; ci < refinedCurves.size(); ++ci)
  {
    const RefinedCurve& rc = refinedCurves[ci];
    const TracedCurve& curve = curves[ci];
    const int n = static_cast<int>(rc.Points.size());
    if (n < 2)
    {
      continue;
    }
    const int edges = static_cast<int>(rc.SubEdgeSource.size());
    const bool cyclic = curve.Closed;
    const auto onBoundary = [&](int i)
    { return boundaryHalfEdge(rc.SubEdgeSource[((i % edges) + edges) % edges]) >= 0; };
    // Patches also end where the curve steps onto or off an open boundary: the cells on its
    // sides change there (a curve from side to side of a square cuts the outside in two, and
    // the pieces meet only beyond the boundary), and a patch's sides are those of its first
    // sub-edge.
    const auto breaksAt = [&](int i)
    {
      return visits[rc.Points[i % n]] > 1 ||
        ((cyclic || (i > 0 && i < edges)) && onBoundary(i - 1) != onBoundary(i));
    };
    // Where patches start: the first break point (closed), or the first point (open).
    int start = 0;
    bool anyBreak = !cyclic;
    if (cyclic)
    {
      for (int i = 0; i < n; ++i)
      {
        if (breaksAt(i))
        {
          start = i;
          anyBreak = true;
          break;
        }
      }
    }
    ArrangementPatch patch;
    auto begin = [&](int i)
    {
      patch = ArrangementPatch();
      patch.Curve = static_cast<int>(ci);
      patch.ShapeId = curve.ShapeId;
      patch.CurveId = curve.CurveId;
      patch.Closed = curve.Closed;
      patch.FirstIndex = i % n;
      patch.Points.push_back(rc.Points[i % n]);
      markEnd(rc.Points[i % n]);
      sides(rc.Points[i % n],
        rc.Points[(i + 1) % n],
        rc.SubEdgeSource[i % edges],
        patch.LeftCell,
        patch.RightCell);
      patch.BoundaryHalfEdge = boundaryHalfEdge(rc.SubEdgeSource[i % edges]);
    };
    auto finish = [&]()
    {
      markEnd(patch.Points.back());
      for (size_t k = 0; k + 1 < patch.Points.size(); ++k)
      {
        patch.Length += Distance(position(patch.Points[k]), position(patch.Points[k + 1]));
      }
      for (int p : patch.Points)
      {
        patch.SurfacePoints.push_back(
          p < nv ? VertexSurfacePoint(mesh, p) : curvePointSurface[p - nv]);
      }
      const int id = static_cast<int>(patches.size());
      if (patch.Closed && patch.LeftCell >= 0 && patch.RightCell >= 0)
      {
        arcs.push_back({ patch.RightCell, patch.LeftCell, patch.ShapeId, id });
      }
      patches.push_back(std::move(patch));
    };
    begin(start);
    for (int e = 0; e < edges; ++e)
    {
      const int i = start + e; // sub-edge from point i to i+1 (mod n)
      const int next = rc.Points[(i + 1) % n];
      patch.Points.push_back(next);
      const bool last = e + 1 == edges;
      if (!last && anyBreak && breaksAt(i + 1))
      {
        finish();
        begin(i + 1);
      }
    }
    finish();
  }
  for (const RefinedCurve& c : refinedCurves)
  {
    for (int p : c.Points)
    {
      visits[p] = 0;
      isEnd[p] = 0;
    }
  }
  return graphVertices;
}

} // namespace boolsurf

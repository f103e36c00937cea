#include "Distributed/MergedBoundaryLoops.h"

#include <algorithm>
#include <numeric>
#include <unordered_map>

namespace boolsurf
{
namespace
{

struct FragmentRef
{
  int Piece = 0, Fragment = 0;
};

std::string HalfEdgeName(std::uint64_t pair)
{
  return "boundary half-edge from global vertex " + std::to_string(pair >> 32) + " to " +
    std::to_string(pair & 0xffffffffu);
}

int FindRoot(std::vector<int>& parent, int x)
{
  while (parent[x] != x)
  {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

// Loops as chains of fragments, each starting at the fragment holding the loop's lowest
// half-edge, sorted by that half-edge (MeshTopology's loop numbers).
bool ChainLoops(const std::vector<PieceSummary>& pieces,
  std::vector<std::vector<FragmentRef>>& loops,
  std::string& error)
{
  std::vector<FragmentRef> all;
  std::unordered_map<std::uint64_t, int> byFirst;
  for (size_t p = 0; p < pieces.size(); ++p)
  {
    for (size_t f = 0; f < pieces[p].LoopFragments.size(); ++f)
    {
      const std::uint64_t first = pieces[p].LoopFragments[f].First;
      if (!byFirst.emplace(first, static_cast<int>(all.size())).second)
      {
        error = HalfEdgeName(first) + " starts two boundary fragments";
        return false;
      }
      all.push_back({ static_cast<int>(p), static_cast<int>(f) });
    }
  }
  const auto fragment = [&](int i) -> const BoundaryLoopFragment&
  { return pieces[all[i].Piece].LoopFragments[all[i].Fragment]; };
  std::vector<int> successor(all.size(), -1);
  std::vector<int> predecessors(all.size(), 0);
  for (size_t i = 0; i < all.size(); ++i)
  {
    const auto found = byFirst.find(fragment(static_cast<int>(i)).Next);
    if (found == byFirst.end())
    {
      error = "the boundary loop through " + HalfEdgeName(fragment(static_cast<int>(i)).First) +
        " does not close (no piece continues it)";
      return false;
    }
    successor[i] = found->second;
    ++predecessors[found->second];
  }
  for (size_t i = 0; i < all.size(); ++i)
  {
    if (predecessors[i] != 1)
    {
      error = HalfEdgeName(fragment(static_cast<int>(i)).First) + " continues " +
        std::to_string(predecessors[i]) + " boundary fragments";
      return false;
    }
  }
  std::vector<char> visited(all.size(), 0);
  std::vector<std::pair<long long, std::vector<FragmentRef>>> found;
  for (size_t i = 0; i < all.size(); ++i)
  {
    if (visited[i])
    {
      continue;
    }
    std::vector<int> cycle;
    for (int j = static_cast<int>(i); !visited[j]; j = successor[j])
    {
      visited[j] = 1;
      cycle.push_back(j);
    }
    size_t lowest = 0;
    for (size_t k = 1; k < cycle.size(); ++k)
    {
      if (fragment(cycle[k]).LowestHalfEdge < fragment(cycle[lowest]).LowestHalfEdge)
      {
        lowest = k;
      }
    }
    std::rotate(cycle.begin(), cycle.begin() + lowest, cycle.end());
    std::vector<FragmentRef> refs;
    for (const int j : cycle)
    {
      refs.push_back(all[j]);
    }
    found.emplace_back(fragment(cycle[0]).LowestHalfEdge, std::move(refs));
  }
  std::sort(
    found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  loops.clear();
  for (auto& f : found)
  {
    loops.push_back(std::move(f.second));
  }
  return true;
}

// The loop's length as MeshTopology sums it: edge by edge from its lowest half-edge.
double LoopLength(const std::vector<PieceSummary>& pieces, const std::vector<FragmentRef>& loop)
{
  const auto fragment = [&](const FragmentRef& r) -> const BoundaryLoopFragment&
  { return pieces[r.Piece].LoopFragments[r.Fragment]; };
  const BoundaryLoopFragment& first = fragment(loop[0]);
  double length = 0;
  for (size_t i = first.LowestIndex; i < first.EdgeLengths.size(); ++i)
  {
    length += first.EdgeLengths[i];
  }
  for (size_t k = 1; k < loop.size(); ++k)
  {
    for (const double l : fragment(loop[k]).EdgeLengths)
    {
      length += l;
    }
  }
  for (int i = 0; i < first.LowestIndex; ++i)
  {
    length += first.EdgeLengths[i];
  }
  return length;
}

// Components of cells and plugs joined by every crossing, numbered by their lowest node.
void NumberComponents(MergedArrangement& out)
{
  const int nodes = out.NumberOfCells + out.NumberOfPlugs;
  std::vector<int> parent(nodes);
  std::iota(parent.begin(), parent.end(), 0);
  for (const std::vector<CellCrossing>* crossings : { &out.Crossings, &out.PlugCrossings })
  {
    for (const CellCrossing& c : *crossings)
    {
      const int a = FindRoot(parent, c.FromCell), b = FindRoot(parent, c.ToCell);
      parent[std::max(a, b)] = std::min(a, b);
    }
  }
  out.NodeComponent.assign(nodes, -1);
  std::vector<int> componentOfRoot(nodes, -1);
  int components = 0;
  for (int n = 0; n < nodes; ++n)
  {
    int& c = componentOfRoot[FindRoot(parent, n)];
    if (c < 0)
    {
      c = components++;
    }
    out.NodeComponent[n] = c;
  }
  out.ZeroNodes.assign(components, -1);
}

} // namespace

//------------------------------------------------------------------------------
bool MergeBoundaryLoops(const std::vector<PieceSummary>& pieces,
  MergedArrangement& out,
  std::string& error)
{
  std::vector<std::vector<FragmentRef>> loops;
  if (!ChainLoops(pieces, loops, error))
  {
    return false;
  }
  out.NumberOfPlugs = static_cast<int>(loops.size());
  std::vector<std::vector<int>> loopOf(pieces.size());
  for (size_t p = 0; p < pieces.size(); ++p)
  {
    loopOf[p].assign(pieces[p].LoopFragments.size(), -1);
  }
  for (size_t l = 0; l < loops.size(); ++l)
  {
    for (const FragmentRef& r : loops[l])
    {
      loopOf[r.Piece][r.Fragment] = static_cast<int>(l);
    }
  }
  out.PlugCrossings.clear();
  for (size_t p = 0; p < pieces.size(); ++p)
  {
    const std::vector<int>& global = out.GlobalCellOfLocal[p];
    for (const PlugCrossing& c : pieces[p].PlugCrossings)
    {
      if (c.Fragment < 0 || c.Fragment >= static_cast<int>(loopOf[p].size()) || c.Cell < 0 ||
        c.Cell >= static_cast<int>(global.size()) || global[c.Cell] < 0)
      {
        error = "a boundary crossing of piece " + std::to_string(p) +
          " names a fragment or cell out of range";
        return false;
      }
      CellCrossing g; // from the plug into the cell, then normalized (cell first)
      g.FromCell = out.NumberOfCells + loopOf[p][c.Fragment];
      g.ToCell = global[c.Cell];
      g.Delta = c.Delta;
      g.Normalize();
      out.PlugCrossings.push_back(std::move(g));
    }
  }
  std::sort(out.PlugCrossings.begin(), out.PlugCrossings.end());
  out.PlugCrossings.erase(
    std::unique(out.PlugCrossings.begin(), out.PlugCrossings.end()), out.PlugCrossings.end());
  NumberComponents(out);
  // Each component's zero node: the plug of its longest loop, the first of equal ones.
  std::vector<double> longest(out.ZeroNodes.size(), 0.0);
  for (int l = 0; l < out.NumberOfPlugs; ++l)
  {
    const int plug = out.NumberOfCells + l;
    const int c = out.NodeComponent[plug];
    const double length = LoopLength(pieces, loops[l]);
    if (out.ZeroNodes[c] < 0 || length > longest[c])
    {
      out.ZeroNodes[c] = plug;
      longest[c] = length;
    }
  }
  return true;
}

} // namespace boolsurf

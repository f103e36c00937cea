#include "Distributed/MergedArrangement.h"

#include "Distributed/MergedBoundaryLoops.h"

#include <algorithm>
#include <cstdlib>
#include <numeric>
#include <tuple>

namespace boolsurf
{
namespace
{

int FindRoot(std::vector<int>& parent, int x)
{
  while (parent[x] != x)
  {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

// Global cells numbered by their lowest refined triangle; each node's cell and the areas.
void NumberCells(const std::vector<PieceSummary>& pieces,
  const std::vector<int>& nodeBase,
  std::vector<int>& parent,
  MergedArrangement& out)
{
  const int nodes = nodeBase.back();
  std::vector<RefinedTriangleKey> lowest(nodes);
  std::vector<char> used(nodes, 0);
  for (size_t p = 0; p < pieces.size(); ++p)
  {
    for (const PieceCell& c : pieces[p].Cells)
    {
      const int root = FindRoot(parent, nodeBase[p] + c.LocalCell);
      lowest[root] = used[root] ? std::min(lowest[root], c.Lowest) : c.Lowest;
      used[root] = 1;
    }
  }
  std::vector<int> roots;
  for (int n = 0; n < nodes; ++n)
  {
    if (used[n])
    {
      roots.push_back(n);
    }
  }
  std::sort(roots.begin(), roots.end(), [&](int a, int b) { return lowest[a] < lowest[b]; });
  std::vector<int> cellOfRoot(nodes, -1);
  out.NumberOfCells = static_cast<int>(roots.size());
  out.CellLowestTriangle.resize(roots.size());
  out.CellArea.assign(roots.size(), 0.0);
  for (size_t i = 0; i < roots.size(); ++i)
  {
    cellOfRoot[roots[i]] = static_cast<int>(i);
    out.CellLowestTriangle[i] = lowest[roots[i]];
  }
  out.GlobalCellOfLocal.resize(pieces.size());
  for (size_t p = 0; p < pieces.size(); ++p)
  {
    std::vector<int>& global = out.GlobalCellOfLocal[p];
    global.assign(pieces[p].NumberOfLocalCells, -1);
    for (const PieceCell& c : pieces[p].Cells)
    {
      const int cell = cellOfRoot[FindRoot(parent, nodeBase[p] + c.LocalCell)];
      global[c.LocalCell] = cell;
      out.CellArea[cell] += c.Area;
    }
  }
}

// The pieces' crossings and the boundary's on global cells.
void GatherCrossings(const std::vector<PieceSummary>& pieces,
  const BoundaryJoins& joins,
  MergedArrangement& out)
{
  out.Crossings.clear();
  for (size_t p = 0; p < pieces.size(); ++p)
  {
    const std::vector<int>& global = out.GlobalCellOfLocal[p];
    for (const CellCrossing& c : pieces[p].Crossings)
    {
      CellCrossing g = c;
      g.FromCell = global[c.FromCell];
      g.ToCell = global[c.ToCell];
      g.Normalize();
      out.Crossings.push_back(std::move(g));
    }
  }
  for (const BoundaryCrossing& b : joins.Crossings)
  {
    CellCrossing g;
    g.FromCell = out.GlobalCellOfLocal[b.From.Piece][b.From.Cell];
    g.ToCell = out.GlobalCellOfLocal[b.To.Piece][b.To.Cell];
    g.Delta = b.Delta;
    g.Normalize();
    out.Crossings.push_back(std::move(g));
  }
  std::sort(out.Crossings.begin(), out.Crossings.end());
  out.Crossings.erase(std::unique(out.Crossings.begin(), out.Crossings.end()), out.Crossings.end());
}

// Whether every cell named is one of the pieces' local cells holding owned triangles (the
// others have no global cell).
bool CheckCellRefs(const std::vector<PieceSummary>& pieces,
  const std::vector<int>& nodeBase,
  const std::vector<char>& owned,
  const BoundaryJoins& joins,
  std::string& error)
{
  const auto valid = [&](const PieceCellRef& r)
  {
    return r.Piece >= 0 && r.Piece < static_cast<int>(pieces.size()) && r.Cell >= 0 &&
      r.Cell < pieces[r.Piece].NumberOfLocalCells && owned[nodeBase[r.Piece] + r.Cell];
  };
  const auto name = [](const PieceCellRef& r)
  { return "cell " + std::to_string(r.Cell) + " of piece " + std::to_string(r.Piece); };
  for (const auto& j : joins.Joins)
  {
    if (!valid(j.first) || !valid(j.second))
    {
      error = "boundary join names " + name(valid(j.first) ? j.second : j.first) +
        ", which holds no owned triangle";
      return false;
    }
  }
  for (const BoundaryCrossing& c : joins.Crossings)
  {
    if (!valid(c.From) || !valid(c.To))
    {
      error = "boundary crossing names " + name(valid(c.From) ? c.To : c.From) +
        ", which holds no owned triangle";
      return false;
    }
  }
  return true;
}

} // namespace

//------------------------------------------------------------------------------
bool MergeCellGraph(const std::vector<PieceSummary>& pieces,
  const BoundaryJoins& joins,
  MergedArrangement& out,
  std::string& error)
{
  out = MergedArrangement();
  std::vector<int> nodeBase(pieces.size() + 1, 0);
  for (size_t p = 0; p < pieces.size(); ++p)
  {
    nodeBase[p + 1] = nodeBase[p] + pieces[p].NumberOfLocalCells;
  }
  std::vector<char> owned(nodeBase.back(), 0);
  for (size_t p = 0; p < pieces.size(); ++p)
  {
    for (const PieceCell& c : pieces[p].Cells)
    {
      owned[nodeBase[p] + c.LocalCell] = 1;
    }
  }
  if (!CheckCellRefs(pieces, nodeBase, owned, joins, error))
  {
    return false;
  }
  std::vector<int> parent(nodeBase.back());
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& j : joins.Joins)
  {
    const int a = FindRoot(parent, nodeBase[j.first.Piece] + j.first.Cell);
    const int b = FindRoot(parent, nodeBase[j.second.Piece] + j.second.Cell);
    parent[std::max(a, b)] = std::min(a, b);
  }
  NumberCells(pieces, nodeBase, parent, out);
  GatherCrossings(pieces, joins, out);
  return MergeBoundaryLoops(pieces, out, error);
}

//------------------------------------------------------------------------------
bool MergePieceSummaries(const std::vector<PieceSummary>& pieces,
  MergedArrangement& out,
  std::string& error)
{
  std::vector<int> ids(pieces.size());
  std::vector<const PieceSummary*> summaries(pieces.size());
  for (size_t p = 0; p < pieces.size(); ++p)
  {
    ids[p] = static_cast<int>(p);
    summaries[p] = &pieces[p];
  }
  BoundaryJoins joins;
  if (!JoinPieceBoundaries(ids, summaries, -1, joins, error))
  {
    return false;
  }
  return MergeCellGraph(pieces, joins, out, error);
}

//------------------------------------------------------------------------------
LabelingInput LabelingInputOfCrossings(int numberOfCells,
  const std::vector<CellCrossing>& crossings,
  const std::vector<int>& shapeIds)
{
  LabelingInput input;
  input.NumberOfCells = numberOfCells;
  input.ShapeIds = shapeIds;
  for (const CellCrossing& c : crossings)
  {
    for (const std::pair<int, int>& d : c.Delta)
    {
      input.ShapeIds.push_back(d.first);
    }
  }
  std::sort(input.ShapeIds.begin(), input.ShapeIds.end());
  input.ShapeIds.erase(
    std::unique(input.ShapeIds.begin(), input.ShapeIds.end()), input.ShapeIds.end());
  input.NumberOfShapes = static_cast<int>(input.ShapeIds.size());
  for (size_t k = 0; k < crossings.size(); ++k)
  {
    const CellCrossing& c = crossings[k];
    if (c.Delta.empty() && c.FromCell != c.ToCell)
    {
      input.Links.push_back({ c.FromCell, c.ToCell }); // curves that cancel: equal labels
    }
    for (const std::pair<int, int>& d : c.Delta)
    {
      CellArc arc;
      arc.RightCell = d.second > 0 ? c.FromCell : c.ToCell;
      arc.LeftCell = d.second > 0 ? c.ToCell : c.FromCell;
      arc.Shape =
        static_cast<int>(std::lower_bound(input.ShapeIds.begin(), input.ShapeIds.end(), d.first) -
          input.ShapeIds.begin());
      arc.Location = static_cast<long long>(k);
      arc.Direction = d.second > 0 ? 1 : -1;
      for (int n = 0; n < std::abs(d.second); ++n)
      {
        input.Arcs.push_back(arc);
      }
    }
  }
  return input;
}

} // namespace boolsurf

#include "Distributed/MergedArrangement.h"

#include <algorithm>
#include <cstdlib>
#include <map>
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

std::string EdgeName(std::uint64_t edge)
{
  return "(" + std::to_string(edge >> 32) + ", " + std::to_string(edge & 0xffffffffu) + ")";
}

// A boundary sub-segment's two sides, by node.
struct SubSegmentSides
{
  int Node[2] = { -1, -1 };
  bool Forward[2] = { false, false };
  int Count = 0, Sides = 0;
  bool Blocked = false;
};

// Joins the two sides of every unblocked boundary sub-segment; `sides` keeps them for the arcs.
bool JoinAcrossBoundary(const std::vector<PieceSummary>& pieces,
  const std::vector<int>& nodeBase,
  std::vector<int>& parent,
  std::map<std::pair<std::uint64_t, int>, SubSegmentSides>& sides,
  std::string& error)
{
  for (size_t p = 0; p < pieces.size(); ++p)
  {
    for (const BoundarySubSegment& b : pieces[p].Boundary)
    {
      SubSegmentSides& s = sides[{ b.Edge, b.Index }];
      if (s.Sides == 2 || (s.Sides == 1 && (s.Count != b.Count || s.Blocked != b.Blocked)))
      {
        error = "pieces disagree on edge " + EdgeName(b.Edge) + " (piece " + std::to_string(p) +
          "): " + (s.Sides == 2 ? "more than two sides" : "different sub-segments");
        return false;
      }
      s.Node[s.Sides] = nodeBase[p] + b.Cell;
      s.Forward[s.Sides] = b.Forward;
      s.Count = b.Count;
      s.Blocked = b.Blocked;
      ++s.Sides;
    }
  }
  for (const auto& entry : sides)
  {
    const SubSegmentSides& s = entry.second;
    if (s.Sides != 2)
    {
      error = "edge " + EdgeName(entry.first.first) +
        " has one side only: a piece lacks its ring of ghost triangles";
      return false;
    }
    if (!s.Blocked)
    {
      const int a = FindRoot(parent, s.Node[0]), b = FindRoot(parent, s.Node[1]);
      parent[std::max(a, b)] = std::min(a, b);
    }
  }
  return true;
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

// The pieces' crossings on global cells, and those of the boundary sub-segments curves run
// along.
void GatherCrossings(const std::vector<PieceSummary>& pieces,
  const std::map<std::pair<std::uint64_t, int>, SubSegmentSides>& sides,
  const std::vector<int>& nodeBase,
  MergedArrangement& out)
{
  std::vector<int> pieceOfNode(nodeBase.back());
  for (size_t p = 0; p < pieces.size(); ++p)
  {
    std::fill(pieceOfNode.begin() + nodeBase[p], pieceOfNode.begin() + nodeBase[p + 1], p);
  }
  const auto cellOfNode = [&](int node)
  { return out.GlobalCellOfLocal[pieceOfNode[node]][node - nodeBase[pieceOfNode[node]]]; };
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
  // Boundary steps, grouped by sub-segment: a step running the edge upwards crosses from the
  // side whose triangle runs it downwards to the other (a triangle lies left of its edges).
  std::vector<BoundaryCurveStep> steps;
  for (const PieceSummary& piece : pieces)
  {
    steps.insert(steps.end(), piece.BoundarySteps.begin(), piece.BoundarySteps.end());
  }
  std::sort(steps.begin(), steps.end());
  for (size_t i = 0; i < steps.size();)
  {
    size_t j = i;
    std::vector<std::pair<int, int>> delta;
    for (; j < steps.size() && steps[j].Edge == steps[i].Edge && steps[j].Index == steps[i].Index;
         ++j)
    {
      delta.push_back({ steps[j].Shape, steps[j].Forward ? 1 : -1 });
    }
    const SubSegmentSides& s = sides.at({ steps[i].Edge, steps[i].Index });
    const int up = s.Forward[0] ? 0 : 1;
    CellCrossing c;
    c.FromCell = cellOfNode(s.Node[1 - up]);
    c.ToCell = cellOfNode(s.Node[up]);
    c.Delta = SumByShape(std::move(delta));
    c.Normalize();
    out.Crossings.push_back(std::move(c));
    i = j;
  }
  std::sort(out.Crossings.begin(), out.Crossings.end());
  out.Crossings.erase(std::unique(out.Crossings.begin(), out.Crossings.end()), out.Crossings.end());
}

} // namespace

//------------------------------------------------------------------------------
bool MergePieceSummaries(const std::vector<PieceSummary>& pieces,
  MergedArrangement& out,
  std::string& error)
{
  out = MergedArrangement();
  std::vector<int> nodeBase(pieces.size() + 1, 0);
  for (size_t p = 0; p < pieces.size(); ++p)
  {
    nodeBase[p + 1] = nodeBase[p] + pieces[p].NumberOfLocalCells;
  }
  std::vector<int> parent(nodeBase.back());
  std::iota(parent.begin(), parent.end(), 0);
  std::map<std::pair<std::uint64_t, int>, SubSegmentSides> sides;
  if (!JoinAcrossBoundary(pieces, nodeBase, parent, sides, error))
  {
    return false;
  }
  NumberCells(pieces, nodeBase, parent, out);
  GatherCrossings(pieces, sides, nodeBase, out);
  return true;
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

#include "Distributed/MergedArrangement.h"

#include "Mesh/EdgeIndex.h"

#include <algorithm>
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

// The pieces' arcs on global cells, and the arcs of the curve steps along the boundary.
void GatherArcs(const std::vector<PieceSummary>& pieces,
  const std::map<std::pair<std::uint64_t, int>, SubSegmentSides>& sides,
  const std::vector<int>& nodeBase,
  MergedArrangement& out)
{
  const auto cellOfNode = [&](int piece, int node)
  { return out.GlobalCellOfLocal[piece][node - nodeBase[piece]]; };
  std::vector<int> pieceOfNode(nodeBase.back());
  for (size_t p = 0; p < pieces.size(); ++p)
  {
    std::fill(pieceOfNode.begin() + nodeBase[p], pieceOfNode.begin() + nodeBase[p + 1], p);
  }
  out.Arcs.clear();
  for (size_t p = 0; p < pieces.size(); ++p)
  {
    const std::vector<int>& global = out.GlobalCellOfLocal[p];
    for (const CellGraphStep& a : pieces[p].Arcs)
    {
      out.Arcs.push_back({ global[a.RightCell], global[a.LeftCell], a.Shape });
    }
    for (const BoundaryCurveStep& step : pieces[p].BoundarySteps)
    {
      const SubSegmentSides& s = sides.at({ step.Edge, step.Index });
      // The left side runs the edge the way the curve does.
      const int left = s.Forward[0] == step.Forward ? 0 : 1;
      const int l = cellOfNode(pieceOfNode[s.Node[left]], s.Node[left]);
      const int r = cellOfNode(pieceOfNode[s.Node[1 - left]], s.Node[1 - left]);
      out.Arcs.push_back({ r, l, step.Shape });
    }
  }
  std::sort(out.Arcs.begin(), out.Arcs.end());
  out.Arcs.erase(std::unique(out.Arcs.begin(), out.Arcs.end()), out.Arcs.end());
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
  GatherArcs(pieces, sides, nodeBase, out);
  return true;
}

//------------------------------------------------------------------------------
std::vector<CellGraphStep> DistinctCellGraphSteps(const std::vector<CellGraphArc>& arcs)
{
  std::vector<CellGraphStep> steps;
  steps.reserve(arcs.size());
  for (const CellGraphArc& a : arcs)
  {
    steps.push_back({ a.RightCell, a.LeftCell, a.Shape });
  }
  std::sort(steps.begin(), steps.end());
  steps.erase(std::unique(steps.begin(), steps.end()), steps.end());
  return steps;
}

//------------------------------------------------------------------------------
LabelingInput LabelingInputOfSteps(int numberOfCells, const std::vector<CellGraphStep>& steps)
{
  LabelingInput input;
  input.NumberOfCells = numberOfCells;
  for (const CellGraphStep& s : steps)
  {
    input.ShapeIds.push_back(s.Shape);
  }
  std::sort(input.ShapeIds.begin(), input.ShapeIds.end());
  input.ShapeIds.erase(
    std::unique(input.ShapeIds.begin(), input.ShapeIds.end()), input.ShapeIds.end());
  input.NumberOfShapes = static_cast<int>(input.ShapeIds.size());
  for (const CellGraphStep& s : steps)
  {
    CellArc arc;
    arc.RightCell = s.RightCell;
    arc.LeftCell = s.LeftCell;
    arc.Shape =
      static_cast<int>(std::lower_bound(input.ShapeIds.begin(), input.ShapeIds.end(), s.Shape) -
        input.ShapeIds.begin());
    arc.Location = static_cast<long long>(
      UndirectedPointPair(std::min(s.RightCell, s.LeftCell), std::max(s.RightCell, s.LeftCell)));
    input.Arcs.push_back(arc);
  }
  return input;
}

} // namespace boolsurf

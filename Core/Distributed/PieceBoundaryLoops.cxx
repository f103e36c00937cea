#include "Distributed/PieceBoundaryLoops.h"

#include "Distributed/PieceSummary.h"
#include "Mesh/EdgeIndex.h"
#include "Mesh/MeshTopology.h"

#include <algorithm>
#include <tuple>
#include <unordered_map>

namespace boolsurf
{

//------------------------------------------------------------------------------
bool PlugCrossing::operator<(const PlugCrossing& o) const
{
  return std::tie(this->Fragment, this->Cell, this->Delta) < std::tie(o.Fragment, o.Cell, o.Delta);
}
bool PlugCrossing::operator==(const PlugCrossing& o) const
{
  return this->Fragment == o.Fragment && this->Cell == o.Cell && this->Delta == o.Delta;
}

namespace
{

// Per refined point pair (UndirectedPointPair) a cell-bounding curve steps along: the shapes'
// steps, +1 from the lower point id to the higher.
std::unordered_map<std::uint64_t, std::vector<std::pair<int, int>>> BoundingSteps(
  const PieceCurves& curves,
  const Arrangement& arr)
{
  std::unordered_map<std::uint64_t, std::vector<std::pair<int, int>>> steps;
  for (size_t c = 0; c < curves.Curves.size(); ++c)
  {
    const std::vector<int>& p = arr.CurvePoints[c];
    if (!curves.BoundsCells(static_cast<int>(c)) || p.size() < 2)
    {
      continue;
    }
    const int shape = curves.Curves[c].ShapeId;
    const auto step = [&](int u, int v)
    {
      if (u != v)
      {
        steps[UndirectedPointPair(u, v)].push_back({ shape, u < v ? 1 : -1 });
      }
    };
    for (size_t i = 0; i + 1 < p.size(); ++i)
    {
      step(p[i], p[i + 1]);
    }
    if (curves.Curves[c].Closed && p.front() != p.back())
    {
      step(p.back(), p.front());
    }
  }
  return steps;
}

// The cells along half-edge h (local edge k of triangle t) of fragment `fragment`: per refined
// sub-edge, a link or the curves' steps from the plug into the cell. A refined triangle's side
// on the edge runs the way the half-edge does (the surface on its left), so a curve stepping
// that way has the cell on its left: stepping from the plug (its right) into the cell adds 1.
void CellsAlongHalfEdge(const TriangleMesh& mesh,
  const Arrangement& arr,
  const std::unordered_map<std::uint64_t, std::vector<std::pair<int, int>>>& steps,
  int h,
  int fragment,
  std::vector<PlugCrossing>& out)
{
  const int t = h / 3, k = h % 3;
  const Triangle& corners = mesh.GetTriangle(t);
  const int a = corners[k], b = corners[(k + 1) % 3];
  const int e = mesh.GetEdgeId(t, k);
  const auto onEdge = [&](int p)
  {
    if (p == a || p == b)
    {
      return true;
    }
    if (p < arr.NumberOfMeshVertices)
    {
      return false;
    }
    const CanonicalPoint q = arr.GetPointOnMesh(p);
    return q.Location == PointLocation::Edge && q.Id == e;
  };
  ForEachRefinedTriangle(mesh,
    arr,
    t,
    [&](int r)
    {
      const Triangle tri = arr.GetTriangle(mesh, r);
      for (int j = 0; j < 3; ++j)
      {
        const int x = tri[j], y = tri[(j + 1) % 3];
        if (x == y || !onEdge(x) || !onEdge(y))
        {
          continue;
        }
        PlugCrossing crossing;
        crossing.Fragment = fragment;
        crossing.Cell = arr.CellOfTriangle(r);
        if (crossing.Cell < 0)
        {
          continue;
        }
        const auto found = steps.find(UndirectedPointPair(x, y));
        if (found != steps.end())
        {
          std::vector<std::pair<int, int>> delta = found->second;
          if (x > y) // the steps count from y to x
          {
            for (std::pair<int, int>& d : delta)
            {
              d.second = -d.second;
            }
          }
          crossing.Delta = SumByShape(std::move(delta));
        }
        out.push_back(std::move(crossing));
      }
    });
}

} // namespace

//------------------------------------------------------------------------------
void SummarizeBoundaryLoops(const PieceMesh& piece,
  const PieceCurves& curves,
  const Arrangement& arr,
  std::vector<BoundaryLoopFragment>& fragments,
  std::vector<PlugCrossing>& crossings)
{
  fragments.clear();
  crossings.clear();
  const TriangleMesh& mesh = piece.Mesh;
  // The owned boundary half-edges, the next one along each loop, and which have an owned
  // predecessor (the others start fragments). Every triangle around an owned triangle's corner
  // is in the piece, so the walk is the whole surface's. The half-edges are listed with the
  // piece's mesh: an edit does not scan the piece for them.
  const std::vector<int>& owned = piece.SurfaceBoundaryHalfEdges;
  std::unordered_map<int, int> next;
  for (const int h : owned)
  {
    next[h] = NextBoundaryHalfEdge(mesh, h);
  }
  if (owned.empty())
  {
    return;
  }
  std::unordered_map<int, char> hasOwnedPredecessor;
  for (const int h : owned)
  {
    const int n = next[h];
    if (n >= 0 && piece.Owned[n / 3])
    {
      hasOwnedPredecessor[n] = 1;
    }
  }
  const auto globalPair = [&](int h)
  {
    const Triangle& tri = mesh.GetTriangle(h / 3);
    return DirectedPointPair(
      piece.GlobalVertex[tri[h % 3]], piece.GlobalVertex[tri[(h % 3 + 1) % 3]]);
  };
  const std::unordered_map<std::uint64_t, std::vector<std::pair<int, int>>> steps =
    BoundingSteps(curves, arr);
  std::unordered_map<int, char> visited;
  const auto walk = [&](int start)
  {
    BoundaryLoopFragment f;
    f.First = globalPair(start);
    const int index = static_cast<int>(fragments.size());
    int h = start;
    while (true)
    {
      visited[h] = 1;
      const Triangle& tri = mesh.GetTriangle(h / 3);
      const long long global = 3LL * piece.GlobalTriangle[h / 3] + h % 3;
      if (f.LowestHalfEdge < 0 || global < f.LowestHalfEdge)
      {
        f.LowestHalfEdge = global;
        f.LowestIndex = static_cast<int>(f.EdgeLengths.size());
      }
      f.EdgeLengths.push_back(
        Distance(mesh.GetPosition(tri[h % 3]), mesh.GetPosition(tri[(h % 3 + 1) % 3])));
      CellsAlongHalfEdge(mesh, arr, steps, h, index, crossings);
      const int n = next[h];
      if (n < 0)
      {
        f.Next = ~std::uint64_t(0); // no next half-edge: the merge reports the loop as broken
        break;
      }
      if (!piece.Owned[n / 3] || visited.count(n))
      {
        f.Next = globalPair(n);
        break;
      }
      h = n;
    }
    fragments.push_back(std::move(f));
  };
  for (const int h : owned) // fragments that start at another piece's half-edge
  {
    if (!hasOwnedPredecessor.count(h) && !visited.count(h))
    {
      walk(h);
    }
  }
  for (const int h : owned) // loops the piece holds whole
  {
    if (!visited.count(h))
    {
      walk(h);
    }
  }
  std::sort(crossings.begin(), crossings.end());
  crossings.erase(std::unique(crossings.begin(), crossings.end()), crossings.end());
}

} // namespace boolsurf

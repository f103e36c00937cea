#include "Distributed/PieceSummary.h"

#include "Arrangement/ArrangementOfRuns.h"
#include "Mesh/EdgeIndex.h"

#include <algorithm>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

namespace boolsurf
{

//------------------------------------------------------------------------------
bool BoundaryCurveStep::operator<(const BoundaryCurveStep& o) const
{
  return std::tie(this->Edge, this->Index, this->Shape, this->Forward) <
    std::tie(o.Edge, o.Index, o.Shape, o.Forward);
}
bool CellCrossing::operator<(const CellCrossing& o) const
{
  return std::tie(this->FromCell, this->ToCell, this->Delta) <
    std::tie(o.FromCell, o.ToCell, o.Delta);
}
bool CellCrossing::operator==(const CellCrossing& o) const
{
  return this->FromCell == o.FromCell && this->ToCell == o.ToCell && this->Delta == o.Delta;
}
void CellCrossing::Normalize()
{
  const bool flip = this->FromCell > this->ToCell ||
    (this->FromCell == this->ToCell && !this->Delta.empty() && this->Delta[0].second < 0);
  if (flip)
  {
    std::swap(this->FromCell, this->ToCell);
    for (std::pair<int, int>& d : this->Delta)
    {
      d.second = -d.second;
    }
  }
}

//------------------------------------------------------------------------------
std::vector<std::pair<int, int>> SumByShape(std::vector<std::pair<int, int>> steps)
{
  std::sort(steps.begin(), steps.end());
  std::vector<std::pair<int, int>> delta;
  for (const std::pair<int, int>& s : steps)
  {
    if (!delta.empty() && delta.back().first == s.first)
    {
      delta.back().second += s.second;
    }
    else
    {
      delta.push_back(s);
    }
  }
  delta.erase(
    std::remove_if(
      delta.begin(), delta.end(), [](const std::pair<int, int>& d) { return d.second == 0; }),
    delta.end());
  return delta;
}

//------------------------------------------------------------------------------
std::size_t PieceSummary::GetBytes() const
{
  std::size_t crossings = 0;
  for (const CellCrossing& c : this->Crossings)
  {
    crossings += 2 * sizeof(int) + c.Delta.size() * sizeof(std::pair<int, int>);
  }
  for (const PlugCrossing& c : this->PlugCrossings)
  {
    crossings += 2 * sizeof(int) + c.Delta.size() * sizeof(std::pair<int, int>);
  }
  for (const BoundaryLoopFragment& f : this->LoopFragments)
  {
    crossings += 2 * sizeof(std::uint64_t) + sizeof(long long) + sizeof(int) +
      f.EdgeLengths.size() * sizeof(double);
  }
  return sizeof(int) + this->Cells.size() * sizeof(PieceCell) + this->GetBoundaryBytes() +
    crossings;
}

std::size_t PieceSummary::GetBoundaryBytes() const
{
  return this->Boundary.size() * sizeof(BoundarySubSegment) +
    this->BoundarySteps.size() * sizeof(BoundaryCurveStep);
}

namespace
{

double RefinedTriangleArea(const TriangleMesh& mesh, const Arrangement& arr, int r)
{
  const Triangle c = arr.GetTriangle(mesh, r);
  const Vec3 a = arr.GetPosition(mesh, c[0]);
  return 0.5 * Length(Cross(arr.GetPosition(mesh, c[1]) - a, arr.GetPosition(mesh, c[2]) - a));
}

// Per local cell with owned triangles: its lowest owned refined triangle and owned area. With
// `sums`, a clean tile adds its precomputed figures and only the other tiles' triangles are
// read (an edit's cost is the tiles curves touch, plus one entry per tile).
void SummarizeCells(const PieceMesh& piece,
  const Arrangement& arr,
  PieceTileSums* sums,
  PieceSummary& out)
{
  const TriangleMesh& mesh = piece.Mesh;
  std::vector<int> entry(arr.NumberOfCells, -1);
  const auto add = [&](int c, const RefinedTriangleKey& key, double area)
  {
    if (entry[c] < 0)
    {
      entry[c] = static_cast<int>(out.Cells.size());
      out.Cells.push_back({ c, key, 0.0 });
    }
    PieceCell& cell = out.Cells[entry[c]];
    cell.Lowest = std::min(cell.Lowest, key);
    cell.Area += area;
  };
  const auto addTriangle = [&](int t)
  {
    int index = 0;
    ForEachRefinedTriangle(mesh,
      arr,
      t,
      [&](int r)
      {
        const RefinedTriangleKey key{ piece.GlobalTriangle[t], index++ };
        const int c = arr.CellOfTriangle(r);
        if (c >= 0)
        {
          add(c, key, RefinedTriangleArea(mesh, arr, r));
        }
      });
  };
  const MeshTiles* tiles = arr.Tiles.get();
  if (sums && tiles && arr.TileCell.size() == static_cast<std::size_t>(tiles->GetNumberOfTiles()))
  {
    if (!sums->Matches(*tiles))
    {
      sums->Compute(piece, *tiles);
    }
    for (int k = 0; k < tiles->GetNumberOfTiles(); ++k)
    {
      const int c = arr.TileCell[k];
      if (c >= 0)
      {
        if (sums->LowestOwned[k] >= 0)
        {
          add(c, { sums->LowestOwned[k], 0 }, sums->OwnedArea[k]);
        }
        continue;
      }
      for (int m = tiles->Offset[k]; m < tiles->Offset[k + 1]; ++m)
      {
        if (piece.Owned[tiles->Members[m]])
        {
          addTriangle(tiles->Members[m]);
        }
      }
    }
    for (int t : sums->Untiled)
    {
      addTriangle(t);
    }
  }
  else
  {
    for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
    {
      if (piece.Owned[t])
      {
        addTriangle(t);
      }
    }
  }
  std::sort(out.Cells.begin(),
    out.Cells.end(),
    [](const PieceCell& a, const PieceCell& b) { return a.LocalCell < b.LocalCell; });
}

// Where refined point p lies on local edge k of triangle t, from corner k (0) to corner k + 1
// (1); -1 when it is not on that edge.
double PositionOnEdge(const TriangleMesh& mesh, const Arrangement& arr, int t, int k, int p)
{
  const Triangle& tri = mesh.GetTriangle(t);
  const int a = tri[k], b = tri[(k + 1) % 3];
  if (p < arr.NumberOfMeshVertices)
  {
    return p == a ? 0.0 : (p == b ? 1.0 : -1.0);
  }
  const CanonicalPoint c = arr.GetPointOnMesh(p);
  const int e = mesh.GetEdgeId(t, k);
  if (c.Location != PointLocation::Edge || c.Id != e)
  {
    return -1.0;
  }
  return mesh.GetEdgeVertices(e)[0] == a ? c.T : 1.0 - c.T;
}

// The refined point pairs along which cell-bounding curves run.
std::unordered_set<std::uint64_t> BoundingSubEdges(const PieceCurves& curves,
  const Arrangement& arr)
{
  std::unordered_set<std::uint64_t> pairs;
  for (size_t c = 0; c < curves.Curves.size(); ++c)
  {
    const std::vector<int>& p = arr.CurvePoints[c];
    if (!curves.BoundsCells(static_cast<int>(c)) || p.size() < 2)
    {
      continue;
    }
    for (size_t i = 0; i + 1 < p.size(); ++i)
    {
      pairs.insert(UndirectedPointPair(p[i], p[i + 1]));
    }
    if (curves.Curves[c].Closed && p.front() != p.back())
    {
      pairs.insert(UndirectedPointPair(p.back(), p.front()));
    }
  }
  return pairs;
}

// A boundary sub-segment by its refined points: which record it is and the direction of its
// owned triangle's edge (for the steps of curves along it).
struct SubSegmentPlace
{
  int Record = -1;
  double FromPosition = 0; ///< position of the pair's lower point id along the owned edge
  double ToPosition = 0;
};

// The sub-segments of owned edges whose other triangle is another piece's.
void SummarizeBoundary(const PieceMesh& piece,
  const Arrangement& arr,
  const std::unordered_set<std::uint64_t>& bounding,
  PieceSummary& out,
  std::unordered_map<std::uint64_t, SubSegmentPlace>& places)
{
  const TriangleMesh& mesh = piece.Mesh;
  struct Side
  {
    double Lo, Hi;
    int X, Y, Cell;
  };
  std::vector<Side> sides;
  // The border's sides, listed with the piece's mesh (an edit does not scan the piece).
  for (const int h : piece.BorderHalfEdges)
  {
    const int t = h / 3, k = h % 3;
    sides.clear();
    ForEachRefinedTriangle(mesh,
      arr,
      t,
      [&](int r)
      {
        const Triangle c = arr.GetTriangle(mesh, r);
        for (int j = 0; j < 3; ++j)
        {
          const double x = PositionOnEdge(mesh, arr, t, k, c[j]);
          const double y = PositionOnEdge(mesh, arr, t, k, c[(j + 1) % 3]);
          if (x >= 0 && y >= 0 && x != y)
          {
            sides.push_back(
              { std::min(x, y), std::max(x, y), c[j], c[(j + 1) % 3], arr.CellOfTriangle(r) });
          }
        }
      });
    std::sort(sides.begin(), sides.end(), [](const Side& a, const Side& b) { return a.Lo < b.Lo; });
    const Triangle& tri = mesh.GetTriangle(t);
    const int ga = piece.GlobalVertex[tri[k]], gb = piece.GlobalVertex[tri[(k + 1) % 3]];
    const bool forward = ga < gb;
    const int count = static_cast<int>(sides.size());
    for (int i = 0; i < count; ++i)
    {
      const Side& s = sides[i];
      const std::uint64_t pair = UndirectedPointPair(s.X, s.Y);
      BoundarySubSegment b;
      b.Edge = UndirectedPointPair(ga, gb);
      b.Index = forward ? i : count - 1 - i;
      b.Count = count;
      b.Cell = s.Cell;
      b.Forward = forward;
      b.Blocked = bounding.count(pair) > 0;
      const bool xLow = s.X < s.Y;
      const double px = PositionOnEdge(mesh, arr, t, k, s.X);
      const double py = PositionOnEdge(mesh, arr, t, k, s.Y);
      places[pair] = { static_cast<int>(out.Boundary.size()), xLow ? px : py, xLow ? py : px };
      out.Boundary.push_back(b);
    }
  }
}

// The owned refined triangle with the directed side u -> v, -1 when none.
int OwnedHolder(const PieceMesh& piece,
  const Arrangement& arr,
  const std::unordered_map<std::uint64_t, int>& holder,
  int u,
  int v)
{
  const auto found = holder.find(DirectedPointPair(u, v));
  if (found != holder.end())
  {
    return found->second;
  }
  if (u >= arr.NumberOfMeshVertices || v >= arr.NumberOfMeshVertices)
  {
    return -1;
  }
  const TriangleMesh& mesh = piece.Mesh;
  for (int c : mesh.GetVertexCorners(u))
  {
    const int t = c / 3;
    if (piece.Owned[t] && arr.GetRefinedSlot(t) < 0 && mesh.GetTriangle(t)[(c % 3 + 1) % 3] == v)
    {
      return t;
    }
  }
  return -1;
}

// The crossings whose two sides are owned, and the curves' steps along the piece boundary.
void SummarizeCurveSteps(const PieceMesh& piece,
  const PieceCurves& curves,
  const Arrangement& arr,
  const std::unordered_map<std::uint64_t, SubSegmentPlace>& places,
  PieceSummary& out)
{
  const TriangleMesh& mesh = piece.Mesh;
  // Directed sides of the refined triangles of owned crossed triangles, where steps inside
  // triangles and through edge points lie; a step from vertex to vertex along a mesh edge may
  // leave both triangles unrefined, and is looked up around its first vertex.
  std::unordered_map<std::uint64_t, int> holder;
  for (int t : arr.RefinedSources)
  {
    if (!piece.Owned[t])
    {
      continue;
    }
    ForEachRefinedTriangle(mesh,
      arr,
      t,
      [&](int r)
      {
        const Triangle c = arr.GetTriangle(mesh, r);
        for (int j = 0; j < 3; ++j)
        {
          holder.emplace(DirectedPointPair(c[j], c[(j + 1) % 3]), r);
        }
      });
  }
  // Per place off the boundary (refined point pair x < y): the shapes crossing it, +1 for a
  // step from x to y.
  std::unordered_map<std::uint64_t, std::vector<std::pair<int, int>>> placeSteps;
  const auto step = [&](int u, int v, int shape)
  {
    if (u == v)
    {
      return;
    }
    const auto place = places.find(UndirectedPointPair(u, v));
    if (place != places.end())
    {
      const BoundarySubSegment& b = out.Boundary[place->second.Record];
      if (b.Forward) // the other side reports the steps of the other half
      {
        // Travel along the owned edge's direction when the lower id comes first and lies lower.
        const bool alongEdge = (u < v) == (place->second.FromPosition < place->second.ToPosition);
        out.BoundarySteps.push_back({ b.Edge, b.Index, shape, alongEdge });
      }
      return;
    }
    placeSteps[UndirectedPointPair(u, v)].push_back({ shape, u < v ? 1 : -1 });
  };
  for (size_t c = 0; c < curves.Curves.size(); ++c)
  {
    const std::vector<int>& p = arr.CurvePoints[c];
    if (!curves.BoundsCells(static_cast<int>(c)) || p.size() < 2)
    {
      continue;
    }
    const int shape = curves.Curves[c].ShapeId;
    for (size_t i = 0; i + 1 < p.size(); ++i)
    {
      step(p[i], p[i + 1], shape);
    }
    if (curves.Curves[c].Closed && p.front() != p.back())
    {
      step(p.back(), p.front(), shape);
    }
  }
  std::sort(out.BoundarySteps.begin(), out.BoundarySteps.end());
  for (auto& entry : placeSteps)
  {
    const int x = static_cast<int>(entry.first >> 32);
    const int y = static_cast<int>(entry.first & 0xffffffffu);
    // A step x -> y has the triangle holding x -> y on its left: it crosses from the right.
    const int lt = OwnedHolder(piece, arr, holder, x, y);
    const int rt = OwnedHolder(piece, arr, holder, y, x);
    if (lt < 0 || rt < 0)
    {
      continue; // a ghost's side, or the surface's open boundary
    }
    CellCrossing crossing;
    crossing.FromCell = arr.CellOfTriangle(rt);
    crossing.ToCell = arr.CellOfTriangle(lt);
    if (crossing.FromCell < 0 || crossing.ToCell < 0)
    {
      continue;
    }
    crossing.Delta = SumByShape(std::move(entry.second));
    crossing.Normalize();
    out.Crossings.push_back(std::move(crossing));
  }
  std::sort(out.Crossings.begin(), out.Crossings.end());
  out.Crossings.erase(std::unique(out.Crossings.begin(), out.Crossings.end()), out.Crossings.end());
}

} // namespace

//------------------------------------------------------------------------------
void SummarizePiece(const PieceMesh& piece,
  const PieceCurves& curves,
  const Arrangement& arr,
  PieceSummary& out,
  PieceTileSums* sums)
{
  out = PieceSummary();
  out.NumberOfLocalCells = arr.NumberOfCells;
  SummarizeCells(piece, arr, sums, out);
  const std::unordered_set<std::uint64_t> bounding = BoundingSubEdges(curves, arr);
  std::unordered_map<std::uint64_t, SubSegmentPlace> places;
  SummarizeBoundary(piece, arr, bounding, out, places);
  SummarizeCurveSteps(piece, curves, arr, places, out);
  SummarizeBoundaryLoops(piece, curves, arr, out.LoopFragments, out.PlugCrossings);
}

//------------------------------------------------------------------------------
bool ArrangePiece(const PieceMesh& piece,
  const PieceCurves& curves,
  const ArrangementOptions& options,
  Arrangement& arr,
  PieceSummary& out,
  std::string& error,
  PieceTileSums* sums)
{
  if (!ComputeArrangementOfRuns(
        piece.Mesh, curves.Curves, curves.CutFromClosed, options, arr, error))
  {
    return false;
  }
  SummarizePiece(piece, curves, arr, out, sums);
  return true;
}

} // namespace boolsurf

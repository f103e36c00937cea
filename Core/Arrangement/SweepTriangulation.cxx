#include "Arrangement/SweepTriangulation.h"

#include "Arrangement/Predicates.h"
#include "Mesh/EdgeIndex.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <memory_resource>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace boolsurf
{
namespace
{

using EdgeKey = std::uint64_t;

/// An edge of the sweep: a boundary edge or a curve piece, A visited before B.
struct SweepEdge
{
  int A, B;
  /// Whether the triangle's inside lies above the edge (left of A -> B): always for pieces;
  /// for boundary edges, those whose counter-clockwise direction is A -> B.
  bool InsideAbove;
};

/// How an edge entered the sweep; boundary edges win over a piece along them.
enum EdgeOrigin : int
{
  BoundaryInsideAbove = 0,
  BoundaryInsideBelow = 1,
  Piece = 2
};

class Sweep;

/// The status order: edges crossing the sweep line, bottom to top. A key below zero stands for
/// point -1 - key, to locate a point among the edges.
struct StatusOrder
{
  const Sweep* S;
  bool operator()(int x, int y) const;
};

using Status = std::pmr::set<int, StatusOrder>;

/// Buffers kept per thread: an edit refines thousands of crossed triangles, and each one
/// allocated them anew. The status tree's nodes come from the pool.
struct SweepBuffers
{
  std::vector<int> Order, Rank, Incidence, IncidenceStart, Left, Right;
  std::vector<std::pair<EdgeKey, int>> Keys;
  std::vector<SweepEdge> Edges;
  std::vector<std::vector<int>> Low, High;
  std::vector<Status::iterator> Where;
  std::vector<std::pair<EdgeKey, int>> Sides;
  std::vector<char> Used;
  std::pmr::unsynchronized_pool_resource Pool;
};

SweepBuffers& ThreadSweepBuffers()
{
  thread_local SweepBuffers buffers;
  return buffers;
}

class Sweep
{
public:
  Sweep(LocalArrangement& arrangement, SweepBuffers& buffers)
    : Arr(arrangement)
    , B(buffers)
    , Line(StatusOrder{ this }, &buffers.Pool)
  {
  }

  bool Run()
  {
    this->Arr.Triangles.clear();
    if (!this->SortPoints() || !this->CollectEdges())
    {
      return false;
    }
    for (int z : this->B.Order)
    {
      if (this->Arr.Alias[z] == z && !this->Visit(z))
      {
        return false;
      }
    }
    if (!this->Line.empty())
    {
      return this->Fail("the sweep ends with curve pieces still open");
    }
    return this->RewritePaths() && this->CheckTiling();
  }

  /// The status order (StatusOrder): whether x lies below y on the sweep line.
  bool Below(int x, int y) const
  {
    if (x == y)
    {
      return false;
    }
    if (x < 0 || y < 0)
    {
      const bool pointFirst = x < 0;
      const int z = pointFirst ? -1 - x : -1 - y;
      const SweepEdge& f = this->B.Edges[pointFirst ? y : x];
      const int o = this->Orient(f.A, f.B, z);
      if (o == 0)
      {
        this->OnEdge = pointFirst ? y : x;
      }
      return pointFirst ? o < 0 : o > 0;
    }
    const SweepEdge& e = this->B.Edges[x];
    const SweepEdge& f = this->B.Edges[y];
    int o;
    if (e.A == f.A)
    {
      o = this->Orient(e.A, e.B, f.B); // f above e when positive
    }
    else if (this->B.Rank[e.A] > this->B.Rank[f.A])
    {
      o = -this->Orient(f.A, f.B, e.A); // e starts later: which side of f it starts on
    }
    else
    {
      o = this->Orient(e.A, e.B, f.A);
    }
    if (o == 0)
    {
      this->Overlap = true;
    }
    return o > 0;
  }

private:
  bool IsCrossing(int i) const { return this->Arr.Points[i].Crossing >= 0; }

  int Orient(int a, int b, int c) const
  {
    const std::vector<LocalPoint>& p = this->Arr.Points;
    if (!this->IsCrossing(a) && !this->IsCrossing(b) && !this->IsCrossing(c))
    {
      return Orient2dSign(p[a].P, p[b].P, p[c].P);
    }
    return ExactOrient(
      ExactPointOf(this->Arr, a), ExactPointOf(this->Arr, b), ExactPointOf(this->Arr, c));
  }

  int Compare(int a, int b, int axis) const
  {
    if (!this->IsCrossing(a) && !this->IsCrossing(b))
    {
      const Vec2 pa = this->Arr.Points[a].P, pb = this->Arr.Points[b].P;
      const double u = axis == 0 ? pa.x : pa.y, v = axis == 0 ? pb.x : pb.y;
      return u < v ? -1 : (u > v ? 1 : 0);
    }
    return ExactCompare(ExactPointOf(this->Arr, a), ExactPointOf(this->Arr, b), axis);
  }

  bool Fail(const std::string& why)
  {
    if (this->Arr.Error.empty())
    {
      this->Arr.Error = "triangle " + std::to_string(this->Arr.Triangle) + ": " + why;
    }
    return false;
  }

  static std::string Pair(int a, int b) { return std::to_string(a) + "-" + std::to_string(b); }

  /// Sorts the points lexicographically; equal points become one, a boundary point first.
  bool SortPoints()
  {
    const std::vector<LocalPoint>& points = this->Arr.Points;
    const int n = static_cast<int>(points.size());
    std::vector<int>& order = this->B.Order;
    order.resize(n);
    for (int i = 0; i < n; ++i)
    {
      order[i] = i;
    }
    std::sort(order.begin(),
      order.end(),
      [&](int i, int j)
      {
        for (int axis = 0; axis < 2; ++axis)
        {
          const int c = this->Compare(i, j, axis);
          if (c != 0)
          {
            return c < 0;
          }
        }
        const bool bi = points[i].Where >= 0, bj = points[j].Where >= 0;
        return bi != bj ? bi : i < j;
      });
    this->Arr.Alias.resize(n);
    this->B.Rank.assign(n, -1);
    for (int k = 0; k < n; ++k)
    {
      const int i = order[k];
      this->Arr.Alias[i] = i;
      if (k > 0)
      {
        const int previous = order[k - 1];
        if (this->Compare(previous, i, 0) == 0 && this->Compare(previous, i, 1) == 0)
        {
          if (points[i].Where >= 0)
          {
            return this->Fail("boundary points " + Pair(previous, i) + " coincide");
          }
          this->Arr.Alias[i] = this->Arr.Alias[previous];
        }
      }
      this->B.Rank[i] = k;
    }
    return true;
  }

  /// Bit k set when point p lies on the triangle's side k (from corner k to corner k + 1).
  int Sides(int p) const { return this->Arr.Points[p].Sides(); }

  /// Whether the piece a-b runs along the triangle's boundary (both ends on one side).
  bool AlongBoundary(int a, int b) const { return (this->Sides(a) & this->Sides(b)) != 0; }

  /// The boundary edges and the curve pieces (each once), with per-point incidences.
  bool CollectEdges()
  {
    const std::vector<int>& alias = this->Arr.Alias;
    const std::vector<int>& boundary = this->Arr.Boundary;
    const std::vector<int>& rank = this->B.Rank;
    std::vector<std::pair<EdgeKey, int>>& keys = this->B.Keys;
    keys.clear();
    const int nb = static_cast<int>(boundary.size());
    for (int i = 0; i < nb; ++i)
    {
      const int a = boundary[i], b = boundary[(i + 1) % nb];
      keys.push_back({ UndirectedPointPair(a, b),
        rank[a] < rank[b] ? BoundaryInsideAbove : BoundaryInsideBelow });
    }
    for (const std::vector<int>& chain : this->Arr.Chains)
    {
      for (std::size_t i = 0; i + 1 < chain.size(); ++i)
      {
        const int a = alias[chain[i]], b = alias[chain[i + 1]];
        if (a != b && !this->AlongBoundary(a, b))
        {
          keys.push_back({ UndirectedPointPair(a, b), Piece });
        }
      }
    }
    std::sort(keys.begin(), keys.end());
    keys.erase(
      std::unique(
        keys.begin(), keys.end(), [](const auto& x, const auto& y) { return x.first == y.first; }),
      keys.end());

    const int n = static_cast<int>(this->Arr.Points.size());
    const int ne = static_cast<int>(keys.size());
    std::vector<SweepEdge>& edges = this->B.Edges;
    edges.resize(ne);
    std::vector<int>& start = this->B.IncidenceStart;
    start.assign(n + 1, 0);
    for (int e = 0; e < ne; ++e)
    {
      int a = static_cast<int>(keys[e].first >> 32);
      int b = static_cast<int>(keys[e].first & 0xffffffffu);
      if (rank[a] > rank[b])
      {
        std::swap(a, b);
      }
      edges[e] = { a, b, keys[e].second != BoundaryInsideBelow };
      ++start[a + 1];
      ++start[b + 1];
    }
    for (int i = 0; i < n; ++i)
    {
      start[i + 1] += start[i];
    }
    std::vector<int>& incidence = this->B.Incidence;
    incidence.resize(2 * ne);
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int e = 0; e < ne; ++e)
    {
      incidence[fill[edges[e].A]++] = e;
      incidence[fill[edges[e].B]++] = e;
    }
    if (static_cast<int>(this->B.Low.size()) < ne)
    {
      this->B.Low.resize(ne);
      this->B.High.resize(ne);
    }
    this->B.Where.resize(ne);
    return true;
  }

  bool Inside(int e) const { return e >= 0 && this->B.Edges[e].InsideAbove; }

  void Emit(int a, int b, int c) { this->Arr.Triangles.push_back({ a, b, c }); }

  /// Point z enters the region above edge e: z sees the region's rightmost visited point (the
  /// top of Low); triangles are fanned from it towards both ends of the region's polyline
  /// while they are strictly counter-clockwise, and z takes the fanned vertices' place.
  bool Fan(int e, int z)
  {
    std::vector<int>& low = this->B.Low[e];
    std::vector<int>& high = this->B.High[e];
    if (low.empty())
    {
      return this->Fail("a region of the sweep has no boundary at point " + std::to_string(z));
    }
    const int peak = low.back();
    int current = peak;
    while (!high.empty() && this->Orient(current, high.back(), z) < 0)
    {
      this->Emit(high.back(), current, z);
      current = high.back();
      high.pop_back();
    }
    high.push_back(current);
    current = peak;
    low.pop_back();
    while (!low.empty() && this->Orient(low.back(), current, z) < 0)
    {
      this->Emit(current, low.back(), z);
      current = low.back();
      low.pop_back();
    }
    low.push_back(current);
    low.push_back(z);
    return true;
  }

  /// After z ends the region's upper edge `upper`: the region's upper part is all fanned.
  bool UpperClosed(int e, int upper, int z)
  {
    std::vector<int>& high = this->B.High[e];
    if (high.size() != 1 || high[0] != this->B.Edges[upper].A)
    {
      return this->Fail("curve pieces cross or a point lies on a piece near point " +
        std::to_string(z) + " (piece " + Pair(this->B.Edges[upper].A, z) + " does not close)");
    }
    high.clear();
    return true;
  }

  /// After z ends the region's lower edge e: the region's lower part is all fanned.
  bool LowerClosed(int e, int z)
  {
    std::vector<int>& low = this->B.Low[e];
    if (low.size() != 2 || low[0] != this->B.Edges[e].A || low[1] != z)
    {
      return this->Fail("curve pieces cross or a point lies on a piece near point " +
        std::to_string(z) + " (piece " + Pair(this->B.Edges[e].A, z) + " does not close)");
    }
    low.assign(1, z);
    return true;
  }

  /// Sorts z's edges to the left and to the right bottom to top; two along one direction are
  /// overlapping pieces that stage 2 did not cut.
  bool SortIncidentEdges(int z)
  {
    std::vector<int>& left = this->B.Left;
    std::vector<int>& right = this->B.Right;
    left.clear();
    right.clear();
    const std::vector<SweepEdge>& edges = this->B.Edges;
    for (int k = this->B.IncidenceStart[z]; k < this->B.IncidenceStart[z + 1]; ++k)
    {
      const int e = this->B.Incidence[k];
      (edges[e].B == z ? left : right).push_back(e);
    }
    const auto rightBelow = [&](int r, int s)
    { return this->Orient(z, edges[r].B, edges[s].B) > 0; };
    const auto leftBelow = [&](int l, int m)
    { return this->Orient(edges[l].A, z, edges[m].A) > 0; };
    std::sort(right.begin(), right.end(), rightBelow);
    std::sort(left.begin(), left.end(), leftBelow);
    for (std::size_t i = 0; i + 1 < right.size(); ++i)
    {
      if (!rightBelow(right[i], right[i + 1]))
      {
        return this->Fail("curve pieces " + Pair(z, edges[right[i]].B) + " and " +
          Pair(z, edges[right[i + 1]].B) + " overlap");
      }
    }
    for (std::size_t i = 0; i + 1 < left.size(); ++i)
    {
      if (!leftBelow(left[i], left[i + 1]))
      {
        return this->Fail("curve pieces " + Pair(edges[left[i]].A, z) + " and " +
          Pair(edges[left[i + 1]].A, z) + " overlap");
      }
    }
    return true;
  }

  /// Whether z lies strictly above edge `below` and strictly below edge `above` (-1: none),
  /// as it must when its own edges are between them in the status.
  bool BetweenNeighbours(int below, int above, int z)
  {
    for (const int e : { below, above })
    {
      if (e < 0)
      {
        continue;
      }
      const SweepEdge& edge = this->B.Edges[e];
      const int side = this->Orient(edge.A, edge.B, z);
      if (side == 0 || (side > 0) != (e == below))
      {
        const bool boundary = this->Arr.Points[edge.A].Where >= 0 &&
          this->Arr.Points[edge.B].Where >= 0 && this->AlongBoundary(edge.A, edge.B);
        return this->Fail("point " + std::to_string(z) +
          (boundary ? " lies outside the triangle"
                    : " lies on or across curve piece " + Pair(edge.A, edge.B)));
      }
    }
    return true;
  }

  /// One event of the sweep: point z closes the edges ending at it, triangulates the regions
  /// it touches and opens its edges to the right.
  bool Visit(int z)
  {
    if (!this->SortIncidentEdges(z))
    {
      return false;
    }
    const std::vector<int>& left = this->B.Left;
    const std::vector<int>& right = this->B.Right;
    const std::vector<SweepEdge>& edges = this->B.Edges;
    std::vector<Status::iterator>& where = this->B.Where;
    int below = -1;
    Status::iterator hint = this->Line.end();
    // The region whose upper part continues above z's topmost edge to the right.
    int upperSource = -1;
    if (left.empty())
    {
      if (!this->Line.empty())
      {
        this->OnEdge = -1;
        hint = this->Line.lower_bound(-1 - z);
        if (this->OnEdge >= 0)
        {
          return this->Fail("point " + std::to_string(z) + " lies inside curve piece " +
            Pair(edges[this->OnEdge].A, edges[this->OnEdge].B));
        }
        below = hint == this->Line.begin() ? -1 : *std::prev(hint);
        if (!this->Inside(below))
        {
          return this->Fail("point " + std::to_string(z) + " lies outside the triangle");
        }
        if (!this->Fan(below, z))
        {
          return false;
        }
        upperSource = below;
      }
    }
    else
    {
      const std::size_t p = left.size();
      for (std::size_t i = 0; i + 1 < p; ++i)
      {
        if (std::next(where[left[i]]) != where[left[i + 1]])
        {
          return this->Fail("curve pieces cross near point " + std::to_string(z));
        }
      }
      const Status::iterator first = where[left.front()];
      below = first == this->Line.begin() ? -1 : *std::prev(first);
      hint = std::next(where[left.back()]);
      if (!this->BetweenNeighbours(below, hint == this->Line.end() ? -1 : *hint, z))
      {
        return false;
      }
      if (this->Inside(below) &&
        (!this->Fan(below, z) || !this->UpperClosed(below, left.front(), z)))
      {
        return false;
      }
      for (std::size_t i = 0; i + 1 < p; ++i)
      {
        const int e = left[i];
        if (this->Inside(e) &&
          (!this->Fan(e, z) || !this->UpperClosed(e, left[i + 1], z) || !this->LowerClosed(e, z)))
        {
          return false;
        }
        this->B.Low[e].clear();
      }
      const int top = left.back();
      if (this->Inside(top) && (!this->Fan(top, z) || !this->LowerClosed(top, z)))
      {
        return false;
      }
      upperSource = top;
      for (int e : left)
      {
        this->Line.erase(where[e]);
      }
    }

    this->Overlap = false;
    for (int r : right)
    {
      where[r] = this->Line.insert(hint, r);
      this->B.Low[r].clear();
      this->B.High[r].clear();
      if (this->Inside(r))
      {
        this->B.Low[r].push_back(z);
      }
    }
    if (this->Overlap)
    {
      return this->Fail("curve pieces from point " + std::to_string(z) + " overlap others");
    }
    const int topRight = right.empty() ? -1 : right.back();
    if (!left.empty() && right.empty())
    {
      // z closes the regions between its left edges; the ones below and above merge.
      if (this->Inside(below) != this->Inside(upperSource))
      {
        return this->Fail("the boundary is open at point " + std::to_string(z));
      }
      if (this->Inside(below))
      {
        std::swap(this->B.High[below], this->B.High[upperSource]);
      }
    }
    else if (topRight >= 0 && upperSource >= 0)
    {
      if (this->Inside(upperSource) != this->Inside(topRight))
      {
        return this->Fail("the boundary is open at point " + std::to_string(z));
      }
      if (this->Inside(upperSource))
      {
        std::swap(this->B.High[topRight], this->B.High[upperSource]);
      }
    }
    if (!left.empty())
    {
      this->B.Low[left.back()].clear();
      this->B.High[left.back()].clear();
    }
    return true;
  }

  /// Chains as paths of surviving points; a piece along the boundary goes through the
  /// boundary points on it.
  bool RewritePaths()
  {
    const std::vector<int>& alias = this->Arr.Alias;
    const std::vector<int>& boundary = this->Arr.Boundary;
    const int nb = static_cast<int>(boundary.size());
    std::vector<int>& position = this->B.Order; // reused: boundary index per point
    position.assign(this->Arr.Points.size(), -1);
    for (int i = 0; i < nb; ++i)
    {
      position[boundary[i]] = i;
    }
    std::vector<int> path;
    for (std::vector<int>& chain : this->Arr.Chains)
    {
      path.clear();
      for (int id : chain)
      {
        const int p = alias[id];
        if (!path.empty() && path.back() == p)
        {
          continue;
        }
        if (!path.empty() && this->AlongBoundary(path.back(), p))
        {
          const int side = this->Sides(path.back()) & this->Sides(p);
          const int from = position[path.back()], to = position[p];
          // Along the side both points share: forwards if the next boundary point is on it.
          const int step = (this->Sides(boundary[(from + 1) % nb]) & side) ? 1 : nb - 1;
          for (int i = (from + step) % nb; i != to; i = (i + step) % nb)
          {
            if ((this->Sides(boundary[i]) & side) == 0)
            {
              return this->Fail(
                "curve piece " + Pair(path.back(), p) + " runs outside the triangle's boundary");
            }
            path.push_back(boundary[i]);
          }
        }
        path.push_back(p);
      }
      chain.assign(path.begin(), path.end());
    }
    return true;
  }

  /// The triangles tile the triangle exactly once: their edges cancel in pairs except the
  /// boundary's, each once and counter-clockwise (with every triangle counter-clockwise, the
  /// covering number of every point is then 1), every surviving point is a vertex, and every
  /// piece is an edge.
  bool CheckTiling()
  {
    std::vector<std::pair<EdgeKey, int>>& sides = this->B.Sides;
    sides.clear();
    const int n = static_cast<int>(this->Arr.Points.size());
    std::vector<char>& used = this->B.Used;
    used.assign(n, 0);
    for (const std::array<int, 3>& t : this->Arr.Triangles)
    {
      for (int j = 0; j < 3; ++j)
      {
        const int a = t[j], b = t[(j + 1) % 3];
        sides.push_back({ UndirectedPointPair(a, b), a < b ? 1 : -1 });
        used[a] = 1;
      }
    }
    const std::vector<int>& boundary = this->Arr.Boundary;
    const int nb = static_cast<int>(boundary.size());
    for (int i = 0; i < nb; ++i)
    {
      const int a = boundary[i], b = boundary[(i + 1) % nb];
      sides.push_back({ UndirectedPointPair(a, b), a < b ? -1 : 1 }); // cancels the boundary's own
    }
    std::sort(sides.begin(), sides.end());
    for (std::size_t i = 0; i < sides.size();)
    {
      int sum = 0;
      std::size_t j = i;
      for (; j < sides.size() && sides[j].first == sides[i].first; ++j)
      {
        sum += sides[j].second;
      }
      if (sum != 0)
      {
        return this->Fail("the sweep's triangles do not tile the triangle (edge " +
          Pair(static_cast<int>(sides[i].first >> 32),
            static_cast<int>(sides[i].first & 0xffffffffu)) +
          ")");
      }
      i = j;
    }
    for (int i = 0; i < n; ++i)
    {
      if (this->Arr.Alias[i] == i && !used[i])
      {
        return this->Fail("point " + std::to_string(i) + " is no vertex of the triangulation");
      }
    }
    for (const std::vector<int>& chain : this->Arr.Chains)
    {
      for (std::size_t i = 0; i + 1 < chain.size(); ++i)
      {
        const EdgeKey key = UndirectedPointPair(chain[i], chain[i + 1]);
        const auto it = std::lower_bound(
          sides.begin(), sides.end(), std::make_pair(key, std::numeric_limits<int>::min()));
        if (it == sides.end() || it->first != key)
        {
          return this->Fail("curve piece " + Pair(chain[i], chain[i + 1]) + " is not an edge");
        }
      }
    }
    return true;
  }

  LocalArrangement& Arr;
  SweepBuffers& B;
  Status Line;
  /// Set by the status order when a point lies on an edge, or two edges overlap.
  mutable int OnEdge = -1;
  mutable bool Overlap = false;
};

bool StatusOrder::operator()(int x, int y) const
{
  return this->S->Below(x, y);
}

} // namespace

bool SweepTriangulate(LocalArrangement& arrangement)
{
  Sweep sweep(arrangement, ThreadSweepBuffers());
  return sweep.Run();
}

} // namespace boolsurf

#include "Arrangement/TriangleRefinement.h"

#include "Arrangement/PieceSplitting.h"
#include "Arrangement/Predicates.h"

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>

namespace boolsurf
{
namespace
{

using EdgeKey = std::uint64_t;

inline EdgeKey Directed(int a, int b)
{
  return (static_cast<EdgeKey>(static_cast<std::uint32_t>(a)) << 32) |
    static_cast<std::uint32_t>(b);
}

inline EdgeKey Undirected(int a, int b)
{
  return a < b ? Directed(a, b) : Directed(b, a);
}

// A triangulation of a few dozen points, kept simple on purpose: every search is a linear
// scan, which is faster than maintaining a point-location structure at these sizes.
struct Crossing
{
  double S; ///< parameter along the piece
  int X, Y; ///< crossed edge: X on the right of the piece, Y on its left
};

/// The buffers of a LocalTriangulation, kept per thread: an edit refines a few thousand
/// crossed triangles, and each one allocated them anew.
struct TriangulationBuffers
{
  std::vector<std::array<int, 3>> Tris;
  std::vector<char> Alive;
  std::vector<char> IsInserted;
  std::vector<EdgeKey> ClosedEdges;
};

TriangulationBuffers& ThreadTriangulationBuffers()
{
  thread_local TriangulationBuffers buffers;
  return buffers;
}

class LocalTriangulation
{
public:
  /// `buffers` are emptied and used by this triangulation only, for its lifetime.
  LocalTriangulation(LocalArrangement& arrangement, TriangulationBuffers& buffers)
    : Arr(arrangement)
    , UseMap(arrangement.Points.size() > 24)
    , Tris(buffers.Tris)
    , Alive(buffers.Alive)
    , IsInserted(buffers.IsInserted)
  {
    this->Tris.clear();
    this->Alive.clear();
    this->IsInserted.clear();
  }

  Vec2 P(int i) const { return this->Arr.Points[i].P; }
  int Orient(int a, int b, int c) const { return Orient2dSign(this->P(a), this->P(b), this->P(c)); }

  void Add(int a, int b, int c)
  {
    const int t = static_cast<int>(this->Tris.size());
    this->Tris.push_back({ a, b, c });
    this->Alive.push_back(1);
    if (this->UseMap)
    {
      this->HalfEdges[Directed(a, b)] = t;
      this->HalfEdges[Directed(b, c)] = t;
      this->HalfEdges[Directed(c, a)] = t;
    }
  }

  void Remove(int t)
  {
    const std::array<int, 3>& v = this->Tris[t];
    if (this->UseMap)
    {
      for (int j = 0; j < 3; ++j)
      {
        this->HalfEdges.erase(Directed(v[j], v[(j + 1) % 3]));
      }
    }
    this->Alive[t] = 0;
  }

  int Find(int a, int b) const
  {
    if (!this->UseMap)
    {
      for (int t = 0; t < static_cast<int>(this->Tris.size()); ++t)
      {
        const std::array<int, 3>& v = this->Tris[t];
        if (this->Alive[t] &&
          ((v[0] == a && v[1] == b) || (v[1] == a && v[2] == b) || (v[2] == a && v[0] == b)))
        {
          return t;
        }
      }
      return -1;
    }
    auto it = this->HalfEdges.find(Directed(a, b));
    return it == this->HalfEdges.end() ? -1 : it->second;
  }

  bool Fail(const std::string& why)
  {
    if (this->Arr.Error.empty())
    {
      this->Arr.Error = "triangle " + std::to_string(this->Arr.Triangle) + ": " + why;
    }
    return false;
  }

  /// Triangulates a simple counter-clockwise polygon by ear clipping. An ear needs a strictly
  /// convex tip and no other polygon vertex in its closed triangle.
  bool EarClip(std::vector<int> poly)
  {
    while (poly.size() > 3)
    {
      const int n = static_cast<int>(poly.size());
      bool clipped = false;
      for (int i = 0; i < n && !clipped; ++i)
      {
        const int a = poly[(i + n - 1) % n], b = poly[i], c = poly[(i + 1) % n];
        if (this->Orient(a, b, c) <= 0)
        {
          continue;
        }
        bool empty = true;
        for (int j = 0; j < n && empty; ++j)
        {
          const int v = poly[j];
          if (v == a || v == b || v == c)
          {
            continue;
          }
          empty = !(
            this->Orient(a, b, v) >= 0 && this->Orient(b, c, v) >= 0 && this->Orient(c, a, v) >= 0);
        }
        if (empty)
        {
          this->Add(a, b, c);
          poly.erase(poly.begin() + i);
          clipped = true;
        }
      }
      if (!clipped)
      {
        return this->Fail("a polygon has no ear (degenerate local geometry)");
      }
    }
    if (this->Orient(poly[0], poly[1], poly[2]) <= 0)
    {
      return this->Fail("a polygon degenerates to a flat triangle");
    }
    this->Add(poly[0], poly[1], poly[2]);
    return true;
  }

  /// Splits edge (x, y) and its twin at point p, keeping constraints and paths through it.
  bool SplitEdge(int x, int y, int p)
  {
    const int t1 = this->Find(x, y), t2 = this->Find(y, x);
    int z1 = -1, z2 = -1;
    for (int j = 0; j < 3; ++j)
    {
      if (t1 >= 0 && this->Tris[t1][j] != x && this->Tris[t1][j] != y)
        z1 = this->Tris[t1][j];
      if (t2 >= 0 && this->Tris[t2][j] != x && this->Tris[t2][j] != y)
        z2 = this->Tris[t2][j];
    }
    if ((t1 >= 0 && (this->Orient(x, p, z1) <= 0 || this->Orient(p, y, z1) <= 0)) ||
      (t2 >= 0 && (this->Orient(y, p, z2) <= 0 || this->Orient(p, x, z2) <= 0)))
    {
      return this->Fail("a point to insert is not on the edge it should split");
    }
    if (t1 >= 0)
    {
      this->Remove(t1);
      this->Add(x, p, z1);
      this->Add(p, y, z1);
    }
    if (t2 >= 0)
    {
      this->Remove(t2);
      this->Add(y, p, z2);
      this->Add(p, x, z2);
    }
    if (this->Constrained.erase(Undirected(x, y)) > 0)
    {
      this->Constrained.insert(Undirected(x, p));
      this->Constrained.insert(Undirected(p, y));
      for (std::vector<int>& path : this->Paths)
      {
        for (size_t i = 0; i + 1 < path.size(); ++i)
        {
          if ((path[i] == x && path[i + 1] == y) || (path[i] == y && path[i + 1] == x))
          {
            path.insert(path.begin() + i + 1, p);
            ++i;
          }
        }
      }
    }
    return true;
  }

  /// Inserts interior point p (or aliases it to an existing point with equal coordinates).
  bool InsertPoint(int p)
  {
    for (int t = 0; t < static_cast<int>(this->Tris.size()); ++t)
    {
      if (!this->Alive[t])
      {
        continue;
      }
      const std::array<int, 3> v = this->Tris[t];
      int o[3];
      bool outside = false;
      for (int j = 0; j < 3; ++j)
      {
        o[j] = this->Orient(v[j], v[(j + 1) % 3], p);
        outside = outside || o[j] < 0;
      }
      if (outside)
      {
        continue;
      }
      const int zeros = (o[0] == 0) + (o[1] == 0) + (o[2] == 0);
      if (zeros >= 2)
      {
        // Equal coordinates: the vertex opposite the nonzero one... i.e. the common vertex of
        // the two zero edges.
        for (int j = 0; j < 3; ++j)
        {
          if (o[j] == 0 && o[(j + 2) % 3] == 0)
          {
            this->Arr.Alias[p] = v[j];
          }
        }
        return true;
      }
      if (zeros == 1)
      {
        for (int j = 0; j < 3; ++j)
        {
          if (o[j] == 0)
          {
            return this->SplitEdge(v[j], v[(j + 1) % 3], p);
          }
        }
      }
      this->Remove(t);
      this->Add(v[0], v[1], p);
      this->Add(v[1], v[2], p);
      this->Add(v[2], v[0], p);
      return true;
    }
    return this->Fail("an interior point lies in no sub-triangle");
  }

  /// Makes (a, b) a chain of triangulation edges, appending the points it passes through
  /// (b included) to path `pi`.
  bool InsertConstraint(int a, int b, int pi)
  {
    const size_t guardLimit = 4 * this->Arr.Points.size() + 64;
    for (size_t guard = 0; a != b; ++guard)
    {
      // Every step of every insertion counts against one budget: detours around rounded
      // crossings call this recursively, and must end.
      if (guard > guardLimit || ++this->Steps > this->StepBudget)
      {
        return this->Fail("constraint insertion does not converge");
      }
      if (this->Find(a, b) >= 0 || this->Find(b, a) >= 0)
      {
        this->Constrained.insert(Undirected(a, b));
        this->Paths[pi].push_back(b);
        return true;
      }
      // A vertex exactly on the open piece: go through it.
      int on = -1;
      double onParameter = 0.0;
      const Vec2 pa = this->P(a), pb = this->P(b);
      for (int v = 0; v < static_cast<int>(this->Arr.Points.size()); ++v)
      {
        if (v == a || v == b || this->Arr.Alias[v] != v || !this->Inserted(v))
        {
          continue;
        }
        if (this->Orient(a, b, v) == 0 && StrictlyBetween(pa, pb, this->P(v)))
        {
          const double s = ParameterAlong(pa, pb, this->P(v));
          if (on < 0 || s < onParameter)
          {
            on = v;
            onParameter = s;
          }
        }
      }
      if (on >= 0)
      {
        if (!this->InsertConstraint(a, on, pi))
        {
          return false;
        }
        a = on;
        continue;
      }
      // Edges the open piece crosses, in order from a, found by walking the triangles it
      // passes through (ordering by computed parameters could disagree with the topology).
      std::vector<Crossing> crossings;
      if (!this->WalkCrossings(a, b, crossings))
      {
        return false;
      }
      const Crossing* blocking = nullptr;
      for (const Crossing& c : crossings)
      {
        if (this->Constrained.count(Undirected(c.X, c.Y)) > 0)
        {
          blocking = &c;
          break;
        }
      }
      if (blocking)
      {
        // Rounded crossings made two pieces cross after all. Such a crossing lies within
        // rounding of a point already there (an end of the other piece, usually a rounded
        // crossing itself): the piece goes through that point. Otherwise both pieces go
        // through a new point at the crossing; its rounded coordinates may put it beside the
        // other piece rather than on it, so it is inserted like any point and the other piece
        // is bent through it.
        const int x = blocking->X, y = blocking->Y;
        const Vec2 at = pa + blocking->S * (pb - pa);
        const int near = Length(this->P(x) - at) <= Length(this->P(y) - at) ? x : y;
        if (near != a && Length(this->P(near) - at) <= SnapDistance)
        {
          if (!this->InsertConstraint(a, near, pi))
          {
            return false;
          }
          a = near;
          continue;
        }
        const int np = static_cast<int>(this->Arr.Points.size());
        this->Arr.Points.push_back({ pa + blocking->S * (pb - pa), -1, -1 });
        this->Arr.Alias.push_back(np);
        this->IsInserted.push_back(0);
        if (!this->InsertPoint(np))
        {
          return false;
        }
        this->IsInserted[np] = 1;
        const int q = this->Arr.Alias[np];
        if (q != x && q != y && this->Constrained.count(Undirected(x, y)) > 0 &&
          !this->RerouteConstraint(x, y, q))
        {
          return false;
        }
        if (q != a && !this->InsertConstraint(a, q, pi))
        {
          return false;
        }
        a = q;
        continue;
      }
      if (!this->CavityInsert(a, b, crossings))
      {
        return false;
      }
      this->Constrained.insert(Undirected(a, b));
      this->Paths[pi].push_back(b);
      return true;
    }
    return true;
  }

  /// Replaces constrained edge (x, y) by constrained pieces x -> q -> y, in the triangulation
  /// and in every path that runs along it (either way).
  bool RerouteConstraint(int x, int y, int q)
  {
    this->Constrained.erase(Undirected(x, y));
    const int tmp = static_cast<int>(this->Paths.size());
    this->Paths.push_back({ x });
    if (!this->InsertConstraint(x, q, tmp) || !this->InsertConstraint(q, y, tmp))
    {
      return false;
    }
    const std::vector<int> chain = std::move(this->Paths[tmp]);
    this->Paths.pop_back();
    for (std::vector<int>& path : this->Paths)
    {
      for (size_t i = 0; i + 1 < path.size(); ++i)
      {
        const bool along = path[i] == x && path[i + 1] == y;
        if (along || (path[i] == y && path[i + 1] == x))
        {
          std::vector<int> inner(chain.begin() + 1, chain.end() - 1);
          if (!along)
          {
            std::reverse(inner.begin(), inner.end());
          }
          path.insert(path.begin() + i + 1, inner.begin(), inner.end());
          i += inner.size();
        }
      }
    }
    return true;
  }

  /// Edges crossed by the open segment (a, b), which must contain no vertex, in order from a;
  /// X is the endpoint on the right of a -> b, Y the one on the left.
  bool WalkCrossings(int a, int b, std::vector<Crossing>& crossings)
  {
    int x = -1, y = -1;
    for (int t = 0; t < static_cast<int>(this->Tris.size()) && x < 0; ++t)
    {
      if (!this->Alive[t])
      {
        continue;
      }
      for (int j = 0; j < 3; ++j)
      {
        if (this->Tris[t][j] != a)
        {
          continue;
        }
        const int u = this->Tris[t][(j + 1) % 3], v = this->Tris[t][(j + 2) % 3];
        if (this->Orient(a, u, b) > 0 && this->Orient(a, v, b) < 0)
        {
          x = u;
          y = v;
        }
      }
    }
    if (x < 0)
    {
      return this->Fail("a curve piece leaves its start point through no triangle");
    }
    const Vec2 pa = this->P(a), pb = this->P(b);
    for (size_t guard = 0; guard <= this->Tris.size(); ++guard)
    {
      const double oa = Orient2d(this->P(x), this->P(y), pa);
      const double ob = Orient2d(this->P(x), this->P(y), pb);
      crossings.push_back({ oa / (oa - ob), x, y });
      const int twin = this->Find(y, x);
      if (twin < 0)
      {
        return this->Fail("a curve piece leaves the triangle");
      }
      const std::array<int, 3>& v = this->Tris[twin];
      const int z = v[0] != x && v[0] != y ? v[0] : (v[1] != x && v[1] != y ? v[1] : v[2]);
      if (z == b)
      {
        return true;
      }
      const int side = this->Orient(a, b, z);
      if (side > 0)
      {
        y = z;
      }
      else if (side < 0)
      {
        x = z;
      }
      else
      {
        return this->Fail("a vertex on a curve piece was missed");
      }
    }
    return this->Fail("walking along a curve piece does not end");
  }

  /// Removes the triangles crossed by (a, b) and re-triangulates the two sides.
  bool CavityInsert(int a, int b, const std::vector<Crossing>& crossings)
  {
    std::vector<int> left, right;
    std::unordered_set<int> doomed;
    for (const auto& c : crossings)
    {
      const int l = c.Y, r = c.X;
      if (left.empty() || left.back() != l)
        left.push_back(l);
      if (right.empty() || right.back() != r)
        right.push_back(r);
      doomed.insert(this->Find(c.X, c.Y));
      doomed.insert(this->Find(c.Y, c.X));
    }
    std::vector<int> doomedSorted(doomed.begin(), doomed.end());
    std::sort(doomedSorted.begin(), doomedSorted.end());
    for (int t : doomedSorted)
    {
      if (t >= 0)
      {
        this->Remove(t);
      }
    }
    std::vector<int> leftPolygon{ a, b };
    leftPolygon.insert(leftPolygon.end(), left.rbegin(), left.rend());
    std::vector<int> rightPolygon{ b, a };
    rightPolygon.insert(rightPolygon.end(), right.begin(), right.end());
    return this->EarClip(leftPolygon) && this->EarClip(rightPolygon);
  }

  bool Inserted(int v) const
  {
    return v < static_cast<int>(this->IsInserted.size()) && this->IsInserted[v];
  }

  LocalArrangement& Arr;
  /// Small triangulations (the vast majority) find half-edges by scanning, which beats
  /// maintaining a hash map; large ones keep the map.
  bool UseMap = false;
  std::vector<std::array<int, 3>>& Tris;
  std::vector<char>& Alive;
  std::unordered_map<EdgeKey, int> HalfEdges;
  std::unordered_set<EdgeKey> Constrained;
  std::vector<std::vector<int>> Paths;
  std::vector<char>& IsInserted;
  /// Distance (unit-triangle coordinates) within which a rounded crossing is taken to be an
  /// existing point: far above the rounding of crossings (~1e-16), far below any feature
  /// the curves can resolve.
  static constexpr double SnapDistance = 1e-12;
  size_t Steps = 0;
  size_t StepBudget = 0;
};

// Fast path: chords only. Each chord splits the one convex polygon that holds both of its
// endpoints (non-adjacent); a chord already present as a polygon side is a duplicate.
bool SplitByChords(LocalTriangulation& tri, const LocalArrangement& arr)
{
  std::vector<std::vector<int>> polygons{ arr.Boundary };
  for (const std::vector<int>& chain : arr.Chains)
  {
    const int a = chain.front(), b = chain.back();
    for (size_t pi = 0; pi < polygons.size(); ++pi)
    {
      std::vector<int>& poly = polygons[pi];
      const int n = static_cast<int>(poly.size());
      const int ia = static_cast<int>(std::find(poly.begin(), poly.end(), a) - poly.begin());
      const int ib = static_cast<int>(std::find(poly.begin(), poly.end(), b) - poly.begin());
      if (ia == n || ib == n)
      {
        continue;
      }
      if ((ia + 1) % n == ib || (ib + 1) % n == ia)
      {
        break; // already a side
      }
      std::vector<int> first, second;
      for (int i = ia;; i = (i + 1) % n)
      {
        first.push_back(poly[i]);
        if (i == ib)
          break;
      }
      for (int i = ib;; i = (i + 1) % n)
      {
        second.push_back(poly[i]);
        if (i == ia)
          break;
      }
      poly = std::move(first);
      polygons.push_back(std::move(second));
      break;
    }
  }
  for (const std::vector<int>& poly : polygons)
  {
    if (!tri.EarClip(poly))
    {
      return false;
    }
  }
  return true;
}

} // namespace

//------------------------------------------------------------------------------
namespace
{
bool RefineOnce(LocalArrangement& arr)
{
  const int n = static_cast<int>(arr.Points.size());
  arr.Alias.resize(n);
  for (int i = 0; i < n; ++i)
  {
    arr.Alias[i] = i;
  }
  TriangulationBuffers& buffers = ThreadTriangulationBuffers();
  LocalTriangulation tri(arr, buffers);
  tri.StepBudget = 32 * static_cast<size_t>(n) + 1024;
  tri.Tris.reserve(4 * n);
  tri.Alive.reserve(4 * n);
  tri.IsInserted.assign(n, 0);
  bool hasInterior = false;
  for (int i = 0; i < n; ++i)
  {
    hasInterior = hasInterior || arr.Points[i].Where < 0;
  }

  if (!hasInterior)
  {
    if (!SplitByChords(tri, arr))
    {
      return false;
    }
    tri.Paths.swap(arr.Chains); // unchanged: handed back below
  }
  else
  {
    if (!tri.EarClip(arr.Boundary))
    {
      return false;
    }
    for (int b : arr.Boundary)
    {
      tri.IsInserted[b] = 1;
    }
    for (int i = 0; i < n; ++i)
    {
      if (arr.Points[i].Where < 0)
      {
        if (!tri.InsertPoint(i))
        {
          return false;
        }
        tri.IsInserted[i] = 1;
      }
    }
    tri.Paths.resize(arr.Chains.size());
    for (size_t c = 0; c < arr.Chains.size(); ++c)
    {
      const std::vector<int>& chain = arr.Chains[c];
      tri.Paths[c].push_back(arr.Alias[chain.front()]);
      for (size_t i = 1; i < chain.size(); ++i)
      {
        const int from = tri.Paths[c].back();
        const int to = arr.Alias[chain[i]];
        if (to != from && !tri.InsertConstraint(from, to, static_cast<int>(c)))
        {
          return false;
        }
      }
    }
  }

  // Sub-edges on closed curves block the flood fill.
  std::vector<EdgeKey>& closedEdges = buffers.ClosedEdges;
  closedEdges.clear();
  for (size_t c = 0; c < tri.Paths.size(); ++c)
  {
    if (arr.ChainClosed[c])
    {
      const std::vector<int>& path = tri.Paths[c];
      for (size_t i = 0; i + 1 < path.size(); ++i)
      {
        closedEdges.push_back(Undirected(path[i], path[i + 1]));
      }
    }
  }
  std::sort(closedEdges.begin(), closedEdges.end());
  arr.Triangles.clear();
  arr.Blocked.clear();
  for (size_t t = 0; t < tri.Tris.size(); ++t)
  {
    if (!tri.Alive[t])
    {
      continue;
    }
    const std::array<int, 3>& v = tri.Tris[t];
    unsigned char mask = 0;
    for (int j = 0; j < 3; ++j)
    {
      if (std::binary_search(
            closedEdges.begin(), closedEdges.end(), Undirected(v[j], v[(j + 1) % 3])))
      {
        mask |= static_cast<unsigned char>(1u << j);
      }
    }
    arr.Triangles.push_back(v);
    arr.Blocked.push_back(mask);
  }
  arr.Chains = std::move(tri.Paths);
  arr.NumberOfNewPoints = 0;
  for (size_t i = 0; i < arr.Points.size(); ++i)
  {
    if (arr.Points[i].Where < 0 && arr.Alias[i] == static_cast<int>(i))
    {
      ++arr.NumberOfNewPoints;
    }
  }
  return true;
}
} // namespace

bool RefineTriangle(LocalArrangement& arr)
{
  if (!arr.Error.empty())
  {
    return false;
  }
  const std::size_t firstPoints = arr.Points.size();
  if (RefineOnce(arr))
  {
    return true;
  }
  // The incremental insertion failed (in practice: detours around rounded crossings that do
  // not end, on a triangle crowded with pieces). Start again from stage 2's points and chains,
  // split until no two pieces cross (PieceSplitting.h), and triangulate that: no constraint
  // can then block another.
  const std::string first = arr.Error;
  arr.Error.clear();
  arr.Points.resize(firstPoints);
  std::string problem;
  if (!SplitPiecesAtCrossings(arr, LocalTriangulation::SnapDistance, problem))
  {
    arr.Error = first + "; " + problem;
    return false;
  }
  if (!RefineOnce(arr))
  {
    arr.Error = first + "; after splitting crossing pieces: " + arr.Error;
    return false;
  }
  return true;
}

} // namespace boolsurf

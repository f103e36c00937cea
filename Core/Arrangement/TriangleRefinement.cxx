#include "Arrangement/TriangleRefinement.h"

#include "Arrangement/EdgeIndex.h"
#include "Arrangement/Predicates.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
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

/// Whether d lies inside the circle through a, b, c (counter-clockwise), by more than the
/// rounding of the determinant: points on the circle, or within rounding of it, are not.
bool InCircle(Vec2 a, Vec2 b, Vec2 c, Vec2 d)
{
  const double adx = a.x - d.x, ady = a.y - d.y, bdx = b.x - d.x, bdy = b.y - d.y;
  const double cdx = c.x - d.x, cdy = c.y - d.y;
  const double alift = adx * adx + ady * ady, blift = bdx * bdx + bdy * bdy;
  const double clift = cdx * cdx + cdy * cdy;
  const double bc = bdx * cdy - cdx * bdy, ca = cdx * ady - adx * cdy, ab = adx * bdy - bdx * ady;
  const double det = alift * bc + blift * ca + clift * ab;
  const double permanent = alift * std::abs(bc) + blift * std::abs(ca) + clift * std::abs(ab);
  return det > 1e-12 * permanent;
}

/// An edge of the triangulation a piece crosses: X on the right of the piece, Y on its left.
struct Crossing
{
  int X, Y;
};

/// The buffers of a LocalTriangulation, kept per thread: an edit refines a few thousand
/// crossed triangles, and each one allocated them anew.
struct TriangulationBuffers
{
  std::vector<std::array<int, 3>> Tris;
  std::vector<char> Alive;
  std::vector<EdgeKey> ClosedEdges;
  EdgeIndex HalfEdges; ///< large triangulations only
};

TriangulationBuffers& ThreadTriangulationBuffers()
{
  thread_local TriangulationBuffers buffers;
  return buffers;
}

// A triangulation of a triangle's points. Small ones (the vast majority: a few dozen points)
// are searched by linear scans, faster than maintaining any structure at these sizes. Large
// ones (a triangle crowded with curve pieces: thousands of points and crossings) keep a map of
// half-edges and a triangle per vertex, locate points by walking and find the vertices on a
// piece along the walk, so that the cost per point and per piece does not grow with the
// triangle's size.
class LocalTriangulation
{
public:
  /// `buffers` are emptied and used by this triangulation only, for its lifetime.
  LocalTriangulation(LocalArrangement& arrangement, TriangulationBuffers& buffers)
    : Arr(arrangement)
    , UseMap(arrangement.Points.size() > 24)
    , Flip(arrangement.Points.size() > 1024)
    , Tris(buffers.Tris)
    , Alive(buffers.Alive)
    , HalfEdges(buffers.HalfEdges)
  {
    this->Tris.clear();
    this->Alive.clear();
    if (this->UseMap)
    {
      // Room for the half-edges of the points' triangulation (about 6 per point); crossings
      // found later add points, and the map grows for them.
      this->HalfEdges.Reset(6 * arrangement.Points.size());
      // About two points per cell: a walk from the cell's last triangle is a few steps long.
      this->StartGridSize = std::max(
        1, static_cast<int>(std::sqrt(0.5 * static_cast<double>(arrangement.Points.size()))));
      this->WalkStarts.assign(
        static_cast<std::size_t>(this->StartGridSize) * this->StartGridSize, -1);
    }
  }

  Vec2 P(int i) const { return this->Arr.Points[i].P; }
  bool IsCrossing(int i) const { return this->Arr.Points[i].Crossing >= 0; }

  /// Exact orientation of three points, crossings included (ExactCrossings.h).
  int Orient(int a, int b, int c) const
  {
    if (!this->IsCrossing(a) && !this->IsCrossing(b) && !this->IsCrossing(c))
    {
      return Orient2dSign(this->P(a), this->P(b), this->P(c));
    }
    return ExactOrient(
      ExactPointOf(this->Arr, a), ExactPointOf(this->Arr, b), ExactPointOf(this->Arr, c));
  }

  /// For q on the line through a and b: whether it lies strictly between them; exact.
  bool Between(int a, int b, int q) const
  {
    if (!this->IsCrossing(a) && !this->IsCrossing(b) && !this->IsCrossing(q))
    {
      return StrictlyBetween(this->P(a), this->P(b), this->P(q));
    }
    return ExactStrictlyBetween(
      ExactPointOf(this->Arr, a), ExactPointOf(this->Arr, b), ExactPointOf(this->Arr, q));
  }

  void Add(int a, int b, int c)
  {
    const int t = static_cast<int>(this->Tris.size());
    this->Tris.push_back({ a, b, c });
    this->Alive.push_back(1);
    if (this->UseMap)
    {
      this->HalfEdges.Set(Directed(a, b), t);
      this->HalfEdges.Set(Directed(b, c), t);
      this->HalfEdges.Set(Directed(c, a), t);
      const int most = std::max(a, std::max(b, c));
      if (most >= static_cast<int>(this->VertexTriangle.size()))
      {
        this->VertexTriangle.resize(most + 1, -1);
      }
      this->VertexTriangle[a] = this->VertexTriangle[b] = this->VertexTriangle[c] = t;
      this->LastAdded = t;
      this->WalkStarts[this->StartCell((1.0 / 3.0) * (this->P(a) + this->P(b) + this->P(c)))] = t;
    }
  }

  /// Cell of the grid of walk starts that holds q (clamped to the unit square).
  std::size_t StartCell(Vec2 q) const
  {
    const int n = this->StartGridSize;
    const int i = std::min(n - 1, std::max(0, static_cast<int>(q.x * n)));
    const int j = std::min(n - 1, std::max(0, static_cast<int>(q.y * n)));
    return static_cast<std::size_t>(j) * n + i;
  }

  void Remove(int t)
  {
    const std::array<int, 3>& v = this->Tris[t];
    if (this->UseMap)
    {
      for (int j = 0; j < 3; ++j)
      {
        this->HalfEdges.Erase(Directed(v[j], v[(j + 1) % 3]));
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
    return this->HalfEdges.Find(Directed(a, b));
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
    if (this->Flip)
    {
      this->FlipTowardsDelaunay(p, { { z1, x }, { y, z1 }, { z2, y }, { x, z2 } });
    }
    return true;
  }

  /// After inserting p: flips the edges opposite p (directed as in p's triangles) while the
  /// vertex across one lies inside the circumcircle of p's triangle, as Lawson's algorithm
  /// does. Incremental insertion alone leaves long slivers, which make walks long and cavities
  /// large; near-Delaunay triangles keep both local. Constrained and boundary edges are never
  /// flipped, a flip needs a strictly convex quadrilateral (exact orientations), and their
  /// number is bounded, so ties on co-circular lattice points cannot loop.
  void FlipTowardsDelaunay(int p, std::initializer_list<std::pair<int, int>> opposite)
  {
    std::vector<std::pair<int, int>>& stack = this->FlipStack;
    stack.assign(opposite.begin(), opposite.end());
    for (int flips = 0; !stack.empty() && flips < 64;)
    {
      const auto [a, b] = stack.back();
      stack.pop_back();
      if (a < 0 || b < 0 || this->Constrained.count(Undirected(a, b)) > 0)
      {
        continue;
      }
      const int t = this->Find(a, b), u = this->Find(b, a);
      if (t < 0 || u < 0 || this->CornerOf(t, p) < 0)
      {
        continue;
      }
      const std::array<int, 3>& w = this->Tris[u];
      const int q = w[0] != a && w[0] != b ? w[0] : (w[1] != a && w[1] != b ? w[1] : w[2]);
      if (!InCircle(this->P(a), this->P(b), this->P(p), this->P(q)) || this->Orient(a, q, p) <= 0 ||
        this->Orient(q, b, p) <= 0)
      {
        continue;
      }
      this->Remove(t);
      this->Remove(u);
      this->Add(a, q, p);
      this->Add(q, b, p);
      stack.push_back({ a, q });
      stack.push_back({ q, b });
      ++flips;
    }
  }

  /// Whether p lies in the closed triangle t, with the orientations of p to its edges.
  bool Holds(int t, int p, int o[3]) const
  {
    const std::array<int, 3>& v = this->Tris[t];
    for (int j = 0; j < 3; ++j)
    {
      o[j] = this->Orient(v[j], v[(j + 1) % 3], p);
      if (o[j] < 0)
      {
        return false;
      }
    }
    return true;
  }

  /// An alive triangle holding p (closed), by scanning them all; -1 if none.
  int LocateByScan(int p, int o[3]) const
  {
    for (int t = 0; t < static_cast<int>(this->Tris.size()); ++t)
    {
      if (this->Alive[t] && this->Holds(t, p, o))
      {
        return t;
      }
    }
    return -1;
  }

  /// An alive triangle holding p (closed), by walking towards p from the last triangle made in
  /// p's cell of the walk-start grid (else the last one made): across an edge that has p
  /// strictly on its other side, the edge tried first varying from step to step (a visibility
  /// walk can cycle in a non-Delaunay triangulation; this one is bounded, and the scan takes
  /// over when it does not arrive).
  int LocateByWalk(int p, int o[3]) const
  {
    int t = this->WalkStarts[this->StartCell(this->P(p))];
    if (t < 0 || !this->Alive[t])
    {
      t = this->LastAdded;
    }
    if (t < 0 || !this->Alive[t])
    {
      return this->LocateByScan(p, o);
    }
    const std::size_t limit = 2 * this->Tris.size() + 16;
    for (std::size_t step = 0; step < limit; ++step)
    {
      const std::array<int, 3>& v = this->Tris[t];
      int next = -1;
      const int first = static_cast<int>((step * 2654435761u + static_cast<unsigned>(p)) % 3);
      for (int k = 0; k < 3 && next < 0; ++k)
      {
        const int j = (first + k) % 3;
        if (this->Orient(v[j], v[(j + 1) % 3], p) < 0)
        {
          next = this->Find(v[(j + 1) % 3], v[j]);
          if (next < 0)
          {
            return this->LocateByScan(p, o); // beyond the boundary: not ours to decide here
          }
        }
      }
      if (next < 0)
      {
        return this->Holds(t, p, o) ? t : this->LocateByScan(p, o);
      }
      t = next;
    }
    return this->LocateByScan(p, o);
  }

  /// Inserts interior point p (or aliases it to an existing point with equal coordinates).
  bool InsertPoint(int p)
  {
    int o[3];
    const int t = this->UseMap ? this->LocateByWalk(p, o) : this->LocateByScan(p, o);
    if (t >= 0)
    {
      const std::array<int, 3> v = this->Tris[t];
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
      if (this->Flip)
      {
        this->FlipTowardsDelaunay(p, { { v[0], v[1] }, { v[1], v[2] }, { v[2], v[0] } });
      }
      return true;
    }
    return this->Fail("an interior point lies in no sub-triangle");
  }

  /// Makes (a, b) a chain of triangulation edges, appending the points it passes through
  /// (b included) to path `pi`. Stage 2's exact crossings guarantee that no constrained edge
  /// crosses the open piece: a vertex on it is passed through, and each call ends after at
  /// most one step per vertex on the piece.
  bool InsertConstraint(int a, int b, int pi)
  {
    while (a != b)
    {
      if (this->Find(a, b) >= 0 || this->Find(b, a) >= 0)
      {
        this->Constrained.insert(Undirected(a, b));
        this->Paths[pi].push_back(b);
        return true;
      }
      // Edges the open piece crosses, in order from a, found by walking the triangles it
      // passes through; or the first vertex exactly on the open piece, which the piece then
      // goes through.
      std::vector<Crossing> crossings;
      int on = -1;
      if (!this->WalkCrossings(a, b, crossings, on))
      {
        return false;
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
      for (const Crossing& c : crossings)
      {
        if (this->Constrained.count(Undirected(c.X, c.Y)) > 0)
        {
          // Exact crossings make this impossible: it would be a bug in stage 2 or here.
          return this->Fail("two curve pieces cross between points " + std::to_string(a) + "-" +
            std::to_string(b) + " and " + std::to_string(c.X) + "-" + std::to_string(c.Y) +
            " (inconsistent local arrangement)");
        }
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

  /// Index of vertex a in triangle t, or -1.
  int CornerOf(int t, int a) const
  {
    const std::array<int, 3>& v = this->Tris[t];
    return v[0] == a ? 0 : (v[1] == a ? 1 : (v[2] == a ? 2 : -1));
  }

  /// Visits the alive triangles around vertex a (with a's index in each) until `visit` returns
  /// true: by turning around a through the half-edge map when the triangulation keeps one,
  /// else by scanning.
  template <class Visit>
  void AroundVertex(int a, Visit&& visit) const
  {
    int start = -1;
    if (this->UseMap && a < static_cast<int>(this->VertexTriangle.size()))
    {
      start = this->VertexTriangle[a];
      if (start >= 0 && (!this->Alive[start] || this->CornerOf(start, a) < 0))
      {
        start = -1;
      }
    }
    if (start < 0)
    {
      for (int t = 0; t < static_cast<int>(this->Tris.size()); ++t)
      {
        const int j = this->Alive[t] ? this->CornerOf(t, a) : -1;
        if (j >= 0 && visit(t, j))
        {
          return;
        }
      }
      return;
    }
    // Counter-clockwise from `start` (the triangle after (a, u, w) holds a -> w), then, if the
    // fan is open (a on the boundary), clockwise from it (the one before holds u -> a).
    const std::size_t limit = this->Tris.size();
    int t = start;
    for (std::size_t k = 0; k < limit; ++k)
    {
      const int j = this->CornerOf(t, a);
      if (visit(t, j))
      {
        return;
      }
      t = this->Find(a, this->Tris[t][(j + 2) % 3]);
      if (t < 0 || t == start)
      {
        break;
      }
    }
    if (t == start)
    {
      return;
    }
    t = start;
    for (std::size_t k = 0; k < limit; ++k)
    {
      const int j = this->CornerOf(t, a);
      t = this->Find(this->Tris[t][(j + 1) % 3], a);
      if (t < 0 || t == start || visit(t, this->CornerOf(t, a)))
      {
        return;
      }
    }
  }

  /// Edges crossed by the open segment (a, b), in order from a; X is the endpoint on the right
  /// of a -> b, Y the one on the left. If the open segment passes through a vertex, `on` is the
  /// first one from a (and the crossings before it are of no use).
  bool WalkCrossings(int a, int b, std::vector<Crossing>& crossings, int& on)
  {
    int x = -1, y = -1;
    on = -1;
    this->AroundVertex(a,
      [&](int t, int j)
      {
        const int u = this->Tris[t][(j + 1) % 3], w = this->Tris[t][(j + 2) % 3];
        const int ou = this->Orient(a, u, b), ow = this->Orient(a, w, b);
        if (ou > 0 && ow < 0)
        {
          x = u;
          y = w;
        }
        else if (ou == 0 && this->Between(a, b, u))
        {
          on = u;
        }
        else if (ow == 0 && this->Between(a, b, w))
        {
          on = w;
        }
        return x >= 0 || on >= 0;
      });
    if (on >= 0)
    {
      return true;
    }
    if (x < 0)
    {
      return this->Fail("a curve piece leaves its start point through no triangle");
    }
    for (size_t guard = 0; guard <= this->Tris.size(); ++guard)
    {
      crossings.push_back({ x, y });
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
      else if (this->Between(a, b, z))
      {
        on = z;
        return true;
      }
      else
      {
        return this->Fail("a curve piece passes a vertex beyond its end");
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

  LocalArrangement& Arr;
  /// Small triangulations (the vast majority) find half-edges by scanning, which beats
  /// maintaining a hash map; large ones keep the map.
  bool UseMap = false;
  /// Very large triangulations (thousands of points) also flip towards Delaunay after each
  /// point (FlipTowardsDelaunay); below that the flips cost more than the walks they shorten.
  bool Flip = false;
  std::vector<std::array<int, 3>>& Tris;
  std::vector<char>& Alive;
  EdgeIndex& HalfEdges;
  /// With the map: an alive triangle at each vertex, and the last triangle added (where the
  /// walk to the next point starts).
  std::vector<int> VertexTriangle;
  int LastAdded = -1;
  /// A square grid over the unit triangle's (u, v) coordinates: per cell, the last triangle
  /// added whose centroid is in it, where the walk to a point of that cell starts.
  std::vector<int> WalkStarts;
  std::vector<std::pair<int, int>> FlipStack; ///< edges FlipTowardsDelaunay has yet to look at
  int StartGridSize = 1;
  std::unordered_set<EdgeKey> Constrained;
  std::vector<std::vector<int>> Paths;
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
  tri.Tris.reserve(4 * n);
  tri.Alive.reserve(4 * n);
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
    for (int i = 0; i < n; ++i)
    {
      if (arr.Points[i].Where < 0)
      {
        if (!tri.InsertPoint(i))
        {
          return false;
        }
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
  return RefineOnce(arr);
}

} // namespace boolsurf

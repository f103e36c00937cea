#include "Winding/WindingLevelSet.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace boolsurf
{

namespace
{

constexpr int NoSide = -1;

/// A point of the level set as the segments meeting there name it, so that segments chain by
/// equal keys: refined point Lo (Hi = -1), or the threshold crossing on refined edge Lo < Hi.
/// Where both sides of the edge carry the same values the crossing is one point (Side =
/// NoSide); across a jump each side crosses at its own parameter (Side: that refined
/// triangle), even when the two parameters happen to coincide, so no point is met by more than
/// one segment in and one out there.
struct PointKey
{
  int Lo = -1, Hi = -1, Side = NoSide;
  bool operator==(const PointKey& o) const
  {
    return this->Lo == o.Lo && this->Hi == o.Hi && this->Side == o.Side;
  }
};

struct PointKeyHash
{
  std::size_t operator()(const PointKey& k) const
  {
    std::uint64_t h = 1469598103934665603ull;
    for (int v : { k.Lo, k.Hi, k.Side })
    {
      h = (h ^ static_cast<std::uint64_t>(static_cast<unsigned>(v))) * 1099511628211ull;
    }
    return static_cast<std::size_t>(h);
  }
};

/// Where a keyed point lies: the fraction S of the way from refined point Lo to Hi (Hi = -1:
/// refined point Lo itself), in mesh triangle Source.
struct KeyedPoint
{
  int Lo = -1, Hi = -1;
  double S = 0;
  int Source = -1;
};

/// A directed piece of the level set, with {w >= threshold} on its left.
struct Segment
{
  int From, To;
  int Triangle; ///< the refined triangle it comes from, for messages
};

/// The level set's segments, their end points interned as they are met (in triangle order, so
/// the loops do not depend on hashing).
class SegmentCollector
{
public:
  int Vertex(int p) { return this->Intern({ p, -1, NoSide }, { p, -1, 0.0, -1 }); }
  int Crossing(int lo, int hi, int side, double s, int source)
  {
    return this->Intern({ lo, hi, side }, { lo, hi, s, source });
  }
  void Add(int from, int to, int r) { this->Segments.push_back({ from, to, r }); }

  std::vector<Segment> Segments;
  std::vector<KeyedPoint> Points;

private:
  int Intern(const PointKey& key, const KeyedPoint& point)
  {
    const auto [it, added] = this->Ids.emplace(key, static_cast<int>(this->Points.size()));
    if (added)
    {
      this->Points.push_back(point);
    }
    return it->second;
  }
  std::unordered_map<PointKey, int, PointKeyHash> Ids;
};

/// A refined triangle with its corner values.
struct ValuedTriangle
{
  int R = -1;
  int Source = -1;
  Triangle Points{ -1, -1, -1 };
  std::array<double, 3> Values{ 0.0, 0.0, 0.0 };
};

ValuedTriangle ReadTriangle(const TriangleMesh& mesh,
  const Arrangement& arr,
  const LevelSetInput& input,
  int r)
{
  ValuedTriangle t;
  t.R = r;
  t.Source = arr.GetSourceTriangle(mesh, r);
  t.Points = arr.GetTriangle(mesh, r);
  for (int k = 0; k < 3; ++k)
  {
    t.Values[k] = input.CornerValue(r, k);
  }
  return t;
}

/// Parameter of the threshold crossing from lo to hi, computed from the values at the lower
/// refined point id to the higher whichever side asks, so that two triangles sharing an edge
/// with the same values get the same bits.
double CrossingParameter(double valueLo, double valueHi, double threshold)
{
  return (threshold - valueLo) / (valueHi - valueLo);
}

/// The local edges of mesh triangle t that canonical point c lies on, as bits.
unsigned MeshEdgesOf(const TriangleMesh& mesh, const CanonicalPoint& c, int t)
{
  const Triangle& tri = mesh.GetTriangle(t);
  unsigned bits = 0;
  for (int i = 0; i < 3; ++i)
  {
    if (c.Location == PointLocation::Vertex && tri[i] == c.Id)
    {
      bits |= (1u << i) | (1u << ((i + 2) % 3));
    }
    else if (c.Location == PointLocation::Edge && mesh.GetEdgeId(t, i) == c.Id)
    {
      bits |= 1u << i;
    }
  }
  return bits;
}

/// Local edge of mesh triangle t that the refined edge p-q (of a piece of t) runs along, -1
/// when it runs inside t.
int MeshEdgeAlong(const TriangleMesh& mesh, const Arrangement& arr, int t, int p, int q)
{
  const unsigned both =
    MeshEdgesOf(mesh, arr.GetPointOnMesh(p), t) & MeshEdgesOf(mesh, arr.GetPointOnMesh(q), t);
  for (int i = 0; i < 3; ++i)
  {
    if (both & (1u << i))
    {
      return i;
    }
  }
  return -1;
}

bool HasBoundaryEdge(const TriangleMesh& mesh, int t)
{
  return mesh.GetNeighbor(t, 0) < 0 || mesh.GetNeighbor(t, 1) < 0 || mesh.GetNeighbor(t, 2) < 0;
}

/// Whether local edge k of refined triangle `tri` lies on the open boundary of the mesh (or on
/// a non-manifold edge, which has no neighbour either: each side is then closed on its own).
bool OnMeshBoundary(const TriangleMesh& mesh,
  const Arrangement& arr,
  const ValuedTriangle& tri,
  int k)
{
  const int t = tri.Source;
  if (!HasBoundaryEdge(mesh, t))
  {
    return false;
  }
  // An unrefined triangle is its own single piece, with the mesh's corners.
  const int along = arr.GetRefinedSlot(t) < 0
    ? k
    : MeshEdgeAlong(mesh, arr, t, tri.Points[k], tri.Points[(k + 1) % 3]);
  return along >= 0 && mesh.GetNeighbor(t, along) < 0;
}

/// One side of a refined edge: its triangle's values at the edge's ends (lower refined point id
/// first) and whether the triangle walks the edge from lo to hi.
struct EdgeSide
{
  int Triangle = -1;
  double ValueLo = 0, ValueHi = 0;
  bool Forward = true;
};

EdgeSide SideOf(const ValuedTriangle& tri, int k)
{
  const int p = tri.Points[k], q = tri.Points[(k + 1) % 3];
  EdgeSide side;
  side.Triangle = tri.R;
  side.Forward = p < q;
  side.ValueLo = side.Forward ? tri.Values[k] : tri.Values[(k + 1) % 3];
  side.ValueHi = side.Forward ? tri.Values[(k + 1) % 3] : tri.Values[k];
  return side;
}

/// The point where `side` crosses the threshold on refined edge lo-hi.
int CrossingOn(SegmentCollector& out,
  int lo,
  int hi,
  const EdgeSide& side,
  bool jump,
  int source,
  double threshold)
{
  return out.Crossing(lo,
    hi,
    jump ? side.Triangle : NoSide,
    CrossingParameter(side.ValueLo, side.ValueHi, threshold),
    source);
}

/// The segments along refined edge lo-hi between one side (the mesh boundary: `count` 1) or two
/// sides (a jump: `count` 2): the parts where exactly one side is above, walked in that side's
/// direction so that its region is on the left. Each side is above on one end of the edge up
/// to its crossing; breakpoints are taken in parameter order, ties side 0 first (the piece
/// between two equal parameters has no length and is dropped with the duplicate points).
void AddEdgeSegments(SegmentCollector& out,
  int lo,
  int hi,
  const EdgeSide* sides,
  int count,
  int source,
  double threshold)
{
  struct Breakpoint
  {
    double S;
    int Side;
    int Point;
  };
  std::array<Breakpoint, 2> breaks;
  int numberOfBreaks = 0;
  std::array<bool, 2> above{ false, false };
  for (int i = 0; i < count; ++i)
  {
    const EdgeSide& side = sides[i];
    above[i] = side.ValueLo >= threshold;
    if (above[i] != (side.ValueHi >= threshold))
    {
      breaks[numberOfBreaks++] = { CrossingParameter(side.ValueLo, side.ValueHi, threshold),
        i,
        CrossingOn(out, lo, hi, side, count == 2, source, threshold) };
    }
  }
  if (numberOfBreaks == 2 && breaks[1].S < breaks[0].S)
  {
    std::swap(breaks[0], breaks[1]);
  }
  int from = -1; // interned on first use: an edge with no segment adds no point
  auto addPiece = [&](int to)
  {
    if (above[0] == above[1])
    {
      return;
    }
    const EdgeSide& owner = sides[above[0] ? 0 : 1];
    if (from < 0)
    {
      from = out.Vertex(lo);
    }
    if (owner.Forward)
    {
      out.Add(from, to, owner.Triangle);
    }
    else
    {
      out.Add(to, from, owner.Triangle);
    }
  };
  for (int b = 0; b < numberOfBreaks; ++b)
  {
    addPiece(breaks[b].Point);
    above[breaks[b].Side] = !above[breaks[b].Side];
    from = breaks[b].Point;
  }
  if (above[0] != above[1]) // not interning hi for nothing
  {
    addPiece(out.Vertex(hi));
  }
}

/// Directed refined edges of the jump triangles: (p, q) -> 3 * slot + local edge.
using JumpEdgeMap = std::unordered_map<std::uint64_t, int>;

std::uint64_t DirectedKey(int p, int q)
{
  return (static_cast<std::uint64_t>(static_cast<unsigned>(p)) << 32) | static_cast<unsigned>(q);
}

/// The segments that refined triangle `tri` contributes: its iso segment, its part of the
/// boundary, and the jumps across its edges to jump triangles of higher id (each jump edge is
/// walked once). `jumpSlot`: its index among the jump triangles, -1 when it is not one.
void AddTriangleSegments(const TriangleMesh& mesh,
  const Arrangement& arr,
  const ValuedTriangle& tri,
  int jumpSlot,
  const std::vector<ValuedTriangle>& jumpTriangles,
  const JumpEdgeMap& jumpEdges,
  double threshold,
  SegmentCollector& out)
{
  std::array<bool, 3> boundary{ false, false, false };
  // The jump triangle across each edge where the values jump, and that edge's index in it.
  std::array<const ValuedTriangle*, 3> across{ nullptr, nullptr, nullptr };
  std::array<int, 3> acrossEdge{ -1, -1, -1 };
  for (int k = 0; k < 3; ++k)
  {
    boundary[k] = OnMeshBoundary(mesh, arr, tri, k);
    if (jumpSlot < 0 || boundary[k])
    {
      continue; // no jump: neighbours outside the list agree with it
    }
    const int p = tri.Points[k], q = tri.Points[(k + 1) % 3];
    const auto found = jumpEdges.find(DirectedKey(q, p));
    if (found == jumpEdges.end())
    {
      continue;
    }
    const ValuedTriangle& other = jumpTriangles[found->second / 3];
    const int kn = found->second % 3; // walks q -> p
    if (other.Values[kn] != tri.Values[(k + 1) % 3] || other.Values[(kn + 1) % 3] != tri.Values[k])
    {
      across[k] = &other;
      acrossEdge[k] = kn;
    }
  }

  std::array<bool, 3> above;
  for (int k = 0; k < 3; ++k)
  {
    above[k] = tri.Values[k] >= threshold;
  }
  auto crossingOnEdge = [&](int k)
  {
    const int p = tri.Points[k], q = tri.Points[(k + 1) % 3];
    return CrossingOn(out,
      std::min(p, q),
      std::max(p, q),
      SideOf(tri, k),
      across[k] != nullptr,
      tri.Source,
      threshold);
  };
  // Walking the corners counter-clockwise, the region leaves the triangle's border on one edge
  // and comes back on another: the iso segment closes it from the leaving point to the
  // returning one, with the region on its left.
  int leaving = -1, returning = -1;
  for (int k = 0; k < 3; ++k)
  {
    if (above[k] && !above[(k + 1) % 3])
    {
      leaving = k;
    }
    else if (!above[k] && above[(k + 1) % 3])
    {
      returning = k;
    }
  }
  if (leaving >= 0)
  {
    out.Add(crossingOnEdge(leaving), crossingOnEdge(returning), tri.R);
  }

  for (int k = 0; k < 3; ++k)
  {
    const int p = tri.Points[k], q = tri.Points[(k + 1) % 3];
    const int lo = std::min(p, q), hi = std::max(p, q);
    if (boundary[k] && (above[k] || above[(k + 1) % 3]))
    {
      const EdgeSide side = SideOf(tri, k);
      AddEdgeSegments(out, lo, hi, &side, 1, tri.Source, threshold);
    }
    else if (across[k] && tri.R < across[k]->R)
    {
      const std::array<EdgeSide, 2> sides{ SideOf(tri, k), SideOf(*across[k], acrossEdge[k]) };
      AddEdgeSegments(out, lo, hi, sides.data(), 2, tri.Source, threshold);
    }
  }
}

/// The mesh edge that canonical points a and b (on the border of mesh triangle t) both lie on,
/// -1 when none does.
int CommonMeshEdge(const TriangleMesh& mesh,
  const CanonicalPoint& a,
  const CanonicalPoint& b,
  int t)
{
  const unsigned both = MeshEdgesOf(mesh, a, t) & MeshEdgesOf(mesh, b, t);
  for (int i = 0; i < 3; ++i)
  {
    if (both & (1u << i))
    {
      return mesh.GetEdgeId(t, i);
    }
  }
  return -1;
}

/// Parameter along mesh edge e (its canonical direction) of a point on it.
double ParameterOnEdge(const TriangleMesh& mesh, const CanonicalPoint& c, int e)
{
  if (c.Location == PointLocation::Edge)
  {
    return c.T;
  }
  return mesh.GetEdgeVertices(e)[0] == c.Id ? 0.0 : 1.0;
}

/// Canonical form of a keyed point: a refined point is read from the arrangement; a crossing
/// interpolates its edge's ends, along the mesh edge the refined edge runs on (so both mesh
/// triangles of that edge give the same point), else by barycentrics in its mesh triangle.
CanonicalPoint ToCanonical(const TriangleMesh& mesh, const Arrangement& arr, const KeyedPoint& k)
{
  if (k.Hi < 0 || k.S <= 0.0)
  {
    return arr.GetPointOnMesh(k.Lo);
  }
  if (k.S >= 1.0)
  {
    return arr.GetPointOnMesh(k.Hi);
  }
  const CanonicalPoint a = arr.GetPointOnMesh(k.Lo), b = arr.GetPointOnMesh(k.Hi);
  const int e = CommonMeshEdge(mesh, a, b, k.Source);
  if (e >= 0)
  {
    const double ta = ParameterOnEdge(mesh, a, e), tb = ParameterOnEdge(mesh, b, e);
    const double t = (1.0 - k.S) * ta + k.S * tb;
    CanonicalPoint c;
    if (t <= 0.0 || t >= 1.0)
    {
      c.Location = PointLocation::Vertex;
      c.Id = mesh.GetEdgeVertices(e)[t <= 0.0 ? 0 : 1];
      return c;
    }
    c.Location = PointLocation::Edge;
    c.Id = e;
    c.T = t;
    return c;
  }
  const std::array<double, 3> wa = WeightsInTriangle(mesh, a, k.Source);
  const std::array<double, 3> wb = WeightsInTriangle(mesh, b, k.Source);
  SurfacePoint p;
  p.Triangle = k.Source;
  p.U = (1.0 - k.S) * wa[1] + k.S * wb[1];
  p.V = (1.0 - k.S) * wa[2] + k.S * wb[2];
  return Canonicalize(mesh, p, SurfacePointSnap);
}

/// Chains the segments into closed loops of point ids. Every point must have as many segments
/// in as out; where several leave one point (corner values equal to the threshold, regions
/// touching at a refined point) they are taken in the order they were added.
bool ChainSegments(const SegmentCollector& in,
  std::vector<std::vector<int>>& loops,
  std::string& error)
{
  const int numberOfPoints = static_cast<int>(in.Points.size());
  std::vector<int> outStart(numberOfPoints + 1, 0), balance(numberOfPoints, 0);
  for (const Segment& s : in.Segments)
  {
    ++outStart[s.From + 1];
    ++balance[s.From];
    --balance[s.To];
  }
  for (const Segment& s : in.Segments)
  {
    if (balance[s.From] != 0)
    {
      error = "the level set does not close at a point of refined triangle " +
        std::to_string(s.Triangle) +
        " (the corner values of neighbouring triangles differ across an edge where no jump is "
        "listed?)";
      return false;
    }
  }
  for (int p = 0; p < numberOfPoints; ++p)
  {
    outStart[p + 1] += outStart[p];
  }
  std::vector<int> cursor(outStart.begin(), outStart.end() - 1);
  std::vector<int> leaving(in.Segments.size());
  for (int i = 0; i < static_cast<int>(in.Segments.size()); ++i)
  {
    leaving[cursor[in.Segments[i].From]++] = i;
  }
  cursor.assign(outStart.begin(), outStart.end() - 1);
  std::vector<char> used(in.Segments.size(), 0);
  for (int i = 0; i < static_cast<int>(in.Segments.size()); ++i)
  {
    if (used[i])
    {
      continue;
    }
    std::vector<int> loop;
    const int start = in.Segments[i].From;
    int s = i;
    while (true)
    {
      used[s] = 1;
      loop.push_back(in.Segments[s].From);
      const int at = in.Segments[s].To;
      if (at == start)
      {
        break;
      }
      while (cursor[at] < outStart[at + 1] && used[leaving[cursor[at]]])
      {
        ++cursor[at];
      }
      // Balanced points always have a way out: every arrival has its own departure.
      s = leaving[cursor[at]];
    }
    loops.push_back(std::move(loop));
  }
  return true;
}

/// The loop of keyed points as a level-set loop: canonical points without consecutive
/// repeats or spikes (a point that the loop leaves and comes straight back to, which only
/// values equal to the threshold produce: a region of no width), their written form, and the
/// length. False when it collapses to fewer than three points (a region reduced to a point or
/// a segment).
bool MakeLoop(const TriangleMesh& mesh,
  const Arrangement& arr,
  const std::vector<KeyedPoint>& points,
  const std::vector<int>& ids,
  LevelSetLoop& loop)
{
  std::vector<CanonicalPoint>& out = loop.Points;
  for (int id : ids)
  {
    const CanonicalPoint c = ToCanonical(mesh, arr, points[id]);
    if (!out.empty() && out.back() == c)
    {
      continue;
    }
    if (out.size() >= 2 && out[out.size() - 2] == c)
    {
      out.pop_back(); // a -> b -> a: back at a
      continue;
    }
    out.push_back(c);
  }
  // The same where the loop closes: its last points lead back to its first ones.
  while (out.size() >= 2)
  {
    const std::size_t n = out.size();
    if (out[n - 1] == out[0])
    {
      out.pop_back();
    }
    else if (n >= 3 && out[n - 2] == out[0])
    {
      out.pop_back(); // ..., a, b | a, ...
    }
    else if (n >= 3 && out[n - 1] == out[1])
    {
      out.erase(out.begin()); // ..., b | a, b, ...
    }
    else
    {
      break;
    }
  }
  const int n = static_cast<int>(loop.Points.size());
  if (n < 3)
  {
    return false;
  }
  loop.SurfacePoints.resize(n);
  loop.Length = 0;
  for (int i = 0; i < n; ++i)
  {
    const CanonicalPoint& a = loop.Points[i];
    const CanonicalPoint& b = loop.Points[(i + 1) % n];
    loop.SurfacePoints[i] = WriteSurfacePoint(mesh, a, SharedTriangle(mesh, a, b));
    loop.Length += Length(PositionOf(mesh, b) - PositionOf(mesh, a));
  }
  return true;
}

std::string NameTriangle(const Arrangement& arr, const TriangleMesh& mesh, int r)
{
  return "refined triangle " + std::to_string(r) + " (in mesh triangle " +
    std::to_string(arr.GetSourceTriangle(mesh, r)) + ")";
}

} // namespace

//------------------------------------------------------------------------------
bool ExtractLevelSet(const TriangleMesh& mesh,
  const Arrangement& arr,
  const LevelSetInput& input,
  std::vector<LevelSetLoop>& loops,
  std::string& error)
{
  loops.clear();
  const double threshold = input.Threshold;
  if (!std::isfinite(threshold))
  {
    error = "the level set's threshold is not finite";
    return false;
  }
  if (!input.CornerValue)
  {
    error = "the level set has no corner values";
    return false;
  }

  // One pass over the refined surface: the triangles the level set crosses, and those with a
  // corner above on the mesh's boundary, which the boundary may close. Everything else is
  // entirely above or below, with neighbours that agree, so it contributes nothing.
  const int numberOfTriangles = arr.GetNumberOfTriangles();
  std::vector<int> candidates;
  for (int r = 0; r < numberOfTriangles; ++r)
  {
    const int source = arr.GetSourceTriangle(mesh, r);
    if (source < 0)
    {
      continue; // a hole
    }
    int numberAbove = 0;
    for (int k = 0; k < 3; ++k)
    {
      const double v = input.CornerValue(r, k);
      if (!std::isfinite(v))
      {
        error = "the level set's value at corner " + std::to_string(k) + " of " +
          NameTriangle(arr, mesh, r) + " is not finite";
        return false;
      }
      numberAbove += v >= threshold ? 1 : 0;
    }
    if ((numberAbove > 0 && numberAbove < 3) || (numberAbove > 0 && HasBoundaryEdge(mesh, source)))
    {
      candidates.push_back(r);
    }
  }

  // The jump triangles, and their directed edges: a jump across an edge needs both sides to be
  // listed, so only their own edges are hashed.
  std::vector<int> jumpIds;
  if (input.JumpTriangles)
  {
    for (int r : *input.JumpTriangles)
    {
      if (r >= 0 && r < numberOfTriangles && arr.GetSourceTriangle(mesh, r) >= 0)
      {
        jumpIds.push_back(r);
      }
    }
    std::sort(jumpIds.begin(), jumpIds.end());
    jumpIds.erase(std::unique(jumpIds.begin(), jumpIds.end()), jumpIds.end());
  }
  std::vector<ValuedTriangle> jumpTriangles;
  jumpTriangles.reserve(jumpIds.size());
  JumpEdgeMap jumpEdges;
  jumpEdges.reserve(3 * jumpIds.size());
  for (int r : jumpIds)
  {
    const int slot = static_cast<int>(jumpTriangles.size());
    jumpTriangles.push_back(ReadTriangle(mesh, arr, input, r));
    const Triangle& t = jumpTriangles.back().Points;
    for (int k = 0; k < 3; ++k)
    {
      jumpEdges.emplace(DirectedKey(t[k], t[(k + 1) % 3]), 3 * slot + k);
    }
  }

  // Candidates and jump triangles together, ascending, so the segments come in triangle order.
  SegmentCollector segments;
  std::size_t c = 0, j = 0;
  while (c < candidates.size() || j < jumpIds.size())
  {
    const bool fromJump =
      j < jumpIds.size() && (c == candidates.size() || jumpIds[j] <= candidates[c]);
    const int r = fromJump ? jumpIds[j] : candidates[c];
    if (c < candidates.size() && candidates[c] == r)
    {
      ++c;
    }
    int slot = -1;
    if (fromJump)
    {
      slot = static_cast<int>(j++);
    }
    const ValuedTriangle tri = slot >= 0 ? jumpTriangles[slot] : ReadTriangle(mesh, arr, input, r);
    AddTriangleSegments(mesh, arr, tri, slot, jumpTriangles, jumpEdges, threshold, segments);
  }

  std::vector<std::vector<int>> chained;
  if (!ChainSegments(segments, chained, error))
  {
    return false;
  }
  for (const std::vector<int>& ids : chained)
  {
    LevelSetLoop loop;
    if (MakeLoop(mesh, arr, segments.Points, ids, loop))
    {
      loops.push_back(std::move(loop));
    }
  }
  return true;
}

} // namespace boolsurf

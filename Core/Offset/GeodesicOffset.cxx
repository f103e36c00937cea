#include "Offset/GeodesicOffset.h"

#include "Geodesic/ExactGeodesicSearch.h"
#include "Geodesic/StraightestGeodesic.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <unordered_map>
#include <unordered_set>

namespace boolsurf
{
namespace
{
constexpr double Infinity = std::numeric_limits<double>::infinity();
constexpr double Pi = 3.14159265358979323846;

// Contour points stay this far (in edge parameter) from the edge's ends, well above the
// tolerance that would read them as the vertex (SurfacePointSnap), so every contour point lies
// strictly inside its edge and is shared by exactly the edge's triangles.
constexpr double EdgeMargin = 1e-9;

using Clock = std::chrono::steady_clock;
double Milliseconds(Clock::time_point from, Clock::time_point to)
{
  return std::chrono::duration<double, std::milli>(to - from).count();
}

std::string BudgetMessage(int windows)
{
  return "the band within the distance is too large for the distance computation (over " +
    std::to_string(windows) + " windows): use a smaller distance";
}

// A flat end: the geodesic normal to the curve at its end point, walked straightest from the
// end point to both sides (on a flat mesh the straight line through it normal to the last
// piece), and per piece of it the unit direction leaving the curve. Points within Reach of the
// end point on the far side of the normal are beyond the end.
struct EndCap
{
  Vec3 Point;
  double Reach = 0.0;
  std::vector<Vec3> Normal; // from one side of the curve to the other
  std::vector<Vec3> Beyond; // per piece of Normal
};

// How far x lies beyond the end (negative: on the curve's side), measured from the nearest
// piece of the normal.
double BeyondEnd(const EndCap& cap, const Vec3& x)
{
  double nearest = Infinity, beyond = 0.0;
  for (size_t j = 0; j + 1 < cap.Normal.size(); ++j)
  {
    const double distance = SegmentPointDistance(cap.Normal[j], cap.Normal[j + 1], x);
    if (distance < nearest)
    {
      nearest = distance;
      beyond = Dot(x - cap.Normal[j], cap.Beyond[j]);
    }
  }
  return beyond;
}

// The cap at `end`, whose neighbour on the curve is `next`. False when the end piece has no
// direction.
bool MakeEndCap(const TriangleMesh& mesh,
  const CanonicalPoint& end,
  const CanonicalPoint& next,
  double distance,
  EndCap& cap)
{
  const int t = SharedTriangle(mesh, end, next);
  const Vec3 a = PositionOf(mesh, end);
  const Vec3 along = a - PositionOf(mesh, next);
  if (t < 0 || !(Length(along) > 0.0))
  {
    return false;
  }
  const Vec3 outward = (1.0 / Length(along)) * along;
  const Vec3 side = Cross(TriangleNormal(mesh, t), outward);
  if (!(Length(side) > 0.0))
  {
    return false;
  }
  cap.Point = a;
  cap.Reach = 1.05 * distance;
  // Samples of the normal every eighth of its half length, each walked from the end point (a
  // walk returns its end only); the half length covers every point within Reach.
  constexpr int Samples = 8;
  const double half = 1.25 * distance;
  const std::array<double, 3> w = WeightsInTriangle(mesh, end, t);
  SurfacePoint start;
  start.Triangle = t;
  start.U = w[1];
  start.V = w[2];
  std::vector<Vec3> points[2];
  std::vector<int> triangles[2];
  for (int s = 0; s < 2; ++s)
  {
    const Vec3 direction = (s == 0 ? 1.0 : -1.0) * side;
    for (int i = 1; i <= Samples; ++i)
    {
      const StraightestWalk walk = WalkStraightest(mesh, start, direction, half * i / Samples);
      if (!(walk.Length > 0.0) || walk.End.Triangle < 0)
      {
        break;
      }
      points[s].push_back(mesh.Evaluate(walk.End.Triangle, walk.End.U, walk.End.V));
      triangles[s].push_back(walk.End.Triangle);
      if (walk.HitBoundary)
      {
        break;
      }
    }
  }
  // From the far end of side 1 through the end point to the far end of side 0 (direction +side).
  std::vector<int> pieceTriangle;
  for (size_t i = points[1].size(); i-- > 0;)
  {
    cap.Normal.push_back(points[1][i]);
    pieceTriangle.push_back(triangles[1][i]);
  }
  cap.Normal.push_back(a);
  for (size_t i = 0; i < points[0].size(); ++i)
  {
    pieceTriangle.push_back(triangles[0][i]);
    cap.Normal.push_back(points[0][i]);
  }
  for (size_t j = 0; j + 1 < cap.Normal.size(); ++j)
  {
    // Across the piece, in the plane of the triangle of its sample farther from the end point:
    // (+side) x normal is the outward direction at the end point.
    const Vec3 across =
      Cross(cap.Normal[j + 1] - cap.Normal[j], TriangleNormal(mesh, pieceTriangle[j]));
    cap.Beyond.push_back(Length(across) > 0.0 ? (1.0 / Length(across)) * across : outward);
  }
  if (cap.Beyond.empty())
  {
    cap.Normal = { a - half * side, a + half * side };
    cap.Beyond = { outward };
  }
  return true;
}

// The turn of an open curve at its interior point i, as the unfolded strip sees it: at a
// crossing of a mesh edge, the difference of the angles its pieces make with the edge; elsewhere
// the angle between the pieces.
double TurnAt(const TriangleMesh& mesh, const std::vector<CanonicalPoint>& curve, size_t i)
{
  const Vec3 x = PositionOf(mesh, curve[i]);
  const Vec3 in = x - PositionOf(mesh, curve[i - 1]), out = PositionOf(mesh, curve[i + 1]) - x;
  if (!(Length(in) > 0.0 && Length(out) > 0.0))
  {
    return 0.0;
  }
  auto angle = [](const Vec3& u, const Vec3& v)
  { return std::atan2(Length(Cross(u, v)), Dot(u, v)); };
  if (curve[i].Location == PointLocation::Edge)
  {
    const std::array<int, 2> ev = mesh.GetEdgeVertices(curve[i].Id);
    const Vec3 edge = mesh.GetPosition(ev[1]) - mesh.GetPosition(ev[0]);
    return std::abs(angle(in, edge) - angle(out, edge));
  }
  return angle(in, out);
}

// Where the distance to a flat-ended curve without its end stretch takes over: the first point
// (from `end`, stepping by `step`) at least `length` along the curve from it, or an earlier corner.
// -1 when the curve ends first.
int TrimmedEnd(const TriangleMesh& mesh,
  const std::vector<CanonicalPoint>& curve,
  int end,
  int step,
  double length)
{
  // Below ~3 degrees a turn counts as straight: cutting past it loses at most a sliver of
  // that angle by d^2 beyond the end (see ComputeGeodesicOffset's flat ends).
  constexpr double Corner = 0.05;
  const int n = static_cast<int>(curve.size());
  double along = 0.0;
  for (int i = end + step; i >= 0 && i < n; i += step)
  {
    along += Distance(PositionOf(mesh, curve[i]), PositionOf(mesh, curve[i - step]));
    const bool interior = i > 0 && i + 1 < n;
    if (!interior)
    {
      return -1;
    }
    if (along >= length || TurnAt(mesh, curve, static_cast<size_t>(i)) > Corner)
    {
      return i;
    }
  }
  return -1;
}

// A flat-ended open curve as two distances: Head, the curve without the stretch next to its
// last point, cut at its first point; Tail, the curve without the stretch next to its first
// point, cut at its last point. A curve too short or too straight for that is one Head cut at
// both ends.
struct FlatCurve
{
  std::vector<CanonicalPoint> Head, Tail;
  std::vector<int> HeadCaps, TailCaps; // into OffsetField::Caps
  std::vector<Vec3> Positions;         // of the whole curve, to group curves
  std::array<Vec3, 2> Ends;
};

// Whether an end of one curve comes within `gap` of the other (straight-line distance, a lower
// bound of the distance on the surface).
bool NearEnds(const FlatCurve& a, const FlatCurve& b, double gap)
{
  for (const FlatCurve* one : { &a, &b })
  {
    const FlatCurve& other = one == &a ? b : a;
    for (const Vec3& end : one->Ends)
    {
      for (size_t i = 0; i + 1 < other.Positions.size(); ++i)
      {
        if (SegmentPointDistance(other.Positions[i], other.Positions[i + 1], end) < gap)
        {
          return true;
        }
      }
    }
  }
  return false;
}

// The signed field F (distance inside negative) minus the offset distance, on the mesh.
class OffsetField
{
public:
  OffsetField(const TriangleMesh& mesh,
    const OffsetRegion& region,
    double distance,
    OffsetBuffers& buffers)
    : Mesh(mesh)
    , Region(region)
    , Level(distance)
    , Closed(buffers.Closed)
    , Open(buffers.Open)
    , Buffers(buffers)
  {
    // New marks for this run; the buffers are sized once per mesh.
    const size_t nv = mesh.GetNumberOfVertices(), nt = mesh.GetNumberOfTriangles();
    if (buffers.VertexStamp.size() != nv || buffers.TriangleStamp.size() != nt ||
      ++buffers.Stamp == 0)
    {
      buffers.VertexValue.assign(nv, 0.0);
      buffers.VertexInside.assign(nv, 0);
      buffers.VertexStamp.assign(nv, 0u);
      buffers.InsideStamp.assign(nv, 0u);
      buffers.TriangleStamp.assign(nt, 0u);
      buffers.Stamp = 1;
    }
  }

  bool Compute(const OffsetOptions& options, OffsetStatistics& stats, std::string& error)
  {
    const TriangleMesh& mesh = this->Mesh;
    const double d = std::abs(this->Level);
    this->HasClosed = !this->Region.Boundary.empty();
    this->HasOpen = this->Level > 0.0 && !this->Region.Bands.empty();
    // Values below the radius are exact; the contour only reads values near d.
    const double radius = d * (1.0 + 1e-3) + 1e-12;
    if (this->HasClosed)
    {
      for (const auto& loop : this->Region.Boundary)
      {
        stats.Sources += static_cast<int>(loop.size());
        for (const CanonicalPoint& p : loop)
        {
          if (p.Location == PointLocation::Edge)
          {
            this->Crossings[p.Id].push_back(p.T);
          }
          else if (p.Location == PointLocation::Vertex)
          {
            this->OnBoundary.insert(p.Id);
          }
        }
      }
      for (auto& entry : this->Crossings)
      {
        std::sort(entry.second.begin(), entry.second.end());
      }
      // The boundary's straight pieces in each triangle they pass (both of a mesh edge's
      // triangles for a piece along it), to tell the sides apart inside touched triangles.
      std::vector<int> fromTriangles, toTriangles;
      for (const auto& loop : this->Region.Boundary)
      {
        for (size_t i = 0; i < loop.size(); ++i)
        {
          const CanonicalPoint& p = loop[i];
          const CanonicalPoint& q = loop[(i + 1) % loop.size()];
          TrianglesOf(mesh, p, fromTriangles);
          TrianglesOf(mesh, q, toTriangles);
          for (int t : fromTriangles)
          {
            if (std::find(toTriangles.begin(), toTriangles.end(), t) != toTriangles.end())
            {
              this->BoundaryPieces[t].push_back({ PositionOf(mesh, p), PositionOf(mesh, q) });
            }
          }
        }
      }
      this->Closed.SetMaximumWindows(options.MaximumWindows);
      if (this->Region.TriangleSide)
      {
        const std::function<int(int)>& side = this->Region.TriangleSide;
        const int useless = this->Level > 0.0 ? 1 : -1;
        this->Closed.SetFieldTriangleFilter([&side, useless](int t) { return side(t) != useless; });
      }
      else
      {
        this->Closed.SetFieldTriangleFilter(nullptr);
      }
      const std::vector<char> loopsClosed(this->Region.Boundary.size(), 1);
      if (!this->Closed.ComputeDistanceField(this->Region.Boundary, loopsClosed, radius))
      {
        error = BudgetMessage(options.MaximumWindows);
        return false;
      }
      stats.Windows += this->Closed.GetLastWindowCount();
    }
    if (this->HasOpen)
    {
      std::vector<std::vector<CanonicalPoint>> curves;
      std::vector<char> curvesClosed;
      std::vector<FlatCurve> flat;
      for (const TracedCurve& band : this->Region.Bands)
      {
        const std::vector<CanonicalPoint>& curve = band.Points;
        if (curve.size() < 2)
        {
          continue;
        }
        stats.Sources += static_cast<int>(curve.size());
        if (options.Ends != OffsetEndStyle::Flat || band.Closed ||
          !this->AddFlatCurve(curve, d, flat))
        {
          curves.push_back(curve);
          curvesClosed.push_back(band.Closed ? 1 : 0);
        }
      }
      if (!curves.empty())
      {
        this->Open.SetMaximumWindows(options.MaximumWindows);
        if (!this->Open.ComputeDistanceField(curves, curvesClosed, radius))
        {
          error = BudgetMessage(options.MaximumWindows);
          return false;
        }
        stats.Windows += this->Open.GetLastWindowCount();
        this->BandFields.push_back({ &this->Open, {} });
      }
      if (!this->ComputeFlatFields(flat, options, radius, stats, error))
      {
        return false;
      }
    }
    return true;
  }

  /// Vertices either distance reached: the contour lies in their triangles.
  void ReachedVertices(std::vector<int>& out) const
  {
    out.clear();
    if (this->HasClosed)
    {
      out = this->Closed.GetFieldVertices();
    }
    for (const BandField& band : this->BandFields)
    {
      const std::vector<int>& more = band.Search->GetFieldVertices();
      out.insert(out.end(), more.begin(), more.end());
    }
  }

  /// F - d at mesh vertex v (never exactly 0, see Combine).
  double AtVertex(int v)
  {
    OffsetBuffers& b = this->Buffers;
    if (b.VertexStamp[v] == b.Stamp)
    {
      return b.VertexValue[v];
    }
    const double value = this->Combine(this->Mesh.GetPosition(v),
      this->HasClosed ? this->Closed.GetFieldDistanceAtVertex(v) : Infinity,
      this->HasClosed && this->Inside(v),
      [v](const ExactGeodesicSearch& search) { return search.GetFieldDistanceAtVertex(v); });
    b.VertexStamp[v] = b.Stamp;
    b.VertexValue[v] = value;
    return value;
  }

  /// True the first time triangle t is asked about in this run.
  bool FirstVisit(int t)
  {
    OffsetBuffers& b = this->Buffers;
    if (b.TriangleStamp[t] == b.Stamp)
    {
      return false;
    }
    b.TriangleStamp[t] = b.Stamp;
    return true;
  }

  /// F - d on mesh edge `edge` at parameter s from its canonical vertex 0.
  double OnEdge(int edge, double s)
  {
    const TriangleMesh& mesh = this->Mesh;
    const std::array<int, 2> ev = mesh.GetEdgeVertices(edge);
    const Vec3 x = (1.0 - s) * mesh.GetPosition(ev[0]) + s * mesh.GetPosition(ev[1]);
    bool inside = false;
    double closed = Infinity;
    if (this->HasClosed)
    {
      closed = this->Closed.GetFieldDistanceOnEdge(edge, s);
      // The side of the boundary: from a vertex off the boundary, flipped at each crossing
      // between it and s.
      const auto it = this->Crossings.find(edge);
      const std::vector<double>* crossings = it == this->Crossings.end() ? nullptr : &it->second;
      const bool fromStart = !this->OnBoundary.count(ev[0]) || this->OnBoundary.count(ev[1]);
      inside = this->Inside(fromStart ? ev[0] : ev[1]);
      if (crossings)
      {
        for (double c : *crossings)
        {
          if (fromStart ? c < s : c > s)
          {
            inside = !inside;
          }
        }
      }
    }
    return this->Combine(x,
      closed,
      inside,
      [edge, s](const ExactGeodesicSearch& search)
      { return search.GetFieldDistanceOnEdge(edge, s); });
  }

  /// F - d inside triangle `face` at weights w.
  double InTriangle(int face, const std::array<double, 3>& w)
  {
    const TriangleMesh& mesh = this->Mesh;
    const Triangle& tri = mesh.GetTriangle(face);
    const Vec3 x = w[0] * mesh.GetPosition(tri[0]) + w[1] * mesh.GetPosition(tri[1]) +
      w[2] * mesh.GetPosition(tri[2]);
    return this->Combine(x,
      this->HasClosed ? this->Closed.GetFieldDistanceInTriangle(face, w) : Infinity,
      this->HasClosed && this->InsideInTriangle(face, w, x),
      [face, &w](const ExactGeodesicSearch& search)
      { return search.GetFieldDistanceInTriangle(face, w); });
  }

private:
  // The side of the boundary at x (weights w) in triangle `face`: a corner's off the boundary,
  // flipped at each boundary piece the segment from that corner to x crosses. An inset thinner
  // than a triangle (|d| below the mesh size) has its corners in triangles the boundary passes
  // too. The corner is the one x is farthest from in weight: a segment from a corner to x near
  // one of its sides would run along that side, where the pieces end, and the crossings would
  // be decided by rounding.
  bool InsideInTriangle(int face, const std::array<double, 3>& w, const Vec3& x)
  {
    const TriangleMesh& mesh = this->Mesh;
    const Triangle& tri = mesh.GetTriangle(face);
    const auto it = this->BoundaryPieces.find(face);
    if (it == this->BoundaryPieces.end())
    {
      return this->Inside(tri[0]);
    }
    int k = -1;
    for (int j = 0; j < 3; ++j)
    {
      if (!this->OnBoundary.count(tri[j]) && (k < 0 || w[j] < w[k]))
      {
        k = j;
      }
    }
    if (k < 0)
    {
      // Every corner on the boundary: near the level set (the only place asked about) the
      // side is the level set's.
      return this->Level < 0.0;
    }
    const Vec3 from = mesh.GetPosition(tri[k]);
    const Vec3 normal = TriangleNormal(mesh, face);
    auto orient = [&normal](const Vec3& a, const Vec3& b, const Vec3& c)
    { return Dot(Cross(b - a, c - a), normal); };
    bool inside = this->Inside(tri[k]);
    for (const std::array<Vec3, 2>& piece : it->second)
    {
      const double s1 = orient(piece[0], piece[1], from), s2 = orient(piece[0], piece[1], x);
      const double s3 = orient(from, x, piece[0]), s4 = orient(from, x, piece[1]);
      if (((s1 < 0.0 && s2 > 0.0) || (s1 > 0.0 && s2 < 0.0)) &&
        ((s3 < 0.0 && s4 > 0.0) || (s3 > 0.0 && s4 < 0.0)))
      {
        inside = !inside;
      }
    }
    return inside;
  }

  bool Inside(int v)
  {
    OffsetBuffers& b = this->Buffers;
    if (b.InsideStamp[v] != b.Stamp)
    {
      b.InsideStamp[v] = b.Stamp;
      b.VertexInside[v] = this->Region.InsideVertex && this->Region.InsideVertex(v) ? 1 : 0;
    }
    return b.VertexInside[v] != 0;
  }

  // The distance to a flat-ended curve's stretch next to an end point and a fixed length of
  // the rest, which the other part of the curve's distance covers (FlatCurve), and the caps.
  bool AddFlatCurve(const std::vector<CanonicalPoint>& curve,
    double d,
    std::vector<FlatCurve>& flat)
  {
    const TriangleMesh& mesh = this->Mesh;
    const int n = static_cast<int>(curve.size());
    EndCap first, last;
    if (!MakeEndCap(mesh, curve[0], curve[1], d, first) ||
      !MakeEndCap(mesh, curve[n - 1], curve[n - 2], d, last))
    {
      return false;
    }
    FlatCurve c;
    for (const CanonicalPoint& p : curve)
    {
      c.Positions.push_back(PositionOf(mesh, p));
    }
    c.Ends = { first.Point, last.Point };
    // Past the first point's stretch (at least d long, unless a corner comes first) the curve's
    // band is not cut at the first point: a disk of radius d around its first point there stays on
    // this side of the first point's normal.
    const double stretch = 1.01 * d;
    const int head = TrimmedEnd(mesh, curve, n - 1, -1, stretch);
    const int tail = TrimmedEnd(mesh, curve, 0, 1, stretch);
    const int firstCap = static_cast<int>(this->Caps.size());
    this->Caps.push_back(std::move(first));
    this->Caps.push_back(std::move(last));
    // Head and tail must overlap (cover the curve between them): on a curve shorter than the
    // two stretches, a gap between them would pull the band's sides in at its middle.
    if (head < 0 || tail < 0 || head < tail)
    {
      c.Head = curve;
      c.HeadCaps = { firstCap, firstCap + 1 };
    }
    else
    {
      c.Head.assign(curve.begin(), curve.begin() + head + 1);
      c.Tail.assign(curve.begin() + tail, curve.end());
      c.HeadCaps = { firstCap };
      c.TailCaps = { firstCap + 1 };
    }
    flat.push_back(std::move(c));
    return true;
  }

  // The flat-ended curves in groups whose ends keep away from each other's curves (so the caps
  // of one curve's ends cut nothing near another's), two distances per group: the curves' heads
  // and their tails.
  bool ComputeFlatFields(const std::vector<FlatCurve>& flat,
    const OffsetOptions& options,
    double radius,
    OffsetStatistics& stats,
    std::string& error)
  {
    const double gap = 2.0 * 1.05 * std::abs(this->Level) * 1.01;
    std::vector<std::vector<int>> groups;
    for (size_t i = 0; i < flat.size(); ++i)
    {
      size_t g = 0;
      for (; g < groups.size(); ++g)
      {
        bool near = false;
        for (int j : groups[g])
        {
          near = near || NearEnds(flat[i], flat[j], gap);
        }
        if (!near)
        {
          break;
        }
      }
      if (g == groups.size())
      {
        groups.emplace_back();
      }
      groups[g].push_back(static_cast<int>(i));
    }
    std::vector<std::unique_ptr<ExactGeodesicSearch>>& searches = this->Buffers.Flat;
    for (const std::vector<int>& group : groups)
    {
      for (int part = 0; part < 2; ++part)
      {
        std::vector<std::vector<CanonicalPoint>> curves;
        std::vector<int> caps;
        for (int i : group)
        {
          const FlatCurve& c = flat[i];
          if (!(part == 0 ? c.Head : c.Tail).empty())
          {
            curves.push_back(part == 0 ? c.Head : c.Tail);
            const std::vector<int>& more = part == 0 ? c.HeadCaps : c.TailCaps;
            caps.insert(caps.end(), more.begin(), more.end());
          }
        }
        if (curves.empty())
        {
          continue;
        }
        const size_t used = this->BandFields.size();
        if (searches.size() <= used)
        {
          searches.push_back(std::make_unique<ExactGeodesicSearch>(this->Mesh));
        }
        ExactGeodesicSearch& search = *searches[used];
        search.SetMaximumWindows(options.MaximumWindows);
        if (!search.ComputeDistanceField(curves, std::vector<char>(curves.size(), 0), radius))
        {
          error = BudgetMessage(options.MaximumWindows);
          return false;
        }
        stats.Windows += search.GetLastWindowCount();
        this->BandFields.push_back({ &search, std::move(caps) });
      }
    }
    return true;
  }

  template <class DistanceOf>
  double Combine(const Vec3& x, double closedDistance, bool inside, DistanceOf distanceOf) const
  {
    double f = Infinity;
    if (this->HasClosed)
    {
      f = inside ? -closedDistance : closedDistance;
    }
    // Within rounding of the level on a flat end's line: the band's corner there is convex.
    const double tie = 1e-9 * std::abs(this->Level);
    bool convexTie = false;
    for (const BandField& band : this->BandFields)
    {
      const double distance = distanceOf(*band.Search);
      double value = distance, cut = -Infinity;
      // Flat ends: the band of this part of the curves minus what lies beyond their ends,
      // max(distance, d + beyond) near an end. The cut applies within Reach of the end point,
      // not only inside the band: the sign is the same either way, but the contour also reads
      // the field's size (a tip's two crossings of an edge lie around the field's minimum along
      // it, convex near a corner; a corner is where the fronts' tangents meet). Uncut, the field
      // beyond an end's line just outside the disk of radius d around the end point would be
      // the distance, barely above d, where the band's field is d plus the distance beyond the
      // line: a false minimum next to each of the end's corners, by which a search along an
      // edge missed the tip's crossings and its corner was cut by a chord. The cut is at most d
      // plus what is left to Reach, so it gives way to the distance toward Reach: the field is
      // continuous there too.
      for (int c : band.Caps)
      {
        const EndCap& cap = this->Caps[c];
        const double fromEnd = Distance(x, cap.Point);
        if (fromEnd <= cap.Reach)
        {
          cut = std::max(cut, this->Level + std::min(BeyondEnd(cap, x), cap.Reach - fromEnd));
        }
      }
      value = std::max(value, cut);
      convexTie =
        convexTie || (std::abs(value - this->Level) <= tie && std::abs(cut - this->Level) <= tie);
      f = std::min(f, value);
    }
    // A point on the level set (to rounding) goes to the side whose sharp corners meet there:
    // the region's when shrinking (an inset's corners are convex) or at a flat end's line (the
    // end's corners are), its complement's when growing (a margin's sharp corners are concave).
    // The contour then keeps the corner's tip.
    const double value = f - this->Level;
    if (std::abs(value) <= tie)
    {
      const double tiny = std::numeric_limits<double>::min();
      return this->Level < 0.0 || convexTie ? -tiny : tiny;
    }
    return value;
  }

  struct BandField
  {
    ExactGeodesicSearch* Search;
    std::vector<int> Caps; // cut from this distance's band (into Caps)
  };

  const TriangleMesh& Mesh;
  const OffsetRegion& Region;
  const double Level;
  ExactGeodesicSearch& Closed;
  ExactGeodesicSearch& Open;
  bool HasClosed = false, HasOpen = false;
  std::unordered_map<int, std::vector<double>> Crossings; // edge -> boundary parameters
  std::unordered_set<int> OnBoundary;                     // vertices on the boundary
  // Triangle -> the boundary's straight pieces in it (end positions).
  std::unordered_map<int, std::vector<std::array<Vec3, 2>>> BoundaryPieces;
  std::vector<EndCap> Caps;
  std::vector<BandField> BandFields;
  OffsetBuffers& Buffers;
};

bool DoubleCrossing(OffsetField& field, int edge, double sign, CanonicalPoint crossing[2]);

// The contour F = d: points on edges, one directed piece per crossed triangle (two where the
// level set crosses the triangle's edge opposite its odd corner twice), chained.
class Contour
{
public:
  Contour(const TriangleMesh& mesh, OffsetField& field)
    : Mesh(mesh)
    , Field(field)
  {
  }

  void Build(const std::vector<int>& reached)
  {
    const TriangleMesh& mesh = this->Mesh;
    for (int v : reached)
    {
      for (int corner : mesh.GetVertexCorners(v))
      {
        const int t = corner / 3;
        if (mesh.IsUsable(t) && this->Field.FirstVisit(t))
        {
          this->AddTriangle(t);
        }
      }
    }
  }

  /// Closed chains as lists of pieces; chains that end on the surface's boundary in `open`.
  int GetNumberOfCrossedTriangles() const { return static_cast<int>(this->Pieces.size()); }

  struct Piece
  {
    int Triangle;
    int From, To; // contour point ids
  };
  std::vector<CanonicalPoint> Points;
  std::vector<Piece> Pieces;
  std::vector<int> PieceFrom; // contour point -> piece starting there, -1 none
  std::vector<int> PieceTo;   // contour point -> piece ending there, -1 none
  std::vector<char> Twice;    // contour point -> on an edge the level set crosses twice

private:
  int AddPoint(const CanonicalPoint& p, bool twice)
  {
    const int id = static_cast<int>(this->Points.size());
    this->Points.push_back(p);
    this->PieceFrom.push_back(-1);
    this->PieceTo.push_back(-1);
    this->Twice.push_back(twice ? 1 : 0);
    return id;
  }

  // Where the odd corners of both triangles of `edge` (t's and its neighbour's, opposite it)
  // lie on one side of the level set and the edge's ends on the other, the region of the odd
  // corners' side may still cross the edge: a sharp corner or a neck thinner than the mesh
  // (a flat end's corner on an irregular mesh), which the vertices' signs alone would split
  // into two loops, its tip dropped as a sliver. The level set then crosses the edge twice:
  // the two crossings (in the order of the edge), found on the exact field along it.
  bool CrossedTwice(int t, int edge, bool oddNegative, std::array<int, 2>& crossings)
  {
    const auto it = this->TwiceAt.find(edge);
    if (it != this->TwiceAt.end())
    {
      crossings = it->second;
      return crossings[0] >= 0;
    }
    const TriangleMesh& mesh = this->Mesh;
    crossings = { -1, -1 };
    int beyond = -1;
    for (int j = 0; j < 3; ++j)
    {
      if (mesh.GetEdgeId(t, j) == edge)
      {
        beyond = mesh.GetNeighbor(t, j);
      }
    }
    if (beyond >= 0)
    {
      const std::array<int, 2> ev = mesh.GetEdgeVertices(edge);
      const Triangle& other = mesh.GetTriangle(beyond);
      int odd = -1;
      for (int j = 0; j < 3; ++j)
      {
        if (other[j] != ev[0] && other[j] != ev[1])
        {
          odd = other[j];
        }
      }
      CanonicalPoint crossing[2];
      if (odd >= 0 && (this->Field.AtVertex(odd) < 0.0) == oddNegative &&
        DoubleCrossing(this->Field, edge, oddNegative ? 1.0 : -1.0, crossing))
      {
        crossings = { this->AddPoint(crossing[0], true), this->AddPoint(crossing[1], true) };
      }
    }
    this->TwiceAt.emplace(edge, crossings);
    return crossings[0] >= 0;
  }

  int PointOnEdge(int edge)
  {
    const auto it = this->EdgePoint.find(edge);
    if (it != this->EdgePoint.end())
    {
      return it->second;
    }
    const std::array<int, 2> ev = this->Mesh.GetEdgeVertices(edge);
    double lo = 0.0, hi = 1.0;
    const bool startInside = this->Field.AtVertex(ev[0]) < 0.0;
    for (int i = 0; i < 60 && hi - lo > 1e-15; ++i)
    {
      const double mid = 0.5 * (lo + hi);
      if ((this->Field.OnEdge(edge, mid) < 0.0) == startInside)
      {
        lo = mid;
      }
      else
      {
        hi = mid;
      }
    }
    CanonicalPoint p;
    p.Location = PointLocation::Edge;
    p.Id = edge;
    p.T = std::min(1.0 - EdgeMargin, std::max(EdgeMargin, 0.5 * (lo + hi)));
    const int id = this->AddPoint(p, false);
    this->EdgePoint.emplace(edge, id);
    return id;
  }

  void AddTriangle(int t)
  {
    const TriangleMesh& mesh = this->Mesh;
    const Triangle& tri = mesh.GetTriangle(t);
    bool negative[3];
    int count = 0;
    for (int k = 0; k < 3; ++k)
    {
      negative[k] = this->Field.AtVertex(tri[k]) < 0.0;
      count += negative[k] ? 1 : 0;
    }
    if (count == 0 || count == 3)
    {
      return;
    }
    // The odd corner k (alone on its side). Local edge k joins corners k and k+1.
    int k = 0;
    while (negative[k] != (count == 1))
    {
      ++k;
    }
    // One corner inside: from edge (k, k+1) to edge (k+2, k) keeps it on the left; one
    // corner outside: the other way round.
    int fromEdge = mesh.GetEdgeId(t, k), toEdge = mesh.GetEdgeId(t, (k + 2) % 3);
    if (count == 2)
    {
      std::swap(fromEdge, toEdge);
    }
    const int from = this->PointOnEdge(fromEdge), to = this->PointOnEdge(toEdge);
    const int opposite = mesh.GetEdgeId(t, (k + 1) % 3);
    std::array<int, 2> twice;
    if (this->CrossedTwice(t, opposite, negative[k], twice))
    {
      // Each piece ends at the crossing nearer the end of `opposite` its other point's edge
      // shares: the level set cuts that end's corner off.
      const std::array<int, 2> ev = mesh.GetEdgeVertices(opposite);
      const std::array<int, 2> fv = mesh.GetEdgeVertices(fromEdge);
      const int near = fv[0] == ev[0] || fv[1] == ev[0] ? 0 : 1;
      this->AddPiece(t, from, twice[near]);
      this->AddPiece(t, twice[1 - near], to);
      return;
    }
    this->AddPiece(t, from, to);
  }

  void AddPiece(int t, int from, int to)
  {
    const int id = static_cast<int>(this->Pieces.size());
    this->Pieces.push_back({ t, from, to });
    this->PieceFrom[from] = id;
    this->PieceTo[to] = id;
  }

  const TriangleMesh& Mesh;
  OffsetField& Field;
  std::unordered_map<int, int> EdgePoint;
  std::unordered_map<int, std::array<int, 2>> TwiceAt; // edge -> its two crossings, or -1s
};

// The point of triangle `t` with barycentric weights `w`, kept 1e-9 inside the triangle: a
// point found by bisection on the level set lies in the triangle's interior, never on an edge
// or a corner, whose canonical forms are the crossings'.
CanonicalPoint InteriorPoint(const TriangleMesh& mesh, int t, const std::array<double, 3>& w)
{
  SurfacePoint p;
  p.Triangle = t;
  p.U = std::max(w[1], 1e-9);
  p.V = std::max(w[2], 1e-9);
  if (p.U + p.V > 1.0 - 1e-9)
  {
    const double scale = (1.0 - 1e-9) / (p.U + p.V);
    p.U *= scale;
    p.V *= scale;
  }
  return LocateSurfacePoint(mesh, p);
}

// Points on the level set inside a crossed triangle between a piece's two end points, found by
// bisection along the chord's normal in the triangle's plane.
void RefinePiece(const TriangleMesh& mesh,
  OffsetField& field,
  int t,
  const CanonicalPoint& a,
  const CanonicalPoint& b,
  int count,
  std::vector<CanonicalPoint>& out)
{
  const Triangle& tri = mesh.GetTriangle(t);
  const Vec3 p0 = mesh.GetPosition(tri[0]), p1 = mesh.GetPosition(tri[1]),
             p2 = mesh.GetPosition(tri[2]);
  const Vec3 normal = Cross(p1 - p0, p2 - p0);
  const std::array<double, 3> wa = WeightsInTriangle(mesh, a, t);
  const std::array<double, 3> wb = WeightsInTriangle(mesh, b, t);
  const Vec3 xa = PositionOf(mesh, a), xb = PositionOf(mesh, b);
  const Vec3 left = Cross(normal, xb - xa); // the region's side
  const double leftLength = Length(left);
  if (!(leftLength > 0.0))
  {
    return;
  }
  // Not clamped: the step below leaves the triangle.
  const TrianglePlaneWeights weightsOf(p0, p1, p2);
  if (weightsOf.IsDegenerate())
  {
    return;
  }
  for (int i = 1; i <= count; ++i)
  {
    const double f = static_cast<double>(i) / (count + 1);
    std::array<double, 3> w{
      (1.0 - f) * wa[0] + f * wb[0], (1.0 - f) * wa[1] + f * wb[1], (1.0 - f) * wa[2] + f * wb[2]
    };
    const Vec3 m = w[0] * p0 + w[1] * p1 + w[2] * p2;
    const double fm = field.InTriangle(t, w);
    // Inside (negative) the level set lies to the right, outside to the left.
    const Vec3 dir = (fm < 0.0 ? -1.0 : 1.0) / leftLength * left;
    // How far the triangle extends from m along dir: the largest step keeping the weights >= 0.
    const std::array<double, 3> wd = weightsOf(m + dir);
    double reach = Infinity;
    for (int k = 0; k < 3; ++k)
    {
      const double rate = wd[k] - w[k];
      if (rate < 0.0)
      {
        reach = std::min(reach, -w[k] / rate);
      }
    }
    if (!(reach > 0.0) || reach == Infinity)
    {
      continue;
    }
    double lo = 0.0, hi = reach * (1.0 - 1e-6);
    std::array<double, 3> wHi = weightsOf(m + hi * dir);
    if ((field.InTriangle(t, wHi) < 0.0) == (fm < 0.0))
    {
      continue; // no sign change inside the triangle: keep the chord
    }
    for (int it = 0; it < 50; ++it)
    {
      const double mid = 0.5 * (lo + hi);
      if ((field.InTriangle(t, weightsOf(m + mid * dir)) < 0.0) == (fm < 0.0))
      {
        lo = mid;
      }
      else
      {
        hi = mid;
      }
    }
    out.push_back(InteriorPoint(mesh, t, weightsOf(m + (0.5 * (lo + hi)) * dir)));
  }
}

// Where the level set turns sharply inside a crossed triangle (shrinking past a convex corner,
// growing into a concave one: two fronts from different parts of the boundary meet), the chord
// between the piece's end points would cut the corner off. The corner is where the level set's
// tangents at the two end points meet; it is kept when the field there is much closer to the
// level than at the chord's middle (a round join's tangents meet outside it, and are not).
// `outside`, when given, tells whether the fronts turn sharply but their tangents meet outside
// the triangle: the tip may go on into the next one (TipAcrossEdge). A corner outside the
// triangle by less than `slack` (in barycentric weight) is kept, moved onto its side.
bool SharpCorner(const TriangleMesh& mesh,
  OffsetField& field,
  int t,
  const CanonicalPoint& a,
  const CanonicalPoint& b,
  CanonicalPoint& corner,
  bool* outside = nullptr,
  double slack = 1e-9)
{
  const Triangle& tri = mesh.GetTriangle(t);
  const Vec3 p0 = mesh.GetPosition(tri[0]), p1 = mesh.GetPosition(tri[1]),
             p2 = mesh.GetPosition(tri[2]);
  const TrianglePlaneWeights plane(p0, p1, p2);
  if (plane.IsDegenerate())
  {
    return false;
  }
  // Plane coordinates: x along p0 -> p1, y normal to it in the plane.
  const double l1 = Distance(p0, p1);
  const Vec3 ux = (1.0 / l1) * (p1 - p0);
  const Vec3 uy0 = (p2 - p0) - Dot(p2 - p0, ux) * ux;
  const Vec3 uy = (1.0 / Length(uy0)) * uy0;
  auto weightsOf = [&](double x, double y) { return plane(p0 + x * ux + y * uy); };
  auto value = [&](double x, double y) { return field.InTriangle(t, weightsOf(x, y)); };
  const Vec3 centroid = (1.0 / 3.0) * (p0 + p1 + p2);
  const double cx = Dot(centroid - p0, ux), cy = Dot(centroid - p0, uy);
  // Gradients sampled well within the front of each end point: a tip that barely enters the
  // triangle (end points much closer than the triangle's size) needs samples as close.
  const double chord = Distance(PositionOf(mesh, a), PositionOf(mesh, b));
  const double h = std::min(1e-4 * l1, 1e-2 * chord);
  Vec2 point[2], gradient[2];
  const CanonicalPoint* ends[2] = { &a, &b };
  for (int i = 0; i < 2; ++i)
  {
    const Vec3 x = PositionOf(mesh, *ends[i]);
    const double px = Dot(x - p0, ux), py = Dot(x - p0, uy);
    point[i] = { px, py };
    // Just inside the triangle from the end point.
    const double toCentroid = std::hypot(cx - px, cy - py);
    const double inward = toCentroid > 0.0 ? std::min(1e-2, 0.1 * chord / toCentroid) : 0.0;
    // A corner closer to the end point than the sample (a tip just across the triangle's side
    // from where the other front leaves it) puts the sample, or part of its stencil, on the other
    // front, whose tangent misses the end point: the corner would land on the wrong line. The
    // sample's front must pass through the end point (its linear extrapolation there is the end
    // point's value to within a thousandth of the step; a round join's curvature stays well
    // within that), else samples ten times closer are tried, down to ~1e-5 of the triangle's
    // size, where a tip still cut is negligible and rounding (~1e-9 of it) starts to matter.
    const double atEnd = value(px, py);
    for (double fraction = inward;; fraction *= 0.1)
    {
      const double distance = fraction * toCentroid;
      const double step = std::min(h, 0.5 * distance);
      const double sx = px + fraction * (cx - px), sy = py + fraction * (cy - py);
      const double f = value(sx, sy);
      gradient[i] = { (value(sx + step, sy) - f) / step, (value(sx, sy + step) - f) / step };
      const double miss = f - atEnd - (gradient[i].x * (sx - px) + gradient[i].y * (sy - py));
      if (!(distance > 1e-4 * l1) || std::abs(miss) <= 1e-3 * distance + 1e-9 * l1)
      {
        break;
      }
    }
  }
  const double g0 = Length(gradient[0]), g1 = Length(gradient[1]);
  const double sine = Cross(gradient[0], gradient[1]) / (g0 * g1);
  if (!(g0 > 0.0 && g1 > 0.0) || std::abs(sine) < 0.1)
  {
    // Fronts facing each other (turned by half a turn, give or take ~6 degrees) are the sides of
    // a strip thinner than the triangle: their tangents meet nowhere near, and the strip may go
    // on across the triangle's side to its end (TipAcrossEdge). Otherwise the fronts turn by
    // less than ~6 degrees: no corner to keep.
    if (outside && g0 > 0.0 && g1 > 0.0 && Dot(gradient[0], gradient[1]) < 0.0)
    {
      *outside = true;
    }
    return false;
  }
  // Tangent lines g_i . (x - p_i) = 0, solved by Cramer's rule.
  const double r0 = Dot(gradient[0], point[0]), r1 = Dot(gradient[1], point[1]);
  const double den = gradient[0].x * gradient[1].y - gradient[0].y * gradient[1].x;
  const double x = (r0 * gradient[1].y - r1 * gradient[0].y) / den;
  const double y = (gradient[0].x * r1 - gradient[1].x * r0) / den;
  // The corner may lie on the triangle's side or corner (a vertex exactly on the level set).
  std::array<double, 3> w = weightsOf(x, y);
  if (!(w[0] > -slack && w[1] > -slack && w[2] > -slack))
  {
    if (outside)
    {
      *outside = std::isfinite(w[0] + w[1] + w[2]);
    }
    return false;
  }
  for (double& wk : w)
  {
    wk = std::max(0.0, wk);
  }
  const double mid = value(0.5 * (point[0].x + point[1].x), 0.5 * (point[0].y + point[1].y));
  if (!(std::abs(value(x, y)) < 0.25 * std::abs(mid)))
  {
    return false;
  }
  SurfacePoint sp;
  sp.Triangle = t;
  sp.U = w[1] / (w[0] + w[1] + w[2]);
  sp.V = w[2] / (w[0] + w[1] + w[2]);
  corner = LocateSurfacePoint(mesh, sp);
  return !(corner == a) && !(corner == b);
}

// Where mesh edge `edge` holds a stretch on the `sign` side of the level set (sign * F < 0)
// between two ends on the other side: the two crossings, in the order of the edge. The field
// along the edge near a tip is the distance to the two sides meeting at its corner, convex: its
// extremum by golden section after a coarse scan, then a bisection on each side.
bool DoubleCrossing(OffsetField& field, int edge, double sign, CanonicalPoint crossing[2])
{
  auto value = [&](double s) { return sign * field.OnEdge(edge, s); };
  constexpr int Scan = 16;
  int best = 1;
  for (int i = 2; i < Scan; ++i)
  {
    if (value(static_cast<double>(i) / Scan) < value(static_cast<double>(best) / Scan))
    {
      best = i;
    }
  }
  double lo = static_cast<double>(best - 1) / Scan, hi = static_cast<double>(best + 1) / Scan;
  constexpr double Golden = 0.6180339887498949;
  for (int i = 0; i < 80 && hi - lo > 1e-15; ++i)
  {
    const double m1 = hi - Golden * (hi - lo), m2 = lo + Golden * (hi - lo);
    if (value(m1) < value(m2))
    {
      hi = m2;
    }
    else
    {
      lo = m1;
    }
  }
  const double middle = 0.5 * (lo + hi);
  if (!(value(middle) < 0.0))
  {
    return false;
  }
  for (int side = 0; side < 2; ++side)
  {
    double inner = middle, outer = side == 0 ? 0.0 : 1.0;
    for (int i = 0; i < 60 && std::abs(outer - inner) > 1e-15; ++i)
    {
      const double mid = 0.5 * (inner + outer);
      (value(mid) < 0.0 ? inner : outer) = mid;
    }
    crossing[side].Location = PointLocation::Edge;
    crossing[side].Id = edge;
    crossing[side].T = std::min(1.0 - EdgeMargin, std::max(EdgeMargin, 0.5 * (inner + outer)));
  }
  return crossing[0].T < crossing[1].T;
}

// The triangle across `edge` from triangle t, -1 on the surface's boundary.
int NeighborAcross(const TriangleMesh& mesh, int t, int edge)
{
  for (int j = 0; j < 3; ++j)
  {
    if (mesh.GetEdgeId(t, j) == edge)
    {
      return mesh.GetNeighbor(t, j);
    }
  }
  return -1;
}

// Where a tip whose sides face each other (the end of a strip thinner than the mesh) ends in
// triangle t between p and q on its sides, crossing no edge beyond: a flat end's two corners lie
// in t, and the chord p -> q would cut them both. The end's front is found on the strip's axis
// (normal to the sides' gradients) from the chord's middle, where the field changes sign inside
// t, and each corner is SharpCorner's between a side's end point and that point. False, with
// nothing added, unless both are found (a round end keeps its chord).
bool FlatEndCorners(const TriangleMesh& mesh,
  OffsetField& field,
  int t,
  const CanonicalPoint& p,
  const CanonicalPoint& q,
  std::vector<CanonicalPoint>& out)
{
  const Triangle& tri = mesh.GetTriangle(t);
  const Vec3 p0 = mesh.GetPosition(tri[0]), p1 = mesh.GetPosition(tri[1]),
             p2 = mesh.GetPosition(tri[2]);
  const TrianglePlaneWeights weightsOf(p0, p1, p2);
  const Vec3 xp = PositionOf(mesh, p), xq = PositionOf(mesh, q);
  const double chord = Distance(xp, xq);
  const Vec3 normal = Cross(p1 - p0, p2 - p0);
  if (weightsOf.IsDegenerate() || !(chord > 0.0))
  {
    return false;
  }
  // The sides' gradients by one-sided differences toward the triangle's inside, a tenth of the
  // chord from each end point (the chord may lie on t's side).
  const Vec3 along = (1.0 / chord) * (xq - xp);
  Vec3 across = Cross(normal, along);
  across = (1.0 / Length(across)) * across;
  const Vec3 centroid = (1.0 / 3.0) * (p0 + p1 + p2);
  if (Dot(centroid - 0.5 * (xp + xq), across) < 0.0)
  {
    across = -1.0 * across;
  }
  const double h = 1e-3 * chord;
  auto value = [&](const Vec3& x) { return field.InTriangle(t, weightsOf(x)); };
  auto gradient = [&](const Vec3& x)
  {
    const double f = value(x);
    return ((value(x + h * along) - f) / h) * along + ((value(x + h * across) - f) / h) * across;
  };
  const Vec3 axis = Cross(normal, gradient(xp + 0.1 * (xq - xp)) - gradient(xq + 0.1 * (xp - xq)));
  if (!(Length(axis) > 0.0))
  {
    return false;
  }
  const Vec3 middle = 0.5 * (xp + xq);
  const std::array<double, 3> wm = weightsOf(middle);
  const double fm = value(middle);
  for (double s : { 1.0, -1.0 })
  {
    const Vec3 dir = (s / Length(axis)) * axis;
    // How far t extends from the middle along dir: the largest step keeping the weights >= 0.
    const std::array<double, 3> wd = weightsOf(middle + dir);
    double reach = Infinity;
    for (int k = 0; k < 3; ++k)
    {
      const double rate = wd[k] - wm[k];
      if (rate < 0.0)
      {
        reach = std::min(reach, -std::max(0.0, wm[k]) / rate);
      }
    }
    double lo = 0.0, hi = reach * (1.0 - 1e-6);
    if (!(hi > 0.0) || reach == Infinity || (value(middle + hi * dir) < 0.0) == (fm < 0.0))
    {
      continue;
    }
    for (int it = 0; it < 50; ++it)
    {
      const double mid = 0.5 * (lo + hi);
      ((value(middle + mid * dir) < 0.0) == (fm < 0.0) ? lo : hi) = mid;
    }
    const CanonicalPoint m = InteriorPoint(mesh, t, weightsOf(middle + (0.5 * (lo + hi)) * dir));
    CanonicalPoint corners[2];
    if (SharpCorner(mesh, field, t, p, m, corners[0]) &&
      SharpCorner(mesh, field, t, m, q, corners[1]))
    {
      out.push_back(corners[0]);
      out.push_back(corners[1]);
      return true;
    }
    return false;
  }
  return false;
}

// Where the tangents at a piece's end points meet just outside triangle t but no tip goes on
// beyond it (the field along t's side stays on the other side of the level), the corner lies in
// t to within the gradients' precision, on its side or near it: SharpCorner's gradients are
// finite differences over ~1e-4 of the triangle, off by the exact field's rounding over that
// step (~1e-5 of their length), and move a corner near the side by up to ~1e-5 of the triangle
// across it. Such a corner (within 1e-4 of t in weight) is kept on t's side, where the chord
// would cut it (a flat end's corner on the side, 2.6e-5 short), when that side holds neither
// end point: one that does is where the level set crosses it, and a corner there would only be
// the crossing again, to rounding. False, with nothing added, when there is none.
bool CornerOnSide(const TriangleMesh& mesh,
  OffsetField& field,
  int t,
  const CanonicalPoint& a,
  const CanonicalPoint& b,
  std::vector<CanonicalPoint>& out)
{
  CanonicalPoint corner;
  if (!SharpCorner(mesh, field, t, a, b, corner, nullptr, 1e-4) ||
    corner.Location != PointLocation::Edge ||
    (a.Location == PointLocation::Edge && a.Id == corner.Id) ||
    (b.Location == PointLocation::Edge && b.Id == corner.Id))
  {
    return false;
  }
  out.push_back(corner);
  return true;
}

// The crossings of `edge` ordered so that the first is the nearer to `last`: the way in.
void OrderFrom(const TriangleMesh& mesh, const Vec3& last, CanonicalPoint crossing[2])
{
  if (Distance(PositionOf(mesh, crossing[1]), last) < Distance(PositionOf(mesh, crossing[0]), last))
  {
    std::swap(crossing[0], crossing[1]);
  }
}

// The tip's part beyond `edge` of triangle `from`, which the level set crosses twice
// (`crossing`, the way in first): the way in, the tip's points beyond, the way out. In the
// triangle beyond, wholly on the other side at its corners, the tip ends at a sharp corner
// (SharpCorner there), or goes on through another edge the field crosses twice (a sharp
// corner's tip), or through both other edges (the end of a strip thinner than the mesh, an
// inset that nearly collapses a rectangle, whose two corners lie beyond them: round the
// triangle from the way in, the edge at the end of `edge` nearer the way in first), or ends in
// it (a strip's flat end: FlatEndCorners), or its corner lies on the triangle's side to the
// gradients' precision (CornerOnSide). A tip of a few triangles at most (its corners are right
// angles or sharper at mesh resolution): `steps` counts them.
void AppendTipBeyond(const TriangleMesh& mesh,
  OffsetField& field,
  int from,
  int edge,
  double sign,
  const CanonicalPoint crossing[2],
  int steps,
  std::vector<CanonicalPoint>& out)
{
  out.push_back(crossing[0]);
  const int beyond = NeighborAcross(mesh, from, edge);
  bool otherSide = beyond >= 0;
  for (int j = 0; j < 3 && otherSide; ++j)
  {
    otherSide = sign * field.AtVertex(mesh.GetTriangle(beyond)[j]) > 0.0;
  }
  CanonicalPoint corner;
  bool outside = false;
  if (otherSide && SharpCorner(mesh, field, beyond, crossing[0], crossing[1], corner, &outside))
  {
    out.push_back(corner);
  }
  else if (otherSide && outside && steps < 3)
  {
    const std::array<int, 2> ev = mesh.GetEdgeVertices(edge);
    const int near = crossing[0].T < crossing[1].T ? ev[0] : ev[1];
    int edges[2] = { -1, -1 };
    CanonicalPoint next[2][2];
    int count = 0;
    for (int j = 0; j < 3; ++j)
    {
      const int e = mesh.GetEdgeId(beyond, j);
      if (e != edge && DoubleCrossing(field, e, sign, next[count]))
      {
        edges[count++] = e;
      }
    }
    if (count > 0)
    {
      // One edge: its way in nearer the last one. Two: the edge at `near` first, and on each
      // the crossing nearer the end reached first (`near`, or the corner opposite `edge`). The
      // corner of each stretch between is kept (a strip's end with one corner here).
      const std::array<int, 2> e0 = mesh.GetEdgeVertices(edges[0]);
      const int first = count == 2 && !(e0[0] == near || e0[1] == near) ? 1 : 0;
      CanonicalPoint previous = crossing[0];
      for (int i : { first, 1 - first })
      {
        if (i >= count)
        {
          continue;
        }
        const std::array<int, 2> v = mesh.GetEdgeVertices(edges[i]);
        const bool atNear = v[0] == near || v[1] == near;
        const int reached = atNear ? near : (v[0] == ev[0] || v[0] == ev[1] ? v[1] : v[0]);
        if (count == 1)
        {
          OrderFrom(mesh, PositionOf(mesh, crossing[0]), next[i]);
        }
        else if (v[0] != reached)
        {
          std::swap(next[i][0], next[i][1]);
        }
        // A corner between (a strip's end with one corner here, the other beyond).
        if (SharpCorner(mesh, field, beyond, previous, next[i][0], corner))
        {
          out.push_back(corner);
        }
        AppendTipBeyond(mesh, field, beyond, edges[i], sign, next[i], steps + 1, out);
        previous = next[i][1];
      }
      if (SharpCorner(mesh, field, beyond, previous, crossing[1], corner))
      {
        out.push_back(corner);
      }
    }
    else if (!FlatEndCorners(mesh, field, beyond, crossing[0], crossing[1], out))
    {
      CornerOnSide(mesh, field, beyond, crossing[0], crossing[1], out);
    }
  }
  out.push_back(crossing[1]);
}

// Where the tip of a sharp corner, or the end of a strip thinner than the mesh, leaves the
// crossed triangle t (piece a -> b) through its edge whose two ends lie on the other side of the
// level set, no edge of the triangles it enters straddles the level set and the contour's pieces
// never go there: the chord a -> b would cut the tip off. The level set crosses each edge the
// tip passes twice: the crossings, found on the exact field along the edges, and the corners in
// the triangles where the tip ends (SharpCorner there), are the points to add after a. A strip
// whose end lies in t keeps its corners there (FlatEndCorners), and a corner whose tangents meet
// just across t's side, the tip crossing no edge, is kept on the side (CornerOnSide). False
// when none is found.
bool TipAcrossEdge(const TriangleMesh& mesh,
  OffsetField& field,
  int t,
  const CanonicalPoint& a,
  const CanonicalPoint& b,
  std::vector<CanonicalPoint>& out)
{
  const Triangle& tri = mesh.GetTriangle(t);
  bool negative[3];
  int count = 0;
  for (int k = 0; k < 3; ++k)
  {
    negative[k] = field.AtVertex(tri[k]) < 0.0;
    count += negative[k] ? 1 : 0;
  }
  if (count == 0 || count == 3)
  {
    return false;
  }
  int k = 0;
  while (negative[k] != (count == 1))
  {
    ++k;
  }
  // The tip's side of the level set is the odd corner's; it leaves t through the opposite edge.
  const double sign = negative[k] ? 1.0 : -1.0;
  const int edge = mesh.GetEdgeId(t, (k + 1) % 3);
  CanonicalPoint crossing[2];
  if (!DoubleCrossing(field, edge, sign, crossing))
  {
    return FlatEndCorners(mesh, field, t, a, b, out) || CornerOnSide(mesh, field, t, a, b, out);
  }
  // The way in is the crossing nearer to a, with the corners in t itself between a or b and the
  // tip's way (a strip's end with one corner in t, the other beyond).
  OrderFrom(mesh, PositionOf(mesh, a), crossing);
  CanonicalPoint corner;
  if (SharpCorner(mesh, field, t, a, crossing[0], corner))
  {
    out.push_back(corner);
  }
  AppendTipBeyond(mesh, field, t, edge, sign, crossing, 0, out);
  if (SharpCorner(mesh, field, t, crossing[1], b, corner))
  {
    out.push_back(corner);
  }
  return true;
}

// Length of a loop and its turning sense: the area it encloses projected on the mean normal of
// the triangles it passes (positive: counter-clockwise, a region; negative: a hole). Only read
// for loops far smaller than the surface's curvature radius.
void LoopExtent(const TriangleMesh& mesh,
  const std::vector<CanonicalPoint>& loop,
  double& length,
  double& area)
{
  Vec3 normal{ 0.0, 0.0, 0.0 }, twice{ 0.0, 0.0, 0.0 };
  length = 0.0;
  const Vec3 origin = PositionOf(mesh, loop[0]);
  for (size_t i = 0; i < loop.size(); ++i)
  {
    const Vec3 a = PositionOf(mesh, loop[i]), b = PositionOf(mesh, loop[(i + 1) % loop.size()]);
    length += Distance(a, b);
    twice = twice + Cross(a - origin, b - origin);
    const int t = AnyTriangleOf(mesh, loop[i]);
    if (t >= 0)
    {
      const Triangle& tri = mesh.GetTriangle(t);
      normal = normal +
        Cross(mesh.GetPosition(tri[1]) - mesh.GetPosition(tri[0]),
          mesh.GetPosition(tri[2]) - mesh.GetPosition(tri[0]));
    }
  }
  const double n = Length(normal);
  area = n > 0.0 ? 0.5 * Dot(twice, (1.0 / n) * normal) : 0.0;
}

// Outgoing boundary half-edge (3 t + k, from corner k to k + 1) of each boundary vertex.
std::unordered_map<int, int> BoundaryNext(const MeshTopology& topology)
{
  std::unordered_map<int, int> next;
  for (const BoundaryLoop& loop : topology.BoundaryLoops)
  {
    for (size_t i = 0; i < loop.HalfEdges.size(); ++i)
    {
      next.emplace(loop.Vertices[i], loop.HalfEdges[i]);
    }
  }
  return next;
}

/// A run of contour pieces joined end to start: closed, or open from and to boundary edges of
/// the surface.
struct ContourChain
{
  std::vector<int> Pieces;
  bool Closed = false;
};

/// The contour's chains: follow the pieces from point to point. A chain that starts at a point
/// no piece ends at (on a boundary edge of the surface) is open; the rest close on themselves.
std::vector<ContourChain> FollowChains(const Contour& contour)
{
  const int np = static_cast<int>(contour.Points.size());
  std::vector<char> used(contour.Pieces.size(), 0);
  std::vector<ContourChain> chains;
  auto follow = [&](int piece)
  {
    ContourChain chain;
    while (piece >= 0 && !used[piece])
    {
      used[piece] = 1;
      chain.Pieces.push_back(piece);
      piece = contour.PieceFrom[contour.Pieces[piece].To];
    }
    chain.Closed = piece >= 0 && piece == chain.Pieces.front();
    chains.push_back(std::move(chain));
  };
  for (int p = 0; p < np; ++p)
  {
    if (contour.PieceTo[p] < 0 && contour.PieceFrom[p] >= 0)
    {
      follow(contour.PieceFrom[p]);
    }
  }
  for (size_t i = 0; i < contour.Pieces.size(); ++i)
  {
    if (!used[i])
    {
      follow(static_cast<int>(i));
    }
  }
  return chains;
}

/// Appends the points of `chain` to `loop`: each piece's start, its sharp corner, tip or
/// refinement, and an open chain's last point.
void AppendChain(const TriangleMesh& mesh,
  OffsetField& field,
  const Contour& contour,
  const ContourChain& chain,
  int resolution,
  std::vector<CanonicalPoint>& loop)
{
  for (int id : chain.Pieces)
  {
    const Contour::Piece& piece = contour.Pieces[id];
    const CanonicalPoint& a = contour.Points[piece.From];
    if (loop.empty() || !(loop.back() == a))
    {
      loop.push_back(a);
    }
    CanonicalPoint corner;
    bool outside = false;
    if (SharpCorner(mesh, field, piece.Triangle, a, contour.Points[piece.To], corner, &outside))
    {
      loop.push_back(corner);
    }
    // (A piece ending on an edge crossed twice stops short of that edge: no tip crosses it.)
    else if (!(outside && !contour.Twice[piece.From] && !contour.Twice[piece.To] &&
               TipAcrossEdge(mesh, field, piece.Triangle, a, contour.Points[piece.To], loop)) &&
      resolution > 0)
    {
      RefinePiece(mesh, field, piece.Triangle, a, contour.Points[piece.To], resolution, loop);
    }
  }
  if (!chain.Closed)
  {
    loop.push_back(contour.Points[contour.Pieces[chain.Pieces.back()].To]);
  }
}

/// From the end of open chain `chain` (the last point of `loop`), the surface's boundary walked
/// (the surface on the left of its half-edges) while the offset region continues along it, its
/// vertices appended to `loop`, to the open chain starting on the boundary edge reached: that
/// chain's index, -1 when none is reached.
int WalkBoundary(const TriangleMesh& mesh,
  OffsetField& field,
  const Contour& contour,
  const ContourChain& chain,
  const std::unordered_map<int, int>& chainStartingOnEdge,
  const std::unordered_map<int, int>& boundaryNext,
  std::vector<CanonicalPoint>& loop)
{
  const int lastEdge = loop.back().Id;
  int halfEdge = -1;
  const int t = contour.Pieces[chain.Pieces.back()].Triangle;
  for (int k = 0; k < 3; ++k)
  {
    if (mesh.GetEdgeId(t, k) == lastEdge)
    {
      halfEdge = 3 * t + k;
    }
  }
  int next = -1;
  for (int steps = 0; halfEdge >= 0 && steps <= mesh.GetNumberOfVertices(); ++steps)
  {
    const int ht = halfEdge / 3, hk = halfEdge % 3;
    const int to = mesh.GetTriangle(ht)[(hk + 1) % 3];
    if (field.AtVertex(to) >= 0.0)
    {
      break; // the offset region does not continue this way: inconsistent contour
    }
    CanonicalPoint vertex;
    vertex.Location = PointLocation::Vertex;
    vertex.Id = to;
    loop.push_back(vertex);
    const auto it = boundaryNext.find(to);
    if (it == boundaryNext.end())
    {
      break;
    }
    halfEdge = it->second;
    const auto starts = chainStartingOnEdge.find(mesh.GetEdgeId(halfEdge / 3, halfEdge % 3));
    if (starts != chainStartingOnEdge.end())
    {
      next = starts->second;
      break;
    }
  }
  return next;
}
} // namespace

//------------------------------------------------------------------------------
bool ComputeGeodesicOffset(const TriangleMesh& mesh,
  const MeshTopology& topology,
  const OffsetRegion& region,
  const OffsetOptions& options,
  std::vector<std::vector<CanonicalPoint>>& loops,
  std::string& error,
  OffsetStatistics* statistics,
  OffsetBuffers* buffers)
{
  loops.clear();
  OffsetStatistics stats;
  const double d = options.Distance;
  if (!std::isfinite(d))
  {
    error = "the offset distance is not a finite number";
    return false;
  }
  if (region.Boundary.empty() && region.Bands.empty())
  {
    error = "the region to offset has no boundary and no open curve";
    return false;
  }
  if (d == 0.0)
  {
    loops = region.Boundary; // the identity; a band of width 0 is empty
    if (statistics)
    {
      *statistics = stats;
    }
    return true;
  }
  if (d < 0.0 && region.Boundary.empty())
  {
    error = "a negative distance shrinks a region, and only curves to draw bands around were given";
    return false;
  }
  const Clock::time_point start = Clock::now();
  std::unique_ptr<OffsetBuffers> own;
  if (!buffers)
  {
    own = std::make_unique<OffsetBuffers>(mesh);
    buffers = own.get();
  }
  OffsetField field(mesh, region, d, *buffers);
  if (!field.Compute(options, stats, error))
  {
    return false;
  }
  const Clock::time_point computed = Clock::now();
  std::vector<int> reached;
  field.ReachedVertices(reached);
  stats.FieldVertices = static_cast<int>(reached.size());
  Contour contour(mesh, field);
  contour.Build(reached);
  stats.CrossedTriangles = contour.GetNumberOfCrossedTriangles();

  const std::vector<ContourChain> chains = FollowChains(contour);

  // Open chains end on boundary edges of the surface: the region continues along the boundary
  // (the surface is on the left of its half-edges) to the start of the next open chain.
  std::unordered_map<int, int> chainStartingOnEdge; // boundary edge -> open chain
  for (size_t i = 0; i < chains.size(); ++i)
  {
    if (!chains[i].Closed)
    {
      const int first = contour.Pieces[chains[i].Pieces.front()].From;
      chainStartingOnEdge.emplace(contour.Points[first].Id, static_cast<int>(i));
    }
  }
  const std::unordered_map<int, int> boundaryNext =
    chainStartingOnEdge.empty() ? std::unordered_map<int, int>() : BoundaryNext(topology);
  std::vector<char> placed(chains.size(), 0);
  for (size_t i = 0; i < chains.size(); ++i)
  {
    if (placed[i])
    {
      continue;
    }
    std::vector<CanonicalPoint> loop;
    int current = static_cast<int>(i);
    while (!placed[current])
    {
      placed[current] = 1;
      AppendChain(mesh, field, contour, chains[current], options.Resolution, loop);
      if (chains[current].Closed)
      {
        break;
      }
      const int lastEdge = loop.back().Id; // the walk appends to the loop
      const int next = WalkBoundary(
        mesh, field, contour, chains[current], chainStartingOnEdge, boundaryNext, loop);
      if (next < 0)
      {
        error = "the offset contour reaches the surface's boundary at edge " +
          std::to_string(lastEdge) + " and cannot be closed along it";
        return false;
      }
      current = next;
    }
    if (loop.size() < 3)
    {
      continue;
    }
    // Slivers: where a sharp corner of the offset region is thinner than the mesh, the contour
    // of the mesh vertices' signs can split its tip off as a tiny loop. A grown region contains
    // a disk of radius d around each of its boundary's points, so none of its parts is that
    // small (and no hole of a shrunk region is): such loops are dropped.
    double length, area;
    LoopExtent(mesh, loop, length, area);
    if (length < Pi * std::abs(d) && (d > 0.0 ? area > 0.0 : area < 0.0))
    {
      ++stats.DroppedSlivers;
      continue;
    }
    loops.push_back(std::move(loop));
  }
  stats.ContourMilliseconds = Milliseconds(computed, Clock::now());
  stats.FieldMilliseconds = Milliseconds(start, computed);
  if (statistics)
  {
    *statistics = stats;
  }
  if (loops.empty())
  {
    if (d < 0.0)
    {
      error = "shrinking by " + std::to_string(-d) +
        " leaves nothing: no point of the region is farther than that from its boundary";
      return false;
    }
    // No contour: the grown region either covers every component it touches or (for an
    // isolated region far from everything) is unchanged, which cannot happen for d > 0.
    error = "growing by " + std::to_string(d) +
      " covers the whole surface around the region (no boundary is left to draw)";
    return false;
  }
  return true;
}

} // namespace boolsurf

#include "Distributed/PieceRegionBoundary.h"

#include "Distributed/PieceWire.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iterator>
#include <map>
#include <set>
#include <utility>

namespace boolsurf
{
namespace
{

/// Words of a point in the messages (PackBoundaryPoint).
constexpr std::size_t BoundaryPointWords = 18;

enum KeyLocation : std::int64_t
{
  VertexKey = 0,
  EdgeKey = 1,
  FaceKey = 2
};

/// The piece's triangles holding refined point p (local ids, ascending, at most a few). At a
/// vertex, its usable triangles from the mesh's corner lists (built with the mesh: a table of
/// its own cost a pass over the piece on every update).
void TrianglesAt(const TriangleMesh& mesh, const CanonicalPoint& c, std::vector<int>& out)
{
  out.clear();
  switch (c.Location)
  {
    case PointLocation::Face:
      out.push_back(c.Id);
      break;
    case PointLocation::Edge:
    {
      const int h = mesh.GetEdgeHalfEdge(c.Id);
      out.push_back(h / 3);
      const int twin = mesh.GetTwin(h);
      if (twin >= 0)
      {
        out.push_back(twin / 3);
      }
      break;
    }
    case PointLocation::Vertex:
      for (int corner : mesh.GetVertexCorners(c.Id))
      {
        out.push_back(corner / 3);
      }
      break;
  }
  std::sort(out.begin(), out.end());
}

BoundaryPointRecord RecordOf(const PieceMesh& piece, const Arrangement& arr, int p)
{
  const TriangleMesh& mesh = piece.Mesh;
  const CanonicalPoint c = arr.GetPointOnMesh(p);
  BoundaryPointRecord r;
  switch (c.Location)
  {
    case PointLocation::Vertex:
      r.Key = { VertexKey, piece.GlobalVertex[c.Id], 0, 0 };
      break;
    case PointLocation::Edge:
    {
      const std::array<int, 2> ends = mesh.GetEdgeVertices(c.Id);
      r.Key = {
        EdgeKey, piece.GlobalVertex[ends[0]], piece.GlobalVertex[ends[1]], WireBitsOf(c.T)
      };
      break;
    }
    case PointLocation::Face:
      r.Key = { FaceKey, piece.GlobalTriangle[c.Id], WireBitsOf(c.U), WireBitsOf(c.V) };
      break;
  }
  r.Position = arr.GetPosition(mesh, p);
  r.Surface = arr.GetPointSurface(mesh, p);
  if (r.Surface.Triangle >= 0)
  {
    r.SurfacePosition = mesh.Evaluate(r.Surface.Triangle, r.Surface.U, r.Surface.V);
    r.Surface.Triangle = piece.GlobalTriangle[r.Surface.Triangle];
  }
  return r;
}

/// Station `local` of the piece's curve c on the global curve it is a run of: the run's first
/// traced point's index added to the whole part, so that the sum is rounded as the whole
/// surface's arrangement rounds its station (traced point index plus fraction).
double GlobalStation(const PieceCurveRuns& runs, int c, double local)
{
  const double whole = std::floor(local);
  return static_cast<double>(runs.FirstPoint[c] + static_cast<long long>(whole)) + (local - whole);
}

/// Station on the global curve of point `i` of patch `patch` of the piece's arrangement.
double PatchPointStation(const Arrangement& arr,
  const PieceCurveRuns& runs,
  const ArrangementPatch& patch,
  std::size_t i)
{
  const std::vector<double>& stations = arr.CurveStations[patch.Curve];
  const std::size_t n = stations.size();
  return GlobalStation(runs, patch.Curve, stations[(patch.FirstIndex + i) % n]);
}

/// Whether refined triangle r is in a selected global cell.
bool InSelectedCell(const Arrangement& arr,
  const std::vector<int>& globalCellOfLocal,
  const std::vector<char>& selected,
  int r)
{
  const int local = arr.CellOfTriangle(r);
  if (local < 0 || local >= static_cast<int>(globalCellOfLocal.size()))
  {
    return false;
  }
  const int global = globalCellOfLocal[local];
  return global >= 0 && global < static_cast<int>(selected.size()) && selected[global] != 0;
}

/// Calls f(r, p, q) for every refined triangle r, in an owned triangle, with the segment a-b as
/// its edge p -> q (r on the left of p -> q).
template <class F>
void ForEachOwnedSide(const PieceMesh& piece,
  const Arrangement& arr,
  int a,
  int b,
  std::vector<int>& from,
  std::vector<int>& at,
  std::vector<int>& common,
  F f)
{
  const TriangleMesh& mesh = piece.Mesh;
  TrianglesAt(mesh, arr.GetPointOnMesh(a), from);
  TrianglesAt(mesh, arr.GetPointOnMesh(b), at);
  common.clear();
  std::set_intersection(from.begin(), from.end(), at.begin(), at.end(), std::back_inserter(common));
  for (int t : common)
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
        const Triangle corners = arr.GetTriangle(mesh, r);
        for (int k = 0; k < 3; ++k)
        {
          const int p = corners[k], q = corners[(k + 1) % 3];
          if ((p == a && q == b) || (p == b && q == a))
          {
            f(r, p, q);
          }
        }
      });
  }
}

/// The points of a run joined into one sequence: each run's first point after the first is
/// the previous one's last.
void Append(std::vector<BoundaryPointRecord>& to, const BoundaryRun& run)
{
  if (!to.empty())
  {
    to.back().Next = run.Points.front().Next; // the segment leaving the joint is the run's
  }
  to.insert(to.end(), run.Points.begin() + (to.empty() ? 0 : 1), run.Points.end());
}

bool KeysLess(const std::vector<BoundaryPointRecord>& a, const std::vector<BoundaryPointRecord>& b)
{
  return std::lexicographical_compare(a.begin(),
    a.end(),
    b.begin(),
    b.end(),
    [](const BoundaryPointRecord& x, const BoundaryPointRecord& y) { return x.Key < y.Key; });
}

/// Chains runs into loops and open chains, joining runs only at points where canJoin(key)
/// (every point when it is null): at each point, the runs ending there by their point before
/// it, the runs starting there by their point after it (then by their whole sequence, for runs
/// along the same stretch), the i-th of one continued by the i-th of the other -- a pairing
/// that only depends on the segments at the point, never on where a piece border cut the runs.
std::vector<BoundaryRun> ChainRuns(const std::vector<BoundaryRun>& runs,
  const std::function<bool(const BoundaryPointKey&)>& canJoin)
{
  const int n = static_cast<int>(runs.size());
  std::map<BoundaryPointKey, std::pair<std::vector<int>, std::vector<int>>> at;
  for (int i = 0; i < n; ++i)
  {
    if (runs[i].Points.size() < 2)
    {
      continue;
    }
    at[runs[i].Points.back().Key].first.push_back(i);
    at[runs[i].Points.front().Key].second.push_back(i);
  }
  std::vector<int> next(n, -1), previous(n, -1);
  for (auto& entry : at)
  {
    if (canJoin && !canJoin(entry.first))
    {
      continue; // the runs end here: other pieces may have segments at this point
    }
    std::vector<int>& in = entry.second.first;
    std::vector<int>& out = entry.second.second;
    std::sort(in.begin(),
      in.end(),
      [&](int x, int y)
      {
        const auto& a = runs[x].Points;
        const auto& b = runs[y].Points;
        if (a[a.size() - 2].Key != b[b.size() - 2].Key)
        {
          return a[a.size() - 2].Key < b[b.size() - 2].Key;
        }
        return KeysLess(std::vector<BoundaryPointRecord>(a.rbegin(), a.rend()),
          std::vector<BoundaryPointRecord>(b.rbegin(), b.rend()));
      });
    std::sort(out.begin(),
      out.end(),
      [&](int x, int y) { return KeysLess(runs[x].Points, runs[y].Points); });
    for (std::size_t k = 0; k < std::min(in.size(), out.size()); ++k)
    {
      next[in[k]] = out[k];
      previous[out[k]] = in[k];
    }
  }
  std::vector<BoundaryRun> result;
  std::vector<char> used(n, 0);
  // Open chains first (from a run nothing continues into), then the cycles.
  for (int pass = 0; pass < 2; ++pass)
  {
    for (int i = 0; i < n; ++i)
    {
      if (used[i] || runs[i].Points.size() < 2 || (pass == 0 && previous[i] >= 0))
      {
        continue;
      }
      BoundaryRun line;
      int r = i;
      while (r >= 0 && !used[r])
      {
        used[r] = 1;
        Append(line.Points, runs[r]);
        r = next[r];
      }
      line.Closed = r == i;
      if (line.Closed)
      {
        line.Points.pop_back(); // back at its first point
        // Start at the lowest point (then the lowest point after it, for a loop passing a
        // point twice).
        const std::size_t m = line.Points.size();
        std::size_t best = 0;
        for (std::size_t k = 1; k < m; ++k)
        {
          const auto& kk = line.Points[k].Key;
          const auto& bk = line.Points[best].Key;
          if (kk < bk ||
            (kk == bk && line.Points[(k + 1) % m].Key < line.Points[(best + 1) % m].Key))
          {
            best = k;
          }
        }
        std::rotate(line.Points.begin(), line.Points.begin() + best, line.Points.end());
      }
      result.push_back(std::move(line));
    }
  }
  std::sort(result.begin(),
    result.end(),
    [](const BoundaryRun& a, const BoundaryRun& b)
    {
      if (a.Closed != b.Closed)
      {
        return a.Closed;
      }
      return KeysLess(a.Points, b.Points);
    });
  return result;
}

} // namespace

//------------------------------------------------------------------------------
PieceCurveRuns CurveRunsOf(const PieceCurves& curves)
{
  PieceCurveRuns runs;
  runs.SourceCurve = curves.SourceCurve;
  runs.FirstPoint = curves.FirstPoint;
  runs.OfOpenCurve.resize(curves.Curves.size());
  runs.CutFromClosed = curves.CutFromClosed;
  for (std::size_t c = 0; c < curves.Curves.size(); ++c)
  {
    runs.OfOpenCurve[c] = curves.BoundsCells(static_cast<int>(c)) ? 0 : 1;
  }
  return runs;
}

//------------------------------------------------------------------------------
void PieceRegionBoundaryRuns(const PieceMesh& piece,
  const Arrangement& arr,
  const std::vector<int>& globalCellOfLocal,
  const std::vector<char>& selected,
  std::vector<BoundaryRun>& out,
  const PieceCurveRuns* curves)
{
  out.clear();
  const TriangleMesh& mesh = piece.Mesh;
  const auto isSelected = [&](int r)
  { return InSelectedCell(arr, globalCellOfLocal, selected, r); };
  // Per segment in its curve's direction, the curve it runs along (the first patch's, where
  // curves overlap).
  std::map<std::pair<int, int>, BoundarySegmentCurve> along;
  // The patches' ends: the whole surface's, since a run's own ends lie beyond the owned
  // triangles (in its ring) and no boundary segment reaches them.
  std::set<int> patchEnds;
  // Each side of a curve segment is seen by the piece owning the mesh triangle on that side
  // (its refined triangle there is owned, so its local cell has a global number): a selected
  // side gives the segment with that side on its left. A segment selected on both sides is
  // given twice, once each way, and cancels (here when both sides are this piece's, on the
  // chaining rank when they are two pieces'); a patch's own LeftCell and RightCell are not
  // read, since on a piece one of them may be a cell of ghosts only, with no global number.
  std::map<std::pair<int, int>, int> given; // directed (point, point) -> how many times
  std::vector<int> from, at, common;
  for (const ArrangementPatch& patch : arr.Patches)
  {
    if (curves && !patch.Points.empty() && patch.Curve >= 0)
    {
      // Not where a run of a closed curve was cut at the curve's start (the whole surface's
      // patches pass it) -- unless another curve meets it there too, which this cannot tell.
      const bool cut = curves->CutFromClosed[patch.Curve] != 0;
      const std::size_t n = arr.CurvePoints[patch.Curve].size();
      if (!cut || patch.FirstIndex != 0)
      {
        patchEnds.insert(patch.Points.front());
      }
      if (!cut || patch.FirstIndex + patch.Points.size() != n)
      {
        patchEnds.insert(patch.Points.back());
      }
    }
    for (std::size_t i = 0; i + 1 < patch.Points.size(); ++i)
    {
      const int a = patch.Points[i], b = patch.Points[i + 1];
      if (a == b)
      {
        continue;
      }
      // r runs p -> q, so r is on the left of p -> q.
      bool boundary = false;
      ForEachOwnedSide(piece,
        arr,
        a,
        b,
        from,
        at,
        common,
        [&](int r, int p, int q)
        {
          if (isSelected(r))
          {
            ++given[{ p, q }];
            boundary = true;
          }
        });
      // Only for the segments this piece gives: O(boundary) entries, not O(curves).
      if (boundary && curves && patch.Curve >= 0 && along.count({ a, b }) == 0)
      {
        along[{ a, b }] = { curves->SourceCurve[patch.Curve],
          false,
          PatchPointStation(arr, *curves, patch, i),
          PatchPointStation(arr, *curves, patch, i + 1) };
      }
    }
  }
  const auto curveOf = [&](int p, int q)
  {
    auto it = along.find({ p, q });
    if (it != along.end())
    {
      return it->second;
    }
    it = along.find({ q, p });
    if (it == along.end())
    {
      return BoundarySegmentCurve();
    }
    return BoundarySegmentCurve{ it->second.Curve, true, it->second.To, it->second.From };
  };
  // A point all of whose triangles this piece owns has all its boundary segments here: runs
  // are chained through such points, and end at the others (on a border with another piece).
  const auto inside = [&](int p)
  {
    TrianglesAt(mesh, arr.GetPointOnMesh(p), at);
    return std::all_of(at.begin(), at.end(), [&](int t) { return piece.Owned[t] != 0; });
  };
  std::vector<BoundaryRun> segments;
  std::set<BoundaryPointKey> joinable;
  for (const auto& entry : given)
  {
    const auto reverse = given.find({ entry.first.second, entry.first.first });
    const int count = entry.second - (reverse == given.end() ? 0 : reverse->second);
    for (int c = 0; c < count; ++c)
    {
      BoundaryRun run;
      run.Points = { RecordOf(piece, arr, entry.first.first),
        RecordOf(piece, arr, entry.first.second) };
      run.Points[0].Next = curveOf(entry.first.first, entry.first.second);
      for (int k = 0; k < 2; ++k)
      {
        run.Points[k].PatchEnd =
          patchEnds.count(k == 0 ? entry.first.first : entry.first.second) != 0;
      }
      for (int k = 0; k < 2; ++k)
      {
        if (inside(k == 0 ? entry.first.first : entry.first.second))
        {
          joinable.insert(run.Points[k].Key);
        }
      }
      segments.push_back(std::move(run));
    }
  }
  // A segment along an edge with another piece's triangle stays alone: it may be cancelled
  // there. Its ends are not inside, so no run is chained through them.
  out = ChainRuns(segments, [&](const BoundaryPointKey& key) { return joinable.count(key) != 0; });
}

//------------------------------------------------------------------------------
void PieceClippedSegments(const PieceMesh& piece,
  const Arrangement& arr,
  const std::vector<int>& globalCellOfLocal,
  const std::vector<char>& selected,
  const PieceCurveRuns& curves,
  std::vector<ClippedSegment>& out)
{
  out.clear();
  std::vector<int> from, at, common;
  for (const ArrangementPatch& patch : arr.Patches)
  {
    if (patch.Curve < 0 || !curves.OfOpenCurve[patch.Curve])
    {
      continue;
    }
    for (std::size_t i = 0; i + 1 < patch.Points.size(); ++i)
    {
      const int a = patch.Points[i], b = patch.Points[i + 1];
      if (a == b)
      {
        continue;
      }
      // A side in an owned triangle in a selected cell: the patch's LeftCell or RightCell is
      // selected (every segment of a patch has the same cells on its sides).
      bool inside = false;
      ForEachOwnedSide(piece,
        arr,
        a,
        b,
        from,
        at,
        common,
        [&](int r, int, int)
        { inside = inside || InSelectedCell(arr, globalCellOfLocal, selected, r); });
      if (inside)
      {
        out.push_back({ curves.SourceCurve[patch.Curve],
          PatchPointStation(arr, curves, patch, i),
          PatchPointStation(arr, curves, patch, i + 1),
          RecordOf(piece, arr, a),
          RecordOf(piece, arr, b) });
      }
    }
  }
}

//------------------------------------------------------------------------------
std::vector<BoundaryRun> ChainBoundaryRuns(const std::vector<BoundaryRun>& given)
{
  // A segment given once each way (its two sides selected, on two pieces) is no boundary.
  std::map<std::pair<BoundaryPointKey, BoundaryPointKey>, std::vector<int>> single;
  for (std::size_t i = 0; i < given.size(); ++i)
  {
    if (given[i].Points.size() == 2 && !given[i].Closed)
    {
      single[{ given[i].Points[0].Key, given[i].Points[1].Key }].push_back(static_cast<int>(i));
    }
  }
  std::vector<char> cancelled(given.size(), 0);
  for (auto& entry : single)
  {
    auto reverse = single.find({ entry.first.second, entry.first.first });
    if (reverse == single.end() || !(entry.first < reverse->first))
    {
      continue;
    }
    const std::size_t pairs = std::min(entry.second.size(), reverse->second.size());
    for (std::size_t k = 0; k < pairs; ++k)
    {
      cancelled[entry.second[k]] = cancelled[reverse->second[k]] = 1;
    }
  }
  std::vector<BoundaryRun> runs;
  for (std::size_t i = 0; i < given.size(); ++i)
  {
    if (!cancelled[i])
    {
      runs.push_back(given[i]);
      if (runs.back().Closed && !runs.back().Points.empty())
      {
        // A loop a piece chained whole: back to its first point, as a run.
        runs.back().Points.push_back(runs.back().Points.front());
        runs.back().Closed = false;
      }
    }
  }
  return ChainRuns(runs, nullptr);
}

//------------------------------------------------------------------------------
void PackBoundaryRuns(const std::vector<BoundaryRun>& runs, std::vector<long long>& out)
{
  out.clear();
  out.push_back(static_cast<long long>(runs.size()));
  for (const BoundaryRun& run : runs)
  {
    out.push_back(static_cast<long long>(run.Points.size()));
    out.push_back(run.Closed ? 1 : 0);
    for (const BoundaryPointRecord& p : run.Points)
    {
      PackBoundaryPoint(p, out);
    }
  }
}

//------------------------------------------------------------------------------
void PackBoundaryPoint(const BoundaryPointRecord& p, std::vector<long long>& out)
{
  out.insert(out.end(), p.Key.begin(), p.Key.end());
  out.insert(out.end(),
    { WireBitsOf(p.Position.x),
      WireBitsOf(p.Position.y),
      WireBitsOf(p.Position.z),
      static_cast<long long>(p.Surface.Triangle),
      WireBitsOf(p.Surface.U),
      WireBitsOf(p.Surface.V),
      WireBitsOf(p.SurfacePosition.x),
      WireBitsOf(p.SurfacePosition.y),
      WireBitsOf(p.SurfacePosition.z),
      static_cast<long long>(p.Next.Curve),
      p.Next.Reversed ? 1LL : 0LL,
      WireBitsOf(p.Next.From),
      WireBitsOf(p.Next.To),
      p.PatchEnd ? 1LL : 0LL });
}

//------------------------------------------------------------------------------
bool UnpackBoundaryPoint(const std::vector<long long>& in, std::size_t& at, BoundaryPointRecord& p)
{
  if (in.size() < at || in.size() - at < BoundaryPointWords)
  {
    return false;
  }
  std::copy(in.begin() + at, in.begin() + at + 4, p.Key.begin());
  p.Position = { WireDoubleOf(in[at + 4]), WireDoubleOf(in[at + 5]), WireDoubleOf(in[at + 6]) };
  p.Surface.Triangle = static_cast<int>(in[at + 7]);
  p.Surface.U = WireDoubleOf(in[at + 8]);
  p.Surface.V = WireDoubleOf(in[at + 9]);
  p.SurfacePosition = {
    WireDoubleOf(in[at + 10]), WireDoubleOf(in[at + 11]), WireDoubleOf(in[at + 12])
  };
  p.Next.Curve = static_cast<int>(in[at + 13]);
  p.Next.Reversed = in[at + 14] != 0;
  p.Next.From = WireDoubleOf(in[at + 15]);
  p.Next.To = WireDoubleOf(in[at + 16]);
  p.PatchEnd = in[at + 17] != 0;
  at += BoundaryPointWords;
  return true;
}

//------------------------------------------------------------------------------
bool UnpackBoundaryRuns(const std::vector<long long>& in,
  std::vector<BoundaryRun>& out,
  std::string& error)
{
  std::size_t at = 0;
  if (!UnpackBoundaryRuns(in, at, out, error))
  {
    return false;
  }
  if (at != in.size())
  {
    error = "message 4 (the region's boundary runs) is short or corrupt";
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool UnpackBoundaryRuns(const std::vector<long long>& in,
  std::size_t& at,
  std::vector<BoundaryRun>& out,
  std::string& error)
{
  constexpr std::size_t PointWords = BoundaryPointWords;
  const auto fail = [&]()
  {
    error = "message 4 (the region's boundary runs) is short or corrupt";
    return false;
  };
  if (at >= in.size() || in[at] < 0)
  {
    return fail();
  }
  const long long count = in[at++];
  for (long long r = 0; r < count; ++r)
  {
    if (at + 2 > in.size() || in[at] < 0 ||
      static_cast<std::size_t>(in[at]) > (in.size() - at - 2) / PointWords)
    {
      return fail();
    }
    BoundaryRun run;
    run.Points.resize(static_cast<std::size_t>(in[at++]));
    run.Closed = in[at++] != 0;
    for (BoundaryPointRecord& p : run.Points)
    {
      UnpackBoundaryPoint(in, at, p); // the count was checked against the length
    }
    out.push_back(std::move(run));
  }
  return true;
}

} // namespace boolsurf

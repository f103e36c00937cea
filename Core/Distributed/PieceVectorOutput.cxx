#include "Distributed/PieceVectorOutput.h"

#include "Distributed/PieceWire.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

namespace boolsurf
{
namespace
{

/// Stations this close are one point's (the same point's station computed on two pieces).
constexpr double SameStation = 1e-9;

/// Why a sub-curve cannot be given on pieces, or empty when it can.
std::string Unusable(const std::vector<CurveSource>& sources, int curve)
{
  if (curve < 0 || curve >= static_cast<int>(sources.size()))
  {
    return "a segment of the result names no input curve (" + std::to_string(curve) + ")";
  }
  const CurveSource& source = sources[curve];
  if (source.Type != CurveType::GeodesicPolygon)
  {
    return "curve " + std::to_string(curve) +
      " is a cubic Bezier, whose pieces are split by geodesic de Casteljau on the whole "
      "surface (not on pieces)";
  }
  if (source.Points.empty() || source.Parameter.empty())
  {
    return "curve " + std::to_string(curve) + " has no control points";
  }
  return std::string();
}

/// A closed curve's station of its start reached at the end of a turn is its first point's.
double Normalized(const CurveSource& source, double station)
{
  const double n = static_cast<double>(source.Parameter.size());
  return source.Closed && station >= n ? station - n : station;
}

/// One end of a sub-curve: its station, and the point when it lies between control points.
struct End
{
  double Station = 0;
  const BoundaryPointRecord* Point = nullptr;
};

/// The forward sub-curve of `curve` from `first` to `last` (whole: once around from `first`),
/// as BoundaryControlPoints' SubCurve gives a geodesic polygon's.
ControlSubCurve MakeSubCurve(const std::vector<CurveSource>& sources,
  const ControlPointPositions& positions,
  int curve,
  const End& first,
  const End& last,
  bool whole)
{
  const CurveSource& source = sources[curve];
  ControlSubCurve out = SubCurveOfSource(sources, curve);
  out.Whole = whole;
  out.T0 = StationParameter(source, Normalized(source, first.Station));
  out.T1 = StationParameter(source, Normalized(source, last.Station));
  SubCurveParameterRange(source, whole, out.T0, out.T1);
  std::vector<int> own;
  PolygonSubCurveControls(source, out.T0, out.T1, whole, own);
  for (std::size_t i = 0; i < own.size(); ++i)
  {
    if (own[i] >= 0)
    {
      out.Points.push_back(source.Points[static_cast<std::size_t>(own[i])]);
      out.Positions.push_back(positions[curve][static_cast<std::size_t>(own[i])]);
    }
    else
    {
      const BoundaryPointRecord* p = i == 0 ? first.Point : last.Point;
      if (!p)
      {
        // A whole curve starts at its first control point (a trace's parameter 0).
        out.Points.push_back(source.Points[0]);
        out.Positions.push_back(positions[curve][0]);
        continue;
      }
      out.Points.push_back(p->Surface);
      out.Positions.push_back(p->SurfacePosition);
    }
  }
  return out;
}

/// Whether the segment leaving b continues the one leaving a along the same curve, same way.
bool Continues(const std::vector<CurveSource>& sources,
  const BoundarySegmentCurve& a,
  const BoundarySegmentCurve& b)
{
  if (a.Curve != b.Curve || a.Reversed != b.Reversed)
  {
    return false;
  }
  const CurveSource& source = sources[a.Curve];
  return std::abs(Normalized(source, a.To) - Normalized(source, b.From)) <= SameStation;
}

} // namespace

//------------------------------------------------------------------------------
bool PieceBoundaryControlCurves(const std::vector<BoundaryRun>& loops,
  const std::vector<CurveSource>& sources,
  const ControlPointPositions& positions,
  std::vector<ControlSubCurve>& out,
  std::string& error)
{
  out.clear();
  for (std::size_t l = 0; l < loops.size(); ++l)
  {
    const std::vector<BoundaryPointRecord>& points = loops[l].Points;
    const std::size_t m = points.size();
    const std::size_t segments = loops[l].Closed ? m : (m > 0 ? m - 1 : 0);
    if (segments == 0)
    {
      continue;
    }
    for (std::size_t i = 0; i < segments; ++i)
    {
      error = Unusable(sources, points[i].Next.Curve);
      if (!error.empty())
      {
        return false;
      }
    }
    const auto segment = [&](std::size_t i) -> const BoundarySegmentCurve&
    { return points[i % m].Next; };
    // A closed loop's sub-curves start where it goes from one curve to another.
    std::size_t start = 0;
    if (loops[l].Closed)
    {
      start = m;
      for (std::size_t i = 0; i < m && start == m; ++i)
      {
        if (!Continues(sources, segment(i + m - 1), segment(i)))
        {
          start = i;
        }
      }
      if (start == m)
      {
        // One closed curve all around: the whole curve, started as one rank starts it. There
        // the loop's first patch is the curve's first (from its lowest patch end b0 to the
        // next, b1), its pieces joined in walking order: forward from b0; backwards from b1,
        // over [t(b1) - turn, t(b1)]; from the curve's start when nothing meets it.
        const BoundarySegmentCurve& along = segment(0);
        std::vector<std::pair<double, std::size_t>> ends;
        for (std::size_t i = 0; i < m; ++i)
        {
          if (points[i].PatchEnd)
          {
            ends.push_back({ Normalized(sources[along.Curve], segment(i).From), i });
          }
        }
        std::sort(ends.begin(), ends.end());
        const bool backwards = along.Reversed && ends.size() >= 2;
        End from{ 0.0 };
        if (!ends.empty())
        {
          const auto& end = ends[backwards ? 1 : 0];
          from = End{ end.first, &points[end.second] };
        }
        ControlSubCurve whole = MakeSubCurve(sources, positions, along.Curve, from, from, true);
        if (backwards)
        {
          whole.T1 = whole.T0;
          whole.T0 = whole.T1 - whole.Segments;
        }
        whole.Group = static_cast<int>(l);
        whole.Reversed = along.Reversed;
        if (whole.Reversed)
        {
          // Still from its first point (a closed curve does not repeat it).
          std::reverse(whole.Points.begin() + 1, whole.Points.end());
          std::reverse(whole.Positions.begin() + 1, whole.Positions.end());
        }
        out.push_back(std::move(whole));
        continue;
      }
    }
    for (std::size_t k = 0; k < segments;)
    {
      const std::size_t a = start + k;
      std::size_t b = a; // the group's last segment
      while (k + 1 < segments && Continues(sources, segment(b), segment(b + 1)))
      {
        ++b;
        ++k;
      }
      ++k;
      const BoundarySegmentCurve& along = segment(a);
      const End walkFrom{ along.From, &points[a % m] };
      const End walkTo{ segment(b).To, &points[(b + 1) % m] };
      ControlSubCurve sub = along.Reversed
        ? MakeSubCurve(sources, positions, along.Curve, walkTo, walkFrom, false)
        : MakeSubCurve(sources, positions, along.Curve, walkFrom, walkTo, false);
      sub.Group = static_cast<int>(l);
      sub.Reversed = along.Reversed;
      if (sub.Reversed)
      {
        std::reverse(sub.Points.begin(), sub.Points.end());
        std::reverse(sub.Positions.begin(), sub.Positions.end());
      }
      out.push_back(std::move(sub));
    }
  }
  error.clear();
  return true;
}

//------------------------------------------------------------------------------
bool PieceClippedControlCurves(std::vector<ClippedSegment> segments,
  const std::vector<CurveSource>& sources,
  const ControlPointPositions& positions,
  std::vector<ControlSubCurve>& out,
  std::string& error)
{
  out.clear();
  // In curve order; a segment two pieces gave (along an edge between them) once.
  std::sort(segments.begin(),
    segments.end(),
    [](const ClippedSegment& x, const ClippedSegment& y)
    {
      return std::tie(x.Curve, x.From, x.A.Key, x.B.Key) <
        std::tie(y.Curve, y.From, y.A.Key, y.B.Key);
    });
  segments.erase(std::unique(segments.begin(),
                   segments.end(),
                   [](const ClippedSegment& x, const ClippedSegment& y)
                   { return x.Curve == y.Curve && x.A.Key == y.A.Key && x.B.Key == y.B.Key; }),
    segments.end());
  for (std::size_t i = 0; i < segments.size();)
  {
    error = Unusable(sources, segments[i].Curve);
    if (!error.empty())
    {
      return false;
    }
    std::size_t last = i;
    while (last + 1 < segments.size() && segments[last + 1].Curve == segments[i].Curve &&
      segments[last + 1].A.Key == segments[last].B.Key)
    {
      ++last;
    }
    ControlSubCurve piece = MakeSubCurve(sources,
      positions,
      segments[i].Curve,
      End{ segments[i].From, &segments[i].A },
      End{ segments[last].To, &segments[last].B },
      false);
    piece.Group = static_cast<int>(out.size());
    out.push_back(std::move(piece));
    i = last + 1;
  }
  error.clear();
  return true;
}

//------------------------------------------------------------------------------
void PackOwnedControlPositions(const PieceMesh& piece,
  const std::vector<std::vector<SurfacePoint>>& controls,
  std::vector<long long>& out)
{
  const std::size_t countAt = out.size();
  out.push_back(0);
  long long count = 0;
  for (std::size_t c = 0; c < controls.size(); ++c)
  {
    for (std::size_t k = 0; k < controls[c].size(); ++k)
    {
      const SurfacePoint& p = controls[c][k];
      const int t = piece.LocalTriangle(p.Triangle);
      if (t < 0 || !piece.Owned[t])
      {
        continue;
      }
      const Vec3 x = piece.Mesh.Evaluate(t, p.U, p.V);
      out.insert(out.end(),
        { static_cast<long long>(c),
          static_cast<long long>(k),
          WireBitsOf(x.x),
          WireBitsOf(x.y),
          WireBitsOf(x.z) });
      ++count;
    }
  }
  out[countAt] = count;
}

//------------------------------------------------------------------------------
bool UnpackControlPositions(const std::vector<long long>& in,
  std::size_t& at,
  ControlPointPositions& positions,
  std::string& error)
{
  error = "the control points' positions are short or corrupt";
  if (at >= in.size() || in[at] < 0 || static_cast<std::size_t>(in[at]) > (in.size() - at - 1) / 5)
  {
    return false;
  }
  const long long count = in[at++];
  for (long long i = 0; i < count; ++i, at += 5)
  {
    const long long c = in[at], k = in[at + 1];
    if (c < 0 || c >= static_cast<long long>(positions.size()) || k < 0 ||
      k >= static_cast<long long>(positions[c].size()))
    {
      return false;
    }
    positions[c][k] = {
      WireDoubleOf(in[at + 2]), WireDoubleOf(in[at + 3]), WireDoubleOf(in[at + 4])
    };
  }
  error.clear();
  return true;
}

//------------------------------------------------------------------------------
void PackClippedSegments(const std::vector<ClippedSegment>& segments, std::vector<long long>& out)
{
  out.push_back(static_cast<long long>(segments.size()));
  for (const ClippedSegment& s : segments)
  {
    out.insert(
      out.end(), { static_cast<long long>(s.Curve), WireBitsOf(s.From), WireBitsOf(s.To) });
    PackBoundaryPoint(s.A, out);
    PackBoundaryPoint(s.B, out);
  }
}

//------------------------------------------------------------------------------
bool UnpackClippedSegments(const std::vector<long long>& in,
  std::size_t& at,
  std::vector<ClippedSegment>& out,
  std::string& error)
{
  error = "the clipped curves' segments are short or corrupt";
  if (at >= in.size() || in[at] < 0)
  {
    return false;
  }
  const long long count = in[at++];
  for (long long i = 0; i < count; ++i)
  {
    if (in.size() - at < 3)
    {
      return false;
    }
    ClippedSegment s;
    s.Curve = static_cast<int>(in[at]);
    s.From = WireDoubleOf(in[at + 1]);
    s.To = WireDoubleOf(in[at + 2]);
    at += 3;
    if (!UnpackBoundaryPoint(in, at, s.A) || !UnpackBoundaryPoint(in, at, s.B))
    {
      return false;
    }
    out.push_back(std::move(s));
  }
  error.clear();
  return true;
}

} // namespace boolsurf

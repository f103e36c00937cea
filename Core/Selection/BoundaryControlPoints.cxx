#include "Selection/BoundaryControlPoints.h"

#include "Geodesic/GeodesicBezier.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <unordered_map>

namespace boolsurf
{

namespace
{

/// Parameters this close to a control point's are that control point (the stations of
/// intersection points are fractions of traced segments, rounded).
constexpr double SameParameter = 1e-9;

/// The control points of curve `c` from parameter t0 to t1 (t1 > t0; past the end of a closed
/// curve when it wraps), between the arranged points `first` and `last`.
bool SubCurve(GeodesicPathSolver& solver,
  const Arrangement& arrangement,
  const CurveSource& source,
  int first,
  int last,
  double t0,
  double t1,
  bool whole,
  BezierPieces* pieces,
  int curve,
  std::vector<SurfacePoint>& points,
  std::string& error)
{
  const TriangleMesh& mesh = solver.GetMesh();
  const int controls = static_cast<int>(source.Points.size());
  const int segments = NumberOfSourceSegments(source);
  points.clear();
  const double k0 = std::round(t0), k1 = std::round(t1);
  const bool startsAtControl = std::abs(t0 - k0) <= SameParameter;
  const bool endsAtControl = std::abs(t1 - k1) <= SameParameter;
  if (source.Type == CurveType::GeodesicPolygon)
  {
    std::vector<int> own;
    PolygonSubCurveControls(source, t0, t1, whole, own);
    points.reserve(own.size());
    for (std::size_t i = 0; i < own.size(); ++i)
    {
      points.push_back(own[i] >= 0 ? source.Points[static_cast<std::size_t>(own[i])]
                                   : arrangement.GetPointSurface(mesh, i == 0 ? first : last));
    }
    return true;
  }

  // Cubic Bezier: each segment over [t0, t1], cut at the range's ends.
  auto canonical = [&](int k) { return LocateSurfacePoint(mesh, source.Points[k % controls]); };
  std::vector<CanonicalPoint> out;
  const int s0 = static_cast<int>(std::floor(t0 + SameParameter));
  const int s1 = static_cast<int>(std::ceil(t1 - SameParameter));
  for (int s = s0; s < s1; ++s)
  {
    const int seg = ((s % segments) + segments) % segments;
    std::array<CanonicalPoint, 4> piece = {
      canonical(3 * seg), canonical(3 * seg + 1), canonical(3 * seg + 2), canonical(3 * seg + 3)
    };
    const double a = std::max(t0 - s, 0.0), b = std::min(t1 - s, 1.0);
    std::array<CanonicalPoint, 4> left, right;
    bool found = false;
    if (pieces && !pieces->Get(solver, curve, seg, a, b, left, found, error))
    {
      return false;
    }
    if (found)
    {
      piece = left;
    }
    else if (a > SameParameter)
    {
      if (!SplitGeodesicBezier(solver, piece, a, left, right, error))
      {
        return false;
      }
      piece = right;
    }
    if (!found && b < 1 - SameParameter)
    {
      const double local = a > SameParameter ? (b - a) / (1 - a) : b;
      if (!SplitGeodesicBezier(solver, piece, local, left, right, error))
      {
        return false;
      }
      piece = left;
    }
    out.insert(out.end(), out.empty() ? piece.begin() : piece.begin() + 1, piece.end());
  }
  if (whole && out.size() > 1)
  {
    out.pop_back(); // a closed spline does not repeat its first anchor
  }
  for (std::size_t i = 0; i < out.size(); ++i)
  {
    // Anchors that are the user's own keep the user's bits.
    const double t = s0 + static_cast<double>(i) / 3.0;
    const bool anchor = i % 3 == 0;
    const bool own = anchor &&
      ((i == 0 && startsAtControl) || (i + 1 == out.size() && endsAtControl) ||
        (i > 0 && i + 1 < out.size()));
    if (own)
    {
      points.push_back(
        source
          .Points[(3 * static_cast<long long>(std::llround(t)) % controls + controls) % controls]);
    }
    else
    {
      points.push_back(ToSurfacePoint(mesh, out[i]));
    }
  }
  return true;
}

/// The sub-curve of curve `c` made of the arranged points from index `first` on, `count` of
/// them.
/// The parameter range [t0, t1] on curve `c` of its arranged points from index `first` on,
/// `count` of them (t1 past the curve's end when a closed curve's piece passes its start).
void SubCurveRange(const Arrangement& arrangement,
  const std::vector<CurveSource>& sources,
  int c,
  int first,
  int count,
  double& t0,
  double& t1,
  bool& whole)
{
  const CurveSource& source = sources[c];
  const int n = static_cast<int>(arrangement.CurvePoints[c].size());
  const int last = (first + count - 1) % n;
  whole = source.Closed && count == n + 1;
  t0 = ArrangedPointParameter(arrangement, sources, c, first);
  t1 = ArrangedPointParameter(arrangement, sources, c, last);
  SubCurveParameterRange(source, whole, t0, t1);
}

bool MakeSubCurve(GeodesicPathSolver& solver,
  const Arrangement& arrangement,
  const std::vector<CurveSource>& sources,
  int c,
  int first,
  int count,
  BezierPieces* pieces,
  ControlSubCurve& out,
  std::string& error)
{
  const CurveSource& source = sources[c];
  const int n = static_cast<int>(arrangement.CurvePoints[c].size());
  const int last = (first + count - 1) % n;
  out = SubCurveOfSource(sources, c);
  SubCurveRange(arrangement, sources, c, first, count, out.T0, out.T1, out.Whole);
  const bool ok = SubCurve(solver,
    arrangement,
    source,
    arrangement.CurvePoints[c][first],
    arrangement.CurvePoints[c][last],
    out.T0,
    out.T1,
    out.Whole,
    pieces,
    c,
    out.Points,
    error);
  out.Positions.clear();
  out.Positions.reserve(out.Points.size());
  for (const SurfacePoint& p : out.Points)
  {
    out.Positions.push_back(solver.GetMesh().Evaluate(p.Triangle, p.U, p.V));
  }
  return ok;
}

/// Appends `next` to `into` when both are pieces of one curve walked the same way and `next`
/// starts where `into` ends; false (nothing changed) otherwise.
bool Join(ControlSubCurve& into, ControlSubCurve& next)
{
  if (into.Curve != next.Curve || into.Reversed != next.Reversed || into.Type != next.Type ||
    into.Whole || next.Whole || into.Points.empty() || next.Points.empty())
  {
    return false;
  }
  // Forward pieces run T0 -> T1; reversed ones T1 -> T0 (parameters of a closed curve may
  // differ by whole turns).
  const double gap = into.Reversed ? into.T0 - next.T1 : next.T0 - into.T1;
  if (std::abs(gap - std::round(gap)) > SameParameter || std::abs(gap) > 1e6)
  {
    return false;
  }
  // A polygon's junction inside one of its legs is no control point (the leg is one
  // geodesic); a spline keeps it as the anchor between its two split pieces.
  const double junction = into.Reversed ? into.T0 : into.T1;
  if (into.Type == CurveType::GeodesicPolygon &&
    std::abs(junction - std::round(junction)) > SameParameter)
  {
    into.Points.pop_back();
    into.Positions.pop_back();
  }
  if (!into.Reversed)
  {
    into.T1 = next.T1 + (into.T1 - next.T0);
  }
  else
  {
    into.T0 = next.T0 + (into.T0 - next.T1);
  }
  into.Points.insert(into.Points.end(), next.Points.begin() + 1, next.Points.end());
  into.Positions.insert(into.Positions.end(), next.Positions.begin() + 1, next.Positions.end());
  return true;
}

} // namespace

//------------------------------------------------------------------------------
double ArrangedPointParameter(const Arrangement& arrangement,
  const std::vector<CurveSource>& sources,
  int curve,
  int index)
{
  return StationParameter(sources[curve], arrangement.CurveStations[curve][index]);
}

//------------------------------------------------------------------------------
int NumberOfSourceSegments(const CurveSource& source)
{
  const int n = static_cast<int>(source.Points.size());
  if (source.Type == CurveType::CubicBezier)
  {
    return source.Closed ? n / 3 : (n - 1) / 3;
  }
  return source.Closed ? n : n - 1;
}

//------------------------------------------------------------------------------
ControlSubCurve SubCurveOfSource(const std::vector<CurveSource>& sources, int curve)
{
  const CurveSource& source = sources[static_cast<std::size_t>(curve)];
  ControlSubCurve out;
  out.Curve = curve;
  out.Type = source.Type;
  out.Segments = NumberOfSourceSegments(source);
  out.CurveClosed = source.Closed;
  out.SourceShapeId = source.ShapeId;
  out.SourceCurveId = source.CurveId;
  return out;
}

//------------------------------------------------------------------------------
double StationParameter(const CurveSource& source, double station)
{
  const std::vector<double>& parameter = source.Parameter;
  const int n = static_cast<int>(parameter.size());
  const int i = std::min(static_cast<int>(station), n - 1);
  const double f = station - i;
  if (f <= 0)
  {
    return parameter[i];
  }
  const double next = i + 1 < n ? parameter[i + 1] : NumberOfSourceSegments(source);
  return parameter[i] + f * (next - parameter[i]);
}

//------------------------------------------------------------------------------
void PolygonSubCurveControls(const CurveSource& source,
  double t0,
  double t1,
  bool whole,
  std::vector<int>& out)
{
  const int controls = static_cast<int>(source.Points.size());
  const auto control = [&](long long k)
  { return static_cast<int>(((k % controls) + controls) % controls); };
  const double k0 = std::round(t0), k1 = std::round(t1);
  const long long from = static_cast<long long>(std::floor(t0 + SameParameter)) + 1;
  const long long to = static_cast<long long>(std::ceil(t1 - SameParameter)) - 1;
  out.clear();
  out.reserve(static_cast<std::size_t>(std::max(0LL, to - from + 1)) + 2);
  out.push_back(std::abs(t0 - k0) <= SameParameter ? control(static_cast<long long>(k0)) : -1);
  for (long long k = from; k <= to; ++k)
  {
    out.push_back(control(k));
  }
  if (!whole)
  {
    out.push_back(std::abs(t1 - k1) <= SameParameter ? control(static_cast<long long>(k1)) : -1);
  }
}

//------------------------------------------------------------------------------
void SubCurveParameterRange(const CurveSource& source, bool whole, double& t0, double& t1)
{
  // A closed curve's piece that passes the curve's start ends on the next turn; a piece too
  // short for its two parameters to differ stays where it is.
  if (source.Closed && (whole || t1 < t0 - SameParameter))
  {
    t1 += NumberOfSourceSegments(source);
  }
  else if (t1 < t0)
  {
    t1 = t0;
  }
}

//------------------------------------------------------------------------------
BezierPieces::BezierPieces(const Arrangement& arrangement, const std::vector<CurveSource>& sources)
  : Arranged(arrangement)
  , Sources(sources)
  , PatchesOfCurve(sources.size())
  , CurveCut(sources.size(), 0)
{
  for (std::size_t p = 0; p < arrangement.Patches.size(); ++p)
  {
    const ArrangementPatch& patch = arrangement.Patches[p];
    if (patch.Curve >= 0 && patch.Curve < static_cast<int>(sources.size()) && patch.FirstIndex >= 0)
    {
      this->PatchesOfCurve[patch.Curve].push_back(static_cast<int>(p));
    }
  }
}

void BezierPieces::CollectCuts(const TriangleMesh& mesh, int curve, std::vector<SegmentCuts>& jobs)
{
  this->CurveCut[curve] = 1;
  const CurveSource& source = this->Sources[curve];
  if (source.Type != CurveType::CubicBezier || source.Points.empty())
  {
    return;
  }
  const int segments = NumberOfSourceSegments(source);
  const int controls = static_cast<int>(source.Points.size());
  // Every patch end inside a segment (not at its anchors) is a cut of that segment.
  std::vector<std::vector<double>> cuts(segments);
  for (int p : this->PatchesOfCurve[curve])
  {
    const ArrangementPatch& patch = this->Arranged.Patches[p];
    double t0, t1;
    bool whole;
    SubCurveRange(this->Arranged,
      this->Sources,
      curve,
      patch.FirstIndex,
      static_cast<int>(patch.Points.size()),
      t0,
      t1,
      whole);
    for (double t : { t0, t1 })
    {
      const double s = std::floor(t + SameParameter);
      const double local = t - s;
      if (local > SameParameter && local < 1 - SameParameter)
      {
        const int seg = ((static_cast<int>(s) % segments) + segments) % segments;
        cuts[seg].push_back(local);
      }
    }
  }
  for (int seg = 0; seg < segments; ++seg)
  {
    std::vector<double>& at = cuts[seg];
    if (at.empty())
    {
      continue;
    }
    std::sort(at.begin(), at.end());
    // The same cut twice (the end of one patch is the start of the next) is one cut.
    std::size_t kept = 0;
    for (double t : at)
    {
      if (t - (kept > 0 ? at[kept - 1] : 0.0) > SameParameter)
      {
        at[kept++] = t;
      }
    }
    at.resize(kept);
    SegmentCuts job;
    job.Curve = curve;
    job.Segment = seg;
    for (int k = 0; k < 4; ++k)
    {
      job.Whole[k] = LocateSurfacePoint(mesh, source.Points[(3 * seg + k) % controls]);
    }
    job.At = std::move(at);
    jobs.push_back(std::move(job));
  }
}

//------------------------------------------------------------------------------
bool BezierPieces::CutCurve(GeodesicPathSolver& solver, int curve, std::string& error)
{
  std::vector<SegmentCuts> jobs;
  this->CollectCuts(solver.GetMesh(), curve, jobs);
  for (const SegmentCuts& job : jobs)
  {
    std::vector<Piece>& pieces =
      this->Segments[(static_cast<long long>(job.Curve) << 32) | job.Segment];
    if (!CutSegmentRecursively(
          solver, job.Whole, 0.0, 1.0, job.At.data(), job.At.data() + job.At.size(), pieces, error))
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
// Segments are independent (each is split from its own control polygon), and so are the two
// halves of a split: every split of a level is one task (CutSegmentsByLevels); a segment's
// pieces are what CutCurve gives them, since a leg does not depend on the solver.
bool BezierPieces::CutCurves(const std::vector<int>& curves,
  const std::vector<GeodesicPathSolver*>& solvers,
  std::string& error)
{
  if (solvers.empty())
  {
    return true;
  }
  std::vector<SegmentCuts> jobs;
  for (int curve : curves)
  {
    if (curve >= 0 && curve < static_cast<int>(this->Sources.size()) && !this->CurveCut[curve])
    {
      this->CollectCuts(solvers[0]->GetMesh(), curve, jobs);
    }
  }
  std::vector<BezierCutJob> cuts(jobs.size());
  for (std::size_t j = 0; j < jobs.size(); ++j)
  {
    cuts[j] = { &jobs[j].Whole, &jobs[j].At };
  }
  std::vector<std::vector<Piece>> pieces;
  std::vector<std::string> errors;
  std::vector<char> cut;
  CutSegmentsByLevels(solvers, cuts, pieces, errors, cut);
  for (std::size_t j = 0; j < jobs.size(); ++j)
  {
    if (!cut[j])
    {
      error = errors[j];
      return false;
    }
    this->Segments[(static_cast<long long>(jobs[j].Curve) << 32) | jobs[j].Segment] =
      std::move(pieces[j]);
  }
  return true;
}

//------------------------------------------------------------------------------
bool BezierPieces::Get(GeodesicPathSolver& solver,
  int curve,
  int segment,
  double a,
  double b,
  std::array<CanonicalPoint, 4>& out,
  bool& found,
  std::string& error)
{
  found = false;
  if (curve < 0 || curve >= static_cast<int>(this->Sources.size()))
  {
    return true;
  }
  if (!this->CurveCut[curve])
  {
    if (!this->CutCurve(solver, curve, error))
    {
      return false;
    }
  }
  auto it = this->Segments.find((static_cast<long long>(curve) << 32) | segment);
  if (it == this->Segments.end())
  {
    return true;
  }
  // The pieces tile the segment left to right (CutSegmentRecursively): a binary search, not a scan,
  // since a segment that another curve runs along holds thousands of them and every patch asks.
  const std::vector<Piece>& pieces = it->second;
  auto piece = std::lower_bound(pieces.begin(),
    pieces.end(),
    a - SameParameter,
    [](const Piece& p, double value) { return p.A < value; });
  for (; piece != pieces.end() && piece->A <= a + SameParameter; ++piece)
  {
    if (std::abs(piece->B - b) <= SameParameter)
    {
      out = piece->Controls;
      found = true;
      break;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool PatchControlCurve(GeodesicPathSolver& solver,
  const Arrangement& arrangement,
  const std::vector<CurveSource>& sources,
  int patch,
  ControlSubCurve& out,
  std::string& error,
  BezierPieces* pieces)
{
  const ArrangementPatch& p = arrangement.Patches[patch];
  out = ControlSubCurve();
  if (p.Curve < 0 || p.FirstIndex < 0)
  {
    return true;
  }
  return MakeSubCurve(solver,
    arrangement,
    sources,
    p.Curve,
    p.FirstIndex,
    static_cast<int>(p.Points.size()),
    pieces,
    out,
    error);
}

//------------------------------------------------------------------------------
void AssembleBoundaryLoops(const std::function<const ControlSubCurve*(int)>& patchCurve,
  const std::vector<BoundaryPolyline>& loops,
  std::vector<ControlSubCurve>& out)
{
  out.clear();
  for (std::size_t l = 0; l < loops.size(); ++l)
  {
    const BoundaryPolyline& loop = loops[l];
    const int firstOfLoop = static_cast<int>(out.size());
    for (std::size_t k = 0; k < loop.Patches.size(); ++k)
    {
      const ControlSubCurve* piece = patchCurve(loop.Patches[k]);
      if (!piece || piece->Curve < 0 || piece->Points.empty())
      {
        continue;
      }
      ControlSubCurve sub = *piece;
      sub.Group = static_cast<int>(l);
      sub.Reversed = loop.Reversed[k] != 0;
      if (sub.Reversed)
      {
        // A whole closed curve lists its points without the closing repeat: reversed, it
        // must still start at its first point (a spline's anchor, not the handle before it).
        const std::ptrdiff_t keep = sub.Whole ? 1 : 0;
        std::reverse(sub.Points.begin() + keep, sub.Points.end());
        std::reverse(sub.Positions.begin() + keep, sub.Positions.end());
      }
      // Patches also end where an open curve or a curve of no consequence crosses: pieces of
      // one curve that follow each other are one sub-curve.
      if (static_cast<int>(out.size()) > firstOfLoop && Join(out.back(), sub))
      {
        continue;
      }
      out.push_back(std::move(sub));
    }
    // The loop's last piece may continue into its first.
    if (static_cast<int>(out.size()) > firstOfLoop + 1 && Join(out.back(), out[firstOfLoop]))
    {
      out[firstOfLoop] = std::move(out.back());
      out.pop_back();
    }
    // One piece that goes all around its closed curve is the whole curve.
    if (static_cast<int>(out.size()) == firstOfLoop + 1)
    {
      ControlSubCurve& only = out.back();
      if (only.CurveClosed && !only.Whole &&
        std::abs(only.T1 - only.T0 - only.Segments) <= SameParameter && only.Points.size() > 1)
      {
        only.Whole = true;
        only.Points.pop_back();
        only.Positions.pop_back();
      }
    }
  }
}

//------------------------------------------------------------------------------
void AssembleClippedPieces(const std::function<const ControlSubCurve*(int)>& patchCurve,
  const std::vector<PatchInfo>& patches,
  const std::vector<char>& selected,
  std::vector<ControlSubCurve>& out)
{
  out.clear();
  auto inside = [&](const PatchInfo& p)
  {
    auto in = [&](int cell)
    { return cell >= 0 && cell < static_cast<int>(selected.size()) && selected[cell]; };
    return !p.Closed && p.Curve >= 0 && (in(p.LeftCell) || in(p.RightCell));
  };
  int group = 0;
  // Patches of one curve are consecutive and in curve order.
  for (std::size_t p = 0; p < patches.size(); ++p)
  {
    const ControlSubCurve* piece = patchCurve(static_cast<int>(p));
    if (!inside(patches[p]) || !piece || piece->Points.empty())
    {
      continue;
    }
    const bool continues =
      p > 0 && !out.empty() && inside(patches[p - 1]) && patches[p - 1].Curve == patches[p].Curve;
    ControlSubCurve sub = *piece;
    if (continues && Join(out.back(), sub))
    {
      continue;
    }
    sub.Group = group++;
    out.push_back(std::move(sub));
  }
}

//------------------------------------------------------------------------------
bool BoundaryControlCurves(GeodesicPathSolver& solver,
  const Arrangement& arrangement,
  const std::vector<CurveSource>& sources,
  const std::vector<BoundaryPolyline>& loops,
  std::vector<ControlSubCurve>& out,
  std::string& error,
  BezierPieces* shared)
{
  // Only the boundary's patches are computed (a Bezier piece costs geodesic splits).
  std::unique_ptr<BezierPieces> local;
  if (!shared)
  {
    local = std::make_unique<BezierPieces>(arrangement, sources);
  }
  BezierPieces& bezier = shared ? *shared : *local;
  std::unordered_map<int, ControlSubCurve> pieces;
  for (const BoundaryPolyline& loop : loops)
  {
    for (int p : loop.Patches)
    {
      if (pieces.count(p) == 0)
      {
        if (!PatchControlCurve(solver, arrangement, sources, p, pieces[p], error, &bezier))
        {
          return false;
        }
      }
    }
  }
  AssembleBoundaryLoops(
    [&](int p)
    {
      auto it = pieces.find(p);
      return it == pieces.end() ? nullptr : &it->second;
    },
    loops,
    out);
  return true;
}

//------------------------------------------------------------------------------
bool ClippedControlCurves(GeodesicPathSolver& solver,
  const Arrangement& arrangement,
  const std::vector<CurveSource>& sources,
  const std::vector<char>& selected,
  std::vector<ControlSubCurve>& out,
  std::string& error,
  BezierPieces* shared)
{
  std::vector<PatchInfo> info(arrangement.Patches.size());
  std::unique_ptr<BezierPieces> local;
  if (!shared)
  {
    local = std::make_unique<BezierPieces>(arrangement, sources);
  }
  BezierPieces& bezier = shared ? *shared : *local;
  std::unordered_map<int, ControlSubCurve> pieces;
  for (std::size_t p = 0; p < info.size(); ++p)
  {
    const ArrangementPatch& patch = arrangement.Patches[p];
    info[p] = { patch.Curve, patch.Closed, patch.LeftCell, patch.RightCell };
    const bool inside = [&](int a, int b)
    {
      auto in = [&](int cell)
      { return cell >= 0 && cell < static_cast<int>(selected.size()) && selected[cell]; };
      return in(a) || in(b);
    }(patch.LeftCell, patch.RightCell);
    if (!patch.Closed && inside)
    {
      if (!PatchControlCurve(
            solver, arrangement, sources, static_cast<int>(p), pieces[p], error, &bezier))
      {
        return false;
      }
    }
  }
  AssembleClippedPieces(
    [&](int p)
    {
      auto it = pieces.find(p);
      return it == pieces.end() ? nullptr : &it->second;
    },
    info,
    selected,
    out);
  return true;
}

} // namespace boolsurf

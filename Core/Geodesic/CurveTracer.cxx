#include "Geodesic/CurveTracer.h"

#include "Geodesic/WrittenCurvePoints.h"

#include <algorithm>
#include <functional>
#include <iterator>
#include <tuple>

namespace boolsurf
{
namespace
{
std::string CurveLabel(int curveId)
{
  return "curve " + std::to_string(curveId);
}
} // namespace

//------------------------------------------------------------------------------
void CurveTrace::Clear()
{
  this->Curve.Points.clear();
  this->Segment.clear();
  this->ControlPoint.clear();
  this->Parameter.clear();
  this->OnCurve.clear();
  this->Length = 0.0;
  this->Positions.clear();
  this->Written.clear();
}

//------------------------------------------------------------------------------
void CurveTrace::DropRepeatedClosingPoint()
{
  if (this->Curve.Points.size() > 1 && this->Curve.Points.back() == this->Curve.Points[0])
  {
    this->Curve.Points.pop_back();
    this->Segment.pop_back();
    this->ControlPoint.pop_back();
    this->Parameter.pop_back();
    this->OnCurve.pop_back();
  }
}

//------------------------------------------------------------------------------
CurveTracer::CurveTracer(const TriangleMesh& mesh)
  : Solver(mesh)
{
}

//------------------------------------------------------------------------------
void CurveTracer::SetResolution(int levels)
{
  this->Resolution = std::max(0, std::min(levels, 16));
}

//------------------------------------------------------------------------------
void CurveTracer::AppendPoint(const CanonicalPoint& computed,
  int segment,
  int control,
  double parameter,
  bool onCurve,
  CurveTrace& out) const
{
  // A computed point inside a triangle but within SurfacePointSnap of its edge is located the
  // way every reader of the written curve will locate it, so a traced curve reads back as
  // itself.
  const CanonicalPoint p = computed.Location == PointLocation::Face
    ? LocateSurfacePoint(
        this->Solver.GetMesh(), SurfacePoint{ computed.Id, computed.U, computed.V })
    : computed;
  // Joints (end of one path, start of the next) arrive twice; the first copy stays.
  if (!out.Curve.Points.empty() && out.Curve.Points.back() == p)
  {
    if (control >= 0 && out.ControlPoint.back() < 0)
    {
      out.ControlPoint.back() = control;
    }
    out.OnCurve.back() = out.OnCurve.back() || onCurve;
    return;
  }
  out.Curve.Points.push_back(p);
  out.Segment.push_back(segment);
  out.ControlPoint.push_back(control);
  out.Parameter.push_back(parameter);
  out.OnCurve.push_back(onCurve);
}

//------------------------------------------------------------------------------
void CurveTracer::AppendPath(const GeodesicPath& path,
  int segment,
  double t0,
  double t1,
  int firstControl,
  int lastControl,
  bool firstOnCurve,
  bool lastOnCurve,
  bool interiorOnCurve,
  CurveTrace& out) const
{
  const TriangleMesh& mesh = this->Solver.GetMesh();
  const size_t n = path.Points.size();
  double walked = 0.0;
  for (size_t k = 0; k < n; ++k)
  {
    if (k > 0)
    {
      walked += Distance(PositionOf(mesh, path.Points[k - 1]), PositionOf(mesh, path.Points[k]));
    }
    const bool first = k == 0, last = k + 1 == n;
    const double fraction = last ? 1.0 : (path.Length > 0.0 ? walked / path.Length : 0.0);
    const int control = first ? firstControl : (last ? lastControl : -1);
    const bool onCurve = first ? firstOnCurve : (last ? lastOnCurve : interiorOnCurve);
    this->AppendPoint(
      path.Points[k], segment, control, segment + t0 + (t1 - t0) * fraction, onCurve, out);
  }
}

//------------------------------------------------------------------------------
TraceStatus CurveTracer::TraceGeodesicPolygon(const std::vector<CanonicalPoint>& points,
  bool closed,
  CurveTrace& out,
  int curveId)
{
  out.Clear();
  out.Curve.Closed = closed;
  out.Curve.CurveId = curveId;
  const int n = static_cast<int>(points.size());
  if (n < 2)
  {
    return TraceStatus::Failure(CurveLabel(curveId) +
      ": a geodesic polygon needs at least 2 control points, got " + std::to_string(n));
  }
  const int segments = closed ? n : n - 1;
  for (int i = 0; i < segments; ++i)
  {
    const int j = (i + 1) % n;
    const TraceStatus status = this->ComputeLeg(points[i], points[j], this->Path);
    if (!status)
    {
      out.Clear();
      return TraceStatus::Failure(CurveLabel(curveId) + ", segment " + std::to_string(i) +
        " (control points " + std::to_string(i) + " and " + std::to_string(j) +
        "): " + status.Message);
    }
    this->AppendPath(this->Path, i, 0.0, 1.0, i, j, true, true, true, out);
    out.Length += this->Path.Length;
  }
  if (closed)
  {
    out.DropRepeatedClosingPoint();
  }
  return TraceStatus::Success();
}

//------------------------------------------------------------------------------
TraceStatus CurveTracer::ComputeLeg(const CanonicalPoint& a,
  const CanonicalPoint& b,
  GeodesicPath& path)
{
  const auto key = [](const CanonicalPoint& p)
  { return std::make_tuple(static_cast<int>(p.Location), p.Id, p.T, p.U, p.V); };
  if (!(key(b) < key(a)))
  {
    return this->Solver.Compute(a, b, path);
  }
  const TraceStatus status = this->Solver.Compute(b, a, path);
  std::reverse(path.Points.begin(), path.Points.end());
  return status;
}

//------------------------------------------------------------------------------
TraceStatus CurveTracer::TraceBezierSpline(const std::vector<CanonicalPoint>& points,
  bool closed,
  CurveTrace& out,
  int curveId)
{
  out.Clear();
  out.Curve.Closed = closed;
  out.Curve.CurveId = curveId;
  const int n = static_cast<int>(points.size());
  if (closed ? (n < 3 || n % 3 != 0) : (n < 4 || n % 3 != 1))
  {
    return TraceStatus::Failure(CurveLabel(curveId) + ": " +
      (closed ? "a closed cubic Bezier spline needs 3n control points"
              : "an open cubic Bezier spline needs 3n+1 control points") +
      " (anchor, handle, handle, anchor, ...), got " + std::to_string(n));
  }
  const int segments = closed ? n / 3 : (n - 1) / 3;
  const int pieces = 1 << this->Resolution;
  for (int i = 0; i < segments; ++i)
  {
    const int last = (3 * i + 3) % n;
    const std::array<CanonicalPoint, 4> segment{
      points[3 * i], points[3 * i + 1], points[3 * i + 2], points[last]
    };
    TraceStatus status =
      SubdivideGeodesicBezier(this->Solver, segment, this->Resolution, this->Refined);
    for (int k = 0; status && k < pieces; ++k)
    {
      // The piece's three legs share the parameter range [k, k+1] / pieces by arc length;
      // only the anchors are exactly on the curve.
      const double t0 = static_cast<double>(k) / pieces, t1 = static_cast<double>(k + 1) / pieces;
      double legLength[3];
      GeodesicPath legs[3];
      for (int leg = 0; leg < 3 && status; ++leg)
      {
        status =
          this->ComputeLeg(this->Refined[3 * k + leg], this->Refined[3 * k + leg + 1], legs[leg]);
        legLength[leg] = legs[leg].Length;
      }
      if (!status)
      {
        break;
      }
      const double total = legLength[0] + legLength[1] + legLength[2];
      double start = 0.0;
      for (int leg = 0; leg < 3; ++leg)
      {
        const double a = total > 0 ? t0 + (t1 - t0) * start / total : t0 + (t1 - t0) * leg / 3.0;
        start += legLength[leg];
        const double b =
          total > 0 ? t0 + (t1 - t0) * start / total : t0 + (t1 - t0) * (leg + 1) / 3.0;
        const int firstControl = (leg == 0 && k == 0) ? 3 * i : -1;
        const int lastControl = (leg == 2 && k == pieces - 1) ? last : -1;
        // Only the anchor ends (start of leg 0, end of leg 2) are on the curve.
        this->AppendPath(legs[leg],
          i,
          a,
          leg == 2 ? t1 : b,
          firstControl,
          lastControl,
          leg == 0,
          leg == 2,
          false,
          out);
        out.Length += legLength[leg];
      }
    }
    if (!status)
    {
      out.Clear();
      return TraceStatus::Failure(CurveLabel(curveId) + ", Bezier segment " + std::to_string(i) +
        " (control points " + std::to_string(3 * i) + " to " + std::to_string(last) +
        "): " + status.Message);
    }
  }
  if (closed)
  {
    out.DropRepeatedClosingPoint();
  }
  return TraceStatus::Success();
}

//------------------------------------------------------------------------------
TraceStatus CurveTracer::Trace(const std::vector<SurfacePoint>& points,
  CurveType type,
  bool closed,
  CurveTrace& out,
  int curveId)
{
  out.Clear();
  const TriangleMesh& mesh = this->Solver.GetMesh();
  std::vector<CanonicalPoint> canonical(points.size());
  std::string problem;
  for (size_t i = 0; i < points.size(); ++i)
  {
    if (!CheckSurfacePoint(mesh, points[i], problem))
    {
      return TraceStatus::Failure(
        CurveLabel(curveId) + ", control point " + std::to_string(i) + ": " + problem);
    }
    // A weight within rounding of zero puts the point on the edge (or vertex): a point 1e-16
    // inside a triangle would make its paths cross that edge and come straight back, a
    // zero-length excursion that the arrangement cannot orient. Every reader of surface points
    // uses this same tolerance (SurfacePointSnap).
    canonical[i] = LocateSurfacePoint(mesh, points[i]);
  }
  CurveKey key{ std::move(canonical), type, closed, this->Resolution, this->Solver.GetMethod() };
  auto known = this->Memory.find(key);
  if (known != this->Memory.end())
  {
    known->second.Pass = this->Pass;
    if (this->KeepWrittenForms && known->second.Trace.Written.empty())
    {
      ComputeWrittenForms(mesh, known->second.Trace); // remembered before they were kept
    }
    out = known->second.Trace;
    if (!this->KeepWrittenForms)
    {
      out.Positions.clear();
      out.Written.clear();
    }
    out.Curve.CurveId = curveId;
    ++this->Recalled;
    return TraceStatus::Success();
  }
  TraceStatus status;
  switch (type)
  {
    case CurveType::GeodesicPolygon:
      status = this->TraceGeodesicPolygon(key.Points, closed, out, curveId);
      break;
    case CurveType::CubicBezier:
      status = this->TraceBezierSpline(key.Points, closed, out, curveId);
      break;
    default:
      return TraceStatus::Failure(CurveLabel(curveId) + ": unknown curve type " +
        std::to_string(static_cast<int>(type)) + " (0: geodesic polygon, 1: cubic Bezier)");
  }
  if (status && this->KeepWrittenForms)
  {
    ComputeWrittenForms(mesh, out);
  }
  constexpr std::size_t MemoryLimit = std::size_t(1) << 20;
  if (status && out.Curve.Points.size() <= MemoryLimit)
  {
    if (this->MemoryPoints + out.Curve.Points.size() > MemoryLimit)
    {
      this->Memory.clear();
      this->MemoryPoints = 0;
    }
    RememberedCurve& entry = this->Memory[std::move(key)];
    this->MemoryPoints += out.Curve.Points.size() - entry.Trace.Curve.Points.size();
    entry.Trace = out;
    entry.Pass = this->Pass;
  }
  return status;
}

//------------------------------------------------------------------------------
void CurveTracer::StartPass()
{
  for (auto it = this->Memory.begin(); it != this->Memory.end();)
  {
    if (it->second.Pass < this->Pass)
    {
      this->MemoryPoints -= it->second.Trace.Curve.Points.size();
      it = this->Memory.erase(it);
    }
    else
    {
      ++it;
    }
  }
  ++this->Pass;
}

//------------------------------------------------------------------------------
bool CurveTracer::CurveKey::operator==(const CurveKey& o) const
{
  return this->Type == o.Type && this->Closed == o.Closed && this->Resolution == o.Resolution &&
    this->Method == o.Method && this->Points == o.Points;
}

std::size_t CurveTracer::CurveKeyHash::operator()(const CurveKey& k) const
{
  std::size_t h = static_cast<std::size_t>(k.Type) * 31 + (k.Closed ? 17 : 0) +
    static_cast<std::size_t>(k.Resolution) * 131 + static_cast<std::size_t>(k.Method) * 7;
  auto mix = [&h](std::size_t v) { h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2); };
  for (const CanonicalPoint& p : k.Points)
  {
    mix(static_cast<std::size_t>(p.Location));
    mix(std::hash<int>()(p.Id));
    mix(std::hash<double>()(p.U));
    mix(std::hash<double>()(p.V));
    mix(std::hash<double>()(p.T));
  }
  return h;
}

} // namespace boolsurf

#include "Geodesic/CurveTracer.h"

#include "Geodesic/SlotTasks.h"

#include "Geodesic/WrittenCurvePoints.h"

#include <algorithm>
#include <atomic>
#include <functional>
#include <iterator>
#include <limits>
#include <thread>

#include <tbb/info.h>
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
CurveTracer::CurveTracer(const TriangleMesh& mesh,
  std::shared_ptr<const TriangleComponents> components)
  : Solver(mesh, std::move(components))
{
}

//------------------------------------------------------------------------------
CurveTracer::CurveTracer(const CurveTracer& main, GeodesicPathSolver::HelperTag tag)
  : Solver(main.Solver, tag)
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
int CurveTracer::CountPieces(const std::vector<CanonicalPoint>& points,
  CurveType type,
  bool closed,
  int curveId,
  std::string& error) const
{
  const int n = static_cast<int>(points.size());
  if (type == CurveType::GeodesicPolygon)
  {
    if (n < 2)
    {
      error = CurveLabel(curveId) + ": a geodesic polygon needs at least 2 control points, got " +
        std::to_string(n);
      return -1;
    }
    return closed ? n : n - 1;
  }
  if (closed ? (n < 3 || n % 3 != 0) : (n < 4 || n % 3 != 1))
  {
    error = CurveLabel(curveId) + ": " +
      (closed ? "a closed cubic Bezier spline needs 3n control points"
              : "an open cubic Bezier spline needs 3n+1 control points") +
      " (anchor, handle, handle, anchor, ...), got " + std::to_string(n);
    return -1;
  }
  return closed ? n / 3 : (n - 1) / 3;
}

//------------------------------------------------------------------------------
bool CurveTracer::ComputePiece(const std::vector<CanonicalPoint>& points,
  CurveType type,
  int piece,
  int curveId,
  PieceLegs& legs)
{
  const int n = static_cast<int>(points.size());
  std::string legError;
  if (type == CurveType::GeodesicPolygon)
  {
    const int i = piece, j = (i + 1) % n;
    legs.Legs.resize(1);
    legs.Ok = this->ComputeLeg(points[i], points[j], legs.Legs[0], legError);
    if (!legs.Ok)
    {
      legs.Error = CurveLabel(curveId) + ", segment " + std::to_string(i) + " (control points " +
        std::to_string(i) + " and " + std::to_string(j) + "): " + legError;
    }
    return legs.Ok;
  }
  const int i = piece, last = (3 * i + 3) % n;
  const std::array<CanonicalPoint, 4> segment{
    points[3 * i], points[3 * i + 1], points[3 * i + 2], points[last]
  };
  const int pieces = 1 << this->Resolution;
  legs.Legs.resize(static_cast<std::size_t>(3 * pieces));
  legs.Ok =
    SubdivideGeodesicBezier(this->Solver, segment, this->Resolution, this->Refined, legError);
  for (int leg = 0; legs.Ok && leg < 3 * pieces; ++leg)
  {
    legs.Ok =
      this->ComputeLeg(this->Refined[leg], this->Refined[leg + 1], legs.Legs[leg], legError);
  }
  if (!legs.Ok)
  {
    legs.Error = CurveLabel(curveId) + ", Bezier segment " + std::to_string(i) +
      " (control points " + std::to_string(3 * i) + " to " + std::to_string(last) +
      "): " + legError;
  }
  return legs.Ok;
}

//------------------------------------------------------------------------------
void CurveTracer::AppendPiece(const std::vector<CanonicalPoint>& points,
  CurveType type,
  int piece,
  const PieceLegs& legs,
  CurveTrace& out) const
{
  const int n = static_cast<int>(points.size());
  if (type == CurveType::GeodesicPolygon)
  {
    const int i = piece;
    this->AppendPath(legs.Legs[0], i, 0.0, 1.0, i, (i + 1) % n, true, true, true, out);
    out.Length += legs.Legs[0].Length;
    return;
  }
  const int i = piece, last = (3 * i + 3) % n;
  const int pieces = 1 << this->Resolution;
  for (int k = 0; k < pieces; ++k)
  {
    // The piece's three legs share the parameter range [k, k+1] / pieces by arc length;
    // only the anchors are exactly on the curve.
    const double t0 = static_cast<double>(k) / pieces, t1 = static_cast<double>(k + 1) / pieces;
    double legLength[3];
    for (int leg = 0; leg < 3; ++leg)
    {
      legLength[leg] = legs.Legs[3 * k + leg].Length;
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
      this->AppendPath(legs.Legs[3 * k + leg],
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
}

//------------------------------------------------------------------------------
bool CurveTracer::TracePieces(const std::vector<CanonicalPoint>& points,
  CurveType type,
  bool closed,
  CurveTrace& out,
  std::string& error,
  int curveId)
{
  out.Clear();
  out.Curve.Closed = closed;
  out.Curve.CurveId = curveId;
  const int pieces = this->CountPieces(points, type, closed, curveId, error);
  if (pieces < 0)
  {
    return false;
  }
  for (int i = 0; i < pieces; ++i)
  {
    if (!this->ComputePiece(points, type, i, curveId, this->Legs))
    {
      out.Clear();
      error = this->Legs.Error;
      return false;
    }
    this->AppendPiece(points, type, i, this->Legs, out);
  }
  if (closed)
  {
    out.DropRepeatedClosingPoint();
  }
  return true;
}

//------------------------------------------------------------------------------
bool CurveTracer::TraceGeodesicPolygon(const std::vector<CanonicalPoint>& points,
  bool closed,
  CurveTrace& out,
  std::string& error,
  int curveId)
{
  return this->TracePieces(points, CurveType::GeodesicPolygon, closed, out, error, curveId);
}

//------------------------------------------------------------------------------
bool CurveTracer::ComputeLeg(const CanonicalPoint& a,
  const CanonicalPoint& b,
  GeodesicPath& path,
  std::string& error)
{
  const auto key = [](const CanonicalPoint& p)
  { return std::make_tuple(static_cast<int>(p.Location), p.Id, p.T, p.U, p.V); };
  if (!(key(b) < key(a)))
  {
    return this->Solver.Compute(a, b, path, error);
  }
  const bool ok = this->Solver.Compute(b, a, path, error);
  std::reverse(path.Points.begin(), path.Points.end());
  return ok;
}

//------------------------------------------------------------------------------
bool CurveTracer::TraceBezierSpline(const std::vector<CanonicalPoint>& points,
  bool closed,
  CurveTrace& out,
  std::string& error,
  int curveId)
{
  return this->TracePieces(points, CurveType::CubicBezier, closed, out, error, curveId);
}

//------------------------------------------------------------------------------
bool CurveTracer::Trace(const std::vector<SurfacePoint>& points,
  CurveType type,
  bool closed,
  CurveTrace& out,
  std::string& error,
  int curveId)
{
  out.Clear();
  CurveKey key;
  if (!this->MakeKey(points, type, closed, curveId, key, error))
  {
    return false;
  }
  if (this->Recall(key, out, curveId))
  {
    return true;
  }
  if (!this->TraceNew(key, out, curveId, error))
  {
    return false;
  }
  this->Remember(std::move(key), out);
  return true;
}

//------------------------------------------------------------------------------
bool CurveTracer::MakeKey(const std::vector<SurfacePoint>& points,
  CurveType type,
  bool closed,
  int curveId,
  CurveKey& key,
  std::string& error) const
{
  const TriangleMesh& mesh = this->Solver.GetMesh();
  key.Points.resize(points.size());
  std::string problem;
  for (size_t i = 0; i < points.size(); ++i)
  {
    if (!CheckSurfacePoint(mesh, points[i], problem))
    {
      error = CurveLabel(curveId) + ", control point " + std::to_string(i) + ": " + problem;
      return false;
    }
    // A weight within rounding of zero puts the point on the edge (or vertex): a point 1e-16
    // inside a triangle would make its paths cross that edge and come straight back, a
    // zero-length excursion that the arrangement cannot orient. Every reader of surface points
    // uses this same tolerance (SurfacePointSnap).
    key.Points[i] = LocateSurfacePoint(mesh, points[i]);
  }
  key.Type = type;
  key.Closed = closed;
  key.Resolution = this->Resolution;
  key.Options = this->Solver.GetOptions();
  return true;
}

//------------------------------------------------------------------------------
bool CurveTracer::Recall(const CurveKey& key, CurveTrace& out, int curveId)
{
  auto known = this->Memory.find(key);
  if (known == this->Memory.end())
  {
    return false;
  }
  known->second.Pass = this->Pass;
  if (this->KeepWrittenForms && known->second.Trace.Written.empty())
  {
    ComputeWrittenForms(this->Solver.GetMesh(), known->second.Trace); // remembered before
  }
  out = known->second.Trace;
  if (!this->KeepWrittenForms)
  {
    out.Positions.clear();
    out.Written.clear();
  }
  out.Curve.CurveId = curveId;
  ++this->Recalled;
  return true;
}

//------------------------------------------------------------------------------
bool CurveTracer::TraceNew(const CurveKey& key, CurveTrace& out, int curveId, std::string& error)
{
  bool ok = false;
  switch (key.Type)
  {
    case CurveType::GeodesicPolygon:
    case CurveType::CubicBezier:
      ok = this->TracePieces(key.Points, key.Type, key.Closed, out, error, curveId);
      break;
    default:
      error = CurveLabel(curveId) + ": unknown curve type " +
        std::to_string(static_cast<int>(key.Type)) + " (0: geodesic polygon, 1: cubic Bezier)";
      return false;
  }
  if (ok && this->KeepWrittenForms)
  {
    ComputeWrittenForms(this->Solver.GetMesh(), out);
  }
  return ok;
}

//------------------------------------------------------------------------------
void CurveTracer::Remember(CurveKey&& key, const CurveTrace& trace)
{
  constexpr std::size_t MemoryLimit = std::size_t(1) << 20;
  if (trace.Curve.Points.size() > MemoryLimit)
  {
    return;
  }
  if (this->MemoryPoints + trace.Curve.Points.size() > MemoryLimit)
  {
    this->Memory.clear();
    this->MemoryPoints = 0;
  }
  RememberedCurve& entry = this->Memory[std::move(key)];
  this->MemoryPoints += trace.Curve.Points.size() - entry.Trace.Curve.Points.size();
  entry.Trace = trace;
  entry.Pass = this->Pass;
}

//------------------------------------------------------------------------------
int CurveTracer::PrepareHelpers(int threads, std::size_t tasks)
{
  // No more threads than cores (TBB would not give them) nor than tasks.
  const int cores = std::max(1, tbb::info::default_concurrency());
  int workers = threads > 0 ? std::min(threads, cores) : cores;
  workers = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(workers), tasks));
  if (this->Solver.GetOptions().Method == GeodesicMethod::LocallyShortest)
  {
    workers = 1;
  }
  while (static_cast<int>(this->Helpers.size()) < workers - 1)
  {
    this->Helpers.push_back(
      std::unique_ptr<CurveTracer>(new CurveTracer(*this, GeodesicPathSolver::HelperTag())));
  }
  for (int k = 0; k + 1 < workers; ++k)
  {
    CurveTracer& helper = *this->Helpers[k];
    helper.Resolution = this->Resolution;
    helper.KeepWrittenForms = this->KeepWrittenForms;
    helper.Solver.SetOptions(this->Solver.GetOptions());
  }
  return std::max(1, workers);
}

//------------------------------------------------------------------------------
std::vector<GeodesicPathSolver*> CurveTracer::GetSolvers(int threads)
{
  const int workers = this->PrepareHelpers(threads, std::numeric_limits<std::size_t>::max());
  std::vector<GeodesicPathSolver*> solvers{ &this->Solver };
  for (int k = 0; k + 1 < workers; ++k)
  {
    solvers.push_back(&this->Helpers[k]->Solver);
  }
  return solvers;
}

//------------------------------------------------------------------------------
void CurveTracer::TraceCurves(const std::vector<const ControlCurve*>& curves,
  int threads,
  std::vector<CurveTrace>& out,
  std::vector<std::string>& errors,
  const std::function<bool(double)>& progress)
{
  const std::size_t n = curves.size();
  out.assign(n, CurveTrace());
  errors.assign(n, std::string());
  // Validation and the memory first, in order, on this thread.
  std::vector<CurveKey> keys(n);
  std::vector<std::size_t> todo;
  for (std::size_t c = 0; c < n; ++c)
  {
    const ControlCurve& r = *curves[c];
    if (this->MakeKey(r.Points, r.Type, r.Closed, r.CurveId, keys[c], errors[c]) &&
      !this->Recall(keys[c], out[c], r.CurveId))
    {
      todo.push_back(c);
    }
  }
  // The pieces of a curve (a polygon's legs, a Bezier's segments) are independent once the
  // control points are known. A curve holding a large share of all the pieces (one long curve
  // among short ones, or alone) is split into its pieces, so that it is traced on every thread,
  // then assembled from them in order, as Trace() would; the other curves are one task each
  // (their legs traced in order into one buffer: splitting them only adds copies).
  std::vector<int> pieces(todo.size(), 0);
  std::size_t totalPieces = 0;
  for (std::size_t k = 0; k < todo.size(); ++k)
  {
    const std::size_t c = todo[k];
    const CurveKey& key = keys[c];
    if (key.Type == CurveType::GeodesicPolygon || key.Type == CurveType::CubicBezier)
    {
      out[c].Curve.Closed = key.Closed;
      out[c].Curve.CurveId = curves[c]->CurveId;
      pieces[k] = std::max(
        0, this->CountPieces(key.Points, key.Type, key.Closed, curves[c]->CurveId, errors[c]));
      totalPieces += static_cast<std::size_t>(pieces[k]);
    }
    else
    {
      this->TraceNew(key, out[c], curves[c]->CurveId, errors[c]); // names the unknown type
    }
  }
  const int workers = this->PrepareHelpers(threads, totalPieces);
  const std::size_t splitAbove = totalPieces / (2 * static_cast<std::size_t>(workers));
  struct Task
  {
    std::size_t K; ///< index into todo
    int Piece;     ///< -1: the whole curve
  };
  std::vector<Task> tasks;
  std::vector<std::size_t> firstLeg(todo.size(), 0);
  std::vector<char> split(todo.size(), 0);
  std::size_t splitPieces = 0;
  for (std::size_t k = 0; k < todo.size(); ++k)
  {
    if (pieces[k] == 0)
    {
      continue; // its error is named
    }
    if (workers > 1 && pieces[k] > 1 && static_cast<std::size_t>(pieces[k]) > splitAbove)
    {
      split[k] = 1;
      firstLeg[k] = splitPieces;
      splitPieces += static_cast<std::size_t>(pieces[k]);
      for (int i = 0; i < pieces[k]; ++i)
      {
        tasks.push_back({ k, i });
      }
    }
    else
    {
      tasks.push_back({ k, -1 });
    }
  }
  std::vector<PieceLegs> legs(splitPieces);
  // Stopping is decided per curve, as when curves were the tasks: a curve with a piece begun is
  // finished, the others fail named; progress counts finished curves.
  std::atomic<bool> stopped{ false };
  std::atomic<std::size_t> done{ 0 };
  const std::unique_ptr<std::atomic<int>[]> remaining(new std::atomic<int>[todo.size()]);
  const std::unique_ptr<std::atomic<bool>[]> begun(new std::atomic<bool>[todo.size()]);
  for (std::size_t k = 0; k < todo.size(); ++k)
  {
    remaining[k] = split[k] ? pieces[k] : 1;
    begun[k] = false;
  }
  const std::thread::id caller = std::this_thread::get_id();
  // Each arena slot has its own tracer: this one for slot 0, a helper for each other.
  RunTasksBySlot(workers,
    tasks.size(),
    [&](int slot, std::size_t t)
    {
      const std::size_t k = tasks[t].K, c = todo[k];
      const int piece = tasks[t].Piece;
      const int curveId = curves[c]->CurveId;
      if (!begun[k].load(std::memory_order_acquire))
      {
        if (stopped.load(std::memory_order_acquire))
        {
          (piece < 0 ? errors[c] : legs[firstLeg[k] + piece].Error) =
            CurveLabel(curveId) + ": not traced (aborted)";
          return;
        }
        begun[k].store(true, std::memory_order_release);
      }
      CurveTracer& tracer = slot == 0 ? *this : *this->Helpers[slot - 1];
      if (piece < 0)
      {
        tracer.TracePieces(
          keys[c].Points, keys[c].Type, keys[c].Closed, out[c], errors[c], curveId);
      }
      else
      {
        tracer.ComputePiece(
          keys[c].Points, keys[c].Type, piece, curveId, legs[firstLeg[k] + piece]);
      }
      if (remaining[k].fetch_sub(1, std::memory_order_acq_rel) != 1)
      {
        return; // the curve's last piece reports it
      }
      const std::size_t finished = done.fetch_add(1, std::memory_order_relaxed) + 1;
      if (std::this_thread::get_id() == caller && progress &&
        !progress(static_cast<double>(finished) / todo.size()))
      {
        stopped.store(true, std::memory_order_release);
      }
    });
  // The split curves assembled from their pieces in order, and the written forms, curves in
  // parallel.
  RunTasksBySlot(workers,
    todo.size(),
    [&](int, std::size_t k)
    {
      const std::size_t c = todo[k];
      for (int i = 0; split[k] && errors[c].empty() && i < pieces[k]; ++i)
      {
        PieceLegs& piece = legs[firstLeg[k] + static_cast<std::size_t>(i)];
        if (!piece.Ok)
        {
          out[c].Clear();
          errors[c] = piece.Error;
          break;
        }
        this->AppendPiece(keys[c].Points, keys[c].Type, i, piece, out[c]);
        piece = PieceLegs(); // its paths are in the curve now
        if (i + 1 == pieces[k] && keys[c].Closed)
        {
          out[c].DropRepeatedClosingPoint();
        }
      }
      if (errors[c].empty() && this->KeepWrittenForms)
      {
        ComputeWrittenForms(this->Solver.GetMesh(), out[c]);
      }
    });
  for (std::size_t c : todo)
  {
    if (errors[c].empty())
    {
      this->Remember(CurveKey(keys[c]), out[c]);
    }
  }
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
    this->Options == o.Options && this->Points == o.Points;
}

std::size_t CurveTracer::CurveKeyHash::operator()(const CurveKey& k) const
{
  std::size_t h = static_cast<std::size_t>(k.Type) * 31 + (k.Closed ? 17 : 0) +
    static_cast<std::size_t>(k.Resolution) * 131 + static_cast<std::size_t>(k.Options.Method) * 7;
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

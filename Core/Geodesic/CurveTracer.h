// Traces user curves on the mesh: geodesic polygons and cubic geodesic Bezier splines, open
// or closed, become polylines of canonical surface points (TracedCurve, the input of the
// arrangement) with a vertex at every mesh-edge crossing.
//
// Each traced vertex remembers where it comes from: the input segment, the input control point
// it is (if any), and its curve parameter (segment index + fraction in [0, 1]: of the
// segment's length for polygons, the spline parameter t for Beziers). The Boolean output uses
// these to give results back as control points.
#ifndef boolsurf_CurveTracer_h
#define boolsurf_CurveTracer_h

#include "Curves/ControlCurve.h"
#include "Geodesic/GeodesicBezier.h"
#include "Geodesic/GeodesicPath.h"
#include "Geodesic/TracedCurve.h"

#include <cstddef>
#include <functional>
#include <memory>
#include <unordered_map>
#include <vector>

namespace boolsurf
{

/// One traced curve plus, per point of Curve.Points, where the point comes from.
struct CurveTrace
{
  TracedCurve Curve;             ///< closed curves do not repeat their first point
  std::vector<int> Segment;      ///< input segment index (segment i joins anchors i and i+1)
  std::vector<int> ControlPoint; ///< input control point index, -1 for other points
  std::vector<double> Parameter; ///< segment index + fraction in [0, 1]
  /// True where the point lies on the exact curve at Parameter: every point of a polygon; the
  /// subdivision anchors of a Bezier (edge crossings and handles of the refined control
  /// polygon are within its convergence distance of the curve, not on it).
  std::vector<char> OnCurve;
  double Length = 0.0;
  /// Filled when the tracer keeps written forms (SetKeepWrittenForms), else empty: each
  /// point's position and its form in output arrays (ComputeWrittenForms).
  std::vector<Vec3> Positions;
  std::vector<SurfacePoint> Written;

  void Clear();
  /// A closed curve's trace ends where it started: remove that repeated last point (with its
  /// provenance), since closed curves do not repeat their first point.
  void DropRepeatedClosingPoint();
};

class CurveTracer
{
public:
  /// `mesh` must outlive the tracer. One tracer per thread. `components`: see
  /// GeodesicPathSolver.
  explicit CurveTracer(const TriangleMesh& mesh,
    std::shared_ptr<const TriangleComponents> components = nullptr);

  /// De Casteljau subdivision levels for Beziers (default 4: 16 pieces per segment); clamped
  /// to [0, 16].
  void SetResolution(int levels);
  int GetResolution() const { return this->Resolution; }

  /// Geodesic polygon through `points` (at least 2); closed adds the segment back to point 0.
  bool TraceGeodesicPolygon(const std::vector<CanonicalPoint>& points,
    bool closed,
    CurveTrace& out,
    std::string& error,
    int curveId = 0);

  /// Cubic geodesic Bezier spline: 3n+1 points when open, 3n when closed (segment n-1 then
  /// uses points 3n-3, 3n-2, 3n-1 and point 0).
  bool TraceBezierSpline(const std::vector<CanonicalPoint>& points,
    bool closed,
    CurveTrace& out,
    std::string& error,
    int curveId = 0);

  /// Validates raw triangle + barycentric control points (out-of-range triangles, NaN) and
  /// dispatches on `type`. Messages name the curve and the control point.
  bool Trace(const std::vector<SurfacePoint>& points,
    CurveType type,
    bool closed,
    CurveTrace& out,
    std::string& error,
    int curveId = 0);

  /// Trace() of each curve's points, type and closedness under its CurveId, for every curve of
  /// `curves` (out[c] as Trace() gives it one by one, bit for bit; errors[c] its message, empty
  /// when the curve traced), on up to `threads` threads (0: all cores). Curves the memory recalls
  /// are recalled; the others are traced in parallel, by this tracer and helper tracers it keeps on
  /// the same mesh with its settings, then remembered. A leg's geodesic does not depend on which
  /// solver computes it: the Bounded and Exact methods are functions of the leg's ends (the
  /// surface's site graph and path cache are shared and thread-safe). The locally shortest method
  /// is not (its edge search breaks ties by a landmark table each solver builds lazily), so it
  /// traces on this thread only. A curve holding a large share of all the pieces to trace
  /// (polygon legs, Bezier segments) is split into them, so one long curve is traced on every
  /// thread; the others are one task each. `progress` (may be empty) is called on the calling
  /// thread with the fraction done; returning false stops the tracing (the curves not traced get a
  /// message).
  void TraceCurves(const std::vector<const ControlCurve*>& curves,
    int threads,
    std::vector<CurveTrace>& out,
    std::vector<std::string>& errors,
    const std::function<bool(double)>& progress = {});
  GeodesicPathSolver& GetPathSolver() { return this->Solver; }
  /// This tracer's solver then its helpers' (made as needed, given its settings): one per
  /// thread, up to `threads` (0: all cores), for other work split over threads on the same
  /// legs' terms (see TraceCurves; only this tracer's solver with the locally shortest method).
  std::vector<GeodesicPathSolver*> GetSolvers(int threads);

  /// Trace() remembers the curves it traced: the same control points (bit for bit), type and
  /// closure, at the same resolution and geodesic method, give the same trace again without
  /// tracing. An edit retraces every curve, and usually only one moved. Call StartPass() once
  /// per set of curves (one update): curves neither traced nor recalled during the previous
  /// pass are then forgotten, so the memory holds about two updates' curves. It never holds
  /// more than 2^20 traced points (about 60 MB, 110 MB with written forms): past that it
  /// empties and fills again.
  void StartPass();
  /// How many Trace() calls were answered from memory (for tests and benchmarks).
  std::size_t GetRecalledCurves() const { return this->Recalled; }

  /// Whether Trace() also gives each curve's CurveTrace::Positions and Written, kept with the
  /// curves it remembers (default off). A filter that writes traced curves into arrays turns
  /// it on: a curve an edit did not move is then written by copying, where writing it anew
  /// reads the mesh around every point (most of an edit's writing time on a traced scene).
  /// Remembered curves then take about 50 more bytes per point.
  void SetKeepWrittenForms(bool keep) { this->KeepWrittenForms = keep; }

private:
  /// A helper of TraceCurves: a tracer on `main`'s mesh whose solver shares what `main`'s can.
  CurveTracer(const CurveTracer& main, GeodesicPathSolver::HelperTag tag);
  struct CurveKey;
  /// Validates and canonicalizes a curve's control points into `key`.
  bool MakeKey(const std::vector<SurfacePoint>& points,
    CurveType type,
    bool closed,
    int curveId,
    CurveKey& key,
    std::string& error) const;
  /// The remembered trace of `key` into `out`, if any.
  bool Recall(const CurveKey& key, CurveTrace& out, int curveId);
  /// Traces `key` (without the memory).
  bool TraceNew(const CurveKey& key, CurveTrace& out, int curveId, std::string& error);
  void Remember(CurveKey&& key, const CurveTrace& trace);
  /// The geodesics of one piece of a curve (a polygon's leg, or a Bezier segment's 3 x 2^Resolution
  /// legs), computed apart from the curve's other pieces; Error names the curve and the piece.
  struct PieceLegs
  {
    std::vector<GeodesicPath> Legs;
    bool Ok = false;
    std::string Error;
  };
  /// The number of pieces of a curve of `points`, or -1 and a message when their number does
  /// not make such a curve.
  int CountPieces(const std::vector<CanonicalPoint>& points,
    CurveType type,
    bool closed,
    int curveId,
    std::string& error) const;
  /// Computes piece `piece` of a curve (with this tracer's solver) into `legs`.
  bool ComputePiece(const std::vector<CanonicalPoint>& points,
    CurveType type,
    int piece,
    int curveId,
    PieceLegs& legs);
  /// Appends a computed piece to `out` (pieces in order: the trace Trace() gives).
  void AppendPiece(const std::vector<CanonicalPoint>& points,
    CurveType type,
    int piece,
    const PieceLegs& legs,
    CurveTrace& out) const;
  /// A polygon or Bezier spline traced piece after piece on this thread.
  bool TracePieces(const std::vector<CanonicalPoint>& points,
    CurveType type,
    bool closed,
    CurveTrace& out,
    std::string& error,
    int curveId);
  /// Threads to use for `threads` (0: all cores) on `tasks` tasks, with helpers ready for them.
  int PrepareHelpers(int threads, std::size_t tasks);
  /// The geodesic between a and b, computed from whichever of the two comes first in a fixed
  /// order of surface points and reversed if needed: a leg traced both ways (two polygons
  /// sharing an edge, a spike, a curve and its reverse) is the same polyline bit for bit, so
  /// the arrangement sees the curves overlap exactly rather than run side by side.
  bool ComputeLeg(const CanonicalPoint& a,
    const CanonicalPoint& b,
    GeodesicPath& path,
    std::string& error);
  /// Appends a traced path, mapping arc length onto parameters [t0, t1] of `segment`.
  void AppendPath(const GeodesicPath& path,
    int segment,
    double t0,
    double t1,
    int firstControl,
    int lastControl,
    bool firstOnCurve,
    bool lastOnCurve,
    bool interiorOnCurve,
    CurveTrace& out) const;
  void AppendPoint(const CanonicalPoint& computed,
    int segment,
    int control,
    double parameter,
    bool onCurve,
    CurveTrace& out) const;

  GeodesicPathSolver Solver;
  int Resolution = 4;

  struct CurveKey
  {
    std::vector<CanonicalPoint> Points;
    CurveType Type = CurveType::GeodesicPolygon;
    bool Closed = true;
    int Resolution = 0;
    /// Every setting of the solver, not the method alone: filters on one surface share a
    /// tracer (vtkSurfaceCache), each setting its own before tracing.
    GeodesicPathOptions Options;
    bool operator==(const CurveKey& o) const;
  };
  struct CurveKeyHash
  {
    std::size_t operator()(const CurveKey& k) const;
  };
  struct RememberedCurve
  {
    CurveTrace Trace;
    unsigned Pass = 0;
  };
  std::unordered_map<CurveKey, RememberedCurve, CurveKeyHash> Memory;
  unsigned Pass = 0;
  bool KeepWrittenForms = false;
  std::size_t Recalled = 0;
  std::size_t MemoryPoints = 0; ///< traced points held by Memory
  PieceLegs Legs;               ///< TracePieces' piece being appended
  std::vector<CanonicalPoint> Refined;
  /// TraceCurves()'s other tracers, one per extra thread (built on first use).
  std::vector<std::unique_ptr<CurveTracer>> Helpers;
};

} // namespace boolsurf

#endif

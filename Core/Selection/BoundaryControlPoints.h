// The result as vector curves (paper §3.5 and §4.5, Fig. 9 and 21): the boundary of a selected
// region and the clipped pieces of open curves, given back as control points of sub-curves of
// the input curves rather than as dense polylines.
//
// A boundary patch is a piece of one input curve between two parameters (the arrangement
// knows where each of its points lies on the traced curve, Arrangement::CurveStations, and the
// tracer where each traced point lies on the input curve, CurveTrace::Parameter). Its control
// points are:
// - geodesic polygon: the patch's first point (an intersection, or a vertex), the polygon's
//   vertices strictly inside the parameter range, the patch's last point. A piece of a
//   shortest geodesic is the shortest geodesic between its ends, so tracing these points again
//   gives the patch back.
// - cubic Bezier spline: the spline's segments over the range, the first and last split at the
//   range's ends by geodesic de Casteljau insertion (SplitGeodesicBezier), so each piece is
//   again a cubic spline (anchor, handle, handle, anchor, ...) whose control polygon gives the
//   piece. Its end anchors are on the spline at the range's ends; the patch ends are where the
//   traced polyline (the spline at the tracing resolution) meets other curves, so they agree to
//   the tracing tolerance, exactly on flat meshes only at the spline's own anchors.
#ifndef boolsurf_BoundaryControlPoints_h
#define boolsurf_BoundaryControlPoints_h

#include "Arrangement/Arrangement.h"
#include "Geodesic/CurveTracer.h"
#include "Selection/BezierCutLevels.h"
#include "Selection/RegionBoundary.h"

#include <array>
#include <functional>
#include <string>
#include <unordered_map>
#include <vector>

namespace boolsurf
{

/// What is known of one input curve (same index as the arranged curves): the user's control
/// curve and where each of its traced points lies on it.
struct CurveSource : ControlCurve
{
  std::vector<double> Parameter; ///< per traced point: CurveTrace::Parameter
  /// The user's own id of the curve (a scene's polygon index) when the input gave one, for
  /// messages; -1 otherwise.
  long long InputCurveId = -1;
};

/// One sub-curve of an input curve, as control points.
struct ControlSubCurve
{
  int Group = -1;        ///< the boundary loop, or the clipped piece's curve's piece number
  int Curve = -1;        ///< index of the source curve
  bool Reversed = false; ///< walked against the source curve (region on the left)
  bool Whole = false;    ///< the whole closed source curve (a loop that meets no other curve)
  double T0 = 0, T1 = 0; ///< parameter range on the source curve (T1 > T0; may pass its end)
  CurveType Type = CurveType::GeodesicPolygon;
  /// Control points in walking order: the user's own surface points where they are the input's
  /// control points, the arrangement's where the sub-curve starts or ends at an intersection.
  std::vector<SurfacePoint> Points;
  std::vector<Vec3> Positions; ///< the 3D point of each of Points
  // Of the source curve, so that pieces can be joined without it.
  int Segments = 0;         ///< its number of segments (legs, or cubic segments)
  bool CurveClosed = false; ///< whether it is closed
  int SourceShapeId = 0, SourceCurveId = 0;
};

/// What the pieces of a patch need to know of it to be assembled.
struct PatchInfo
{
  int Curve = -1;
  bool Closed = true; ///< of a closed curve
  int LeftCell = -1, RightCell = -1;
};

/// Parameter on source curve `curve` of the point at index `index` of the arrangement's
/// CurvePoints[curve].
double ArrangedPointParameter(const Arrangement& arrangement,
  const std::vector<CurveSource>& sources,
  int curve,
  int index);

/// The number of segments of `source` (legs, or cubic segments): its parameter's range.
int NumberOfSourceSegments(const CurveSource& source);

/// A sub-curve of source curve `curve` with what it keeps of its source (Curve, Type,
/// Segments, CurveClosed, SourceShapeId, SourceCurveId) and nothing else yet.
ControlSubCurve SubCurveOfSource(const std::vector<CurveSource>& sources, int curve);

/// Parameter on `source` of the point at `station` on its traced curve (traced point index
/// plus fraction, Arrangement::CurveStations): what ArrangedPointParameter reads, for a point
/// known by its station only (an arrangement on pieces, Distributed/PieceVectorOutput.h).
double StationParameter(const CurveSource& source, double station);

/// The parameter range of a sub-curve from the parameters of its ends (t1 may come before t0):
/// a closed curve's piece that passes the curve's start (or a `whole` one) ends on the next
/// turn; a piece too short for its parameters to differ keeps t1 = t0.
void SubCurveParameterRange(const CurveSource& source, bool whole, double& t0, double& t1);

/// The control points of the geodesic polygon `source` from parameter t0 to t1 (as
/// SubCurveParameterRange gives them): per point of the sub-curve, the index of the user's
/// control point it is, or -1 for its first (last) point where that lies between control points
/// (an intersection, whose surface point the caller has). A `whole` curve has no last point.
void PolygonSubCurveControls(const CurveSource& source,
  double t0,
  double t1,
  bool whole,
  std::vector<int>& out);

/// The cubic Bezier pieces of the source curves between every two consecutive patch ends.
/// A curve's segments are cut at all its patches' ends the first time one of its pieces is
/// asked for, each segment split once per cut, left to right: later splits work on ever
/// smaller control polygons (shorter geodesics, the costly part), no parameter is split
/// twice, and a piece is the same whichever patches are asked for and in whichever order (the
/// one-step filter asks for the boundary's, the arrangement stage for all).
class BezierPieces
{
public:
  BezierPieces(const Arrangement& arrangement, const std::vector<CurveSource>& sources);

  /// The control points of the part [a, b] (0 <= a < b <= 1) of segment `segment` of curve
  /// `curve`; `found` is false when [a, b] is not one of the pieces (the caller then splits
  /// the segment itself).
  bool Get(GeodesicPathSolver& solver,
    int curve,
    int segment,
    double a,
    double b,
    std::array<CanonicalPoint, 4>& out,
    bool& found,
    std::string& error);

  /// Cuts now the Bezier segments of `curves` that Get() would cut when first asked, into the
  /// same pieces, on several threads (the halves of every split: CutSegmentsByLevels): `solvers`
  /// holds one solver per thread (the arena slot's), all on the arrangement's mesh with the same
  /// settings and a method whose legs do not depend on the solver (see CurveTracer::TraceCurves).
  bool CutCurves(const std::vector<int>& curves,
    const std::vector<GeodesicPathSolver*>& solvers,
    std::string& error);

private:
  using Piece = BezierCutPiece;
  /// One segment to cut: its control polygon and its cuts (sorted, distinct, inside (0, 1)).
  struct SegmentCuts
  {
    int Curve = -1, Segment = -1;
    std::array<CanonicalPoint, 4> Whole;
    std::vector<double> At;
  };
  /// The segments of `curve` with cuts (the curve is marked cut).
  void CollectCuts(const TriangleMesh& mesh, int curve, std::vector<SegmentCuts>& jobs);
  bool CutCurve(GeodesicPathSolver& solver, int curve, std::string& error);

  const Arrangement& Arranged;
  const std::vector<CurveSource>& Sources;
  std::vector<std::vector<int>> PatchesOfCurve;
  std::vector<char> CurveCut;
  std::unordered_map<long long, std::vector<Piece>> Segments; ///< key: curve << 32 | segment
};

/// The sub-curve of patch `patch` of the arrangement, forward along its curve (Group -1).
/// `pieces` (optional) shares the Bezier splits between the patches of one update.
bool PatchControlCurve(GeodesicPathSolver& solver,
  const Arrangement& arrangement,
  const std::vector<CurveSource>& sources,
  int patch,
  ControlSubCurve& out,
  std::string& error,
  BezierPieces* pieces = nullptr);

/// Boundary loops from per-patch sub-curves (`patchCurve(p)`, forward, or null for a patch
/// without one): each loop's pieces oriented with the region on the left, pieces of one curve
/// that follow each other joined (a polygon's junction inside a leg dropped), a piece going all
/// around its closed curve marked Whole. Group is the loop index.
void AssembleBoundaryLoops(const std::function<const ControlSubCurve*(int)>& patchCurve,
  const std::vector<BoundaryPolyline>& loops,
  std::vector<ControlSubCurve>& out);

/// Pieces of open curves inside the cells with selected[cell] != 0 (a piece along the region's
/// boundary counts as inside), from per-patch sub-curves; consecutive patches of a curve joined.
void AssembleClippedPieces(const std::function<const ControlSubCurve*(int)>& patchCurve,
  const std::vector<PatchInfo>& patches,
  const std::vector<char>& selected,
  std::vector<ControlSubCurve>& out);

/// Sub-curves of the boundary loops `loops` (from ExtractRegionBoundary on the arrangement's
/// patches), each oriented with the region on its left; Group is the loop index. `pieces`
/// (may be null: a local one is used) holds the Bezier segments already cut: pass the same one
/// to ClippedControlCurves on the same arrangement so no segment is split twice.
bool BoundaryControlCurves(GeodesicPathSolver& solver,
  const Arrangement& arrangement,
  const std::vector<CurveSource>& sources,
  const std::vector<BoundaryPolyline>& loops,
  std::vector<ControlSubCurve>& out,
  std::string& error,
  BezierPieces* pieces = nullptr);

/// The pieces of open curves inside the cells with selected[cell] != 0 (a piece along the
/// region's boundary counts as inside), consecutive patches joined; Group numbers the pieces
/// of each curve in curve order. `pieces` as for BoundaryControlCurves.
bool ClippedControlCurves(GeodesicPathSolver& solver,
  const Arrangement& arrangement,
  const std::vector<CurveSource>& sources,
  const std::vector<char>& selected,
  std::vector<ControlSubCurve>& out,
  std::string& error,
  BezierPieces* pieces = nullptr);

} // namespace boolsurf

#endif

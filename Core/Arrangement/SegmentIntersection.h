// Arrangement stage 2: intersections between the curve segments of each triangle.
//
// For one triangle, every segment is cut at every point where it meets another segment of the
// same triangle: proper crossings (a new point strictly inside the triangle), T-junctions (an
// endpoint of one lying on the other), and collinear overlaps (each segment cut at the other's
// endpoints). All decisions use the exact Orient2d, on coordinates that place points of mesh
// edges exactly on their edge's line, so the topology inside a triangle is consistent.
//
// A crossing is kept exact: as the two segments that define it (ExactCrossings.h), with its
// rounded coordinates only for output. The points along a segment are ordered exactly, and
// points found equal there (three or more curves through one point, a crossing on a curve
// point) become one point shared by every segment through it. So consecutive points of a
// segment bound pieces that never cross another piece nor hold a point inside.
//
// Near-coincident points are merged too, by default: three curves drawn through one point of
// a curved surface meet in three crossings a rounding apart (the point's barycentric
// coordinates are rounded), and a user expects one vertex there, not a cell of zero area.
// Crossings and curve points inside the triangle that are neighbours along a segment and
// within NearPointDistance of each other become one point (an explicit one if there is one).
// That bends a few pieces by at most that distance, which can make two of them cross; stage 3
// then fails on that triangle, and the arrangement cuts it again exactly (mergeDistance 0),
// which stage 3 always triangulates.
//
// Intersections ON mesh edges are never computed here: a segment meets the triangle's boundary
// only at its own endpoints, which are canonical points already shared with the neighbour
// (TriangleSegmentMap::EdgePoints). Segments along a mesh edge are split at the edge's points
// by SplitEdgeSegment, from the canonical parameter T alone, identically for both triangles.
#ifndef boolsurf_SegmentIntersection_h
#define boolsurf_SegmentIntersection_h

#include "Arrangement/ExactCrossings.h"
#include "Arrangement/TriangleSegments.h"

#include <array>
#include <string>
#include <vector>

namespace boolsurf
{

/// A point of a triangle's local planar subdivision.
struct LocalPoint
{
  Vec2 P; ///< (u, v) in the unit triangle
  /// Refined-surface point id: the mesh vertex for corners, NumberOfMeshVertices + edge point
  /// index for edge points, assigned during assembly for interior points (-1 before).
  int Global = -1;
  /// -1: strictly inside the triangle; 0..2: on local edge k; 3..5: corner k - 3.
  int Where = -1;
  /// Index in LocalArrangement::Crossings when the point is a crossing of two segments (P is
  /// then its rounded position), else -1.
  int Crossing = -1;
  /// Bit k set when the point lies on the triangle's side k (from corner k to corner k + 1):
  /// one bit on a side, two at a corner (sides k and k - 1 meet at corner k), none inside.
  int Sides() const
  {
    if (this->Where < 0)
    {
      return 0;
    }
    if (this->Where < 3)
    {
      return 1 << this->Where;
    }
    const int corner = this->Where - 3;
    return (1 << corner) | (1 << ((corner + 2) % 3));
  }
};

/// Everything known about one refined triangle. Stage 2 fills the points and the chains;
/// stage 3 (TriangleRefinement) adds the sub-triangles and the final paths.
struct LocalArrangement
{
  int Triangle = -1;
  /// Corners 0..2, then the edge points of local edges 0, 1, 2 (each in edge order), then the
  /// interior points: curve points inside the triangle and crossings.
  std::vector<LocalPoint> Points;
  /// The exact definitions of the crossing points (LocalPoint::Crossing).
  std::vector<SegmentCrossing> Crossings;
  /// The triangle's boundary, counter-clockwise: corner 0, points of edge 0, corner 1, ...
  std::vector<int> Boundary;
  /// Per segment of the slot (same order as in TriangleSegmentMap): local point ids from its
  /// first to its last point, through every intersection in order.
  std::vector<std::vector<int>> Chains;
  /// Per segment: does it belong to a closed curve (does it separate cells)?
  std::vector<char> ChainClosed;

  // --- stage 3
  std::vector<std::array<int, 3>> Triangles; ///< local point ids, counter-clockwise
  /// Per sub-triangle: bit j set when its edge from vertex j to vertex j+1 lies on a closed
  /// curve inside the triangle (sub-edges on mesh edges are handled by edge segments).
  std::vector<unsigned char> Blocked;
  /// Points merged into another (equal exact coordinates): Alias[i] != i.
  std::vector<int> Alias;
  /// Number of interior points that survive (Alias[i] == i), i.e. new refined-surface points.
  int NumberOfNewPoints = 0;

  std::string Error; ///< non-empty when the triangle could not be processed
};

/// Point i of `a` for the exact predicates.
inline ExactPoint ExactPointOf(const LocalArrangement& a, int i)
{
  const LocalPoint& p = a.Points[i];
  return { p.P, p.Crossing >= 0 ? &a.Crossings[p.Crossing] : nullptr };
}

/// Distance in unit-triangle coordinates (L1) within which neighbouring interior points of a
/// segment are merged: far above the rounding of crossings (~1e-16), far below any curve
/// feature a user can draw.
constexpr double NearPointDistance = 1e-13;

/// Stage 2 on a local arrangement whose Chains hold, per segment, its two end points (explicit
/// points of `arr`, distinct): cuts every chain at every point where its segment meets
/// another, adding the crossings as points. Exact when mergeDistance is 0; see the file
/// comment.
void CutSegmentsAtIntersections(LocalArrangement& arr, double mergeDistance = NearPointDistance);

/// Adds to `out` the crossing of the lines (p0, p1) and (q0, q1) as a point (kept exact, its
/// rounded position strictly inside the triangle) and returns its local id.
int AddCrossingPoint(LocalArrangement& out, Vec2 p0, Vec2 p1, Vec2 q0, Vec2 q1);

/// Intersects the segments of slot `slot`, filling `out` (points, boundary, chains); with
/// near points merged within `mergeDistance` (0: exact).
void IntersectTriangleSegments(const TriangleMesh& mesh,
  const TriangleSegmentMap& map,
  const std::vector<TracedCurve>& curves,
  int slot,
  LocalArrangement& out,
  double mergeDistance = NearPointDistance);

/// Refined-surface point ids along edge segment `index`, from its first to its last point,
/// through every edge point strictly between them (sorted by T along the segment).
void SplitEdgeSegment(const TriangleMesh& mesh,
  const TriangleSegmentMap& map,
  int index,
  std::vector<int>& globalIds);

/// Refined-surface id of a canonical vertex or edge point (-1 for face points or points not in
/// the edge point set).
int BoundaryPointId(const TriangleMesh& mesh,
  const TriangleSegmentMap& map,
  const CanonicalPoint& p);

} // namespace boolsurf

#endif

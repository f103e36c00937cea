// Arrangement stage 1: the per-triangle hash map of curve segments.
//
// Every segment of every traced curve lies in one triangle. This stage sorts them by triangle
// and writes each one in the 2D barycentric frame of its unit triangle (corner 0 = (0,0),
// corner 1 = (1,0), corner 2 = (0,1); a point is (u, v)), where the later stages intersect and
// triangulate them.
//
// Points on mesh edges are the one place where two triangles must agree exactly, so they are
// never compared through 2D coordinates across triangles: the set of points on each edge is
// decided once, from the canonical (edge id, T) form, and both triangles of the edge read it
// from here. In each triangle, an edge point's 2D coordinates lie exactly on the edge's line
// (see EdgePointCoordinates), so the triangle's own predicates agree with the edge's order.
//
// A segment between two points of one mesh edge runs ALONG that edge. It is not given to
// either triangle: it becomes an EdgeSegment, a constraint on the edge itself, split at the
// edge's points and blocking the flood fill across the sub-edges it covers.
#ifndef boolsurf_TriangleSegments_h
#define boolsurf_TriangleSegments_h

#include "Geodesic/TracedCurve.h"

#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace boolsurf
{

/// A point of the mesh edge set: strictly inside edge Edge at canonical parameter T.
struct EdgePoint
{
  int Edge = -1;
  double T = 0;
};

/// A curve segment strictly crossing the inside of one triangle (not along an edge).
struct TriangleSegment
{
  int Curve = -1;   ///< index into the curves vector
  int Segment = -1; ///< segment i joins curve point i to point i+1 (mod n when closed)
  CanonicalPoint A, B;
  Vec2 A2, B2; ///< (u, v) of A and B in the unit triangle
};

/// A curve segment lying along a mesh edge, from parameter T0 to T1 along the edge's canonical
/// direction (mesh vertices are 0 and 1).
struct EdgeSegment
{
  int Curve = -1;
  int Segment = -1;
  int Edge = -1;
  double T0 = 0, T1 = 0;
  CanonicalPoint A, B;
};

/// Where the i-th non-degenerate segment of a curve went.
struct SegmentLocation
{
  bool AlongEdge = false;
  int Index = -1; ///< into TriangleSegmentMap::Segments or ::EdgeSegments
};

struct TriangleSegmentMap
{
  /// Triangles that must be refined, in increasing id order: those crossed by a segment and
  /// those with a curve point on one of their edges (so that both sides of an edge conform).
  std::vector<int> Triangles;
  /// Segments of slot s are Segments[SegmentOffset[s] .. SegmentOffset[s+1]), by curve order.
  std::vector<int> SegmentOffset;
  std::vector<TriangleSegment> Segments;
  std::vector<EdgeSegment> EdgeSegments;
  /// Every curve point on an edge interior, sorted by (edge, T), unique. The refined surface
  /// gives edge point i the id NumberOfMeshVertices + i.
  std::vector<EdgePoint> EdgePoints;
  /// Distinct edges holding edge points, ascending, and the start of each one's run in
  /// EdgePoints (one more entry at the end): the map from edge to points, looked up by binary
  /// search, which beat a hash map on every edit measured (no allocation per entry).
  std::vector<int> PointEdges, PointEdgeStart;
  /// [first, last) range of edge e's points in EdgePoints (empty when it holds none).
  std::pair<int, int> FindEdgePoints(int e) const;
  /// Slot of triangle t in Triangles (-1 when t is not refined).
  int FindSlot(int t) const;
  /// Per curve, its non-degenerate segments in order (zero-length segments are dropped).
  std::vector<std::vector<SegmentLocation>> CurveSegments;

  /// Edge points on local edge k of triangle t, ordered from corner k to corner k+1, as
  /// indices into EdgePoints.
  void GetEdgePointsOnLocalEdge(const TriangleMesh& mesh,
    int t,
    int k,
    std::vector<int>& out) const;
};

/// Curve points on one mesh edge whose parameters differ by at most this much are taken to be
/// one point (2^-40 of the edge's length: far above the rounding of traced crossings, far
/// below anything a drawing can resolve).
constexpr double EdgePointMergeDistance = 0x1p-40;

/// Coordinates in the unit triangle of the point at canonical parameter T on local edge k of
/// a triangle whose edge runs along (forward) or against the canonical direction. The result
/// lies EXACTLY on the edge's line: on the hypotenuse u + v = 1 the larger coordinate is
/// rounded and the smaller one is computed from it without error.
Vec2 EdgePointCoordinates(int k, double T, bool forward);

/// Coordinates in the unit triangle of a canonical point that triangle t contains.
Vec2 LocalCoordinates(const TriangleMesh& mesh, const CanonicalPoint& p, int t);

/// Where a curve was refused: its index in the curves and the (first) point involved, -1 when
/// not about one point.
struct CurvePointRef
{
  int Curve = -1;
  int Point = -1;
};

/// Builds the map. Fails with a message naming the curve and point index when a point is
/// invalid (out-of-range id, non-finite or out-of-range parameter) or when two consecutive
/// points share no triangle; `failed` (may be null) then says which.
bool BuildTriangleSegmentMap(const TriangleMesh& mesh,
  const std::vector<TracedCurve>& curves,
  TriangleSegmentMap& map,
  std::string& error,
  CurvePointRef* failed = nullptr);

} // namespace boolsurf

#endif

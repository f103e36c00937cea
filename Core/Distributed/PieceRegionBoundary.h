// The boundary of a Boolean's region on a distributed surface (Docs/Parallel.md, "What runs on
// each rank's piece"): each piece gives the region's boundary segments on its owned triangles,
// named independently of pieces; the segments of every piece are chained into the loops of
// the whole surface's region.
//
// Each side of a curve segment is seen by the piece owning the mesh triangle on that side (the
// one triangle around a segment inside it, one of the two along a mesh edge): when that side's
// cell is selected it gives the segment with that side on its left. A segment selected on both
// sides is given once each way and cancels, on the piece or, along a border between pieces,
// where the segments are chained. So a boundary segment (one side selected) is given exactly
// once, and every piece names its points the same way: a mesh vertex by its global id, an edge
// point by its edge's global vertices and parameter, an interior point by its global triangle
// and barycentric weights, all bit for bit.
//
// The loops are canonical, independent of how the surface is split: at a point where several
// boundary segments meet (curves crossing at a corner of the region) the incoming ones are
// paired with the outgoing ones in order of their point before and after it, and each closed
// loop starts at its lowest point. The one-rank boundary (Selection/RegionBoundary.h) has the
// same points in the same cyclic order, but starts each loop where its first patch starts,
// orders the loops by patch and may group them otherwise where segments meet.
//
// Cost: O(curve segments in owned triangles x their refined triangles) per piece after one
// O(piece) pass (the triangles around each vertex); what travels is O(boundary points), never
// the surface.
#ifndef boolsurf_PieceRegionBoundary_h
#define boolsurf_PieceRegionBoundary_h

#include "Arrangement/Arrangement.h"
#include "Distributed/PieceCurves.h"
#include "Distributed/PieceMesh.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace boolsurf
{

/// A refined point named independently of pieces: (location, then two global ids or a global
/// id and parameters as bits). Ordered by these words.
using BoundaryPointKey = std::array<std::int64_t, 4>;

/// The curve a boundary segment runs along, for the result's control points
/// (PieceVectorOutput.h): of the segment from a run's point to the next one.
struct BoundarySegmentCurve
{
  int Curve = -1;          ///< the global curve; -1 when not known (a run's last point)
  bool Reversed = false;   ///< walked against the curve's direction
  double From = 0, To = 0; ///< stations of its ends on the global curve, in walking order
};

struct BoundaryPointRecord
{
  BoundaryPointKey Key{};
  Vec3 Position{};
  SurfacePoint Surface; ///< Triangle is a global triangle
  /// Surface evaluated on its triangle (TriangleMesh::Evaluate): the position the one-rank
  /// control curves give such a point.
  Vec3 SurfacePosition{};
  BoundarySegmentCurve Next;
  /// A patch of a curve starts or ends here on the whole surface (the curve meets another one,
  /// or steps onto or off the surface's boundary): where one rank starts a loop that is one
  /// closed curve all around.
  bool PatchEnd = false;
};

/// Of each curve of a piece (PieceCurves.h): the global curve it is a run of, the global index
/// of the run's first traced point, and whether that curve is open, so that a piece names its
/// points' stations as the whole surface's arrangement does (Arrangement::CurveStations).
struct PieceCurveRuns
{
  std::vector<int> SourceCurve, FirstPoint;
  std::vector<char> OfOpenCurve;
  std::vector<char> CutFromClosed; ///< per piece curve: an open run of a closed curve
};
PieceCurveRuns CurveRunsOf(const PieceCurves& curves);

/// A segment of an open curve with the region on one side at least: a piece of the clipped
/// curves (PieceClippedSegments).
struct ClippedSegment
{
  int Curve = -1;           ///< the global curve
  double From = 0, To = 0;  ///< stations of A and B on it (curve direction)
  BoundaryPointRecord A, B; ///< its ends in the curve's direction (their Next unused)
};

/// Points along the boundary, the region on their left; consecutive points are one segment.
struct BoundaryRun
{
  std::vector<BoundaryPointRecord> Points;
  bool Closed = false; ///< after chaining: a loop (its first point not repeated)
};

/// The region's boundary segments (selected[global cell], local cells mapped by
/// globalCellOfLocal) given by the piece's owned triangles, the region on their left, chained
/// into runs through the points all of whose triangles the piece owns (there every boundary
/// segment is the piece's, so the pairing is ChainBoundaryRuns'); a run ends at a point it
/// shares with another piece, and a segment along an edge with another piece's triangle is a
/// run of its own (it may be cancelled where the runs are chained). Loops wholly inside the
/// piece come closed.
/// With `curves` (the piece's curves' runs), each segment's point gives the curve it runs along
/// (BoundaryPointRecord::Next).
void PieceRegionBoundaryRuns(const PieceMesh& piece,
  const Arrangement& arr,
  const std::vector<int>& globalCellOfLocal,
  const std::vector<char>& selected,
  std::vector<BoundaryRun>& out,
  const PieceCurveRuns* curves = nullptr);

/// The segments of open curves the piece's owned triangles see with a selected cell on one
/// side at least (a segment along an edge between two pieces may come from both), in no
/// particular order: the one-rank clipped curves' patches (ClippedControlCurves), cut where
/// pieces meet.
void PieceClippedSegments(const PieceMesh& piece,
  const Arrangement& arr,
  const std::vector<int>& globalCellOfLocal,
  const std::vector<char>& selected,
  const PieceCurveRuns& curves,
  std::vector<ClippedSegment>& out);

/// Chains runs (from every piece, in any order) into the region's loops, after cancelling the
/// open two-point runs given once each way: closed loops start at their lowest point; open chains
/// only where a run has no continuation. Sorted by closed first, then by points.
std::vector<BoundaryRun> ChainBoundaryRuns(const std::vector<BoundaryRun>& runs);

/// Message 4 (a piece's runs to the rank that chains them): 18 words per point.
void PackBoundaryRuns(const std::vector<BoundaryRun>& runs, std::vector<long long>& out);
/// Appends the runs of `in` to `out`. False with `error` on a short or corrupt message.
bool UnpackBoundaryRuns(const std::vector<long long>& in,
  std::vector<BoundaryRun>& out,
  std::string& error);
/// The same from word `at` on, which it moves past the runs (a message with more after them).
bool UnpackBoundaryRuns(const std::vector<long long>& in,
  std::size_t& at,
  std::vector<BoundaryRun>& out,
  std::string& error);

/// A point's words in message 4 (and in the clipped segments' message), appended to `out`.
void PackBoundaryPoint(const BoundaryPointRecord& p, std::vector<long long>& out);
/// Reads a point from word `at` on (PackBoundaryPoint's), moving `at` past it; false when the
/// message is too short.
bool UnpackBoundaryPoint(const std::vector<long long>& in, std::size_t& at, BoundaryPointRecord& p);

} // namespace boolsurf

#endif

// The result as vector curves (Selection/BoundaryControlPoints.h, ports 2 and 3 of a Boolean)
// on a distributed surface: the boundary's loops and the open curves' pieces inside the region
// given back as control points of the input curves, from what the pieces send of them, on the
// rank that chains the boundary (PieceRegionBoundary.h). No rank holds the surface.
//
// The boundary's segments carry the curve they run along and their ends' stations on it
// (BoundaryPointRecord::Next), the open curves' segments inside the region theirs
// (ClippedSegment). Stations are turned into the curves' parameters as on one rank
// (StationParameter); consecutive segments of one curve walked one way are one sub-curve, as
// the one-rank assembly joins consecutive patches, and a loop's sub-curves start where the
// loop goes from one curve to another. A geodesic polygon's sub-curve is its ends and the
// user's control points between them, so no geodesic is traced. A cubic Bezier's would need its
// segments split by geodesic de Casteljau on the whole surface: refused, naming the curve.
//
// A loop that is one closed curve all around is the whole curve, started where one rank starts
// it: at the curve's first patch end (where it meets another curve), or walked backwards from
// its second one, or at its start when nothing meets it.
//
// What differs from one rank: the loops come in the pieces' canonical order (closed first,
// then by their points) rather than by patch. Points where a sub-curve starts or ends between
// control points name the triangle the piece found (the other one of an edge may be named on
// one rank), positions evaluated on it.
//
// Cost: O(boundary and clipped segments + control points) on the chaining rank.
#ifndef boolsurf_PieceVectorOutput_h
#define boolsurf_PieceVectorOutput_h

#include "Distributed/PieceMesh.h"
#include "Distributed/PieceRegionBoundary.h"
#include "Selection/BoundaryControlPoints.h"

#include <cstddef>
#include <string>
#include <vector>

namespace boolsurf
{

/// Per source curve, per control point: its position (TriangleMesh::Evaluate on its triangle).
using ControlPointPositions = std::vector<std::vector<Vec3>>;

/// Port 2 from the chained loops (ChainBoundaryRuns, with the segments' curves): each loop's
/// sub-curves, region on the left, Group the loop's index. False with `error` when a segment
/// names no curve, or a sub-curve is of a cubic Bezier.
bool PieceBoundaryControlCurves(const std::vector<BoundaryRun>& loops,
  const std::vector<CurveSource>& sources,
  const ControlPointPositions& positions,
  std::vector<ControlSubCurve>& out,
  std::string& error);

/// Port 3 from every piece's clipped segments (in any order, a segment given by two pieces
/// counted once): consecutive segments of a curve joined, in curve order, Group numbering the
/// pieces. False with `error` as PieceBoundaryControlCurves.
bool PieceClippedControlCurves(std::vector<ClippedSegment> segments,
  const std::vector<CurveSource>& sources,
  const ControlPointPositions& positions,
  std::vector<ControlSubCurve>& out,
  std::string& error);

/// The control points of `sources` whose triangles (global ids) the piece owns, with their
/// positions: (source, point, x, y, z) appended to `out` after their count.
void PackOwnedControlPositions(const PieceMesh& piece,
  const std::vector<std::vector<SurfacePoint>>& controls,
  std::vector<long long>& out);
/// Reads PackOwnedControlPositions' words from `at` on into `positions` (sized as the
/// controls). False with `error` on a short or corrupt message.
bool UnpackControlPositions(const std::vector<long long>& in,
  std::size_t& at,
  ControlPointPositions& positions,
  std::string& error);

/// The clipped segments' words (their count, then per segment the curve, stations and ends).
void PackClippedSegments(const std::vector<ClippedSegment>& segments, std::vector<long long>& out);
/// Appends the segments of `in` from `at` on to `out`. False with `error` when short.
bool UnpackClippedSegments(const std::vector<long long>& in,
  std::size_t& at,
  std::vector<ClippedSegment>& out,
  std::string& error);

} // namespace boolsurf

#endif

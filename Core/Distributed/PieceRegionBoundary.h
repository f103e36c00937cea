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

struct BoundaryPointRecord
{
  BoundaryPointKey Key{};
  Vec3 Position{};
  SurfacePoint Surface; ///< Triangle is a global triangle
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
void PieceRegionBoundaryRuns(const PieceMesh& piece,
  const Arrangement& arr,
  const std::vector<int>& globalCellOfLocal,
  const std::vector<char>& selected,
  std::vector<BoundaryRun>& out);

/// Chains runs (from every piece, in any order) into the region's loops, after cancelling the
/// open two-point runs given once each way: closed loops start at their lowest point; open chains
/// only where a run has no continuation. Sorted by closed first, then by points.
std::vector<BoundaryRun> ChainBoundaryRuns(const std::vector<BoundaryRun>& runs);

/// Message 4 (a piece's runs to the rank that chains them): 10 words per point.
void PackBoundaryRuns(const std::vector<BoundaryRun>& runs, std::vector<long long>& out);
/// Appends the runs of `in` to `out`. False with `error` on a short or corrupt message.
bool UnpackBoundaryRuns(const std::vector<long long>& in,
  std::vector<BoundaryRun>& out,
  std::string& error);

} // namespace boolsurf

#endif

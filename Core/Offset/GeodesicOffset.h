// Geodesic offsets of a region drawn on a surface: the points within distance d of it (d > 0,
// growing), or the region minus the points within |d| of its boundary (d < 0, shrinking), and
// the bands within d of open curves. Beyond the BoolSurf paper, which leaves offsets to future
// work; the planar counterpart is Clipper's offsetting with round joins.
//
// The region is given by its boundary (closed loops of surface points, the region on their
// left, as the arrangement's RegionBoundary gives them) and the side of each mesh vertex.
// 1. Distance: exact polyhedral distance to the boundary by window propagation
//    (ExactGeodesicSearch's field mode): the boundary's points are point sources and each
//    straight piece between two of them a line source (rays normal to it), stopped just past
//    |d|: only the band the offset sweeps is visited. Growing does not propagate inside the
//    region, nor shrinking outside it: a shortest path to the boundary never crosses it.
// 2. Signed field: F = -distance inside the region, +distance outside (the sign flips where
//    an edge crosses the boundary); bands use the distance to the open curves. A flat-ended
//    band is Clipper's butt-ended one: the points within d of the curve but for those only
//    near it beyond an end, past the geodesic normal to the curve at the end point. Each such
//    curve gives two distances, to the curve without a stretch of at least d next to its last
//    point (cut at the first point's normal) and without the one next to its first point (cut
//    at the last point's normal), so a point beyond one end but within d of another part of
//    the curve stays in the band (a curve shorter than the two stretches: one distance, cut at
//    both ends). Exact for ends whose last d of curve is straight; where a
//    corner comes closer to an end, its disk may reach up to d less that distance beyond it.
//    Nearly closed flat curves (ends within 2d of each other) are not checked near their ends.
// 3. Contour: the level set F = d, located on every mesh edge whose ends straddle it by
//    bisection on the exact field along the edge, so each contour point is an exact surface
//    point on a mesh edge; one straight piece per crossed triangle (plus `Resolution` points on
//    the level set inside it, or its sharp corner), oriented with {F < d} on its left; two
//    where a tip or a neck thinner than the mesh crosses the edge opposite the triangle's odd
//    corner twice (both of that edge's triangles having their odd corner on the tip's side).
//    A level set never crosses
//    itself, so fronts that meet (a concave corner filling, two shapes merging, a handle closing)
//    give the true offset region's boundary. Where the contour reaches an open boundary of the
//    surface, the loop is closed along the boundary.
// Each loop is a closed curve of surface points in which consecutive points share a triangle, so
// it is traced as a geodesic polygon exactly as it is (the shortest path between two points of
// one triangle is the straight piece) and takes part in Booleans like any drawn curve.
#ifndef boolsurf_GeodesicOffset_h
#define boolsurf_GeodesicOffset_h

#include "Geodesic/ExactGeodesicSearch.h"
#include "Geodesic/TracedCurve.h"
#include "Mesh/MeshTopology.h"
#include "Mesh/SurfacePoint.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace boolsurf
{

/// How a band ends at an open curve's end points.
enum class OffsetEndStyle : int
{
  Round = 0, ///< half a geodesic disk around the end point
  /// the points within d of the curve but for those near it only beyond an end, cut along
  /// the geodesic normal at the end point (Clipper's butt ends on a plane)
  Flat = 1,
};

struct OffsetOptions
{
  double Distance = 0.0; ///< > 0 grows, < 0 shrinks, 0 gives the boundary back
  OffsetEndStyle Ends = OffsetEndStyle::Round;
  /// Points added on the level set inside each crossed triangle (0: one point per crossed mesh
  /// edge, the contour's mesh resolution).
  int Resolution = 0;
  /// Window budget of the distance computation (about 80 bytes each: 2^23 is ~0.7 GB, a band
  /// of millions of triangles); past it the offset is refused with a message.
  int MaximumWindows = 1 << 23;
};

struct OffsetRegion
{
  /// Closed loops bounding the region, the region on their left.
  std::vector<std::vector<CanonicalPoint>> Boundary;
  /// Whether mesh vertex v lies in the region (asked for vertices near the boundary only).
  std::function<bool(int)> InsideVertex;
  /// Optional: +1 when mesh triangle t lies wholly in the region, -1 wholly outside, 0 when the
  /// boundary may cross it. Growing then never propagates distances inside the region and
  /// shrinking never outside it (a shortest path to the boundary never crosses it), which
  /// halves the work.
  std::function<int(int)> TriangleSide;
  /// Curves whose bands (the points within the distance of them) are added to a grown region,
  /// left out when shrinking: open curves, or closed ones taken as curves rather than as the
  /// boundary of a region (a band around a loop on a handle). A band is around a traced curve
  /// (its points canonical, consecutive ones sharing a triangle), so it is one: only its Points
  /// and Closed matter here (a TracedCurve is closed unless said otherwise).
  std::vector<TracedCurve> Bands;
};

struct OffsetStatistics
{
  int Sources = 0;          ///< boundary points (each piece between two is a line source)
  int Windows = 0;          ///< windows of the distance computation
  int FieldVertices = 0;    ///< vertices the distance reached
  int CrossedTriangles = 0; ///< triangles the contour crosses
  int DroppedSlivers = 0;   ///< tiny loops split off sharp corners at mesh resolution
  double FieldMilliseconds = 0, ContourMilliseconds = 0;
};

/// What an offset keeps between runs on one mesh: the distance searches (to the region's
/// boundary, to the band curves) with their per-vertex state and the mesh's angle sums, and
/// per-vertex and per-triangle marks, so a run costs what its band costs, not the mesh.
struct OffsetBuffers
{
  explicit OffsetBuffers(const TriangleMesh& mesh)
    : Closed(mesh)
    , Open(mesh)
  {
  }
  ExactGeodesicSearch Closed, Open;
  /// Flat-ended bands: two distances per group of curves whose ends keep apart.
  std::vector<std::unique_ptr<ExactGeodesicSearch>> Flat;
  std::vector<double> VertexValue; ///< valid where VertexStamp == Stamp
  std::vector<char> VertexInside;  ///< valid where InsideStamp == Stamp
  std::vector<std::uint32_t> VertexStamp, InsideStamp, TriangleStamp;
  std::uint32_t Stamp = 0;
};

/// The offset region's boundary as closed loops (region on the left) in `loops`. False with a
/// message when the distance is not finite, when a negative distance leaves nothing of the
/// region, when a positive one covers a whole closed surface, or when the window budget runs
/// out. `topology` is needed only on surfaces with boundaries. `buffers` (on `mesh`) are reused
/// when given.
bool ComputeGeodesicOffset(const TriangleMesh& mesh,
  const MeshTopology& topology,
  const OffsetRegion& region,
  const OffsetOptions& options,
  std::vector<std::vector<CanonicalPoint>>& loops,
  std::string& error,
  OffsetStatistics* statistics = nullptr,
  OffsetBuffers* buffers = nullptr);

} // namespace boolsurf

#endif

// Shortest geodesic path between two surface points: the solver and its method policy.
//
// The strip of triangles the path crosses comes, by method (GeodesicPathOptions::Method):
// - Exact: from ExactGeodesicSearch (window propagation): the triangles the exact polyhedral
//   shortest path crosses, so the straightening returns the shortest path itself, not only a
//   locally shortest one;
// - Bounded (default): the same while the window search fits a small budget; past it, from
//   the route of the surface's SurfaceSiteGraph, with other candidates (the policy is in
//   GeodesicPathBounded.cxx);
// - LocallyShortest (or an exact search that gives up): EdgeGraphSearch finds the shortest
//   path along mesh edges (start -> corners of its triangle -> ... -> corners of the end's
//   triangle -> end; exact bidirectional A*). The strip is the chain of triangles along one
//   side of it, turning around each path vertex on the side it came from. The edge path lies
//   in that strip, so the straightened result is never longer than it: a traced path is never
//   longer than the shortest edge path (vtkDijkstraGraphGeodesicPath) between the same points,
//   on any surface, whatever its genus. If the strip cannot be built (a non-manifold vertex on
//   the edge path), DualGraphSearch (greedy A* over triangles) gives the strip instead.
// Whatever the method, StripStraightener (funnel and vertex rerouting) turns the strip into
// the path.
//
// The output is exact in the sense the arrangement needs: every point is canonical (a vertex
// id, an edge id with a parameter, or a triangle with barycentrics) and every two consecutive
// points lie in one common triangle, so each segment is a straight segment of one triangle.
#ifndef boolsurf_GeodesicPath_h
#define boolsurf_GeodesicPath_h

#include "Geodesic/DualGraphSearch.h"
#include "Geodesic/EdgeGraphSearch.h"
#include "Geodesic/ExactGeodesicSearch.h"
#include "Geodesic/GeodesicPathCache.h"
#include "Geodesic/GeodesicPathOptions.h"
#include "Geodesic/StripStraightening.h"
#include "Geodesic/SurfaceSiteGraph.h"
#include "Mesh/SurfacePoint.h"
#include "Mesh/TriangleComponents.h"
#include "Mesh/ZeroPageArray.h"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace boolsurf
{

struct GeodesicPath
{
  /// Start, one point per mesh edge crossed (Edge location), the mesh vertices passed through
  /// (Vertex location), end. Consecutive points share a triangle. A zero-length path (start
  /// == end) holds the single point.
  std::vector<CanonicalPoint> Points;
  double Length = 0.0;
};

/// What the last GeodesicPathSolver::Compute did (for benchmarks and tests).
struct GeodesicPathStatistics
{
  int SettledVertices = 0;     ///< edge-path search work
  int ExpandedTriangles = 0;   ///< dual A* work (only when the edge-path strip failed)
  double EdgePathLength = -1;  ///< shortest edge path (an upper bound of the result)
  int StripTriangles = 0;      ///< final strip length
  int StraighteningRounds = 0; ///< funnel runs
  int Windows = 0;             ///< exact search work (windows created)
  double ExactLength = -1;     ///< exact shortest length found by the window search
  /// True when the path is the exact shortest one (window search done, or the end points
  /// share a triangle); false when the window budget ran out and the locally shortest
  /// straightened edge path was returned instead.
  bool Exact = false;
  /// Bounded method past its window budget: the path was straightened from the surface's
  /// site-graph route (RouteLength: that route's length) ...
  bool Routed = false;
  double RouteLength = -1;
  /// ... and from this many other candidates too (a second route round a handle, the
  /// straightened shortest edge path and the exact path inside a corridor around the route
  /// on meshes up to 100k vertices), the shortest kept.
  int AlternativeRoutes = 0;
  /// Windows of the exact search inside a corridor around a routed leg (RefineInCorridor;
  /// meshes up to 100k vertices), budgeted apart from Windows.
  int CorridorWindows = 0;
  /// The leg came from the surface's GeodesicPathCache (computed before by a solver on the
  /// same surface with the same settings); the work counters above are then zero.
  bool FromCache = false;
};

/// Computes geodesic paths on one mesh. Holds the reusable search state (mesh-sized arrays
/// allocated once in the constructor), so keep one solver per mesh and per thread.
class GeodesicPathSolver
{
public:
  /// `mesh` must outlive the solver. `components`, when given, are the mesh's triangle
  /// components already at hand (TriangleComponents of its MeshTopology), else computed.
  explicit GeodesicPathSolver(const TriangleMesh& mesh,
    std::shared_ptr<const TriangleComponents> components = nullptr);

  struct HelperTag
  {
  };
  /// A solver for another thread, on `main`'s mesh with `main`'s options. It
  /// reads `main`'s connected components (never written after construction, so both may run
  /// at once) and builds its fallback searches (dual strip, edge path) only if a leg needs
  /// them: it holds the exact search's buffers, about 40 bytes per vertex, where a full
  /// solver holds about 150 bytes per triangle. `main` must outlive it.
  GeodesicPathSolver(const GeodesicPathSolver& main, HelperTag);

  /// Locally shortest path from `start` to `end`. Fails with a message on invalid points and
  /// on points lying on different connected components.
  bool Compute(const CanonicalPoint& start,
    const CanonicalPoint& end,
    GeodesicPath& path,
    std::string& error);

  /// Same for raw triangle + barycentric points (validated, then canonicalized exactly).
  bool Compute(const SurfacePoint& start,
    const SurfacePoint& end,
    GeodesicPath& path,
    std::string& error);

  const TriangleMesh& GetMesh() const { return this->Mesh; }
  /// Connected component of usable triangle t (edge adjacency), -1 for unusable triangles.
  int GetComponent(int t) const { return this->Components->GetComponent(t); }
  int GetNumberOfComponents() const { return this->Components->GetNumberOfComponents(); }
  const GeodesicPathStatistics& GetLastStatistics() const { return this->Statistics; }

  /// The settings of every following Compute (see GeodesicPathOptions for the defaults).
  void SetOptions(const GeodesicPathOptions& options);
  const GeodesicPathOptions& GetOptions() const { return this->Options; }

  /// Tracing on a part of a surface (Core/Distributed/PieceTracing): when `reads` is set,
  /// every following Compute appends to it the triangles it read (its ends' triangles, the
  /// exact search's lit triangles, every strip it straightened); the leg is the whole
  /// surface's leg bit for bit when each of them, and each triangle round their corners, is
  /// whole on this mesh (all its neighbours as on the surface, numbered in the same order).
  /// On such a mesh the components are the part's, not the surface's, so legs are not refused
  /// across them, and only the exact window search gives the strip: a leg whose search fails
  /// (a Bounded leg routed on the site graph, an Exact leg past its window budget) and the
  /// LocallyShortest method fail with a message saying so. `exact(t)`, when given, tells
  /// whether triangle t and the triangles round its corners are whole: the exact search then
  /// stops soon after meeting one that is not (ExactGeodesicSearch::SetPieceTriangles, with
  /// `wallSlack`), so that what it read is near the part it needs next, not the whole part it
  /// holds. Null (default): the whole surface.
  void SetPieceReads(std::vector<int>* reads,
    std::function<bool(int)> exact = nullptr,
    double wallSlack = 0.0);
  bool IsOnPiece() const { return this->PieceReads != nullptr; }
  /// The mean edge length the Bounded method's budget test uses (ExceedsBoundedWindows), for a
  /// solver on a part of a surface: the whole surface's EstimateMeanEdgeLength. Default: this
  /// mesh's, computed on first use.
  void SetMeanEdgeLength(double length) { this->MeanEdgeLength = length; }

  /// Builds the landmark table now rather than lazily.
  void PrepareLandmarks() { this->Edges().BuildLandmarks(); }
  const EdgeGraphSearch& GetEdgeSearch() { return this->Edges(); }
  const ExactGeodesicSearch& GetExactSearch() const { return this->Exact; }
  /// The surface's cache of costly legs (null before the first Compute).
  const GeodesicPathCache* GetPathCache() const { return this->Cache.get(); }
  /// The surface's site graph (built on the first routed leg; null before).
  const SurfaceSiteGraph* GetSiteGraph() const { return this->SiteGraph.get(); }

private:
  void CollectTerminals(const CanonicalPoint& start, const CanonicalPoint& end);
  bool StripFromEdgePath(const CanonicalPoint& start, const CanonicalPoint& end);
  /// Bounded method: the strip along the site-graph route avoiding the sites flagged in
  /// AvoidSites (none when empty).
  bool StripFromSiteRoute(const CanonicalPoint& start, const CanonicalPoint& end);
  /// The strip holding VertexPath (a mesh-edge path from a start corner to an end corner).
  bool StripAlongVertexPath(const CanonicalPoint& end);
  /// Bounded method: true when the straight distance between the ends already shows the
  /// window search cannot finish within its budget.
  bool ExceedsBoundedWindows(const CanonicalPoint& start, const CanonicalPoint& end);
  /// The method's strip for a leg whose ends share no triangle (Strip): the exact search's,
  /// a site-graph route's (Bounded), the edge path's or the dual search's. False when none
  /// joins them.
  bool FindStripByMethod(const CanonicalPoint& start, const CanonicalPoint& end);
  /// Bounded method, after a routed leg: the other candidates below; `path` becomes the
  /// shortest.
  void ImproveRoutedLeg(const CanonicalPoint& start, const CanonicalPoint& end, GeodesicPath& path);
  /// Funnel and vertex rerouting on Strip until locally shortest (see StripStraightener).
  bool Straighten(const CanonicalPoint& start, const CanonicalPoint& end);
  /// Bounded method, after a routed leg on a mesh of at most MaximumVerticesForEdgeCandidate
  /// vertices: the straightened shortest edge path too; `path` becomes the shorter.
  void TryEdgePathCandidate(const CanonicalPoint& start,
    const CanonicalPoint& end,
    GeodesicPath& path);
  bool KeepShorterCandidate(const GeodesicPathStatistics& kept, GeodesicPath& path);
  /// Bounded method, after a routed leg: the exact window search inside a corridor of
  /// triangles around `path`, then around the other candidates nearly as short; `path`
  /// becomes the shortest result.
  void RefineInCorridor(const CanonicalPoint& start, const CanonicalPoint& end, GeodesicPath& path);
  bool SearchShorterPath(const CanonicalPoint& start,
    const CanonicalPoint& end,
    GeodesicPath& path,
    bool inCorridor,
    int budget);
  void BuildCorridor(const std::vector<CanonicalPoint>& points);
  /// Whether every triangle of `points` lies in a corridor of generation `first` or later.
  bool InsideSearched(const std::vector<CanonicalPoint>& points, std::uint32_t first);
  /// Bounded method, after a routed leg: other routes, kept out of bands round the middle of
  /// the first, straightened too when nearly as long; `path` becomes the shortest.
  void TryAlternativeRoutes(const CanonicalPoint& start,
    const CanonicalPoint& end,
    GeodesicPath& path);
  /// The fallback searches, built on first use.
  DualGraphSearch& Dual();
  EdgeGraphSearch& Edges();

  const TriangleMesh& Mesh;
  std::unique_ptr<DualGraphSearch> Search;
  std::unique_ptr<EdgeGraphSearch> EdgeSearch;
  std::shared_ptr<const TriangleComponents> Components; // shared with helpers
  // Also the settings of the fallback searches not built yet.
  GeodesicPathOptions Options;
  ExactGeodesicSearch Exact;
  std::shared_ptr<const SurfaceSiteGraph> SiteGraph;
  std::unique_ptr<EdgeGraphSearch> PlainEdgeSearch; // no landmarks: see TryEdgePathCandidate
  static constexpr int MaximumVerticesForEdgeCandidate = 100000;
  /// RefineInCorridor: rings of vertex-adjacent triangles around the path; no ring is added
  /// once the corridor holds MaximumCorridorTriangles; the window budget inside it (the
  /// search makes up to ~90 windows per corridor triangle on scans, about 0.4 us each).
  static constexpr int CorridorRings = 5;
  static constexpr int MaximumCorridorTriangles = 3000;
  static constexpr int CorridorWindows = 1 << 18;
  /// Straightened candidates within this fraction of the kept path's length that leave its
  /// corridor are searched in their own corridors, while at least
  /// MinimumCandidateCorridorWindows of the budget are left.
  static constexpr double CorridorCandidateSlack = 0.01;
  static constexpr int MinimumCandidateCorridorWindows = 1 << 14;
  /// Meshes up to this many triangles (a corridor would hold a quarter of them or more) are
  /// searched whole first, which certifies the leg when it fits the window budget.
  static constexpr int WholeMeshRefinementTriangles = 4 * MaximumCorridorTriangles;
  std::vector<std::uint32_t> CorridorStamp; // == CorridorGeneration: in the corridor
  std::uint32_t CorridorGeneration = 0;
  std::vector<int> Corridor, CorridorSeeds;
  std::shared_ptr<GeodesicPathCache> Cache;
  GeodesicPathCache::Leg CachedLeg;
  SurfaceSiteGraph::Scratch SiteScratch;
  std::vector<char> AvoidSites;
  double MeanEdgeLength = -1; // computed on first use
  std::vector<CanonicalPoint> Alternative;
  /// A routed leg's straightened candidates (length, points), for the corridor.
  std::vector<std::pair<double, std::vector<CanonicalPoint>>> Candidates;
  std::vector<EdgeGraphSearch::Terminal> Sources, Targets;
  std::vector<int> VertexPath;
  GeodesicPathStatistics Statistics;
  std::vector<int>* PieceReads = nullptr; // see SetPieceReads

  // Per-call scratch, kept to reuse capacity.
  std::vector<int> StartTriangles, EndTriangles;
  std::vector<int> Strip;
  StripStraightener Straightener;
};

/// The point at fraction t in [0, 1] of the path's length (t is clamped), found in the
/// triangle shared by the two path points around it. Used for geodesic midpoints.
CanonicalPoint PointAlongPath(const TriangleMesh& mesh, const GeodesicPath& path, double t);

/// The Bounded method's estimate of `mesh`'s mean edge length: the mean over every edge when
/// there are at most 2^16, else over edges 0, s, 2 s, ... (s = edges / 2^16, rounded down),
/// summed in edge order.
double EstimateMeanEdgeLength(const TriangleMesh& mesh);

/// Sum of the straight distances between consecutive points (exact for traced paths, whose
/// consecutive points share a triangle).
double PolylineLength(const TriangleMesh& mesh, const std::vector<CanonicalPoint>& points);

} // namespace boolsurf

#endif

// Shortest geodesic path between two surface points.
//
// The strip of triangles the path crosses comes, by method (SetMethod):
// - Exact: from ExactGeodesicSearch (window propagation): the triangles the exact polyhedral
//   shortest path crosses, so the funnel below returns the shortest path itself, not only a
//   locally shortest one;
// - Bounded (default): the same while the window search fits a small budget; past it, from
//   the route of the surface's SurfaceSiteGraph, straightened below as in stage 3;
// - LocallyShortest (or an exact search that gives up): three stages, after Lee-Preparata and
//   the strip straightening used by BoolSurf/b-Surf:
//  1. EdgeGraphSearch finds the shortest path along mesh edges (start -> corners of its
//     triangle -> ... -> corners of the end's triangle -> end; exact bidirectional A*). The
//     initial strip is the chain of triangles along one side of it, turning around each path
//     vertex on the side it came from. The edge path lies in that strip, so the funnel result
//     is never longer than it, and stage 3 only shortens: a traced path is never longer than
//     the shortest edge path (vtkDijkstraGraphGeodesicPath) between the same points, on any
//     surface, whatever its genus. If the strip cannot be built (a non-manifold vertex on the
//     edge path), DualGraphSearch (greedy A* over triangles) gives the strip instead.
//  2. The strip is unfolded into the plane and the funnel algorithm finds the shortest
//     polyline inside it; it bends only at strip vertices.
//  3. Where that polyline passes through a mesh vertex and the angle on the side outside the
//     strip is below pi, going around the vertex on that side is shorter: the strip is
//     rerouted there and the funnel runs again, until no such vertex is left. The result is
//     locally shortest: at every interior mesh vertex it passes through, both angles are at
//     least pi. A boundary vertex cannot be walked around on the outside, so paths hug
//     boundaries instead of leaving the surface.
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
#include "Geodesic/SurfaceSiteGraph.h"
#include "Mesh/EdgeIndex.h"
#include "Mesh/SurfacePoint.h"
#include "Mesh/TriangleComponents.h"
#include "Mesh/ZeroPageArray.h"

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace boolsurf
{

/// How a geodesic leg is computed (the `GeodesicMethod` property of the filters).
enum class GeodesicMethod : int
{
  /// The shortest path in practice at a bounded cost per leg (default): the exact window
  /// search while its work stays under a fixed budget, otherwise the path in the homotopy
  /// class of the per-surface coarse graph's route, straightened (see SurfaceSiteGraph).
  Bounded = 0,
  /// The exact polyhedral shortest path (window search, budget 2^20 windows); can take
  /// seconds for far points on large meshes.
  Exact = 1,
  /// The straightened shortest mesh-edge path: locally shortest, fast, no guarantee of being
  /// the shortest.
  LocallyShortest = 2,
};

/// "Bounded", "Exact", "LocallyShortest".
const char* GeodesicMethodName(GeodesicMethod method);

/// Outcome of a tracing call: Ok, or a message naming the offending points/curves.
struct TraceStatus
{
  bool Ok = true;
  std::string Message;

  explicit operator bool() const { return this->Ok; }
  static TraceStatus Success() { return {}; }
  static TraceStatus Failure(std::string message) { return { false, std::move(message) }; }
};

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
  /// A solver for another thread, on `main`'s mesh with `main`'s settings (CopySettings). It
  /// reads `main`'s connected components (never written after construction, so both may run
  /// at once) and builds its fallback searches (dual strip, edge path) only if a leg needs
  /// them: it holds the exact search's buffers, about 40 bytes per vertex, where a full
  /// solver holds about 150 bytes per triangle. `main` must outlive it.
  GeodesicPathSolver(const GeodesicPathSolver& main, HelperTag);

  /// Locally shortest path from `start` to `end`. Fails with a message on invalid points and
  /// on points lying on different connected components.
  TraceStatus Compute(const CanonicalPoint& start, const CanonicalPoint& end, GeodesicPath& path);

  /// Same for raw triangle + barycentric points (validated, then canonicalized exactly).
  TraceStatus Compute(const SurfacePoint& start, const SurfacePoint& end, GeodesicPath& path);

  const TriangleMesh& GetMesh() const { return this->Mesh; }
  /// Connected component of usable triangle t (edge adjacency), -1 for unusable triangles.
  int GetComponent(int t) const { return this->Components->GetComponent(t); }
  int GetNumberOfComponents() const { return this->Components->GetNumberOfComponents(); }
  const GeodesicPathStatistics& GetLastStatistics() const { return this->Statistics; }

  /// Upper bound on funnel runs per path (each run after the first shortens the path, so the
  /// loop ends anyway; the bound only guards against numerical ping-pong).
  void SetMaximumStraighteningRounds(int n) { this->MaximumRounds = n; }

  /// See DualGraphSearch::SetHeuristicWeight: the weight of the fallback dual search
  /// (default 2, greedy). The edge-path search is always exact.
  void SetHeuristicWeight(double w);

  /// Landmarks of the exact edge-path search (see EdgeGraphSearch: ALT lower bounds, built
  /// once per mesh; default 16, 0 disables). The edge path found is as short either way.
  void SetNumberOfLandmarks(int n);
  /// See EdgeGraphSearch::SetLandmarkBuildThreshold (default 1; 0 builds on first use).
  void SetLandmarkBuildThreshold(double t);
  /// Builds the landmark table now rather than lazily.
  void PrepareLandmarks() { this->Edges().BuildLandmarks(); }
  const EdgeGraphSearch& GetEdgeSearch() { return this->Edges(); }

  /// Seed with the dual-graph strip only (no edge-path bound); for benchmarks and tests.
  void SetUseEdgePathStrip(bool on) { this->UseEdgePathStrip = on; }

  /// The method of every following Compute (default Bounded).
  void SetMethod(GeodesicMethod method) { this->Method = method; }
  GeodesicMethod GetMethod() const { return this->Method; }
  /// Shorthand: on is Exact, off is LocallyShortest.
  void SetUseExactStrip(bool on)
  {
    this->Method = on ? GeodesicMethod::Exact : GeodesicMethod::LocallyShortest;
  }
  const ExactGeodesicSearch& GetExactSearch() const { return this->Exact; }
  /// See ExactGeodesicSearch::SetPruning (tests compare both).
  void SetExactPruning(bool on) { this->Exact.SetPruning(on); }
  /// Window budget of the Exact method's search (see ExactGeodesicSearch::SetMaximumWindows;
  /// default 2^20); past it the path falls back to the locally shortest one and
  /// GetLastStatistics().Exact is false.
  void SetMaximumWindows(int n) { this->ExactWindows = n; }
  /// Window budget of the Bounded method's exact search (default 2^15, about 10 ms on one
  /// core); past it the leg is routed on the surface's site graph and straightened.
  void SetBoundedWindows(int n) { this->BoundedWindows = n; }
  int GetBoundedWindows() const { return this->BoundedWindows; }
  /// Bounded method: other routes (round a handle or a hole, or the other side of a bump;
  /// see TryAlternativeRoutes) are straightened too when their site-graph length is within
  /// this fraction of the first route's (default 0.15; 0 disables).
  void SetRouteTolerance(double f) { this->RouteTolerance = f; }
  /// Bounded method, on meshes up to 100k vertices: refine a routed leg by the exact search
  /// inside a corridor of triangles around it (default on; off for comparisons).
  void SetCorridorRefinement(bool on) { this->CorridorRefinement = on; }
  /// Takes every setting above from `other` (a solver on the same mesh): a second solver
  /// then computes the same paths, for tracing on several threads.
  void CopySettings(const GeodesicPathSolver& other);
  /// The surface's cache of costly legs (null before the first Compute).
  const GeodesicPathCache* GetPathCache() const { return this->Cache.get(); }
  /// The surface's site graph (built on the first routed leg; null before).
  const SurfaceSiteGraph* GetSiteGraph() const { return this->SiteGraph.get(); }

private:
  struct Portal
  {
    int Left = -1, Right = -1; // mesh vertex ids, seen walking from the start to the end
    Vec2 LeftPosition, RightPosition;
    int Edge = -1;
  };
  struct Corner
  {
    Vec2 Position;
    int Vertex = -1; // -2: start, -3: end
    int Portal = 0;  // funnel portal index it was found at (0 = start)
  };
  struct PathPoint
  {
    CanonicalPoint Point;
    int FirstPortal = -1, LastPortal = -1; // Vertex points: strip portals that contain it
  };

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
  /// Funnel and vertex rerouting on Strip until locally shortest; the result in Points.
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
  void TrimStrip(const CanonicalPoint& start, const CanonicalPoint& end);
  bool UnfoldStrip(const CanonicalPoint& start, const CanonicalPoint& end);
  void RunFunnel();
  void CollectPathPoints(const CanonicalPoint& start, const CanonicalPoint& end);
  void EmitVertex(int vertex, int portal);
  bool RerouteAroundVertices();
  /// Angle at vertex v between the directions to `before` and `after`, swept from strip
  /// triangle `first` away from strip triangle `second` until strip triangle `last`;
  /// negative when a boundary (or a non-manifold fan) blocks the way.
  double OutsideAngle(int v,
    const Vec3& before,
    const Vec3& after,
    int first,
    int second,
    int last,
    std::vector<int>& swept) const;

  /// The fallback searches, built on first use.
  DualGraphSearch& Dual();
  EdgeGraphSearch& Edges();

  const TriangleMesh& Mesh;
  std::unique_ptr<DualGraphSearch> Search;
  std::unique_ptr<EdgeGraphSearch> EdgeSearch;
  std::shared_ptr<const TriangleComponents> Components; // shared with helpers
  // The fallback searches' settings, kept here for searches not built yet.
  double HeuristicWeight = 2.0;
  int LandmarkCount = 16;
  double LandmarkBuildThreshold = 1.0;
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
  int ExactWindows = 1 << 20;
  int BoundedWindows = 1 << 15;
  double RouteTolerance = 0.15;
  bool CorridorRefinement = true;
  double MeanEdgeLength = -1; // computed on first use
  std::vector<CanonicalPoint> Alternative;
  /// A routed leg's straightened candidates (length, points), for the corridor.
  std::vector<std::pair<double, std::vector<CanonicalPoint>>> Candidates;
  bool UseEdgePathStrip = true;
  GeodesicMethod Method = GeodesicMethod::Bounded;
  std::vector<EdgeGraphSearch::Terminal> Sources, Targets;
  std::vector<int> VertexPath;
  GeodesicPathStatistics Statistics;
  int MaximumRounds = 10000;

  // Per-call scratch, kept to reuse capacity.
  std::vector<int> StartTriangles, EndTriangles;
  std::vector<int> Strip, NewStrip, Swept;
  std::vector<std::array<Vec2, 3>> Unfolded;
  std::vector<int> UnfoldedStrip; // the strip Unfolded and Portals were computed for
  std::vector<Portal> Portals;    // Portals[i] joins Strip[i] and Strip[i + 1]
  Vec2 StartPosition, EndPosition;
  std::vector<Corner> Corners;
  std::vector<PathPoint> Points;
  EdgeIndex StripPosition; ///< triangle -> its index in Strip (keyed by triangle id)
};

/// The point at fraction t in [0, 1] of the path's length (t is clamped), found in the
/// triangle shared by the two path points around it. Used for geodesic midpoints.
CanonicalPoint PointAlongPath(const TriangleMesh& mesh, const GeodesicPath& path, double t);

/// Sum of the straight distances between consecutive points (exact for traced paths, whose
/// consecutive points share a triangle).
double PolylineLength(const TriangleMesh& mesh, const std::vector<CanonicalPoint>& points);

} // namespace boolsurf

#endif

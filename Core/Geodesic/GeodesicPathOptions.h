// The settings of a GeodesicPathSolver: how a geodesic leg is computed (the method, the
// `GeodesicMethod` property of the filters) and the parameters of each method's searches.
#ifndef boolsurf_GeodesicPathOptions_h
#define boolsurf_GeodesicPathOptions_h

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

/// Every setting of a GeodesicPathSolver; the defaults are the filters' settings. Two solvers
/// on one mesh with equal options compute the same paths.
struct GeodesicPathOptions
{
  /// The method of every Compute.
  GeodesicMethod Method = GeodesicMethod::Bounded;

  /// Window budget of the Exact method's search (see ExactGeodesicSearch::SetMaximumWindows);
  /// past it the path falls back to the locally shortest one and the statistics' Exact is
  /// false.
  int MaximumWindows = 1 << 20;
  /// Window budget of the Bounded method's exact search (about 10 ms on one core); past it the
  /// leg is routed on the surface's site graph and straightened.
  int BoundedWindows = 1 << 15;
  /// Bounded method: other routes (round a handle or a hole, or the other side of a bump) are
  /// straightened too when their site-graph length is within this fraction of the first
  /// route's (0 disables).
  double RouteTolerance = 0.15;
  /// Bounded method, on meshes up to 100k vertices: refine a routed leg by the exact search
  /// inside a corridor of triangles around it (off for comparisons).
  bool CorridorRefinement = true;
  /// See ExactGeodesicSearch::SetPruning (tests compare both).
  bool ExactPruning = true;

  /// LocallyShortest method (and fallbacks): seed with the shortest edge path's strip; off
  /// seeds with the dual-graph strip only (no edge-path bound), for benchmarks and tests.
  bool UseEdgePathStrip = true;
  /// Landmarks of the exact edge-path search (see EdgeGraphSearch: ALT lower bounds, built
  /// once per mesh; 0 disables). The edge path found is as short either way.
  int NumberOfLandmarks = 16;
  /// See EdgeGraphSearch::SetLandmarkBuildThreshold (0 builds on first use).
  double LandmarkBuildThreshold = 1.0;
  /// See DualGraphSearch::SetHeuristicWeight: the weight of the fallback dual search (2 is
  /// greedy). The edge-path search is always exact.
  double HeuristicWeight = 2.0;

  /// Upper bound on funnel runs per path (each run after the first shortens the path, so the
  /// loop ends anyway; the bound only guards against numerical ping-pong).
  int MaximumStraighteningRounds = 10000;

  bool operator==(const GeodesicPathOptions& o) const
  {
    return Method == o.Method && MaximumWindows == o.MaximumWindows &&
      BoundedWindows == o.BoundedWindows && RouteTolerance == o.RouteTolerance &&
      CorridorRefinement == o.CorridorRefinement && ExactPruning == o.ExactPruning &&
      UseEdgePathStrip == o.UseEdgePathStrip && NumberOfLandmarks == o.NumberOfLandmarks &&
      LandmarkBuildThreshold == o.LandmarkBuildThreshold && HeuristicWeight == o.HeuristicWeight &&
      MaximumStraighteningRounds == o.MaximumStraighteningRounds;
  }
  bool operator!=(const GeodesicPathOptions& o) const { return !(*this == o); }
};

} // namespace boolsurf

#endif

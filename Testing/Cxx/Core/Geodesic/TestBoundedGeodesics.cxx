// The Bounded geodesic method and its per-surface site graph: a fixed window budget per leg,
// far legs routed on the site graph and straightened (valid, never shorter than the exact
// path, within a few percent of it), short legs exact, and one graph per surface.
#include "Geodesic/CurveTracer.h"
#include "Geodesic/GeodesicPath.h"
#include "Geodesic/SurfaceSiteGraph.h"
#include "Mesh/MeshTopology.h"
#include "Mesh/ProceduralMeshes.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <queue>
#include <random>
#include <utility>
#include <vector>

using namespace boolsurf;

namespace
{
/// The message of the last failed trace or path (a test reads it only after a failure).
std::string traceError;
}

namespace
{
TriangleMesh ToMesh(const MeshData& d)
{
  return TriangleMesh(d.Positions, d.Triangles);
}

CanonicalPoint FacePoint(const TriangleMesh& mesh, std::mt19937& rng)
{
  std::uniform_real_distribution<double> unit(0.05, 0.45);
  CanonicalPoint c;
  c.Location = PointLocation::Face;
  c.Id = static_cast<int>(rng() % mesh.GetNumberOfTriangles());
  c.U = unit(rng);
  c.V = unit(rng);
  return c;
}

/// The farthest (straight line) of 64 random face points from p.
CanonicalPoint FarPoint(const TriangleMesh& mesh, const CanonicalPoint& p, std::mt19937& rng)
{
  CanonicalPoint best = FacePoint(mesh, rng);
  for (int i = 0; i < 64; ++i)
  {
    const CanonicalPoint q = FacePoint(mesh, rng);
    if (Distance(PositionOf(mesh, q), PositionOf(mesh, p)) >
      Distance(PositionOf(mesh, best), PositionOf(mesh, p)))
    {
      best = q;
    }
  }
  return best;
}

void ExpectOnSurface(const TriangleMesh& mesh, const GeodesicPath& path)
{
  for (std::size_t i = 1; i < path.Points.size(); ++i)
  {
    EXPECT_GE(SharedTriangle(mesh, path.Points[i - 1], path.Points[i]), 0) << "point " << i;
  }
}

/// Edge hops from vertex `from` to every vertex (breadth-first).
std::vector<int> Hops(const TriangleMesh& mesh, int from)
{
  std::vector<int> hops(mesh.GetNumberOfVertices(), -1);
  std::queue<int> queue;
  hops[from] = 0;
  queue.push(from);
  while (!queue.empty())
  {
    const int v = queue.front();
    queue.pop();
    for (int corner : mesh.GetVertexCorners(v))
    {
      const Triangle& t = mesh.GetTriangle(corner / 3);
      for (int w : { t[(corner % 3 + 1) % 3], t[(corner % 3 + 2) % 3] })
      {
        if (hops[w] < 0)
        {
          hops[w] = hops[v] + 1;
          queue.push(w);
        }
      }
    }
  }
  return hops;
}

/// A random face point a and a far point b from it, traced by each solver into its path;
/// false (with the failure recorded) when a solver fails.
bool TraceFarLeg(const TriangleMesh& mesh,
  std::mt19937& rng,
  const std::vector<std::pair<GeodesicPathSolver*, GeodesicPath*>>& runs,
  CanonicalPoint& a,
  CanonicalPoint& b)
{
  a = FacePoint(mesh, rng);
  b = FarPoint(mesh, a, rng);
  for (const auto& run : runs)
  {
    const bool traced = run.first->Compute(a, b, *run.second, traceError);
    if (!traced)
    {
      ADD_FAILURE() << Describe(a) << " -> " << Describe(b) << ": " << traceError;
      return false;
    }
  }
  return true;
}
} // namespace

// Every vertex lies in a cell whose site is within `hops` edges, sites are more than `hops`
// edges apart, and the cells' parent chains end at their sites.
TEST(SurfaceSiteGraph, CellsCoverTheSurfaceAndSitesAreSpread)
{
  const TriangleMesh mesh = ToMesh(MakeTorus(1.0, 0.35, 64, 24));
  const int hops = 2;
  const SurfaceSiteGraph graph(mesh, hops);
  ASSERT_GT(graph.GetNumberOfSites(), 10);
  ASSERT_GT(graph.GetNumberOfArcs(), graph.GetNumberOfSites());
  for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
    ASSERT_GE(graph.GetCell(v), 0) << "vertex " << v;
  }
  std::vector<int> nearest(mesh.GetNumberOfVertices(), 1 << 30);
  std::vector<int> siteVertices;
  for (int s = 0; s < graph.GetNumberOfSites(); ++s)
  {
    const int v = graph.GetSite(s);
    EXPECT_EQ(graph.GetCell(v), s) << "a site lies in its own cell";
    siteVertices.push_back(v);
    const std::vector<int> h = Hops(mesh, v);
    for (int w = 0; w < mesh.GetNumberOfVertices(); ++w)
    {
      nearest[w] = std::min(nearest[w], h[w]);
    }
  }
  ASSERT_EQ(static_cast<int>(siteVertices.size()), graph.GetNumberOfSites());
  for (int s : siteVertices)
  {
    const std::vector<int> h = Hops(mesh, s);
    for (int t : siteVertices)
    {
      if (t != s)
      {
        EXPECT_GT(h[t], hops) << "sites " << s << " and " << t;
      }
    }
  }
  for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
    EXPECT_LE(nearest[v], hops) << "vertex " << v << " is far from every site";
  }
}

// One graph per surface: solvers on the same mesh share it, another mesh gets its own, and a
// graph is the same whoever builds it (deterministic).
TEST(SurfaceSiteGraph, SharedPerSurfaceAndDeterministic)
{
  const TriangleMesh a = ToMesh(MakeTorus(1.0, 0.35, 48, 20));
  const TriangleMesh b = ToMesh(MakeTorus(1.0, 0.35, 48, 20));
  const auto ga = SurfaceSiteGraph::Get(a);
  EXPECT_EQ(SurfaceSiteGraph::Get(a).get(), ga.get());
  const auto gb = SurfaceSiteGraph::Get(b);
  EXPECT_NE(gb.get(), ga.get());
  ASSERT_EQ(gb->GetNumberOfSites(), ga->GetNumberOfSites());
  ASSERT_EQ(gb->GetNumberOfArcs(), ga->GetNumberOfArcs());
  for (int v = 0; v < a.GetNumberOfVertices(); ++v)
  {
    ASSERT_EQ(ga->GetCell(v), gb->GetCell(v));
  }
}

// A mesh large enough that the graph is built on several threads (adjacency rows, arc
// candidates, the topology beside the sites) gives the graph one thread builds.
TEST(SurfaceSiteGraph, SameGraphOnOneThread)
{
  const TriangleMesh mesh = ToMesh(MakeTorus(1.0, 0.35, 400, 140)); // 56,000 vertices
  const SurfaceSiteGraph parallel(mesh);
  std::unique_ptr<SurfaceSiteGraph> serial;
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    serial = std::make_unique<SurfaceSiteGraph>(mesh);
  }
  ASSERT_EQ(serial->GetNumberOfSites(), parallel.GetNumberOfSites());
  ASSERT_EQ(serial->GetNumberOfArcs(), parallel.GetNumberOfArcs());
  EXPECT_EQ(serial->IsAllSpheres(), parallel.IsAllSpheres());
  for (int s = 0; s < parallel.GetNumberOfSites(); ++s)
  {
    ASSERT_EQ(serial->GetSite(s), parallel.GetSite(s));
  }
  for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
    ASSERT_EQ(serial->GetCell(v), parallel.GetCell(v));
  }
  // The same route, vertex for vertex, between two far points.
  SurfaceSiteGraph::Scratch a, b;
  std::vector<int> routeA, routeB;
  const auto route =
    [&](const SurfaceSiteGraph& g, SurfaceSiteGraph::Scratch& scratch, std::vector<int>& vertices)
  {
    const int from = 0, to = mesh.GetNumberOfVertices() / 2 + 17;
    return g.FindRoute({ { from, 0.0 } },
      mesh.GetPosition(from),
      { { to, 0.0 } },
      mesh.GetPosition(to),
      {},
      scratch,
      vertices);
  };
  EXPECT_EQ(route(*serial, a, routeA), route(parallel, b, routeB));
  EXPECT_EQ(routeA, routeB);
}

// Tracing tasks that all ask for a surface's graph while it is being built (the first far legs
// of a drawing) get one graph, built once (the waiting threads take part in its loops instead
// of sleeping on a lock), and it is the graph one thread builds alone.
TEST(SurfaceSiteGraph, OneGraphWhenManyTasksWaitForIt)
{
  const TriangleMesh mesh = ToMesh(MakeTorus(1.0, 0.35, 400, 140)); // 56,000 vertices
  std::unique_ptr<SurfaceSiteGraph> serial;
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    serial = std::make_unique<SurfaceSiteGraph>(mesh);
  }
  std::vector<std::shared_ptr<const SurfaceSiteGraph>> asked(16);
  tbb::parallel_for(0, 16, [&](int i) { asked[i] = SurfaceSiteGraph::Get(mesh); });
  for (const auto& graph : asked)
  {
    ASSERT_EQ(graph.get(), asked[0].get());
  }
  EXPECT_EQ(SurfaceSiteGraph::Find(mesh).get(), asked[0].get());
  const SurfaceSiteGraph& shared = *asked[0];
  ASSERT_EQ(shared.GetNumberOfSites(), serial->GetNumberOfSites());
  ASSERT_EQ(shared.GetNumberOfArcs(), serial->GetNumberOfArcs());
  EXPECT_EQ(shared.IsAllSpheres(), serial->IsAllSpheres());
  for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
    ASSERT_EQ(shared.GetCell(v), serial->GetCell(v));
  }
  asked.clear();
  EXPECT_EQ(SurfaceSiteGraph::Find(mesh), nullptr) << "held only while someone holds it";
}

// The topology the surface's converter offers (MeshTopology::Share) stands for the one the
// graph would compute: the same sphere test on a sphere, a torus and an open cylinder.
TEST(SurfaceSiteGraph, SharedTopologyGivesTheSameGraph)
{
  for (const MeshData& data :
    { MakeIcosphere(5), MakeTorus(1.0, 0.35, 400, 140), MakeOpenCylinder(1.0, 2.0, 300, 200) })
  {
    const TriangleMesh mesh = ToMesh(data);
    const SurfaceSiteGraph own(mesh);
    const auto topology = std::make_shared<const MeshTopology>(MeshTopology::Compute(mesh));
    MeshTopology::Share(mesh, topology);
    ASSERT_EQ(MeshTopology::FindShared(mesh), topology);
    const SurfaceSiteGraph withShared(mesh);
    EXPECT_EQ(withShared.IsAllSpheres(), own.IsAllSpheres());
    ASSERT_EQ(withShared.GetNumberOfSites(), own.GetNumberOfSites());
    ASSERT_EQ(withShared.GetNumberOfArcs(), own.GetNumberOfArcs());
    for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
    {
      ASSERT_EQ(withShared.GetCell(v), own.GetCell(v));
    }
  }
  const TriangleMesh sphere = ToMesh(MakeIcosphere(3));
  EXPECT_TRUE(SurfaceSiteGraph(sphere).IsAllSpheres());
}

// The route's distortion: on a flat square the geodesic is the straight segment, so a route's
// length over the straight distance is the graph's own error. Routes of single arcs turn only
// where cells meet and zigzag (5-7 % longer on scans); steps over two arcs, unfolded at the
// middle site, keep far routes within a few percent, and about 1 % on average.
TEST(SurfaceSiteGraph, FarRoutesOnAFlatSquareAreNearlyStraight)
{
  const TriangleMesh mesh = ToMesh(MakeFlatSquare(120, 1.0, 0.3, 7));
  const SurfaceSiteGraph graph(mesh, 3);
  SurfaceSiteGraph::Scratch scratch;
  std::vector<int> vertices;
  std::mt19937 rng(11);
  double worst = 0.0, sum = 0.0;
  int routes = 0;
  while (routes < 200)
  {
    // Routes between sites: from any other vertex a route first walks to its cell's site.
    const int a = graph.GetSite(static_cast<int>(rng() % graph.GetNumberOfSites()));
    const int b = graph.GetSite(static_cast<int>(rng() % graph.GetNumberOfSites()));
    const Vec3 pa = mesh.GetPosition(a), pb = mesh.GetPosition(b);
    const double straight = Distance(pa, pb);
    if (straight < 0.5)
    {
      continue; // far pairs: the ends' own cells are a small part of the route
    }
    const double length =
      graph.FindRoute({ { a, 0.0 } }, pa, { { b, 0.0 } }, pb, {}, scratch, vertices);
    ASSERT_GT(length, 0.0);
    ASSERT_GE(vertices.size(), 2u);
    EXPECT_EQ(vertices.front(), a);
    EXPECT_EQ(vertices.back(), b);
    // The mesh-edge path the route expands to is a real path of consecutive neighbours.
    for (std::size_t i = 1; i < vertices.size(); ++i)
    {
      bool neighbours = false;
      for (int corner : mesh.GetVertexCorners(vertices[i - 1]))
      {
        const Triangle& t = mesh.GetTriangle(corner / 3);
        neighbours =
          neighbours || t[0] == vertices[i] || t[1] == vertices[i] || t[2] == vertices[i];
      }
      ASSERT_TRUE(neighbours) << "route vertices " << vertices[i - 1] << ", " << vertices[i];
    }
    const double ratio = length / straight;
    EXPECT_GE(ratio, 1.0 - 1e-12) << "a route is never shorter than the straight distance";
    worst = std::max(worst, ratio);
    sum += ratio;
    ++routes;
  }
  std::cout << "route / straight distance: mean " << sum / routes << ", worst " << worst << "\n";
  EXPECT_LE(sum / routes, 1.02);
  EXPECT_LE(worst, 1.05);
}

// Far legs on a mesh too large for the window budget: every leg's exact search stays within
// the budget, far legs are routed, valid, never shorter than the exact path and within 5 % of
// it; the routed legs of a tracer never rebuild the graph when only the curves change.
TEST(BoundedGeodesics, FarLegsAreRoutedWithinTheBudget)
{
  const TriangleMesh mesh = ToMesh(MakeTorus(1.0, 0.35, 112, 44));
  GeodesicPathSolver bounded(mesh), exact(mesh);
  GeodesicPathOptions exactOptions, boundedOptions;
  exactOptions.Method = GeodesicMethod::Exact;
  exactOptions.MaximumWindows = 1 << 26;
  exact.SetOptions(exactOptions);
  boundedOptions.BoundedWindows = 1 << 12;
  bounded.SetOptions(boundedOptions);
  std::mt19937 rng(27);
  GeodesicPath b, e;
  int routed = 0, same = 0;
  const SurfaceSiteGraph* graph = nullptr;
  for (int i = 0; i < 16; ++i)
  {
    const CanonicalPoint p = FacePoint(mesh, rng);
    const CanonicalPoint q = FarPoint(mesh, p, rng);
    ASSERT_TRUE(bounded.Compute(p, q, b, traceError));
    ASSERT_TRUE(exact.Compute(p, q, e, traceError));
    ASSERT_TRUE(exact.GetLastStatistics().Exact);
    // The search stops at the first propagation past the budget (which adds at most a few).
    EXPECT_LE(bounded.GetLastStatistics().Windows, (1 << 12) + 8);
    ExpectOnSurface(mesh, b);
    EXPECT_GE(b.Length, e.Length * (1 - 1e-9));
    EXPECT_LE(b.Length, e.Length * 1.05);
    routed += bounded.GetLastStatistics().Routed;
    same += std::abs(b.Length - e.Length) <= 1e-9 * e.Length;
    if (bounded.GetSiteGraph())
    {
      if (!graph)
      {
        graph = bounded.GetSiteGraph();
      }
      EXPECT_EQ(bounded.GetSiteGraph(), graph) << "the graph was rebuilt";
    }
  }
  EXPECT_EQ(routed, 16);
  // Routed far legs are the exact ones about half of the time on this torus (9 of 16 when
  // written); the others are locally shortest geodesics at most a few percent longer.
  EXPECT_GE(same, 8) << "far legs equal to the exact ones";

  // A tracer: the same graph for every curve on the mesh.
  CurveTracer tracer(mesh);
  tracer.GetPathSolver().SetOptions(boundedOptions);
  CurveTrace trace;
  const SurfaceSiteGraph* traced = nullptr;
  for (int c = 0; c < 3; ++c)
  {
    std::vector<SurfacePoint> points;
    for (int k = 0; k < 3; ++k)
    {
      const CanonicalPoint p = FacePoint(mesh, rng);
      points.push_back({ p.Id, p.U, p.V });
    }
    ASSERT_TRUE(tracer.Trace(points, CurveType::GeodesicPolygon, true, trace, traceError));
    ASSERT_NE(tracer.GetPathSolver().GetSiteGraph(), nullptr);
    if (!traced)
    {
      traced = tracer.GetPathSolver().GetSiteGraph();
    }
    EXPECT_EQ(tracer.GetPathSolver().GetSiteGraph(), traced);
  }
  EXPECT_EQ(traced, SurfaceSiteGraph::Get(mesh).get()) << "one graph per surface";
}

// A scanned surface has many locally shortest geodesics between far points, one on each side
// of every small bump, within a fraction of a percent of each other: the route cannot tell
// them apart, the exact search inside a corridor around it can. On a noisy square (bumps of a
// third of an edge; 12.8k triangles, above the whole-mesh search's limit), far legs past the
// window budget equal the exact ones with the corridor, far fewer without it; never shorter,
// always on the surface.
TEST(BoundedGeodesics, CorridorRefinementFindsTheShortestOfNearbyGeodesics)
{
  MeshData data = MakeFlatSquare(80, 1.0, 0.2, 11);
  std::mt19937 noise(5);
  std::uniform_real_distribution<double> bump(-0.004, 0.004);
  for (Vec3& p : data.Positions)
  {
    p.z = bump(noise);
  }
  const TriangleMesh mesh = ToMesh(data);
  GeodesicPathSolver refined(mesh), plain(mesh), exact(mesh);
  GeodesicPathOptions exactOptions, refinedOptions;
  exactOptions.Method = GeodesicMethod::Exact;
  exactOptions.MaximumWindows = 1 << 26;
  exact.SetOptions(exactOptions);
  refinedOptions.BoundedWindows = 1 << 10;
  refined.SetOptions(refinedOptions);
  GeodesicPathOptions plainOptions = refinedOptions;
  plainOptions.CorridorRefinement = false;
  plain.SetOptions(plainOptions);
  std::mt19937 rng(30);
  int sameRefined = 0, samePlain = 0, legs = 0;
  GeodesicPath r, p, e;
  for (int i = 0; i < 12; ++i)
  {
    CanonicalPoint a, b;
    ASSERT_TRUE(TraceFarLeg(mesh, rng, { { &refined, &r }, { &plain, &p }, { &exact, &e } }, a, b));
    ASSERT_TRUE(refined.GetLastStatistics().Routed);
    EXPECT_GT(refined.GetLastStatistics().CorridorWindows, 0);
    EXPECT_EQ(plain.GetLastStatistics().CorridorWindows, 0);
    ExpectOnSurface(mesh, r);
    EXPECT_GE(r.Length, e.Length * (1 - 1e-9));
    EXPECT_LE(r.Length, p.Length * (1 + 1e-12)) << "the corridor never makes a leg longer";
    sameRefined += std::abs(r.Length - e.Length) <= 1e-9 * e.Length;
    samePlain += std::abs(p.Length - e.Length) <= 1e-9 * e.Length;
    ++legs;
  }
  EXPECT_GE(sameRefined, legs - 1);
  EXPECT_LT(samePlain, sameRefined) << samePlain << " of " << legs << " without the corridor";
}

// On a mesh of at most 12k triangles a routed leg is refined by the exact search over the
// whole mesh, bounded by the routed length: when that search fits its budget the leg is the
// shortest and says so (Exact), whichever way round the handles the route went. A torus
// whose route is forced (tiny window budget, no second route) against the Exact method.
TEST(BoundedGeodesics, WholeMeshRefinementCertifiesRoutedLegsOnSmallMeshes)
{
  const TriangleMesh mesh = ToMesh(MakeTorus(1.0, 0.35, 48, 20));
  ASSERT_LE(mesh.GetNumberOfTriangles(), 12000);
  GeodesicPathSolver refined(mesh), plain(mesh), exact(mesh);
  GeodesicPathOptions exactOptions, refinedOptions;
  exactOptions.Method = GeodesicMethod::Exact;
  exact.SetOptions(exactOptions);
  refinedOptions.BoundedWindows = 1 << 6;
  refinedOptions.RouteTolerance = 0.0;
  refined.SetOptions(refinedOptions);
  GeodesicPathOptions plainOptions = refinedOptions;
  plainOptions.CorridorRefinement = false;
  plain.SetOptions(plainOptions);
  std::mt19937 rng(31);
  int samePlain = 0, legs = 0;
  GeodesicPath r, p, e;
  for (int i = 0; i < 16; ++i)
  {
    CanonicalPoint a, b;
    ASSERT_TRUE(TraceFarLeg(mesh, rng, { { &refined, &r }, { &plain, &p }, { &exact, &e } }, a, b));
    ASSERT_TRUE(refined.GetLastStatistics().Routed);
    EXPECT_TRUE(refined.GetLastStatistics().Exact) << "the whole-mesh search fits its budget";
    EXPECT_FALSE(plain.GetLastStatistics().Exact);
    ExpectOnSurface(mesh, r);
    EXPECT_NEAR(r.Length, e.Length, 1e-9 * e.Length) << Describe(a) << " -> " << Describe(b);
    EXPECT_LE(r.Length, p.Length * (1 + 1e-12));
    samePlain += std::abs(p.Length - e.Length) <= 1e-9 * e.Length;
    ++legs;
  }
  EXPECT_LT(samePlain, legs) << "the route and the funnel alone are not always the shortest";
}

// Short legs are exact under the Bounded method, whatever the budget's far legs do.
TEST(BoundedGeodesics, ShortLegsAreExact)
{
  const TriangleMesh mesh = ToMesh(MakeTorus(1.0, 0.35, 160, 64));
  GeodesicPathSolver bounded(mesh), exact(mesh);
  GeodesicPathOptions exactOptions;
  exactOptions.Method = GeodesicMethod::Exact;
  exact.SetOptions(exactOptions);
  std::mt19937 rng(28);
  GeodesicPath b, e;
  int tested = 0;
  for (int i = 0; i < 100000 && tested < 40; ++i)
  {
    const CanonicalPoint p = FacePoint(mesh, rng), q = FacePoint(mesh, rng);
    const double d = Distance(PositionOf(mesh, p), PositionOf(mesh, q));
    if (d > 0.15 || d < 0.02)
    {
      continue;
    }
    ASSERT_TRUE(bounded.Compute(p, q, b, traceError));
    ASSERT_TRUE(exact.Compute(p, q, e, traceError));
    EXPECT_TRUE(bounded.GetLastStatistics().Exact);
    EXPECT_FALSE(bounded.GetLastStatistics().Routed);
    EXPECT_EQ(b.Points, e.Points);
    ++tested;
  }
  EXPECT_EQ(tested, 40);
}

// Costly legs are shared through the surface's cache: a second solver on the same surface
// with the same settings gets the first one's legs back, bit for bit, without searching; other
// settings or another surface do not.
TEST(GeodesicPathCache, CostlyLegsAreSharedPerSurfaceAndSettings)
{
  const TriangleMesh mesh = ToMesh(MakeTorus(1.0, 0.35, 112, 44));
  GeodesicPathSolver first(mesh), second(mesh), other(mesh);
  GeodesicPathOptions otherOptions;
  otherOptions.BoundedWindows = 1 << 12;
  other.SetOptions(otherOptions);
  std::mt19937 rng(31);
  GeodesicPath a, b, c;
  int shared = 0;
  for (int i = 0; i < 8; ++i)
  {
    const CanonicalPoint p = FacePoint(mesh, rng);
    const CanonicalPoint q = FarPoint(mesh, p, rng);
    ASSERT_TRUE(first.Compute(p, q, a, traceError));
    EXPECT_FALSE(first.GetLastStatistics().FromCache);
    const bool costly = first.GetLastStatistics().Windows >= GeodesicPathCache::MinimumWindows ||
      first.GetLastStatistics().Routed;
    ASSERT_TRUE(second.Compute(p, q, b, traceError));
    EXPECT_EQ(second.GetLastStatistics().FromCache, costly);
    EXPECT_EQ(b.Points, a.Points);
    EXPECT_EQ(b.Length, a.Length);
    EXPECT_EQ(second.GetLastStatistics().Exact, first.GetLastStatistics().Exact);
    shared += costly;
    ASSERT_TRUE(other.Compute(p, q, c, traceError));
    EXPECT_FALSE(other.GetLastStatistics().FromCache) << "another budget took a cached leg";
  }
  EXPECT_GE(shared, 6);
  ASSERT_NE(first.GetPathCache(), nullptr);
  EXPECT_EQ(first.GetPathCache(), second.GetPathCache());
  EXPECT_GE(first.GetPathCache()->GetHits(), static_cast<std::size_t>(shared));

  const TriangleMesh copy = ToMesh(MakeTorus(1.0, 0.35, 112, 44));
  GeodesicPathSolver elsewhere(copy);
  std::mt19937 again(31);
  const CanonicalPoint p = FacePoint(copy, again);
  ASSERT_TRUE(elsewhere.Compute(p, FarPoint(copy, p, again), c, traceError));
  EXPECT_FALSE(elsewhere.GetLastStatistics().FromCache) << "another surface shares the cache";
  EXPECT_NE(elsewhere.GetPathCache(), first.GetPathCache());
}

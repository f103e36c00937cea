// Traced geodesic lengths against an independent exact polyhedral shortest-path oracle:
// CGAL's Surface_mesh_shortest_path (Chen-Han's algorithm with exact predicates). CGAL is a
// test dependency only; this executable is the one place it is linked.
//
// With the Exact method every traced edge must have the oracle's length to 1e-9 relative:
// none longer (a locally shortest path in the wrong homotopy class, or straightening stopped
// short) and none shorter (a path leaving the surface). With the Bounded method (the default)
// none may be shorter, short pairs must be exact, and far pairs within the measured worst
// excess (see Docs/Decisions.md). Pairs: random points (vertex, edge and face points), short
// pairs (2-6 % of the bounding-box diagonal), far points (the farthest of many random
// candidates) and, on meshes with handles, pairs on opposite sides of a handle.
#include "CgalFaceWeights.h"
#include "Geodesic/GeodesicPath.h"
#include "Mesh/PlyReader.h"
#include "Mesh/ProceduralMeshes.h"
#include "Support/CanonicalPoints.h"
#include "Support/UnrolledPrism.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_shortest_path.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <random>
#include <sstream>
#include <string>

using namespace boolsurf;

namespace
{
/// The message of the last failed trace or path (a test reads it only after a failure).
std::string traceError;
}

namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalMesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Traits = CGAL::Surface_mesh_shortest_path_traits<Kernel, CgalMesh>;
using ShortestPaths = CGAL::Surface_mesh_shortest_path<Traits>;

/// The same surface as `mesh`, vertex i and face t kept as vertex i and face t.
std::unique_ptr<CgalMesh> ToCgal(const TriangleMesh& mesh)
{
  auto out = std::make_unique<CgalMesh>();
  for (const Vec3& p : mesh.GetPositions())
  {
    out->add_vertex(Kernel::Point_3(p.x, p.y, p.z));
  }
  for (const Triangle& t : mesh.GetTriangles())
  {
    const auto f = out->add_face(
      CgalMesh::Vertex_index(t[0]), CgalMesh::Vertex_index(t[1]), CgalMesh::Vertex_index(t[2]));
    if (f == CgalMesh::null_face())
    {
      return nullptr;
    }
  }
  return out;
}

/// CGAL face location of c: barycentric weights in the face's own vertex order.
ShortestPaths::Face_location Locate(const TriangleMesh& mesh,
  const CgalMesh& cgal,
  const CanonicalPoint& c)
{
  const int t = AnyTriangleOf(mesh, c);
  const std::array<double, 3> w = WeightsInTriangle(mesh, c, t);
  const Triangle& tri = mesh.GetTriangle(t);
  const CgalMesh::Face_index f(t);
  std::array<double, 3> b = InCgalVertexOrder(cgal, f, { tri[0], tri[1], tri[2] }, w);
  if (c.Location == PointLocation::Edge)
  {
    // CGAL 5.5's tree is wrong for some points given exactly on an edge (one zero weight):
    // distances from such a source disagree with the same pair traced the other way by up to
    // 5% on an icosphere. A point 1e-13 (relative) inside the face is the same point to far
    // below the 1e-9 tolerance and takes the well-tested face path.
    for (double& x : b)
    {
      x = x == 0.0 ? 1e-13 : x * (1 - 0.5e-13);
    }
  }
  return { f, Traits::Barycentric_coordinates{ b[0], b[1], b[2] } };
}

CanonicalPoint RandomPoint(const TriangleMesh& mesh, std::mt19937& rng)
{
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  CanonicalPoint c;
  switch (rng() % 3)
  {
    case 0:
      c.Location = PointLocation::Vertex;
      c.Id = static_cast<int>(rng() % mesh.GetNumberOfVertices());
      return c;
    case 1:
      c.Location = PointLocation::Edge;
      c.Id = static_cast<int>(rng() % mesh.GetNumberOfEdges());
      c.T = 0.05 + 0.9 * unit(rng);
      return c;
    default:
    {
      double u = unit(rng), v = unit(rng);
      if (u + v > 1)
      {
        u = 1 - u;
        v = 1 - v;
      }
      c.Location = PointLocation::Face;
      c.Id = static_cast<int>(rng() % mesh.GetNumberOfTriangles());
      c.U = 0.01 + 0.97 * u * 0.97;
      c.V = 0.01 + 0.97 * v * 0.97;
      return c;
    }
  }
}

/// The farthest (straight-line) of `candidates` random points from p.
CanonicalPoint FarPoint(const TriangleMesh& mesh, const CanonicalPoint& p, std::mt19937& rng)
{
  CanonicalPoint best = RandomPoint(mesh, rng);
  for (int i = 0; i < 64; ++i)
  {
    const CanonicalPoint q = RandomPoint(mesh, rng);
    if (Distance(PositionOf(mesh, q), PositionOf(mesh, p)) >
      Distance(PositionOf(mesh, best), PositionOf(mesh, p)))
    {
      best = q;
    }
  }
  return best;
}

/// A random point 2-6 % of the bounding-box diagonal from p (p itself if none is found).
CanonicalPoint NearPoint(const TriangleMesh& mesh, const CanonicalPoint& p, std::mt19937& rng)
{
  Vec3 lo = mesh.GetPosition(0), hi = lo;
  for (const Vec3& q : mesh.GetPositions())
  {
    lo = { std::min(lo.x, q.x), std::min(lo.y, q.y), std::min(lo.z, q.z) };
    hi = { std::max(hi.x, q.x), std::max(hi.y, q.y), std::max(hi.z, q.z) };
  }
  const double diagonal = Distance(lo, hi);
  for (int i = 0; i < 200000; ++i)
  {
    const CanonicalPoint q = RandomPoint(mesh, rng);
    const double d = Distance(PositionOf(mesh, q), PositionOf(mesh, p));
    if (d > 0.02 * diagonal && d < 0.06 * diagonal)
    {
      return q;
    }
  }
  return p;
}

struct OracleStats
{
  int Compared = 0;
  int Exact = 0;
  double WorstRelative = 0;
  double Milliseconds = 0; ///< summed Compute time of these pairs (reported, never asserted)
  void Add(double relative)
  {
    ++this->Compared;
    this->Exact += relative <= 1e-9;
    this->WorstRelative = std::max(this->WorstRelative, relative);
  }
};

struct OracleRun
{
  int Compared = 0;
  int Exact = 0;
  double WorstRelative = 0;
  OracleStats Random, Short, Far;
};

/// For `sources` random start points (one oracle tree each), traces to `targets` points
/// (far, random and short in turn) with `method` and compares every length. With the Exact
/// method every length must be the oracle's; with the others none may be shorter and the
/// statistics per kind of pair are returned for the caller's thresholds.
OracleRun CompareWithOracle(const TriangleMesh& mesh,
  int sources,
  int targets,
  std::uint32_t seed,
  const std::string& name,
  GeodesicMethod method = GeodesicMethod::Exact)
{
  OracleRun run;
  std::unique_ptr<CgalMesh> cgal = ToCgal(mesh);
  if (!cgal)
  {
    ADD_FAILURE() << name << ": CGAL refused a face (non-manifold input?)";
    return run;
  }
  GeodesicPathSolver solver(mesh);
  GeodesicPathOptions options;
  options.Method = method;
  solver.SetOptions(options);
  std::mt19937 rng(seed);
  GeodesicPath path;
  for (int s = 0; s < sources; ++s)
  {
    const CanonicalPoint a = RandomPoint(mesh, rng);
    ShortestPaths oracle(*cgal);
    oracle.add_source_point(Locate(mesh, *cgal, a));
    oracle.build_sequence_tree();
    {
      const auto la = Locate(mesh, *cgal, a);
      const auto q = oracle.point(la.first, la.second);
      const Vec3 pa = PositionOf(mesh, a);
      EXPECT_LT(Distance(pa, Vec3{ q.x(), q.y(), q.z() }), 1e-9) << name << " oracle location";
    }
    for (int k = 0; k < targets; ++k)
    {
      const int kind = k % 3; // 0 far, 1 random, 2 short
      const CanonicalPoint b = kind == 0 ? FarPoint(mesh, a, rng)
        : kind == 1                      ? RandomPoint(mesh, rng)
                                         : NearPoint(mesh, a, rng);
      const double expected = oracle
                                .shortest_distance_to_source_points(
                                  Locate(mesh, *cgal, b).first, Locate(mesh, *cgal, b).second)
                                .first;
      const auto computeStart = std::chrono::steady_clock::now();
      const bool traced = solver.Compute(a, b, path, traceError);
      const double computeMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - computeStart)
          .count();
      if (expected < 0)
      {
        EXPECT_FALSE(traced) << name << ": no oracle path, yet traced";
        continue;
      }
      if (!traced)
      {
        ADD_FAILURE() << name << ": " << traceError;
        continue;
      }
      ++run.Compared;
      const double relative = std::abs(path.Length - expected) / std::max(expected, 1e-300);
      run.WorstRelative = std::max(run.WorstRelative, relative);
      run.Exact += relative <= 1e-9;
      OracleStats& stats = kind == 0 ? run.Far : kind == 1 ? run.Random : run.Short;
      stats.Add(relative);
      stats.Milliseconds += computeMs;
      if (method != GeodesicMethod::Exact && relative > 1e-9)
      {
        const GeodesicPathStatistics& st = solver.GetLastStatistics();
        std::cout << name << ": " << Describe(a) << " -> " << Describe(b) << " excess " << relative
                  << " routed " << st.Routed << " route " << st.RouteLength << " candidates "
                  << st.AlternativeRoutes << " corridor windows " << st.CorridorWindows << "\n";
      }
      if (method == GeodesicMethod::Exact)
      {
        EXPECT_LE(relative, 1e-9) << name << ": " << Describe(a) << " -> " << Describe(b)
                                  << " traced " << path.Length << ", shortest " << expected;
      }
      EXPECT_GE(path.Length, expected * (1 - 1e-9))
        << name << " (" << GeodesicMethodName(method) << "): shorter than the shortest path";
      // The polyline really lies on the surface: consecutive points share a triangle.
      for (size_t i = 1; i < path.Points.size(); ++i)
      {
        EXPECT_GE(SharedTriangle(mesh, path.Points[i - 1], path.Points[i]), 0) << name;
      }
    }
  }
  return run;
}

TriangleMesh ToMesh(MeshData data)
{
  return TriangleMesh(std::move(data.Positions), std::move(data.Triangles));
}

/// Square with bumps and dips (a height field): convex, concave and saddle vertices, and
/// shortest paths that go around bumps rather than over them.
MeshData BumpyField(int n)
{
  MeshData data = MakeFlatSquare(n, 2.0, 0.3, 5);
  for (Vec3& p : data.Positions)
  {
    p.z = 0.35 * std::sin(3.0 * p.x) * std::sin(2.5 * p.y) +
      0.2 * std::exp(-8.0 * Dot(p - Vec3{ 1, 1, 0 }, p - Vec3{ 1, 1, 0 }));
  }
  return data;
}

std::string SharedMesh(const std::string& file)
{
  const char* root = std::getenv("BOOLSURF_SHARED_DATA");
  return root ? std::string(root) + "/meshes/" + file : std::string();
}
} // namespace

TEST(GeodesicExactOracle, ProceduralSurfaces)
{
  struct Case
  {
    std::string Name;
    MeshData Data;
  };
  std::vector<Case> cases;
  cases.push_back({ "icosphere", MakeIcosphere(3) });
  cases.push_back({ "torus", MakeTorus(1.0, 0.35, 48, 20) });
  cases.push_back({ "thin torus", MakeTorus(1.0, 0.1, 64, 8) });
  cases.push_back({ "bumpy field", BumpyField(24) });
  cases.push_back({ "jittered square", MakeFlatSquare(16, 1.0, 0.3, 3) });
  cases.push_back({ "box lateral", MakeBoxLateral(2.0, 1.0, 1.5, 12) });
  for (Case& c : cases)
  {
    const TriangleMesh mesh = ToMesh(std::move(c.Data));
    const OracleRun run = CompareWithOracle(mesh, 4, 10, 17, c.Name);
    EXPECT_EQ(run.Exact, run.Compared) << c.Name << " worst relative " << run.WorstRelative;
    EXPECT_GE(run.Compared, 40) << c.Name;
    // The default: these meshes are small enough for the exact search to fit its budget on
    // most pairs; the others are routed and straightened.
    const OracleRun bounded =
      CompareWithOracle(mesh, 4, 12, 23, c.Name + " bounded", GeodesicMethod::Bounded);
    EXPECT_EQ(bounded.Short.Exact, bounded.Short.Compared) << c.Name;
    EXPECT_LE(bounded.WorstRelative, 0.005) << c.Name;
    EXPECT_GE(bounded.Far.Exact, 0.9 * bounded.Far.Compared) << c.Name;
  }
}

// Issue 11's prism case: an open 48-sided prism, near-opposite pairs. Unrolled it is a flat
// rectangle, so the shortest path is the shorter of the two unrolled straight lines (around
// either side); the oracle must agree too.
TEST(GeodesicExactOracle, PrismNearOppositePairs)
{
  const int around = 48, along = 16;
  const double radius = 1.0, height = 3.0;
  const TriangleMesh mesh = ToMesh(MakeOpenCylinder(radius, height, around, along));
  std::unique_ptr<CgalMesh> cgal = ToCgal(mesh);
  ASSERT_TRUE(cgal);
  const boolsurf::testing::UnrolledPrism prism{ around, radius };
  const double width = prism.Width();
  GeodesicPathSolver solver(mesh);
  std::mt19937 rng(48);
  GeodesicPath path;
  int tested = 0;
  for (int i = 0; i < 4000 && tested < 60; ++i)
  {
    const CanonicalPoint a = RandomPoint(mesh, rng), b = RandomPoint(mesh, rng);
    const Vec3 pa = PositionOf(mesh, a), pb = PositionOf(mesh, b);
    if (std::abs(prism.AroundDistance(pa, pb) - 0.5 * width) > 0.1 * width)
    {
      continue; // only near-opposite pairs
    }
    const double expected = prism.ShortestLength(pa, pb);
    ASSERT_TRUE(solver.Compute(a, b, path, traceError));
    EXPECT_NEAR(path.Length, expected, 1e-9 * expected) << Describe(a) << " -> " << Describe(b);
    if (tested < 15) // the oracle agrees (one tree per pair: keep it to a few)
    {
      ShortestPaths oracle(*cgal);
      oracle.add_source_point(Locate(mesh, *cgal, a));
      const auto lb = Locate(mesh, *cgal, b);
      EXPECT_NEAR(oracle.shortest_distance_to_source_points(lb.first, lb.second).first,
        expected,
        1e-9 * expected);
    }
    ++tested;
  }
  EXPECT_EQ(tested, 60);
}

// Random and far pairs (and, through the far pairs, pairs across handles: kitten and torus
// have genus 1, fertility genus 4) on the shared scans issue 19 was reported on.
TEST(GeodesicExactOracle, SharedScans)
{
  // Other shared meshes for a longer check: BOOLSURF_ORACLE_MESHES=armadillo.ply,face.ply
  std::vector<std::string> files = {
    "kitten.ply", "fertility.ply", "spot.ply", "torus.ply", "bob.ply", "camelhead.ply"
  };
  if (const char* chosen = std::getenv("BOOLSURF_ORACLE_MESHES"))
  {
    files.clear();
    std::stringstream list(chosen);
    for (std::string file; std::getline(list, file, ',');)
    {
      files.push_back(file);
    }
  }
  int meshes = 0, farExact = 0, farCompared = 0;
  // Start points per mesh for the Bounded run, 30 pairs each (10 far); more for a longer
  // measurement (BOOLSURF_ORACLE_SOURCES=4 gave Docs/Decisions.md's 240 far pairs).
  const char* sourcesVariable = std::getenv("BOOLSURF_ORACLE_SOURCES");
  const int sources = sourcesVariable ? std::max(1, std::atoi(sourcesVariable)) : 2;
  for (const std::string& file : files)
  {
    const std::string path = SharedMesh(file);
    MeshData data;
    std::string error;
    if (path.empty() || !ReadPly(path, data, error))
    {
      continue;
    }
    ++meshes;
    const TriangleMesh mesh = ToMesh(std::move(data));
    const OracleRun run = CompareWithOracle(mesh, 1, 10, 19, file); // one CGAL tree per mesh
    EXPECT_EQ(run.Exact, run.Compared) << file << " worst relative " << run.WorstRelative;
    // The default, Bounded: short pairs exact; far pairs on these scans mostly past the
    // window budget, routed, straightened and refined by the exact search (on the whole mesh
    // up to 12k triangles, else in a corridor): never shorter, within 0.5 % (issue 27's
    // bound; the measured worst over 240 far pairs is 0.27 %, see Docs/Decisions.md).
    const OracleRun bounded = CompareWithOracle(
      mesh, sources, 30, 29, std::string(file) + " bounded", GeodesicMethod::Bounded);
    EXPECT_EQ(bounded.Short.Exact, bounded.Short.Compared) << file;
    EXPECT_LE(bounded.WorstRelative, 0.005) << file;
    farExact += bounded.Far.Exact;
    farCompared += bounded.Far.Compared;
    std::cout << file << " bounded: far pairs exact " << bounded.Far.Exact << " of "
              << bounded.Far.Compared << ", worst " << bounded.Far.WorstRelative << ", "
              << bounded.Far.Milliseconds / std::max(bounded.Far.Compared, 1) << " ms each"
              << "; random exact " << bounded.Random.Exact << " of " << bounded.Random.Compared
              << "; short exact " << bounded.Short.Exact << " of " << bounded.Short.Compared
              << "\n";
  }
  if (meshes == 0)
  {
    GTEST_SKIP() << "shared meshes not found (set BOOLSURF_SHARED_DATA to the shared data folder)";
  }
  // Far pairs equal to the exact ones (1e-9): 234 of 240 since small meshes are refined by
  // the whole-mesh search (226 with the corridor alone, 137 before it; Docs/Decisions.md).
  EXPECT_GE(farExact, 0.95 * farCompared) << farExact << " of " << farCompared;
}

// Far pairs whose shortest path runs on the other side of a bump from the site graph's first
// route: on face.ply (an open face scan) the route, the second route and the edge path all
// went over the nose and gave a path 0.99 % longer than the shortest, which passes 29 % of
// its length away, round the other side; on bimba (a closed statue) the shortest path ran 5 %
// of its length beside the route, outside the corridor, and the leg was 0.32 % long. The
// routes kept out of wider bands round the first (GeodesicPathSolver::TryAlternativeRoutes)
// find those sides. On armadillo the shortest path ran 4 % of its length beside the kept one
// (0.05 % longer), outside its corridor but inside a band route's, which is searched next.
TEST(GeodesicExactOracle, FarPairsRoundTheOtherSideOfABump)
{
  struct Pair
  {
    std::string File;
    CanonicalPoint A, B;
  };
  using boolsurf::testing::FacePoint;
  const std::vector<Pair> pairs = {
    { "face.ply", FacePoint(48936, 0.278068, 0.0789269), boolsurf::testing::VertexPoint(24081) },
    { "bimba.ply", FacePoint(79782, 0.6516, 0.0811534), FacePoint(88227, 0.393359, 0.183211) },
    { "armadillo.ply",
      FacePoint(41462, 0.278068, 0.0789269),
      FacePoint(11261, 0.337627, 0.165265) },
  };
  int tested = 0;
  for (const Pair& pair : pairs)
  {
    MeshData data;
    std::string error;
    const std::string path = SharedMesh(pair.File);
    if (path.empty() || !ReadPly(path, data, error))
    {
      continue;
    }
    const TriangleMesh mesh = ToMesh(std::move(data));
    std::unique_ptr<CgalMesh> cgal = ToCgal(mesh);
    ASSERT_TRUE(cgal);
    ShortestPaths oracle(*cgal);
    oracle.add_source_point(Locate(mesh, *cgal, pair.A));
    const auto b = Locate(mesh, *cgal, pair.B);
    const double shortest = oracle.shortest_distance_to_source_points(b.first, b.second).first;
    GeodesicPathSolver solver(mesh); // Bounded, the default
    GeodesicPath leg;
    ASSERT_TRUE(solver.Compute(pair.A, pair.B, leg, traceError));
    EXPECT_TRUE(solver.GetLastStatistics().Routed) << pair.File;
    EXPECT_GE(leg.Length, shortest * (1 - 1e-9)) << pair.File;
    EXPECT_LE(leg.Length, shortest * (1 + 1e-6))
      << pair.File << ": " << Describe(pair.A) << " -> " << Describe(pair.B) << " traced "
      << leg.Length << ", shortest " << shortest;
    ++tested;
  }
  if (tested == 0)
  {
    GTEST_SKIP() << "shared meshes not found (set BOOLSURF_SHARED_DATA to the shared data folder)";
  }
}

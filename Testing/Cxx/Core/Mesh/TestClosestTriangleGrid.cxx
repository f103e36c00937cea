// The closest-point grid against brute force (every triangle, the same tie rule) on procedural
// surfaces, with query points near the surface, far outside it, exactly on vertices and edges
// (ties between triangles) and on a mesh with flat (zero-area) triangles; and the closest
// point on one triangle against dense sampling of the triangle.
#include "Mesh/ClosestTriangleGrid.h"
#include "Mesh/ProceduralMeshes.h"

#include <gtest/gtest.h>

#include <random>

using namespace boolsurf;

namespace
{

ClosestTriangleGrid::Hit BruteForce(const TriangleMesh& mesh, const Vec3& p)
{
  ClosestTriangleGrid::Hit best;
  for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    const Vec3 q = ClosestPointOnTriangle(
      p, mesh.GetCornerPosition(t, 0), mesh.GetCornerPosition(t, 1), mesh.GetCornerPosition(t, 2));
    const double d2 = Dot(q - p, q - p);
    if (d2 < best.Distance2 || (d2 == best.Distance2 && t < best.Triangle))
    {
      best = { t, q, d2 };
    }
  }
  return best;
}

void ExpectSameAsBruteForce(const TriangleMesh& mesh, const char* name, std::uint32_t seed)
{
  const ClosestTriangleGrid grid(mesh);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0), spread(-3.0, 3.0), tiny(-1e-3, 1e-3);
  std::vector<Vec3> queries;
  for (int n = 0; n < 300; ++n)
  {
    const int t = static_cast<int>(rng() % mesh.GetNumberOfTriangles());
    const double u = unit(rng), v = unit(rng) * (1.0 - u);
    const Vec3 on = mesh.Evaluate(t, u, v);
    queries.push_back(on + Vec3{ tiny(rng), tiny(rng), tiny(rng) });           // near
    queries.push_back(Vec3{ spread(rng), spread(rng), spread(rng) });          // anywhere
    queries.push_back(mesh.GetCornerPosition(t, static_cast<int>(rng() % 3))); // a vertex
    queries.push_back(0.5 * (mesh.GetCornerPosition(t, 0) + mesh.GetCornerPosition(t, 1))); // edge
  }
  queries.push_back({ 1e6, -1e6, 1e6 }); // far outside the grid
  for (const Vec3& p : queries)
  {
    const ClosestTriangleGrid::Hit got = grid.FindClosest(p), want = BruteForce(mesh, p);
    ASSERT_EQ(got.Triangle, want.Triangle)
      << name << ": query (" << p.x << ", " << p.y << ", " << p.z << ")";
    ASSERT_EQ(got.Distance2, want.Distance2) << name;
  }
}

} // namespace

TEST(ClosestTriangleGrid, MatchesBruteForce)
{
  const MeshData sphere = MakeIcosphere(3);
  ExpectSameAsBruteForce(TriangleMesh(sphere.Positions, sphere.Triangles), "icosphere", 1);
  const MeshData torus = MakeTorus(1.5, 0.4, 40, 16);
  ExpectSameAsBruteForce(TriangleMesh(torus.Positions, torus.Triangles), "torus", 2);
  const MeshData flat = MakeFlatSquare(20, 2.0, 0.4, 3); // a flat box: one cell thick
  ExpectSameAsBruteForce(TriangleMesh(flat.Positions, flat.Triangles), "jittered square", 3);
  // Flat triangles: three collinear corners, and three equal ones.
  MeshData degenerate = MakeFlatSquare(6, 1.0, 0.0, 4);
  const int base = static_cast<int>(degenerate.Positions.size());
  degenerate.Positions.push_back({ 0.1, 0.1, 0.3 });
  degenerate.Positions.push_back({ 0.5, 0.5, 0.3 });
  degenerate.Positions.push_back({ 0.9, 0.9, 0.3 });
  degenerate.Triangles.push_back({ base, base + 1, base + 2 });
  degenerate.Triangles.push_back({ base + 1, base + 1, base + 1 });
  ExpectSameAsBruteForce(
    TriangleMesh(degenerate.Positions, degenerate.Triangles), "flat triangles", 5);
}

TEST(ClosestTriangleGrid, ClosestPointOnTriangleBeatsEverySample)
{
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coord(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial)
  {
    const Vec3 a{ coord(rng), coord(rng), coord(rng) }, b{ coord(rng), coord(rng), coord(rng) },
      c{ coord(rng), coord(rng), coord(rng) }, p{ 2 * coord(rng), 2 * coord(rng), 2 * coord(rng) };
    const Vec3 q = ClosestPointOnTriangle(p, a, b, c);
    // q lies on the triangle: its barycentric weights are in [0, 1].
    const Vec3 n = Cross(b - a, c - a);
    const double area2 = Dot(n, n);
    const double wb = Dot(Cross(q - a, c - a), n) / area2, wc = Dot(Cross(b - a, q - a), n) / area2;
    EXPECT_GE(wb, -1e-9);
    EXPECT_GE(wc, -1e-9);
    EXPECT_LE(wb + wc, 1 + 1e-9);
    EXPECT_NEAR(Dot(q - a, n), 0.0, 1e-9 * std::sqrt(area2));
    const double d2 = Dot(q - p, q - p);
    for (int i = 0; i <= 40; ++i)
    {
      for (int j = 0; i + j <= 40; ++j)
      {
        const Vec3 s = a + (i / 40.0) * (b - a) + (j / 40.0) * (c - a);
        EXPECT_LE(d2, Dot(s - p, s - p) + 1e-12) << "trial " << trial;
      }
    }
  }
}

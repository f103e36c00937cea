#include "Mesh/ProceduralMeshes.h"
#include "Mesh/TriangleMesh.h"

#include <gtest/gtest.h>

using namespace boolsurf;

TEST(TriangleMesh, FlatSquareAdjacency)
{
  MeshData d = MakeFlatSquare(2);
  TriangleMesh mesh(d.Positions, d.Triangles);
  EXPECT_EQ(mesh.GetNumberOfTriangles(), 8);
  EXPECT_EQ(mesh.GetNumberOfEdges(), 16); // V - E + F = 1 with V = 9
  for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int n = mesh.GetNeighbor(t, k);
      if (n >= 0)
      {
        EXPECT_EQ(mesh.GetNeighbor(n, mesh.GetNeighborEdge(t, k)), t);
        EXPECT_EQ(mesh.GetEdgeId(t, k), mesh.GetEdgeId(n, mesh.GetNeighborEdge(t, k)));
      }
    }
  }
  EXPECT_TRUE(mesh.GetMisorientedEdges().empty());
  EXPECT_TRUE(mesh.GetNonManifoldEdges().empty());
}

// Jittered squares stay flat triangulations: no triangle folds over (cells made non-convex
// by the jitter are split through their reflex corner).
TEST(ProceduralMeshes, JitteredFlatSquaresNeverFold)
{
  for (int n : { 2, 5, 13, 20, 48 })
  {
    for (std::uint32_t seed = 1; seed <= 12; ++seed)
    {
      MeshData d = MakeFlatSquare(n, 1.0, 0.4, seed);
      double area = 0;
      for (const auto& t : d.Triangles)
      {
        const Vec3 a = d.Positions[t[0]], b = d.Positions[t[1]], c = d.Positions[t[2]];
        const double twice = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
        EXPECT_GT(twice, 0.0) << "n " << n << " seed " << seed;
        area += 0.5 * twice;
      }
      EXPECT_NEAR(area, 1.0, 1e-12);
    }
  }
}

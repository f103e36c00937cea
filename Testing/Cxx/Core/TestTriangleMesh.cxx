#include "ProceduralMeshes.h"
#include "TriangleMesh.h"

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

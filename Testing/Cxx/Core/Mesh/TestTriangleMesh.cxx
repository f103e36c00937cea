#include "Mesh/MeshTopology.h"
#include "Mesh/ProceduralMeshes.h"
#include "Mesh/TriangleComponents.h"
#include "Mesh/TriangleMesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <vector>

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

// Edge numbering against a plain reference: an edge is the set of usable triangles' half-edges
// on one vertex pair, numbered in the order of its lowest half-edge (corner id), valence the
// set's size, twins only for two half-edges, a misoriented edge when those two run the same
// way, a non-manifold edge for three or more. The mesh (20k triangles: several of the
// parallel blocks) is a torus with holes cut, triangles flipped, duplicated (non-manifold
// edges) and collapsed (unusable), so every kind of edge crosses block boundaries.
TEST(TriangleMesh, EdgesNumberedByLowestHalfEdgeOnAnyDefects)
{
  MeshData data = MakeTorus(1.0, 0.35, 160, 64);
  std::mt19937 rng(7);
  std::vector<Triangle> triangles;
  for (const Triangle& t : data.Triangles)
  {
    const unsigned roll = rng() % 100;
    if (roll < 3)
    {
      continue; // a hole
    }
    if (roll < 5)
    {
      triangles.push_back({ t[0], t[2], t[1] }); // flipped
      continue;
    }
    triangles.push_back(t);
    if (roll < 7)
    {
      triangles.push_back(t); // duplicated: its edges are non-manifold
    }
    else if (roll < 8)
    {
      triangles.push_back({ t[0], t[0], t[1] }); // collapsed: unusable
    }
  }
  const std::size_t nt = triangles.size();
  ASSERT_GT(nt, 2u * 8192u);
  const TriangleMesh mesh(data.Positions, triangles);

  std::map<std::pair<int, int>, std::vector<int>> halfEdgesOf; // sorted vertex pair -> corners
  int unusable = 0;
  for (std::size_t t = 0; t < nt; ++t)
  {
    const Triangle& tri = triangles[t];
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0])
    {
      ++unusable;
      for (int k = 0; k < 3; ++k)
      {
        EXPECT_EQ(mesh.GetEdgeId(static_cast<int>(t), k), -1) << "unusable triangle " << t;
      }
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      const int a = tri[k], b = tri[(k + 1) % 3];
      halfEdgesOf[{ std::min(a, b), std::max(a, b) }].push_back(static_cast<int>(3 * t) + k);
    }
  }
  std::vector<std::vector<int>> edges;
  for (auto& entry : halfEdgesOf)
  {
    edges.push_back(entry.second); // already ascending: corners were added in order
  }
  std::sort(edges.begin(), edges.end(), [](const auto& x, const auto& y) { return x[0] < y[0]; });
  ASSERT_EQ(mesh.GetNumberOfEdges(), static_cast<int>(edges.size()));
  int misoriented = 0, nonManifold = 0;
  for (std::size_t e = 0; e < edges.size(); ++e)
  {
    const std::vector<int>& group = edges[e];
    ASSERT_EQ(mesh.GetEdgeHalfEdge(static_cast<int>(e)), group[0]) << "edge " << e;
    EXPECT_EQ(mesh.GetEdgeValence(static_cast<int>(e)), static_cast<int>(group.size()));
    for (const int h : group)
    {
      EXPECT_EQ(mesh.GetEdgeId(h / 3, h % 3), static_cast<int>(e));
      EXPECT_EQ(mesh.GetTwin(h), group.size() == 2 ? (h == group[0] ? group[1] : group[0]) : -1);
    }
    if (group.size() == 2)
    {
      const auto start = [&](int h) { return triangles[h / 3][h % 3]; };
      misoriented += start(group[0]) == start(group[1]);
    }
    nonManifold += group.size() > 2;
  }
  EXPECT_GT(misoriented, 0);
  EXPECT_GT(nonManifold, 0);
  EXPECT_GT(unusable, 0);
  EXPECT_EQ(static_cast<int>(mesh.GetMisorientedEdges().size()), misoriented);
  EXPECT_EQ(static_cast<int>(mesh.GetNonManifoldEdges().size()), nonManifold);
  // Reported in owner order, as a serial pass meets them.
  for (std::size_t i = 1; i < mesh.GetMisorientedEdges().size(); ++i)
  {
    EXPECT_LE(mesh.GetMisorientedEdges()[i - 1].Triangle0, mesh.GetMisorientedEdges()[i].Triangle0);
  }
}

// Components (parallel union-find) against a breadth-first reference: ids in the order of each
// component's lowest triangle. Three tori with their triangles shuffled together (so every
// component spans every parallel block), a few cut into pieces by holes, and unusable
// triangles (-1).
TEST(TriangleComponents, NumberedByLowestTriangleAsABreadthFirstPass)
{
  MeshData data;
  for (int copy = 0; copy < 3; ++copy)
  {
    MeshData torus = MakeTorus(1.0, 0.3, 96 + 8 * copy, 40);
    const int base = static_cast<int>(data.Positions.size());
    data.Positions.insert(data.Positions.end(), torus.Positions.begin(), torus.Positions.end());
    for (const Triangle& t : torus.Triangles)
    {
      data.Triangles.push_back({ t[0] + base, t[1] + base, t[2] + base });
    }
  }
  std::mt19937 rng(3);
  std::shuffle(data.Triangles.begin(), data.Triangles.end(), rng);
  // A band of holes around one torus's tube cuts it in two; some triangles collapse.
  std::vector<Triangle> triangles;
  for (const Triangle& t : data.Triangles)
  {
    const Vec3 p = data.Positions[t[0]];
    if (t[0] < 96 * 40 && std::abs(p.x) < 0.05)
    {
      continue;
    }
    triangles.push_back(rng() % 50 == 0 ? Triangle{ t[0], t[0], t[1] } : t);
  }
  const TriangleMesh mesh(data.Positions, triangles);
  const TriangleComponents components(mesh);

  const int nt = mesh.GetNumberOfTriangles();
  std::vector<int> expected(nt, -1);
  int count = 0;
  for (int seed = 0; seed < nt; ++seed)
  {
    if (!mesh.IsUsable(seed) || expected[seed] >= 0)
    {
      continue;
    }
    std::vector<int> queue{ seed };
    expected[seed] = count;
    for (std::size_t head = 0; head < queue.size(); ++head)
    {
      for (int k = 0; k < 3; ++k)
      {
        const int n = mesh.GetNeighbor(queue[head], k);
        if (n >= 0 && expected[n] < 0)
        {
          expected[n] = count;
          queue.push_back(n);
        }
      }
    }
    ++count;
  }
  EXPECT_GE(count, 4) << "three tori, one cut in two, and isolated pieces";
  EXPECT_EQ(components.GetNumberOfComponents(), count);
  // The topology's components are the same numbering, and can stand in for them.
  const TriangleComponents fromTopology(
    std::make_shared<const MeshTopology>(MeshTopology::Compute(mesh)));
  EXPECT_EQ(fromTopology.GetNumberOfComponents(), count);
  for (int t = 0; t < nt; ++t)
  {
    ASSERT_EQ(fromTopology.GetComponent(t), expected[t]) << "triangle " << t;
    ASSERT_EQ(components.GetComponent(t), expected[t]) << "triangle " << t;
  }
}

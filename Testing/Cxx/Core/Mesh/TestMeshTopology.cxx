// Topology (components, boundary loops, Euler characteristic, genus) on procedural meshes and
// on every mesh of the shared collection, compared with its manifest.
#include "Mesh/MeshTopology.h"
#include "Mesh/PlyReader.h"
#include "Mesh/ProceduralMeshes.h"
#include "Mesh/SurfaceCheck.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdlib>
#include <fstream>

using namespace boolsurf;

namespace
{
MeshTopology TopologyOf(const MeshData& d, TriangleMesh* keep = nullptr)
{
  TriangleMesh mesh(d.Positions, d.Triangles);
  MeshTopology topo = MeshTopology::Compute(mesh);
  if (keep)
  {
    *keep = mesh;
  }
  return topo;
}

MeshData Concatenate(const MeshData& a, const MeshData& b)
{
  MeshData m = a;
  const int offset = static_cast<int>(a.Positions.size());
  m.Positions.insert(m.Positions.end(), b.Positions.begin(), b.Positions.end());
  for (auto t : b.Triangles)
  {
    m.Triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
  }
  return m;
}
} // namespace

TEST(MeshTopology, FlatSquareIsADisc)
{
  TriangleMesh mesh;
  MeshTopology topo = TopologyOf(MakeFlatSquare(5, 1.0, 0.3, 7), &mesh);
  ASSERT_EQ(topo.GetNumberOfComponents(), 1);
  EXPECT_EQ(topo.Components[0].EulerCharacteristic, 1);
  EXPECT_EQ(topo.Components[0].Genus, 0);
  ASSERT_EQ(topo.BoundaryLoops.size(), 1u);
  const BoundaryLoop& loop = topo.BoundaryLoops[0];
  EXPECT_EQ(loop.Vertices.size(), 20u);
  EXPECT_NEAR(loop.Length, 4.0, 1e-12);
  // The loop is ordered: each half-edge ends where the next starts, and the surface is on
  // its left, so it runs counter-clockwise around the square (positive signed area).
  double signedArea = 0;
  for (size_t i = 0; i < loop.Vertices.size(); ++i)
  {
    const Vec3 p = mesh.GetPosition(loop.Vertices[i]);
    const Vec3 q = mesh.GetPosition(loop.Vertices[(i + 1) % loop.Vertices.size()]);
    signedArea += 0.5 * (p.x * q.y - q.x * p.y);
    const int h = loop.HalfEdges[i];
    EXPECT_EQ(
      mesh.GetTriangle(h / 3)[(h % 3 + 1) % 3], loop.Vertices[(i + 1) % loop.Vertices.size()]);
  }
  EXPECT_NEAR(signedArea, 1.0, 1e-12);
  for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
    const Vec3 p = mesh.GetPosition(v);
    const bool onBorder = p.x == 0 || p.y == 0 || p.x == 1 || p.y == 1;
    EXPECT_EQ(topo.GetVertexBoundaryLoop(v), onBorder ? 0 : -1) << "vertex " << v;
  }
}

TEST(MeshTopology, ClosedSurfacesOfKnownGenus)
{
  MeshTopology sphere = TopologyOf(MakeIcosphere(3));
  EXPECT_EQ(sphere.Components[0].EulerCharacteristic, 2);
  EXPECT_EQ(sphere.Components[0].Genus, 0);
  EXPECT_TRUE(sphere.BoundaryLoops.empty());

  MeshTopology torus = TopologyOf(MakeTorus(2.0, 0.5, 24, 12));
  EXPECT_EQ(torus.Components[0].EulerCharacteristic, 0);
  EXPECT_EQ(torus.Components[0].Genus, 1);

  MeshTopology cylinder = TopologyOf(MakeOpenCylinder(1.0, 2.0, 16, 4));
  EXPECT_EQ(cylinder.Components[0].EulerCharacteristic, 0);
  EXPECT_EQ(cylinder.Components[0].BoundaryLoops, 2);
  EXPECT_EQ(cylinder.Components[0].Genus, 0);

  MeshTopology box = TopologyOf(MakeBoxLateral(1.0, 2.0, 1.0, 3));
  EXPECT_EQ(box.Components[0].BoundaryLoops, 2);
  EXPECT_EQ(box.Components[0].Genus, 0);
}

TEST(MeshTopology, SeveralComponents)
{
  MeshData both = Concatenate(MakeTorus(2.0, 0.5, 12, 8), MakeIcosphere(1));
  MeshTopology topo = TopologyOf(both);
  ASSERT_EQ(topo.GetNumberOfComponents(), 2);
  EXPECT_EQ(topo.Components[0].Genus, 1);
  EXPECT_EQ(topo.Components[1].Genus, 0);
  EXPECT_EQ(topo.GetEulerCharacteristic(), 2);
  EXPECT_EQ(topo.TriangleComponent.front(), 0);
  EXPECT_EQ(topo.TriangleComponent.back(), 1);
}

// Every mesh of ../shared/data/meshes against its manifest entry.
TEST(MeshTopology, SharedMeshesMatchManifest)
{
  const char* root = std::getenv("BOOLSURF_SHARED_DATA");
  const std::string dir = root ? std::string(root) + "/meshes" : std::string();
  std::ifstream manifestFile(dir + "/manifest.json");
  if (!root || !manifestFile)
  {
    GTEST_SKIP() << "shared mesh collection not found (set BOOLSURF_SHARED_DATA to a folder "
                    "with meshes/manifest.json); skipping the manifest comparison";
  }
  const nlohmann::json manifest = nlohmann::json::parse(manifestFile);
  ASSERT_GT(manifest.size(), 0u);
  for (const auto& entry : manifest)
  {
    const std::string file = entry["file"];
    SCOPED_TRACE(file);
    MeshData data;
    std::string error;
    ASSERT_TRUE(ReadPly(dir + "/" + file, data, error)) << error;
    TriangleMesh mesh(data.Positions, data.Triangles);
    MeshTopology topo = MeshTopology::Compute(mesh);
    SurfaceCheckResult check = CheckSurface(mesh, topo);

    EXPECT_EQ(mesh.GetNumberOfTriangles(), entry["triangles"].get<int>());
    EXPECT_EQ(mesh.GetNumberOfEdges(), entry["edges"].get<int>());
    EXPECT_EQ(topo.GetNumberOfComponents(), entry["components"].get<int>());
    EXPECT_EQ(static_cast<int>(topo.BoundaryLoops.size()), entry["boundary_loops"].get<int>());
    EXPECT_EQ(topo.GetEulerCharacteristic(), entry["euler_characteristic"].get<int>());
    int genus = 0;
    for (const ComponentTopology& c : topo.Components)
    {
      genus += c.Genus;
    }
    EXPECT_EQ(genus, entry["genus"].get<int>());
    EXPECT_EQ(mesh.GetNonManifoldEdges().empty(), entry["edge_manifold"].get<bool>());
    EXPECT_EQ(topo.NonManifoldVertices.empty(), entry["vertex_manifold"].get<bool>());
    EXPECT_EQ(mesh.GetMisorientedEdges().empty(), entry["consistently_oriented"].get<bool>());
    EXPECT_EQ(check.Has("DegenerateTriangle"), entry["degenerate_faces"].get<int>() > 0);
    EXPECT_FALSE(check.HasErrors()) << check.ErrorSummary();
  }
}

// The site graph's cells grown on several threads (relaxation rounds, then Dijkstra's choice
// of parents) are the serial Dijkstra's bit for bit: distances, parents and cells, on meshes
// with many exactly tied paths (regular grids), on jittered and curved ones, and on a mesh
// with a zero-length edge (where the parallel pass hands over to the serial search).
#include "Geodesic/SiteCells.h"
#include "Mesh/ProceduralMeshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace
{
using namespace boolsurf;

/// Vertex adjacency over the triangles' edges, as compressed rows.
void Adjacency(const MeshData& data, std::vector<int>& offsets, std::vector<int>& neighbors)
{
  std::vector<std::vector<int>> rows(data.Positions.size());
  for (const auto& t : data.Triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      rows[t[k]].push_back(t[(k + 1) % 3]);
      rows[t[k]].push_back(t[(k + 2) % 3]);
    }
  }
  offsets.assign(1, 0);
  neighbors.clear();
  for (std::vector<int>& row : rows)
  {
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    neighbors.insert(neighbors.end(), row.begin(), row.end());
    offsets.push_back(static_cast<int>(neighbors.size()));
  }
}

void ExpectSameCells(const MeshData& data,
  int siteStride,
  bool parallelKept,
  const std::string& name)
{
  SCOPED_TRACE(name);
  const TriangleMesh mesh(data.Positions, data.Triangles);
  std::vector<int> offsets, neighbors;
  Adjacency(data, offsets, neighbors);
  std::vector<int> sites;
  for (int v = 0; v < mesh.GetNumberOfVertices(); v += siteStride)
  {
    sites.push_back(v);
  }
  SiteCells serial, parallel;
  EXPECT_FALSE(GrowSiteCells(mesh, offsets, neighbors, sites, false, serial));
  EXPECT_EQ(GrowSiteCells(mesh, offsets, neighbors, sites, true, parallel), parallelKept);
  ASSERT_EQ(serial.SiteDistance.size(), parallel.SiteDistance.size());
  for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
    ASSERT_EQ(serial.SiteDistance[v], parallel.SiteDistance[v]) << "vertex " << v; // bit for bit
    ASSERT_EQ(serial.Parent[v], parallel.Parent[v]) << "vertex " << v;
    ASSERT_EQ(serial.Cell[v], parallel.Cell[v]) << "vertex " << v;
  }
}
} // namespace

TEST(SiteCells, ParallelCellsEqualSerialDijkstra)
{
  ExpectSameCells(MakeFlatSquare(120, 1.0), 41, true, "regular grid (tied paths)");
  ExpectSameCells(MakeFlatSquare(120, 1.0, 0.3, 7), 53, true, "jittered grid");
  ExpectSameCells(MakeTorus(1.0, 0.35, 400, 140), 97, true, "torus");
  ExpectSameCells(MakeIcosphere(5), 61, true, "icosphere");
  MeshData collapsed = MakeFlatSquare(60, 1.0, 0.2, 3);
  collapsed.Positions[200] = collapsed.Positions[201]; // a zero-length edge
  ExpectSameCells(collapsed, 29, false, "zero-length edge");
}

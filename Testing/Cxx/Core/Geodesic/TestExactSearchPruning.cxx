// The exact window search's pruning (saddle restarts limited to their shadow, windows trimmed
// by their edge's known distances) against the plain filter it replaces: the same shortest
// distance for every pair, on surfaces full of saddles (a noisy height field, a torus's inner
// half, the shipped scans, one of them open), with far fewer windows. CGAL's exact lengths
// check both in the oracle suite (TestGeodesicExactOracle).
#include "Geodesic/ExactGeodesicSearch.h"
#include "Mesh/PlyReader.h"
#include "Mesh/ProceduralMeshes.h"
#include "Support/SourceTree.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace boolsurf;

namespace
{
/// A square of n x n quads whose heights are random: about half the inner vertices are
/// saddles, as on a scan.
MeshData NoisyField(int n)
{
  MeshData data = MakeFlatSquare(n, 1.0, 0.2, 3);
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> height(-0.25, 0.25);
  for (Vec3& p : data.Positions)
  {
    p.z = height(rng) / n + 0.2 * std::sin(4.0 * p.x) * std::cos(3.0 * p.y);
  }
  return data;
}

/// A random point of the surface: inside a triangle, on an edge or at a vertex.
CanonicalPoint RandomPoint(const TriangleMesh& mesh, std::mt19937& rng)
{
  std::uniform_real_distribution<double> unit(0.05, 0.45);
  CanonicalPoint c;
  switch (rng() % 4)
  {
    case 0:
      c.Location = PointLocation::Vertex;
      c.Id = mesh.GetTriangle(static_cast<int>(rng() % mesh.GetNumberOfTriangles()))[rng() % 3];
      break;
    case 1:
      c.Location = PointLocation::Edge;
      c.Id = static_cast<int>(rng() % mesh.GetNumberOfEdges());
      c.T = 2.0 * unit(rng);
      break;
    default:
      c.Location = PointLocation::Face;
      c.Id = static_cast<int>(rng() % mesh.GetNumberOfTriangles());
      c.U = unit(rng);
      c.V = unit(rng);
  }
  return c;
}

struct PruningRun
{
  int Pairs = 0;
  long long PrunedWindows = 0, PlainWindows = 0;
};

/// `pairs` random pairs (every third one the farthest of 32 candidates from its start), each
/// searched with and without pruning: equal distances, both within the budget.
PruningRun ComparePruning(const TriangleMesh& mesh, int pairs, std::uint32_t seed)
{
  ExactGeodesicSearch pruned(mesh), plain(mesh);
  plain.SetPruning(false);
  for (ExactGeodesicSearch* search : { &pruned, &plain })
  {
    search->SetMaximumWindows(1 << 23);
  }
  std::mt19937 rng(seed);
  PruningRun run;
  std::vector<int> startTriangles, endTriangles, strip;
  for (int i = 0; i < pairs; ++i)
  {
    const CanonicalPoint a = RandomPoint(mesh, rng);
    CanonicalPoint b = RandomPoint(mesh, rng);
    if (i % 3 == 0)
    {
      for (int k = 0; k < 32; ++k)
      {
        const CanonicalPoint c = RandomPoint(mesh, rng);
        if (Distance(PositionOf(mesh, c), PositionOf(mesh, a)) >
          Distance(PositionOf(mesh, b), PositionOf(mesh, a)))
        {
          b = c;
        }
      }
    }
    if (SharedTriangle(mesh, a, b) >= 0)
    {
      continue;
    }
    TrianglesOf(mesh, a, startTriangles);
    TrianglesOf(mesh, b, endTriangles);
    const double withPruning = pruned.FindStrip(a, startTriangles, b, endTriangles, strip);
    const bool prunedComplete = !pruned.GetLastBudgetExceeded();
    const double without = plain.FindStrip(a, startTriangles, b, endTriangles, strip);
    const std::string pair = Describe(a) + " -> " + Describe(b);
    EXPECT_TRUE(prunedComplete && !plain.GetLastBudgetExceeded()) << pair;
    EXPECT_GT(without, 0.0) << pair;
    EXPECT_NEAR(withPruning, without, 1e-9 * without) << pair;
    run.PrunedWindows += pruned.GetLastWindowCount();
    run.PlainWindows += plain.GetLastWindowCount();
    ++run.Pairs;
  }
  return run;
}

TriangleMesh ToMesh(const MeshData& d)
{
  return TriangleMesh(d.Positions, d.Triangles);
}
} // namespace

TEST(ExactSearchPruning, SameDistancesOnSurfacesFullOfSaddles)
{
  const TriangleMesh field = ToMesh(NoisyField(40));
  const PruningRun noisy = ComparePruning(field, 60, 5);
  EXPECT_GE(noisy.Pairs, 50);
  // The point of pruning: on this surface the plain filter makes far more windows (1.4 times
  // as many when written: these searches stay below the windows where trimming starts, so
  // this is the shadow restarts alone).
  EXPECT_LT(5 * noisy.PrunedWindows, 4 * noisy.PlainWindows)
    << noisy.PrunedWindows << " windows pruned, " << noisy.PlainWindows << " plain";

  const TriangleMesh torus = ToMesh(MakeTorus(1.0, 0.35, 48, 20));
  const PruningRun ring = ComparePruning(torus, 60, 7);
  EXPECT_GE(ring.Pairs, 50);
  EXPECT_LE(ring.PrunedWindows, ring.PlainWindows);
}

TEST(ExactSearchPruning, SameDistancesOnTheShippedScans)
{
  // nefertiti_small is open: its boundary vertices restart windows everywhere.
  for (const char* name : { "bunny_npm.ply", "eight.ply", "nefertiti_small.ply" })
  {
    const std::string path = (boolsurf::testing::SourceTree() / "Data" / name).string();
    MeshData data;
    std::string error;
    ASSERT_TRUE(ReadPly(path, data, error)) << path << ": " << error;
    const TriangleMesh mesh = ToMesh(data);
    const PruningRun run = ComparePruning(mesh, 45, 11);
    EXPECT_GE(run.Pairs, 35) << name;
    EXPECT_LT(run.PrunedWindows, run.PlainWindows) << name;
  }
}

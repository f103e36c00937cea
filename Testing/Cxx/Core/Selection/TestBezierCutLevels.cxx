// Cutting Bezier segments level by level with the halves on several threads gives the pieces
// the recursive halving gives on one thread, bit for bit, in order; a job whose split fails
// reports it.
#include "Geodesic/GeodesicBezier.h"
#include "Mesh/ProceduralMeshes.h"
#include "Selection/BezierCutLevels.h"

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

using namespace boolsurf;

TEST(BezierCutLevels, SamePiecesAsTheRecursionOnOneThread)
{
  const MeshData sphere = MakeIcosphere(4);
  const TriangleMesh mesh(sphere.Positions, sphere.Triangles);
  GeodesicPathSolver main(mesh);
  GeodesicPathSolver helper(main, GeodesicPathSolver::HelperTag());
  // Three segments across the sphere, with 1, 7 and 19 cuts (up to five levels).
  std::vector<std::array<CanonicalPoint, 4>> polygons;
  for (int s = 0; s < 3; ++s)
  {
    std::array<CanonicalPoint, 4> polygon;
    for (int k = 0; k < 4; ++k)
    {
      const int t = (97 * s + 613 * k + 11) % mesh.GetNumberOfTriangles();
      polygon[k] = LocateSurfacePoint(mesh, { t, 0.3, 0.25 });
    }
    polygons.push_back(polygon);
  }
  std::vector<std::vector<double>> cuts(3);
  cuts[0] = { 0.5 };
  for (int k = 1; k < 8; ++k)
  {
    cuts[1].push_back(k / 8.0);
  }
  for (int k = 1; k < 20; ++k)
  {
    cuts[2].push_back(k / 20.0 + 0.001 * (k % 3));
  }
  std::vector<BezierCutJob> jobs;
  for (int s = 0; s < 3; ++s)
  {
    jobs.push_back({ &polygons[s], &cuts[s] });
  }
  for (const std::vector<GeodesicPathSolver*>& solvers :
    { std::vector<GeodesicPathSolver*>{ &main },
      std::vector<GeodesicPathSolver*>{ &main, &helper } })
  {
    SCOPED_TRACE(std::to_string(solvers.size()) + " solvers");
    std::vector<std::vector<BezierCutPiece>> pieces;
    std::vector<std::string> errors;
    std::vector<char> ok;
    CutSegmentsByLevels(solvers, jobs, pieces, errors, ok);
    for (int s = 0; s < 3; ++s)
    {
      std::vector<BezierCutPiece> expected;
      std::string error;
      ASSERT_TRUE(CutSegmentRecursively(main,
        polygons[s],
        0.0,
        1.0,
        cuts[s].data(),
        cuts[s].data() + cuts[s].size(),
        expected,
        error))
        << error;
      ASSERT_TRUE(ok[s]) << errors[s];
      ASSERT_EQ(pieces[s].size(), cuts[s].size() + 1);
      ASSERT_EQ(pieces[s].size(), expected.size());
      for (std::size_t i = 0; i < expected.size(); ++i)
      {
        EXPECT_EQ(pieces[s][i].A, expected[i].A);
        EXPECT_EQ(pieces[s][i].B, expected[i].B);
        EXPECT_TRUE(pieces[s][i].Controls == expected[i].Controls)
          << "segment " << s << " piece " << i;
      }
    }
  }
}

// Crowded triangles at scale (issue 28): dense lattice drawings (repeated points, spikes, runs
// shared with earlier polygons, and thousands of crossings through lattice points other
// pieces pass) on a square of very few mesh triangles, so that hundreds of curve pieces and
// thousands of crossings fall in one triangle. Every Boolean and fill rule must give the exact
// planar area (the slab sweep of Support/PlanarWinding.h), with no refusal.
//
// And ten thousand segments in one mesh triangle: polygons on a 7 x 7 lattice, so that
// thousands of segments run along the same lines and thousands of pairs cross at each lattice
// point.
//
// BOOLSURF_CROWDED_SCALE=K multiplies the drawings' size by K (a longer hunt; the refinement
// of one triangle is meant to stay near-linear in its points, see Docs/Decisions.md).
#include "FlatDrawingOracle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <tuple>

using namespace boolsurf;
using namespace boolsurf::testing;

namespace
{

int Scale()
{
  const char* env = std::getenv("BOOLSURF_CROWDED_SCALE");
  return env ? std::max(1, std::atoi(env)) : 1;
}

std::vector<LatticePolygon> CrowdedDrawing(std::uint32_t seed, int lattice, int polygons)
{
  std::mt19937 rng(seed);
  std::vector<LatticePolygon> drawing;
  for (int p = 0; p < polygons; ++p)
  {
    drawing.push_back({ p % 2, LatticePolygonPoints(rng, lattice, drawing) });
  }
  return drawing;
}

/// Most refined triangles any one mesh triangle was cut into.
int MostRefinedTriangles(const TriangleMesh& mesh, const Arrangement& arr)
{
  int most = 0;
  for (int t = 0; t < arr.NumberOfMeshTriangles; ++t)
  {
    most = std::max(most, CountRefinedTriangles(mesh, arr, t));
  }
  return most;
}

/// Every operation under the non-zero and even-odd rules against the exact planar areas.
void ExpectExactAreas(const TriangleMesh& mesh,
  const std::vector<LatticePolygon>& drawing,
  int crowdedAtLeast,
  const std::string& what)
{
  const FlatDrawingAnswer a = AnswerDrawing(mesh, drawing);
  ASSERT_TRUE(a.Ok) << what << " refused: " << a.Error;
  // The drawing must really crowd a triangle, or the test would not test what it says.
  EXPECT_GE(MostRefinedTriangles(mesh, a.Arr), crowdedAtLeast) << what;
  double total = 0;
  for (double c : a.CellArea)
  {
    total += c;
  }
  const int i0 = ShapeIndexOf(a.Labels.ShapeIds, 0), i1 = ShapeIndexOf(a.Labels.ShapeIds, 1);
  for (const FillRule rule : { FillRule::NonZero, FillRule::EvenOdd })
  {
    for (int op = 0; op < 4; ++op)
    {
      auto evaluate = [op](bool x, bool y) {
        return op == 0 ? x || y : op == 1 ? x && y : op == 2 ? x && !y : x != y;
      };
      const double swept = SweepArea(drawing,
        2,
        [&](const std::vector<int>& w)
        { return evaluate(IsInside(w[0], rule), IsInside(w[1], rule)); });
      const double area = SelectedArea(a,
        [&](const std::vector<int>& l)
        { return evaluate(i0 >= 0 && IsInside(l[i0], rule), i1 >= 0 && IsInside(l[i1], rule)); });
      EXPECT_NEAR(area, swept, 1e-9 * total)
        << what << ", operation " << op << ", rule " << static_cast<int>(rule);
    }
  }
}

} // namespace

// Two mesh triangles under the whole drawing, vertices on lattice points: pieces pass through
// the mesh's corners and run along its diagonal.
TEST(CrowdedLatticeDrawings, HundredsOfPiecesInOneTriangleOfAnAlignedSquare)
{
  const int scale = Scale();
  for (const auto& [lattice, polygons, seed] :
    { std::tuple<int, int, std::uint32_t>{ 24, 48, 1 }, { 48, 96, 2 } })
  {
    const int n = lattice * scale;
    const std::vector<LatticePolygon> drawing = CrowdedDrawing(seed, n, polygons * scale);
    const TriangleMesh square = FlatMeshFor(-1, n + 1, 1, true, 0);
    ASSERT_EQ(square.GetNumberOfTriangles(), 2);
    ExpectExactAreas(square,
      drawing,
      1000,
      "lattice " + std::to_string(n) + ", " + std::to_string(polygons * scale) + " polygons");
  }
}

// Eight jittered mesh triangles: the same kind of drawing in general position with the mesh.
TEST(CrowdedLatticeDrawings, HundredsOfPiecesPerTriangleOfAnIrregularSquare)
{
  const int scale = Scale();
  const int n = 32 * scale;
  for (std::uint32_t seed : { 3u, 4u })
  {
    const std::vector<LatticePolygon> drawing = CrowdedDrawing(seed, n, 64 * scale);
    const TriangleMesh square = FlatMeshFor(-1, n + 1, 2, false, seed);
    ExpectExactAreas(square, drawing, 300, "irregular square, seed " + std::to_string(seed));
  }
}

// Ten thousand segments in ONE mesh triangle (issue 28, item 2): 1,500 random lattice polygons
// on a 7 x 7 lattice, all inside a single triangle, so that every segment meets hundreds of
// others, most of them along shared lines and through shared lattice points. About 100 s in a
// release build; the sanitizer pass (BOOLSURF_SANITIZER_PASS) draws 300 polygons.
TEST(CrowdedLatticeDrawings, TenThousandSegmentsInOneTriangle)
{
  const int n = 6;
  const bool sanitizerPass = std::getenv("BOOLSURF_SANITIZER_PASS") != nullptr;
  const std::vector<LatticePolygon> drawing = CrowdedDrawing(28, n, sanitizerPass ? 300 : 1500);
  std::size_t segments = 0;
  for (const LatticePolygon& p : drawing)
  {
    segments += p.Points.size();
  }
  ASSERT_GE(segments, sanitizerPass ? 2000u : 10000u);
  const double far = 2.0 * n + 4.0;
  const TriangleMesh one(
    { { -1.0, -1.0, 0.0 }, { far, -1.0, 0.0 }, { -1.0, far, 0.0 } }, { { 0, 1, 2 } });
  ExpectExactAreas(one, drawing, 1000, std::to_string(segments) + " segments in one triangle");
}

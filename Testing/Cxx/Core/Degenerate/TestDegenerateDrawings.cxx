// The small degenerate drawings of the degenerate-curves issue, on irregular and aligned flat
// meshes: every one answered, with the planar area.
#include "FlatDrawingOracle.h"

#include <gtest/gtest.h>

using namespace boolsurf;
using namespace boolsurf::testing;

namespace
{

void ExpectNonZeroArea(const std::vector<std::array<long long, 2>>& pts,
  double expected,
  double lo,
  double hi,
  double step = 1)
{
  const std::vector<LatticePolygon> drawing{ { 0, pts } };
  for (int m = 0; m < 11; ++m)
  {
    const bool aligned = m == 10;
    const int cells = aligned ? static_cast<int>((hi - lo) / step) : 23 + m;
    const TriangleMesh mesh = FlatMeshFor(lo, hi, cells, aligned, 100 + m);
    const FlatDrawingAnswer a = AnswerDrawing(mesh, drawing);
    ASSERT_TRUE(a.Ok) << (aligned ? "aligned mesh" : "irregular mesh " + std::to_string(m)) << ": "
                      << a.Error;
    const double area = SelectedArea(a, [](const std::vector<int>& l) { return l[0] != 0; });
    const double exact = SweepArea(drawing, 1, [](const std::vector<int>& w) { return w[0] != 0; });
    EXPECT_NEAR(exact, expected, 0.005) << "the issue quotes areas to two decimals";
    EXPECT_NEAR(area, exact, 1e-9 * (hi - lo) * (hi - lo)) << "mesh " << m;
  }
}

} // namespace

TEST(DegenerateDrawings, VertexOnItsOwnSegmentSelfCrossing)
{
  ExpectNonZeroArea({ { 390, 200 },
                      { 10, 510 },
                      { 360, 460 },
                      { 780, 490 },
                      { 20, 90 },
                      { 360, 400 },
                      { 720, 320 },
                      { 500, 470 } },
    95942.65,
    0,
    800,
    10);
}

TEST(DegenerateDrawings, VertexOnItsOwnEdge)
{
  ExpectNonZeroArea({ { 0, 0 }, { 20, 0 }, { 20, 10 }, { 10, 0 }, { 0, 10 } }, 100, -2, 22);
}

TEST(DegenerateDrawings, Keyhole)
{
  ExpectNonZeroArea({ { 0, 0 },
                      { 20, 0 },
                      { 20, 20 },
                      { 0, 20 },
                      { 0, 10 },
                      { 5, 10 },
                      { 5, 15 },
                      { 15, 15 },
                      { 15, 5 },
                      { 5, 5 },
                      { 5, 10 },
                      { 0, 10 } },
    300,
    -2,
    22);
}

TEST(DegenerateDrawings, SpikeOutAndBack)
{
  ExpectNonZeroArea(
    { { 0, 0 }, { 10, 0 }, { 10, 10 }, { 5, 5 }, { 10, 10 }, { 0, 10 } }, 100, -2, 12);
}

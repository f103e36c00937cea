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

TEST(DegenerateDrawings, IssueCasesOnTenIrregularMeshesAndAnAlignedOne)
{
  for (const DegenerateCase& c : DegenerateIssueCases())
  {
    SCOPED_TRACE(c.Name);
    ExpectNonZeroArea(c.Points, c.Area, c.Lo, c.Hi, c.Step);
  }
}

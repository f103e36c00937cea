// On a flat mesh geodesics are straight lines, so BoolSurf's Booleans of polygons must equal
// Clipper's (an independent 2D implementation), for every operation and fill rule, with
// random self-intersecting polygons on an irregular triangulation.
#include "ClipperOracle.h"
#include "FilterTestUtils.h"
#include "vtkBoolSurf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace
{
using testutils::ClipperArea;
using testutils::ToClipper;

testutils::ControlPolygon RandomPolygon(std::mt19937& rng, int shape)
{
  return testutils::RandomGridPolygon(rng, shape);
}
} // namespace

TEST(BooleanClipperOracle, EveryOperationAndFillRuleMatchesClipper)
{
  vtkSmartPointer<vtkPolyData> mesh =
    testutils::ToPolyData(boolsurf::MakeFlatSquare(48, 1.0, 0.3, 11));
  std::mt19937 rng(2024);
  const ClipperLib::ClipType clipperOps[] = {
    ClipperLib::ctUnion, ClipperLib::ctIntersection, ClipperLib::ctDifference, ClipperLib::ctXor
  };
  const ClipperLib::PolyFillType clipperRules[] = {
    ClipperLib::pftNonZero, ClipperLib::pftEvenOdd, ClipperLib::pftPositive, ClipperLib::pftNegative
  };
  int compared = 0, nonEmpty = 0;
  for (int trial = 0; trial < 12; ++trial)
  {
    const auto a = RandomPolygon(rng, 0), b = RandomPolygon(rng, 1);
    vtkNew<vtkBoolSurf> boolsurf;
    boolsurf->SetInputData(0, mesh);
    boolsurf->SetInputData(1, testutils::ToCurves({ a, b }));
    for (int op = 0; op < 4; ++op)
    {
      for (int rule = 0; rule < 4; ++rule)
      {
        boolsurf->SetOperation(op);
        boolsurf->SetFillRule(rule);
        boolsurf->Update();
        const double ours = testutils::Area(boolsurf->GetOutput());

        ClipperLib::Clipper clipper;
        clipper.AddPath(ToClipper(a), ClipperLib::ptSubject, true);
        clipper.AddPath(ToClipper(b), ClipperLib::ptClip, true);
        ClipperLib::Paths solution;
        ASSERT_TRUE(
          clipper.Execute(clipperOps[op], solution, clipperRules[rule], clipperRules[rule]));
        const double expected = ClipperArea(solution);
        EXPECT_NEAR(ours, expected, 1e-9 * std::max(1.0, expected))
          << "trial " << trial << " operation " << op << " fill rule " << rule;
        ++compared;
        nonEmpty += expected > 1e-3 ? 1 : 0;
      }
    }
  }
  EXPECT_EQ(compared, 12 * 16);
  EXPECT_GT(nonEmpty, compared / 3); // the comparison is not between empty results
}

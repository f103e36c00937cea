// Winding labels on hand-made cell graphs (the arrangement's output shape), consistency
// detection, Boolean expressions and fill rules.
#include "BooleanExpression.h"
#include "BooleanSelection.h"
#include "CellLabeling.h"
#include "RegionBoundary.h"

#include <gtest/gtest.h>

#include <random>

using namespace boolsurf;

TEST(CellLabeling, NestedCirclesOnADisc)
{
  // Cells: 0 outside both, 1 inside shape 0 only, 2 inside both (shape 1 nested in 0).
  LabelingInput in;
  in.NumberOfCells = 3;
  in.NumberOfShapes = 2;
  in.Arcs = { { 0, 1, 0, 10 }, { 1, 2, 1, 11 } };
  in.ZeroCells = { 0 };
  LabelingResult r = LabelCells(in);
  EXPECT_EQ(r.GetLabel(0, 0), 0);
  EXPECT_EQ(r.GetLabel(1, 0), 1);
  EXPECT_EQ(r.GetLabel(2, 0), 1);
  EXPECT_EQ(r.GetLabel(2, 1), 1);
  EXPECT_EQ(r.GetLabel(1, 1), 0);
  EXPECT_TRUE(r.ShapeConsistent[0] && r.ShapeConsistent[1]);
}

TEST(CellLabeling, ClockwiseCurveGivesNegativeLabelAndShiftRule)
{
  // A clockwise loop: its interior (cell 1) is on its right. With a zero cell outside the
  // label is -1; without one (closed surface) labels are shifted so the minimum is 0.
  LabelingInput in;
  in.NumberOfCells = 2;
  in.NumberOfShapes = 1;
  in.Arcs = { { 1, 0, 0, 0 } };
  in.ZeroCells = { 0 };
  EXPECT_EQ(LabelCells(in).GetLabel(1, 0), -1);
  in.ZeroCells = { -1 };
  LabelingResult r = LabelCells(in);
  EXPECT_EQ(r.GetLabel(0, 0), 1);
  EXPECT_EQ(r.GetLabel(1, 0), 0);
}

TEST(CellLabeling, SingleMeridianOnATorusIsInconsistent)
{
  // The meridian does not separate the torus: one cell, an arc from it to itself.
  LabelingInput in;
  in.NumberOfCells = 1;
  in.NumberOfShapes = 2;
  in.Arcs = { { 0, 0, 0, 0 } };
  LabelingResult r = LabelCells(in);
  EXPECT_FALSE(r.ShapeConsistent[0]);
  EXPECT_TRUE(r.ShapeConsistent[1]);
  ASSERT_EQ(r.Conflicts.size(), 1u);
  EXPECT_EQ(r.Conflicts[0].Shape, 0);
}

TEST(CellLabeling, TwoOppositeMeridiansBoundABand)
{
  // Meridian 1 has the band (cell 1) on its left; the reversed, shifted meridian 2 too.
  LabelingInput in;
  in.NumberOfCells = 2;
  in.NumberOfShapes = 1;
  in.Arcs = { { 0, 1, 0, 100 }, { 0, 1, 0, 200 } };
  LabelingResult r = LabelCells(in);
  EXPECT_TRUE(r.ShapeConsistent[0]);
  EXPECT_EQ(r.GetLabel(0, 0), 0);
  EXPECT_EQ(r.GetLabel(1, 0), 1);
  // Two meridians in the same direction: crossing one adds 1, the other subtracts it.
  in.Arcs = { { 0, 1, 0, 100 }, { 1, 0, 0, 200 } };
  EXPECT_FALSE(LabelCells(in).ShapeConsistent[0]);
}

TEST(CellLabeling, OverlappingCurvesAreCrossedTogether)
{
  // Shape 0 encloses cells 1 and 2, shape 1 encloses cell 1; their curves coincide where
  // cells 0 and 1 meet (one location, crossed at once). Both are consistent.
  LabelingInput in;
  in.NumberOfCells = 3;
  in.NumberOfShapes = 2;
  in.Arcs = { { 0, 1, 0, 5 }, { 0, 1, 1, 5 }, { 2, 1, 1, 6 }, { 0, 2, 0, 7 } };
  in.ZeroCells = { 0 };
  LabelingResult r = LabelCells(in);
  EXPECT_TRUE(r.ShapeConsistent[0]);
  EXPECT_TRUE(r.ShapeConsistent[1]);
  EXPECT_EQ(r.GetLabel(1, 0), 1);
  EXPECT_EQ(r.GetLabel(1, 1), 1);
  EXPECT_EQ(r.GetLabel(2, 0), 1);
  EXPECT_EQ(r.GetLabel(2, 1), 0);
  // Treating the overlap as two separate places makes shape 1 look inconsistent: the
  // Location grouping is what keeps it right.
  in.Arcs[1].Location = 99;
  EXPECT_FALSE(LabelCells(in).ShapeConsistent[1]);
}

TEST(CellLabeling, ComponentsGetTheirOwnZeroCells)
{
  LabelingInput in;
  in.NumberOfCells = 4;
  in.NumberOfShapes = 1;
  in.CellComponent = { 0, 0, 1, 1 };
  in.Arcs = { { 0, 1, 0, 0 }, { 3, 2, 0, 1 } };
  in.ZeroCells = { 0, 2 };
  LabelingResult r = LabelCells(in);
  EXPECT_EQ(r.GetLabel(1, 0), 1);
  EXPECT_EQ(r.GetLabel(3, 0), -1);
}

TEST(BooleanExpression, PrecedenceAndOperators)
{
  BooleanExpression e;
  std::string error;
  ASSERT_TRUE(e.Parse("S0 | S1 & S2", 3, error)) << error; // & binds tighter
  EXPECT_TRUE(e.Evaluate({ 1, 0, 0 }));
  EXPECT_FALSE(e.Evaluate({ 0, 1, 0 }));
  ASSERT_TRUE(e.Parse("(S0 | S1) & ~S2", 3, error)) << error;
  EXPECT_TRUE(e.Evaluate({ 0, 1, 0 }));
  EXPECT_FALSE(e.Evaluate({ 0, 1, 1 }));
  ASSERT_TRUE(e.Parse("S0 - S1 ^ S2", 3, error)) << error; // (S0 - S1) ^ S2
  EXPECT_TRUE(e.Evaluate({ 1, 0, 0 }));
  EXPECT_FALSE(e.Evaluate({ 1, 0, 1 }));
  EXPECT_TRUE(e.Evaluate({ 1, 1, 1 }));
  EXPECT_EQ(e.GetShapes(), (std::vector<int>{ 0, 1, 2 }));
  ASSERT_TRUE(e.Parse("  ~ ~s1 ", 2, error)) << error;
  EXPECT_TRUE(e.Evaluate({ 0, 1 }));
}

TEST(BooleanExpression, SyntaxErrorsAreNamed)
{
  BooleanExpression e;
  std::string error;
  EXPECT_FALSE(e.Parse("S0 &", 2, error));
  EXPECT_NE(error.find("unexpected end"), std::string::npos) << error;
  EXPECT_FALSE(e.Parse("(S0 | S1", 2, error));
  EXPECT_NE(error.find("missing ')'"), std::string::npos) << error;
  EXPECT_FALSE(e.Parse("S0 + S1", 2, error));
  EXPECT_NE(error.find("position 4"), std::string::npos) << error;
  EXPECT_FALSE(e.Parse("S0 | S7", 3, error));
  EXPECT_NE(error.find("unknown shape S7"), std::string::npos) << error;
  EXPECT_FALSE(e.Parse("X1", 3, error));
  EXPECT_FALSE(e.Parse("S", 3, error));
  EXPECT_NE(error.find("S<id>"), std::string::npos) << error;
  EXPECT_FALSE(e.Parse("", 3, error));
}

TEST(BooleanExpression, NamedOperationsAndVariadicForms)
{
  EXPECT_EQ(BooleanExpression::Union(0, 1, 4), "S0 | S1");
  EXPECT_EQ(BooleanExpression::Union(-1, -1, 3), "S0 | S1 | S2");
  EXPECT_EQ(BooleanExpression::Intersection(-1, -1, 2), "S0 & S1");
  EXPECT_EQ(BooleanExpression::SymmetricDifference(-1, 0, 3), "S0 ^ S1 ^ S2");
  EXPECT_EQ(BooleanExpression::Difference(2, 0, 3), "S2 - S0");
  EXPECT_EQ(BooleanExpression::Difference(0, -1, 3), "S0 - (S1 | S2)");
}

// A random expression evaluated at once equals the fold of its pairwise operations.
TEST(BooleanExpression, ExpressionEqualsFoldOfPairwiseOperations)
{
  std::mt19937 rng(3);
  const char ops[] = { '&', '|', '^', '-' };
  for (int trial = 0; trial < 200; ++trial)
  {
    const int n = 2 + trial % 5;
    // Left fold: ((((S_a op S_b) op S_c) ...)
    std::vector<int> shapes(n);
    std::vector<char> chosen(n - 1);
    std::string text = "S" + std::to_string(shapes[0] = rng() % n);
    for (int i = 1; i < n; ++i)
    {
      shapes[i] = rng() % n;
      chosen[i - 1] = ops[rng() % 4];
      text = "(" + text + " " + chosen[i - 1] + " S" + std::to_string(shapes[i]) + ")";
    }
    BooleanExpression e;
    std::string error;
    ASSERT_TRUE(e.Parse(text, n, error)) << error;
    for (int cell = 0; cell < 16; ++cell)
    {
      std::vector<char> inside(n);
      for (auto& b : inside)
        b = rng() % 2;
      bool fold = inside[shapes[0]];
      for (int i = 1; i < n; ++i)
      {
        const bool b = inside[shapes[i]];
        switch (chosen[i - 1])
        {
          case '&':
            fold = fold && b;
            break;
          case '|':
            fold = fold || b;
            break;
          case '^':
            fold = fold != b;
            break;
          case '-':
            fold = fold && !b;
            break;
        }
      }
      EXPECT_EQ(e.Evaluate(inside), fold) << text;
    }
  }
}

TEST(BooleanSelection, FillRulesAndRefusalOfInconsistentShapes)
{
  LabelingResult labels;
  labels.NumberOfShapes = 2;
  labels.Labels = { 0, 0, 1, 0, 2, 1, -1, 0 }; // 4 cells
  labels.ShapeConsistent = { 1, 0 };
  labels.Conflicts = { { 1, 3, 0, 1 } };
  BooleanExpression e;
  std::string error;
  ASSERT_TRUE(e.Parse("S0", 2, error));
  std::vector<char> sel;
  ASSERT_TRUE(SelectCells(labels, e, FillRule::NonZero, sel, error));
  EXPECT_EQ(sel, (std::vector<char>{ 0, 1, 1, 1 }));
  ASSERT_TRUE(SelectCells(labels, e, FillRule::EvenOdd, sel, error));
  EXPECT_EQ(sel, (std::vector<char>{ 0, 1, 0, 1 }));
  ASSERT_TRUE(SelectCells(labels, e, FillRule::Positive, sel, error));
  EXPECT_EQ(sel, (std::vector<char>{ 0, 1, 1, 0 }));
  ASSERT_TRUE(SelectCells(labels, e, FillRule::Negative, sel, error));
  EXPECT_EQ(sel, (std::vector<char>{ 0, 0, 0, 1 }));
  ASSERT_TRUE(e.Parse("S0 | S1", 2, error));
  EXPECT_FALSE(SelectCells(labels, e, FillRule::NonZero, sel, error));
  EXPECT_NE(error.find("inconsistent shape(s)"), std::string::npos) << error;
  EXPECT_NE(error.find("S1 (cell 3"), std::string::npos) << error;
}

// Two squares' boundaries on a grid of point ids: the union's boundary is one loop that
// skips the patches inside the union; the intersection's is the inner square.
TEST(RegionBoundary, LoopsKeepTheRegionOnTheLeft)
{
  // Cells: 0 outside, 1 inside A only, 2 inside A and B, 3 inside B only.
  // Patches (point ids arbitrary but shared at the two crossings 10 and 20):
  std::vector<BoundaryPatch> patches = {
    { { 10, 1, 2, 20 }, 1, 0 }, // A's outer arc: A-only cell on its left
    { { 20, 3, 10 }, 2, 3 },    // A's arc inside B
    { { 20, 4, 5, 10 }, 3, 0 }, // B's outer arc
    { { 10, 6, 20 }, 2, 1 },    // B's arc inside A
  };
  std::vector<BoundaryPolyline> lines = ExtractRegionBoundary(patches, { 0, 1, 1, 1 });
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_TRUE(lines[0].Closed);
  EXPECT_EQ(lines[0].Points, (std::vector<int>{ 10, 1, 2, 20, 4, 5 }));
  lines = ExtractRegionBoundary(patches, { 0, 0, 1, 0 });
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_TRUE(lines[0].Closed);
  EXPECT_EQ(lines[0].Points, (std::vector<int>{ 20, 3, 10, 6 }));
  // Difference A - B: A's outer arc then B's inner arc walked backwards (region on the left).
  lines = ExtractRegionBoundary(patches, { 0, 1, 0, 0 });
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].Points, (std::vector<int>{ 10, 1, 2, 20, 6 }));
  EXPECT_EQ(lines[0].Reversed, (std::vector<char>{ 0, 1 }));
  EXPECT_TRUE(ExtractRegionBoundary(patches, { 0, 0, 0, 0 }).empty());
}

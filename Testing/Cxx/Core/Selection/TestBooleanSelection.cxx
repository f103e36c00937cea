// Boolean expressions (parser, precedence, variadic forms), fill rules, refusal of
// inconsistent operands and region boundaries on hand-made labels.
#include "Selection/BooleanExpression.h"
#include "Selection/BooleanSelection.h"
#include "Selection/RegionBoundary.h"

#include <gtest/gtest.h>

#include <random>

using namespace boolsurf;

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

// Valid UTF-8 in every message: a non-ASCII character is quoted whole, invalid bytes as \xNN.
TEST(BooleanExpression, MessagesStayValidUtf8)
{
  auto isValidUtf8 = [](const std::string& s)
  {
    for (size_t i = 0; i < s.size();)
    {
      const unsigned char c = static_cast<unsigned char>(s[i]);
      const size_t n = c < 0x80 ? 1
        : (c >> 5) == 6         ? 2
        : (c >> 4) == 14        ? 3
        : (c >> 3) == 30        ? 4
                                : 0;
      if (n == 0 || i + n > s.size())
        return false;
      for (size_t k = 1; k < n; ++k)
        if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80)
          return false;
      i += n;
    }
    return true;
  };
  BooleanExpression e;
  std::string error;
  EXPECT_FALSE(e.Parse("S0 & \xC3\xA9", 2, error)); // "é"
  EXPECT_TRUE(isValidUtf8(error)) << error;
  EXPECT_NE(error.find("unexpected '\xC3\xA9'"), std::string::npos) << error;
  EXPECT_FALSE(e.Parse("S0 | \xFF\xC3", 2, error)); // not UTF-8 at all
  EXPECT_TRUE(isValidUtf8(error)) << error;
  EXPECT_NE(error.find("unexpected '\\xFF'"), std::string::npos) << error;
}

// Deep nesting is refused by name instead of overflowing the stack; runs of '~' are fine.
TEST(BooleanExpression, DeepNestingIsRefusedNotOverflowed)
{
  BooleanExpression e;
  std::string error;
  EXPECT_FALSE(e.Parse(std::string(100000, '(') + "S0", 1, error));
  EXPECT_NE(error.find("parentheses nested deeper than 256"), std::string::npos) << error;
  EXPECT_FALSE(e.Parse(std::string(100000, '(') + "S0" + std::string(100000, ')'), 1, error));
  EXPECT_NE(error.find("nested deeper"), std::string::npos) << error;
  ASSERT_TRUE(e.Parse(std::string(1000001, '~') + "S0", 1, error)) << error;
  EXPECT_FALSE(e.Evaluate({ 1 })); // an odd number of nots
  ASSERT_TRUE(e.Parse(std::string(200, '(') + "S0" + std::string(200, ')'), 1, error)) << error;
  EXPECT_TRUE(e.Evaluate({ 1 }));
}

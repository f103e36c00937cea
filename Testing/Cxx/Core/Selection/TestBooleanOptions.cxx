// The Boolean options the filters hold (Selection/BooleanOptions.h): the defaults of the
// filters' properties, the shapes an operation names, and a selection evaluated from the
// options whole, on hand-made labels.
#include "Selection/BooleanOptions.h"

#include <gtest/gtest.h>

using namespace boolsurf;

TEST(BooleanOptions, DefaultsAreTheFiltersPropertyDefaults)
{
  const BooleanOptions options;
  EXPECT_EQ(options.Operation, BooleanOperation::Union);
  EXPECT_EQ(options.ShapeA, 0);
  EXPECT_EQ(options.ShapeB, 1);
  EXPECT_EQ(options.Expression, "S0 | S1");
  EXPECT_EQ(options.Rule, FillRule::NonZero);
}

TEST(BooleanOptions, ShapesNamedAreTheOperandsOrTheExpressionsShapes)
{
  BooleanOptions options;
  options.ShapeA = 7;
  options.ShapeB = -1; // all shapes: names none in particular
  EXPECT_EQ(ShapesNamed(options), (std::vector<int>{ 7 }));
  options.Operation = BooleanOperation::Expression;
  options.Expression = "(S2 & ~s10) | XS3 | S2147483648 | S4";
  // XS3 is not a shape token; an id past INT_MAX is left to the parser to refuse.
  EXPECT_EQ(ShapesNamed(options), (std::vector<int>{ 2, 10, 4 }));
}

TEST(BooleanOptions, SelectionReadsEveryField)
{
  // Three cells, two shapes with ids 4 and 9: labels (0,0), (1,0), (2,-1).
  LabelingResult labels;
  labels.NumberOfShapes = 2;
  labels.ShapeIds = { 4, 9 };
  labels.Labels = { 0, 0, 1, 0, 2, -1 };
  labels.ShapeConsistent = { 1, 1 };
  BooleanOptions options;
  options.ShapeA = 4;
  options.ShapeB = 9;
  std::vector<char> selected;
  std::string text, error;
  ASSERT_TRUE(SelectBooleanCells(labels, options, selected, text, error)) << error;
  EXPECT_EQ(selected, (std::vector<char>{ 0, 1, 1 }));
  options.Rule = FillRule::EvenOdd; // label 2 is even: outside
  ASSERT_TRUE(SelectBooleanCells(labels, options, selected, text, error)) << error;
  EXPECT_EQ(selected, (std::vector<char>{ 0, 1, 1 })); // S9's -1 is odd
  options.Operation = BooleanOperation::Difference;
  ASSERT_TRUE(SelectBooleanCells(labels, options, selected, text, error)) << error;
  EXPECT_EQ(selected, (std::vector<char>{ 0, 1, 0 }));
  options.Operation = BooleanOperation::Expression;
  options.Expression = "S9";
  ASSERT_TRUE(SelectBooleanCells(labels, options, selected, text, error)) << error;
  EXPECT_EQ(text, "S9");
  EXPECT_EQ(selected, (std::vector<char>{ 0, 0, 1 }));
  options.Operation = BooleanOperation::Union;
  options.ShapeB = 5;
  EXPECT_FALSE(SelectBooleanCells(labels, options, selected, text, error));
  EXPECT_NE(error.find("ShapeB = 5 is not a shape of the input"), std::string::npos) << error;
}

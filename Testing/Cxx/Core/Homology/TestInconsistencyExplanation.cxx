// The explanation of inconsistent shapes from curve classes alone (no surface needed): excess
// per shape, the words for a class, and which shapes and curves the explanation names.
#include "Homology/InconsistencyExplanation.h"

#include <gtest/gtest.h>

using namespace boolsurf;

namespace
{
/// Curves 10 and 11 of shape 3 wind +1 and +1 around G1; curve 12 of shape 5 winds nowhere.
HomologyFields TwoShapes()
{
  HomologyFields h;
  h.Present = true;
  h.NumberOfGenerators = 2;
  h.CurveIds = { 10, 11, 12 };
  h.CurveShapeIds = { 3, 3, 5 };
  h.CurveClasses = { { 0, 1 }, { 0, 1 }, { 0, 0 } };
  return h;
}
} // namespace

TEST(InconsistencyExplanation, ExcessIsTheSumOfAShapesCurves)
{
  const auto excess = ShapeExcess(TwoShapes(), { 3, 5, 7 });
  ASSERT_EQ(excess.size(), 3u);
  EXPECT_EQ(excess[0], (std::vector<int>{ 0, 2 }));
  EXPECT_EQ(excess[1], (std::vector<int>{ 0, 0 }));
  EXPECT_EQ(excess[2], (std::vector<int>{ 0, 0 })); // a shape without curves
}

TEST(InconsistencyExplanation, ClassesInWords)
{
  EXPECT_EQ(DescribeClass({ 0, 0, 0 }), "no generator");
  EXPECT_EQ(DescribeClass({ 1, 0, -2 }), "+1 x G0, -2 x G2");
}

TEST(InconsistencyExplanation, NamesOnlyInconsistentShapesAndTheirWindingCurves)
{
  LabelingResult labels;
  labels.NumberOfShapes = 2;
  labels.ShapeIds = { 3, 5 };
  labels.ShapeConsistent = { false, true };
  const std::string text = ExplainInconsistency(labels, TwoShapes());
  EXPECT_NE(text.find("Shape S3"), std::string::npos) << text;
  EXPECT_NE(text.find("curve 10 winds +1 x G1; curve 11 winds +1 x G1"), std::string::npos) << text;
  EXPECT_NE(text.find("Generators in excess: +2 x G1"), std::string::npos) << text;
  EXPECT_NE(text.find("DuplicateReversed turns each offending curve (10, 11)"), std::string::npos)
    << text;
  EXPECT_EQ(text.find("S5"), std::string::npos) << text;
  labels.ShapeConsistent = { true, true };
  EXPECT_EQ(ExplainInconsistency(labels, TwoShapes()), "");
}

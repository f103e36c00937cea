// The curve editor's drawing (Plugin/pqBoolSurfDrawing): the Surface Curves source's property
// defaults read back, the properties written complete, and the edits a user makes (insert
// after the selected point, a first click starting a curve, deleting a curve's last point).
#include "pqBoolSurfDrawing.h"

#include <gtest/gtest.h>

TEST(CurveEditorDrawing, ReadsTheSourceDefaults)
{
  pqBoolSurfDrawing::Properties values;
  values.Points = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 5, 5, 5, 6, 5, 5 };
  values.CurveSizes = { 3, 2 };
  values.ShapeIds = { 7 };     // curve 1: its index
  values.ClosedCurves = { 0 }; // curve 1: closed
  pqBoolSurfDrawing d = pqBoolSurfDrawing::FromProperties(values);
  ASSERT_EQ(d.Curves.size(), 2u);
  EXPECT_EQ(d.Curves[0].Shape, 7);
  EXPECT_EQ(d.Curves[1].Shape, 1);
  EXPECT_FALSE(d.Curves[0].Closed);
  EXPECT_TRUE(d.Curves[1].Closed);
  EXPECT_EQ(d.Curves[1].Points[1].Position[0], 6);
  EXPECT_EQ(d.Curves[0].Points[0].Triangle, -1); // no TriangleIds: positions to snap

  // Empty CurveSizes: one curve of every point.
  values.CurveSizes.clear();
  EXPECT_EQ(pqBoolSurfDrawing::FromProperties(values).Curves.at(0).Points.size(), 5u);
}

TEST(CurveEditorDrawing, WritesCompleteProperties)
{
  pqBoolSurfDrawing d;
  const int c = d.AddCurve();
  d.InsertPoint(c, -1, { 0, 0, 0 });
  d.InsertPoint(c, -1, { 1, 0, 0 });
  pqBoolSurfDrawing::Point* p = d.Find({ c, 1 });
  ASSERT_NE(p, nullptr);
  p->Triangle = 12;
  p->Weights = { 0.25, 0.5 };
  const pqBoolSurfDrawing::Properties v = d.ToProperties();
  EXPECT_EQ(v.Points, (std::vector<double>{ 0, 0, 0, 1, 0, 0 }));
  EXPECT_EQ(v.TriangleIds, (std::vector<vtkIdType>{ -1, 12 }));
  EXPECT_EQ(v.Barycentrics, (std::vector<double>{ 0, 0, 0.25, 0.5 }));
  EXPECT_EQ(v.CurveSizes, std::vector<int>{ 2 });
  EXPECT_EQ(v.ShapeIds, std::vector<int>{ 0 });
  EXPECT_EQ(v.ClosedCurves, std::vector<int>{ 0 }); // new curves start open
  // Read back: the exact points stay exact.
  pqBoolSurfDrawing again = pqBoolSurfDrawing::FromProperties(v);
  EXPECT_EQ(again.Curves.at(0).Points.at(1).Triangle, 12);
  EXPECT_EQ(again.Curves.at(0).Points.at(1).Weights[1], 0.5);
}

TEST(CurveEditorDrawing, EditsAsAUserMakesThem)
{
  pqBoolSurfDrawing d;
  // A click with no current curve starts one, with an unused shape.
  pqBoolSurfDrawing::Handle h = d.InsertPoint(-1, -1, { 0, 0, 0 });
  EXPECT_EQ(h.Curve, 0);
  d.InsertPoint(0, 0, { 2, 0, 0 });
  // Inserting after the first point puts the new point between the first and the second.
  h = d.InsertPoint(0, 0, { 1, 0, 0 });
  EXPECT_EQ(h.Index, 1);
  EXPECT_EQ(d.Curves[0].Points[1].Position[0], 1);
  EXPECT_EQ(d.Curves[0].Points[2].Position[0], 2);
  const int second = d.AddCurve();
  EXPECT_EQ(d.Curves[second].Shape, 1); // shape 0 is used
  d.InsertPoint(second, -1, { 9, 9, 9 });
  EXPECT_EQ(d.NumberOfPoints(), 4);
  // Deleting a curve's last point deletes the curve.
  EXPECT_TRUE(d.RemovePoint({ second, 0 }));
  EXPECT_EQ(d.Curves.size(), 1u);
  EXPECT_FALSE(d.RemovePoint({ 3, 0 }));
  EXPECT_FALSE(d.RemoveCurve(5));
  EXPECT_TRUE(d.RemoveCurve(0));
  EXPECT_EQ(d.NumberOfPoints(), 0);
}

// Winding labels on hand-made cell graphs (the arrangement's output shape) and consistency
// detection.
#include "Labeling/CellLabeling.h"

#include <gtest/gtest.h>

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

TEST(CellLabeling, PlugsAreLabeledAndLeftOut)
{
  // A strip across a square (cell 1) between the outside's two pieces (cells 0 and 2), drawn
  // clockwise along both sides: its two arcs between cells, its two boundary patches as arcs
  // from the plug (node 3), and both outside pieces linked to the plug, which is the zero node.
  LabelingInput in;
  in.NumberOfCells = 3;
  in.NumberOfPlugs = 1;
  in.NumberOfShapes = 1;
  in.Arcs = { { 1, 0, 0, 0 }, { 1, 2, 0, 1 }, { 1, 3, 0, 2 }, { 1, 3, 0, 3 } };
  in.Links = { { 0, 3 }, { 2, 3 } };
  in.CellComponent = { 0, 0, 0, 0 };
  in.ZeroCells = { 3 };
  LabelingResult r = LabelCells(in);
  EXPECT_TRUE(r.ShapeConsistent[0]);
  ASSERT_EQ(r.Labels.size(), 3u); // the plug is not in the result
  EXPECT_EQ(r.GetLabel(0, 0), 0);
  EXPECT_EQ(r.GetLabel(1, 0), -1);
  EXPECT_EQ(r.GetLabel(2, 0), 0);

  // Without the links the outside pieces would be free: cell 2 is tied to the plug only
  // through them, so dropping the arcs between cells leaves the labels unchanged.
  in.Arcs.erase(in.Arcs.begin(), in.Arcs.begin() + 2);
  r = LabelCells(in);
  EXPECT_EQ(r.GetLabel(0, 0), 0);
  EXPECT_EQ(r.GetLabel(1, 0), -1);
  EXPECT_EQ(r.GetLabel(2, 0), 0);

  // A link that contradicts an arc is a conflict, reported at a cell, never at the plug.
  in.Links.push_back({ 1, 3 });
  r = LabelCells(in);
  EXPECT_FALSE(r.ShapeConsistent[0]);
  ASSERT_EQ(r.Conflicts.size(), 1u);
  EXPECT_LT(r.Conflicts[0].Cell, in.NumberOfCells);
  EXPECT_NE(r.Conflicts[0].FirstLabel, r.Conflicts[0].SecondLabel);
}

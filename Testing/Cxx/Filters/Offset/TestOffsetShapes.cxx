// Offset Shapes (vtkBoolSurfOffset) and BoolSurf's OffsetShape step: on a flat mesh a margin is
// Clipper's round-join offset, and it takes part in Booleans with the other shapes; bad input
// gets named errors.
#include "ClipperOracle.h"
#include "FilterTestUtils.h"
#include "vtkBoolSurf.h"
#include "vtkBoolSurfOffset.h"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace
{
using testutils::ControlPolygon;

// An L (shape 0) and a square across its arm (shape 1), on the dyadic grid Clipper reads
// exactly.
const ControlPolygon LShape{ { { 0.3125, 0.25, 0 },
                               { 0.6875, 0.25, 0 },
                               { 0.6875, 0.4375, 0 },
                               { 0.5, 0.4375, 0 },
                               { 0.5, 0.75, 0 },
                               { 0.3125, 0.75, 0 } },
  0 };
const ControlPolygon Square{
  { { 0.375, 0.125, 0 }, { 0.5625, 0.125, 0 }, { 0.5625, 0.375, 0 }, { 0.375, 0.375, 0 } },
  1
};

constexpr double Scale = 1e9;
ClipperLib::Paths Scaled(const ControlPolygon& p)
{
  ClipperLib::Path path;
  for (const auto& x : p.Points)
  {
    path.push_back({ static_cast<ClipperLib::cInt>(std::llround(x[0] * Scale)),
      static_cast<ClipperLib::cInt>(std::llround(x[1] * Scale)) });
  }
  return { path };
}

// Clipper's offset of `paths` by d with round joins (closed polygons or, for bands, lines).
ClipperLib::Paths ClipperOffset(const ClipperLib::Paths& paths,
  double d,
  ClipperLib::EndType ends = ClipperLib::etClosedPolygon)
{
  ClipperLib::ClipperOffset offset(2.0, 1e-7 * Scale);
  offset.AddPaths(paths, ClipperLib::jtRound, ends);
  ClipperLib::Paths out;
  offset.Execute(out, d * Scale);
  return out;
}

// Clipper's Boolean `op` of two regions (non-zero fill).
ClipperLib::Paths ClipperBoolean(ClipperLib::ClipType op,
  const ClipperLib::Paths& a,
  const ClipperLib::Paths& b)
{
  ClipperLib::Clipper clipper;
  clipper.AddPaths(a, ClipperLib::ptSubject, true);
  clipper.AddPaths(b, ClipperLib::ptClip, true);
  ClipperLib::Paths out;
  clipper.Execute(op, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  return out;
}

double AreaOf(const ClipperLib::Paths& paths)
{
  double a = 0;
  for (const auto& p : paths)
  {
    a += ClipperLib::Area(p);
  }
  return a / (Scale * Scale);
}

struct Fixture
{
  vtkSmartPointer<vtkPolyData> Mesh =
    testutils::ToPolyData(boolsurf::MakeFlatSquare(96, 1.0, 0.3, 5));
  vtkSmartPointer<vtkPolyData> Curves = testutils::ToCurves({ LShape, Square });
};

} // namespace

TEST(OffsetShapes, MarginMatchesClipperAndChainsIntoBoolSurf)
{
  Fixture f;
  vtkNew<vtkBoolSurfOffset> offset;
  offset->SetInputData(0, f.Mesh);
  offset->SetInputData(1, f.Curves);
  offset->SetDistance(0.0625);
  offset->SetShapes("0");
  ASSERT_EQ(testutils::ErrorsOf(offset), "");
  vtkPolyData* out = offset->GetOutput();
  auto* shape = vtkIntArray::SafeDownCast(out->GetCellData()->GetArray("ShapeId"));
  auto* marked = vtkIntArray::SafeDownCast(out->GetCellData()->GetArray("OffsetCurve"));
  ASSERT_TRUE(shape && marked);
  ASSERT_EQ(out->GetNumberOfCells(), 3); // the two input curves, then one offset loop
  EXPECT_EQ(shape->GetValue(2), 2);      // one above the largest input ShapeId
  EXPECT_EQ(marked->GetValue(0) + marked->GetValue(1), 0);
  EXPECT_EQ(marked->GetValue(2), 1);
  EXPECT_EQ(out->GetFieldData()->GetArray("OffsetShapeId")->GetTuple1(0), 2);

  const ClipperLib::Paths margin = ClipperOffset(Scaled(LShape), 0.0625);
  vtkNew<vtkBoolSurf> boolean;
  boolean->SetInputData(0, f.Mesh);
  boolean->SetInputConnection(1, offset->GetOutputPort());
  boolean->SetOperation(4);
  boolean->SetExpression("S2");
  ASSERT_EQ(testutils::ErrorsOf(boolean), "");
  const double grown = testutils::Area(boolean->GetOutput());
  EXPECT_NEAR(grown, AreaOf(margin), 1e-3 * grown);

  // The margin minus the square, against Clipper's difference of the same two regions.
  boolean->SetExpression("S2 - S1");
  ASSERT_EQ(testutils::ErrorsOf(boolean), "");
  const ClipperLib::Paths difference =
    ClipperBoolean(ClipperLib::ctDifference, margin, Scaled(Square));
  const double minus = testutils::Area(boolean->GetOutput());
  EXPECT_NEAR(minus, AreaOf(difference), 1e-3 * minus);

  // The one-step filter's OffsetShape step gives the same region, the offset in the shape's
  // place.
  vtkNew<vtkBoolSurf> oneStep;
  oneStep->SetInputData(0, f.Mesh);
  oneStep->SetInputData(1, f.Curves);
  oneStep->SetOperation(4);
  oneStep->SetExpression("S0 - S1");
  oneStep->SetOffsetShape(0);
  oneStep->SetOffsetDistance(0.0625);
  ASSERT_EQ(testutils::ErrorsOf(oneStep), "");
  EXPECT_NEAR(testutils::Area(oneStep->GetOutput()), minus, 1e-12);
  EXPECT_NE(oneStep->GetOutput()->GetFieldData()->GetArray("OffsetStatistics"), nullptr);
  // Turning the step off again gives the plain difference.
  oneStep->SetOffsetShape(-1);
  ASSERT_EQ(testutils::ErrorsOf(oneStep), "");
  const ClipperLib::Paths plainDifference =
    ClipperBoolean(ClipperLib::ctDifference, Scaled(LShape), Scaled(Square));
  EXPECT_NEAR(testutils::Area(oneStep->GetOutput()), AreaOf(plainDifference), 1e-9);
}

TEST(OffsetShapes, ShrinkingAnExpressionAndBands)
{
  Fixture f;
  vtkNew<vtkBoolSurfOffset> offset;
  offset->SetInputData(0, f.Mesh);
  offset->SetInputData(1, f.Curves);
  offset->SetExpression("S0 | S1");
  offset->SetDistance(-0.03125);
  offset->SetKeepInputCurves(false);
  offset->SetOutputShapeId(7);
  ASSERT_EQ(testutils::ErrorsOf(offset), "");
  EXPECT_EQ(offset->GetOutput()->GetNumberOfCells(), 1);
  vtkNew<vtkBoolSurf> boolean;
  boolean->SetInputData(0, f.Mesh);
  boolean->SetInputConnection(1, offset->GetOutputPort());
  boolean->SetOperation(4);
  boolean->SetExpression("S7");
  ASSERT_EQ(testutils::ErrorsOf(boolean), "");
  const ClipperLib::Paths shrunk =
    ClipperOffset(ClipperBoolean(ClipperLib::ctUnion, Scaled(LShape), Scaled(Square)), -0.03125);
  const double area = testutils::Area(boolean->GetOutput());
  EXPECT_NEAR(area, AreaOf(shrunk), 2e-3 * area);

  // Bands mode: a band of half width 0.02 around the square's outline is a square ring.
  offset->SetExpression("");
  offset->SetShapes("1");
  offset->SetMode(vtkBoolSurfOffset::BANDS);
  offset->SetDistance(0.015625);
  ASSERT_EQ(testutils::ErrorsOf(offset), "");
  EXPECT_EQ(offset->GetOutput()->GetNumberOfCells(), 2); // outer and inner boundary
  ASSERT_EQ(testutils::ErrorsOf(boolean), "");
  const ClipperLib::Paths band = ClipperOffset(Scaled(Square), 0.015625, ClipperLib::etClosedLine);
  const double bandArea = testutils::Area(boolean->GetOutput());
  EXPECT_NEAR(bandArea, AreaOf(band), 2e-3 * bandArea);
}

TEST(OffsetShapes, ABooleanResultsBoundaryIsOffsetAsItsRegion)
{
  // The square minus the L is two pieces; its Boundary output (loops without ShapeIds) grown
  // by a margin is Clipper's offset of Clipper's difference.
  Fixture f;
  vtkNew<vtkBoolSurf> difference;
  difference->SetInputData(0, f.Mesh);
  difference->SetInputData(1, f.Curves);
  difference->SetOperation(2);
  difference->SetShapeA(1);
  difference->SetShapeB(0);
  vtkNew<vtkBoolSurfOffset> offset;
  offset->SetInputData(0, f.Mesh);
  offset->SetInputConnection(1, difference->GetOutputPort(1));
  offset->SetDistance(0.03125);
  offset->SetKeepInputCurves(false);
  ASSERT_EQ(testutils::ErrorsOf(offset), "");
  vtkNew<vtkBoolSurf> grown;
  grown->SetInputData(0, f.Mesh);
  grown->SetInputConnection(1, offset->GetOutputPort());
  grown->SetOperation(0);
  grown->SetShapeA(1);
  grown->SetShapeB(1);
  ASSERT_EQ(testutils::ErrorsOf(grown), "");
  const ClipperLib::Paths expected = ClipperOffset(
    ClipperBoolean(ClipperLib::ctDifference, Scaled(Square), Scaled(LShape)), 0.03125);
  const double area = testutils::Area(grown->GetOutput());
  EXPECT_NEAR(area, AreaOf(expected), 1e-3 * area);
}

TEST(OffsetShapes, NestedShapesOffsetAsTheirUnion)
{
  // S1 inside S0: their union's margin is S0's; a margin of S0 minus S1 (a ring) closes the
  // hole once the distance exceeds the hole's half width.
  Fixture f;
  const ControlPolygon outer{
    { { 0.25, 0.25, 0 }, { 0.75, 0.25, 0 }, { 0.75, 0.75, 0 }, { 0.25, 0.75, 0 } }, 0
  };
  const ControlPolygon inner{
    { { 0.4375, 0.4375, 0 }, { 0.5625, 0.4375, 0 }, { 0.5625, 0.5625, 0 }, { 0.4375, 0.5625, 0 } },
    1
  };
  vtkNew<vtkBoolSurfOffset> offset;
  offset->SetInputData(0, f.Mesh);
  offset->SetInputData(1, testutils::ToCurves({ outer, inner }));
  offset->SetKeepInputCurves(false);
  offset->SetOutputShapeId(5);
  vtkNew<vtkBoolSurf> region;
  region->SetInputData(0, f.Mesh);
  region->SetInputConnection(1, offset->GetOutputPort());
  region->SetOperation(4);
  region->SetExpression("S5");
  for (const char* expression : { "S0 | S1", "S0 - S1" })
  {
    for (double d : { 0.03125, 0.09375 })
    {
      offset->SetExpression(expression);
      offset->SetDistance(d);
      ASSERT_EQ(testutils::ErrorsOf(region), "") << expression << " " << d;
      const ClipperLib::Paths shape = std::string(expression) == "S0 | S1"
        ? Scaled(outer)
        : ClipperBoolean(ClipperLib::ctDifference, Scaled(outer), Scaled(inner));
      const double expected = AreaOf(ClipperOffset(shape, d));
      const double area = testutils::Area(region->GetOutput());
      EXPECT_NEAR(area, expected, 1e-3 * expected) << expression << " " << d;
      // One loop, except the ring at the small distance (its hole stays open).
      const bool ring = std::string(expression) == "S0 - S1" && d < 0.0625;
      EXPECT_EQ(offset->GetOutput()->GetNumberOfCells(), ring ? 2 : 1) << expression << " " << d;
    }
  }
}

TEST(OffsetShapes, BadInputGetsNamedErrors)
{
  Fixture f;
  vtkNew<vtkBoolSurfOffset> offset;
  offset->SetInputData(0, f.Mesh);
  offset->SetInputData(1, f.Curves);
  offset->SetDistance(std::nan(""));
  EXPECT_NE(testutils::ErrorsOf(offset).find("not a finite number"), std::string::npos);
  EXPECT_EQ(offset->GetOutput()->GetNumberOfCells(), 0);
  offset->SetDistance(0.05);
  offset->SetShapes("0 7");
  const std::string unknown = testutils::ErrorsOf(offset);
  EXPECT_NE(unknown.find("shape 7, which no curve has"), std::string::npos) << unknown;
  offset->SetShapes("x");
  EXPECT_NE(testutils::ErrorsOf(offset).find("'x' is not a ShapeId"), std::string::npos);
  offset->SetShapes("1");
  offset->SetDistance(-0.25); // the square is 0.1875 wide
  const std::string vanished = testutils::ErrorsOf(offset);
  EXPECT_NE(vanished.find("leaves nothing"), std::string::npos) << vanished;
  offset->SetShapes("");
  offset->SetDistance(0.05);
  offset->SetExpression("S0 &");
  EXPECT_NE(testutils::ErrorsOf(offset).find("Expression 'S0 &'"), std::string::npos);
  vtkNew<vtkBoolSurf> oneStep;
  oneStep->SetInputData(0, f.Mesh);
  oneStep->SetInputData(1, f.Curves);
  oneStep->SetOffsetShape(4);
  oneStep->SetOffsetDistance(0.05);
  const std::string step = testutils::ErrorsOf(oneStep);
  EXPECT_NE(step.find("OffsetShape: Shapes names shape 4"), std::string::npos) << step;
}

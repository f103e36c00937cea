// Booleans on curved surfaces (sphere, torus), consistency, variadic operations, named errors.
#include "FilterTestUtils.h"
#include "vtkBoolSurf.h"
#include "vtkBoolSurfArrangement.h"
#include "vtkBoolSurfBoolean.h"
#include "vtkBoolSurfLabeling.h"
#include "vtkBoolSurfSurfaceCurves.h"
#include "vtkBoolSurfTraceCurves.h"

#include <vtkCommand.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <random>
#include <string>

using testutils::ControlPolygon;

using testutils::MessageCatcher;

namespace
{
constexpr double Pi = 3.14159265358979323846;

struct Caught
{
  vtkNew<MessageCatcher> Catcher;
  explicit Caught(vtkAlgorithm* a)
  {
    a->AddObserver(vtkCommand::ErrorEvent, this->Catcher);
    a->AddObserver(vtkCommand::WarningEvent, this->Catcher);
  }
};

std::array<double, 3> OnSphere(double lon, double lat)
{
  return { std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat) };
}

// A torus meridian (circle around the tube at angle u), as 8 control points on the mesh
// torus's vertex ring; v increasing, or decreasing when reversed.
ControlPolygon Meridian(double R, double r, int nu, int nv, int column, bool reversed, int shape)
{
  ControlPolygon c;
  c.ShapeId = shape;
  const double u = 2 * Pi * column / nu;
  for (int k = 0; k < 8; ++k)
  {
    const int j = (reversed ? 8 - k : k) % 8 * nv / 8;
    const double v = 2 * Pi * j / nv;
    c.Points.push_back({ (R + r * std::cos(v)) * std::cos(u),
      (R + r * std::cos(v)) * std::sin(u),
      r * std::sin(v) });
  }
  return c;
}

double RunArea(vtkBoolSurf* f)
{
  f->Update();
  return testutils::Area(f->GetOutput());
}
} // namespace

TEST(SurfaceBooleans, SphereInclusionExclusionIsExact)
{
  auto sphere = testutils::ToPolyData(boolsurf::MakeIcosphere(4));
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> lon(-0.6, 0.6), lat(-0.6, 0.6);
  for (int trial = 0; trial < 4; ++trial)
  {
    ControlPolygon a, b;
    a.ShapeId = 0;
    b.ShapeId = 1;
    // Convex-ish quads around two nearby centres (counter-clockwise seen from outside).
    const double ca = lon(rng), la = lat(rng) * 0.5, cb = ca + 0.3, lb = la + 0.1;
    for (int k = 0; k < 4; ++k)
    {
      const double t = Pi / 2 * k + 0.3 * trial;
      a.Points.push_back(OnSphere(ca + 0.4 * std::cos(t), la + 0.4 * std::sin(t)));
      b.Points.push_back(OnSphere(cb + 0.35 * std::cos(t), lb + 0.35 * std::sin(t)));
    }
    vtkNew<vtkBoolSurf> f;
    f->SetInputData(0, sphere);
    f->SetInputData(1, testutils::ToCurves({ a, b }));
    f->SetOperationToExpression();
    f->SetExpression("S0");
    const double areaA = RunArea(f);
    f->SetExpression("S1");
    const double areaB = RunArea(f);
    f->SetOperation(0);
    const double areaUnion = RunArea(f);
    f->SetOperation(1);
    const double areaIntersection = RunArea(f);
    EXPECT_GT(areaIntersection, 0.0) << "trial " << trial << ": the quads should overlap";
    EXPECT_NEAR(areaUnion + areaIntersection, areaA + areaB, 1e-12 * (areaA + areaB));
    EXPECT_LT(areaUnion, areaA + areaB);
  }
}

TEST(SurfaceBooleans, GeodesicTriangleAreaApproachesAngleExcess)
{
  // The octant triangle: three right angles, excess pi/2 on the unit sphere. On coarse
  // icospheres the polyhedral shortest paths wander around the great circles (which way, and
  // so the sign of the error, depends on the triangulation: a coarse level can land close by
  // chance), so the finest error is compared with the worse of the two coarsest rather than
  // level by level; at the finest it must be small, also relative to the inscribed mesh's own
  // area (which removes its shortfall from 4 pi).
  ControlPolygon octant;
  octant.Points = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
  std::vector<double> errors;
  double relative = 1;
  for (int level = 2; level <= 6; ++level)
  {
    auto sphere = testutils::ToPolyData(boolsurf::MakeIcosphere(level));
    vtkNew<vtkBoolSurf> f;
    f->SetInputData(0, sphere);
    f->SetInputData(1, testutils::ToCurves({ octant }));
    f->SetOperationToExpression();
    f->SetExpression("S0");
    const double area = RunArea(f);
    errors.push_back(std::abs(area - Pi / 2));
    relative = std::abs(area / testutils::Area(sphere) - 0.125);
  }
  EXPECT_LT(errors.back(), 0.5 * std::max(errors[0], errors[1]));
  EXPECT_LT(errors.back(), 0.01); // well under 1% of pi/2 at 81920 triangles
  EXPECT_LT(relative, 1e-3);
}

TEST(SurfaceBooleans, TorusMeridianIsInconsistentAndRefused)
{
  const double R = 2, r = 0.7;
  const int nu = 48, nv = 24;
  auto torus = testutils::ToPolyData(boolsurf::MakeTorus(R, r, nu, nv));
  ControlPolygon blob;
  blob.ShapeId = 1;
  for (int k = 0; k < 4; ++k) // a small loop on the outer equator, around u = pi
  {
    const double u = Pi + 0.2 * std::cos(Pi / 2 * k), v = 0.4 * std::sin(Pi / 2 * k);
    blob.Points.push_back({ (R + r * std::cos(v)) * std::cos(u),
      (R + r * std::cos(v)) * std::sin(u),
      r * std::sin(v) });
  }
  vtkNew<vtkBoolSurfTraceCurves> trace;
  trace->SetInputData(0, torus);
  trace->SetInputData(1, testutils::ToCurves({ Meridian(R, r, nu, nv, 0, false, 0), blob }));
  vtkNew<vtkBoolSurfArrangement> arrangement;
  arrangement->SetInputData(0, torus);
  arrangement->SetInputConnection(1, trace->GetOutputPort());
  vtkNew<vtkBoolSurfLabeling> labeling;
  labeling->SetInputConnection(arrangement->GetOutputPort(0));
  Caught labelMessages(labeling);
  labeling->Update();
  auto* consistent =
    vtkIntArray::SafeDownCast(labeling->GetOutput()->GetFieldData()->GetArray("ShapeConsistent"));
  ASSERT_NE(consistent, nullptr);
  EXPECT_EQ(consistent->GetValue(0), 0);
  EXPECT_EQ(consistent->GetValue(1), 1); // consistent shapes are labeled all the same
  EXPECT_NE(labelMessages.Catcher->Warnings.find("shape S0 is inconsistent"), std::string::npos)
    << labelMessages.Catcher->Warnings;

  vtkNew<vtkBoolSurfBoolean> boolean;
  boolean->SetInputConnection(labeling->GetOutputPort());
  Caught booleanMessages(boolean);
  boolean->SetOperationToUnion();
  boolean->Update();
  EXPECT_EQ(boolean->GetOutput()->GetNumberOfCells(), 0);
  EXPECT_NE(booleanMessages.Catcher->Errors.find("inconsistent shape(s)"), std::string::npos);
  EXPECT_NE(booleanMessages.Catcher->Errors.find("S0"), std::string::npos);
  // The consistent shape alone is answered.
  boolean->SetOperationToExpression();
  boolean->SetExpression("S1");
  boolean->Update();
  EXPECT_GT(boolean->GetOutput()->GetNumberOfCells(), 0);
}

TEST(SurfaceBooleans, TwoOppositeMeridiansBoundABand)
{
  const double R = 2, r = 0.7;
  const int nu = 48, nv = 24;
  auto torus = testutils::ToPolyData(boolsurf::MakeTorus(R, r, nu, nv));
  vtkNew<vtkBoolSurf> f;
  f->SetInputData(0, torus);
  f->SetInputData(1,
    testutils::ToCurves(
      { Meridian(R, r, nu, nv, 0, false, 0), Meridian(R, r, nu, nv, nu / 4, true, 0) }));
  f->SetOperationToExpression();
  f->SetExpression("S0");
  Caught messages(f);
  const double band = RunArea(f);
  EXPECT_EQ(messages.Catcher->Errors, "");
  // The meridian at u = 0 (v increasing) has u < 0 on its left, the reversed one at u = pi/2
  // has u > pi/2: the band labeled 1 is u in (pi/2, 2pi), three quarters of the torus.
  const double total = testutils::Area(torus);
  EXPECT_NEAR(band / total, 0.75, 0.01);
  // Every region triangle's cell has label 1 for S0 (labels are per cell: CellLabels row
  // ArrangementCell).
  auto* labels = f->GetOutput()->GetFieldData()->GetArray("CellLabels");
  auto* cellOf = f->GetOutput()->GetCellData()->GetArray("ArrangementCell");
  ASSERT_TRUE(labels && cellOf);
  EXPECT_EQ(f->GetOutput()->GetCellData()->GetArray("Labels"), nullptr);
  for (vtkIdType t = 0; t < f->GetOutput()->GetNumberOfCells(); ++t)
  {
    ASSERT_EQ(labels->GetComponent(static_cast<vtkIdType>(cellOf->GetComponent(t, 0)), 0), 1);
  }
}

TEST(SurfaceBooleans, VariadicOperationsEqualTheirExpressions)
{
  auto mesh = testutils::ToPolyData(boolsurf::MakeFlatSquare(40, 1.0, 0.25, 3));
  std::vector<ControlPolygon> shapes;
  for (int s = 0; s < 4; ++s)
  {
    ControlPolygon c;
    c.ShapeId = s;
    const double cx = 0.35 + 0.1 * (s % 2) + 0.05 * s, cy = 0.35 + 0.12 * (s / 2);
    for (int k = 0; k < 5; ++k)
    {
      c.Points.push_back(
        { cx + 0.2 * std::cos(2 * Pi * k / 5), cy + 0.2 * std::sin(2 * Pi * k / 5), 0 });
    }
    shapes.push_back(c);
  }
  vtkNew<vtkBoolSurf> f;
  f->SetInputData(0, mesh);
  f->SetInputData(1, testutils::ToCurves(shapes));
  f->SetShapeA(-1);
  f->SetShapeB(-1);
  const char* expressions[] = {
    "S0 | S1 | S2 | S3", "S0 & S1 & S2 & S3", "S0 - (S1 | S2 | S3)", "S0 ^ S1 ^ S2 ^ S3"
  };
  for (int op = 0; op < 4; ++op)
  {
    f->SetOperation(op);
    const double variadic = RunArea(f);
    f->SetOperationToExpression();
    f->SetExpression(expressions[op]);
    EXPECT_NEAR(variadic, RunArea(f), 1e-12) << expressions[op];
    EXPECT_GT(variadic, 0.0) << expressions[op];
  }
}

TEST(SurfaceBooleans, BadOperationsAreNamedErrors)
{
  auto mesh = testutils::ToPolyData(boolsurf::MakeFlatSquare(10));
  ControlPolygon a;
  a.Points = { { 0.2, 0.2, 0 }, { 0.6, 0.2, 0 }, { 0.4, 0.6, 0 } };
  vtkNew<vtkBoolSurf> f;
  f->SetInputData(0, mesh);
  f->SetInputData(1, testutils::ToCurves({ a }));
  Caught messages(f);
  f->SetOperationToExpression();
  f->SetExpression("S0 & (S1");
  f->Update();
  EXPECT_NE(messages.Catcher->Errors.find("unknown shape S1"), std::string::npos)
    << messages.Catcher->Errors;
  messages.Catcher->Errors.clear();
  f->SetExpression("S0 &");
  f->Update();
  EXPECT_NE(messages.Catcher->Errors.find("unexpected end"), std::string::npos);
  messages.Catcher->Errors.clear();
  f->SetOperationToUnion();
  f->SetShapeB(3);
  f->Update();
  EXPECT_NE(messages.Catcher->Errors.find("ShapeB = 3 is not a shape"), std::string::npos)
    << messages.Catcher->Errors;
  EXPECT_EQ(f->GetOutput()->GetNumberOfCells(), 0);
}

// The one-step filter reuses its labeled arrangement while only the Boolean properties change;
// any change of the curves (new data, points moved in place) or of a tracing property must
// recompute it.
TEST(SurfaceBooleans, OneStepFilterNeverServesAStaleArrangement)
{
  auto mesh = testutils::ToPolyData(boolsurf::MakeFlatSquare(20, 1.0, 0.2, 8));
  ControlPolygon a{
    { { 0.2, 0.2, 0 }, { 0.6, 0.2, 0 }, { 0.6, 0.6, 0 }, { 0.2, 0.6, 0 } }, 0, true
  };
  ControlPolygon b{
    { { 0.4, 0.4, 0 }, { 0.8, 0.4, 0 }, { 0.8, 0.8, 0 }, { 0.4, 0.8, 0 } }, 1, true
  };
  vtkNew<vtkBoolSurf> f;
  f->SetInputData(0, mesh);
  auto curves = testutils::ToCurves({ a, b });
  f->SetInputData(1, curves);
  f->SetOperationToUnion();
  EXPECT_NEAR(RunArea(f), 0.28, 1e-12);
  f->SetOperationToIntersection(); // labels reused
  EXPECT_NEAR(RunArea(f), 0.04, 1e-12);
  // Move square B in place: the intersection shrinks to [0.5,0.6]^2.
  for (vtkIdType p = 4; p < 8; ++p)
  {
    double x[3];
    curves->GetPoint(p, x);
    curves->GetPoints()->SetPoint(p, x[0] + 0.1, x[1] + 0.1, 0);
  }
  curves->GetPoints()->Modified();
  EXPECT_NEAR(RunArea(f), 0.01, 1e-12);
  // New curves object.
  ControlPolygon c{
    { { 0.1, 0.1, 0 }, { 0.3, 0.1, 0 }, { 0.3, 0.3, 0 }, { 0.1, 0.3, 0 } }, 1, true
  };
  f->SetInputData(1, testutils::ToCurves({ a, c }));
  EXPECT_NEAR(RunArea(f), 0.01, 1e-12); // [0.2,0.3]^2
  // A tracing property: Bezier resolution changes the traced curve.
  ControlPolygon bezier{ { { 0.1, 0.5, 0 },
                           { 0.3, 0.9, 0 },
                           { 0.7, 0.9, 0 },
                           { 0.9, 0.5, 0 },
                           { 0.7, 0.1, 0 },
                           { 0.3, 0.1, 0 } },
    0,
    true,
    1 };
  f->SetInputData(1, testutils::ToCurves({ bezier }));
  f->SetOperationToExpression();
  f->SetExpression("S0");
  f->SetResolution(1);
  const double coarse = RunArea(f);
  f->SetResolution(6);
  const double fine = RunArea(f);
  EXPECT_GT(std::abs(fine - coarse), 1e-6);
}

TEST(SurfaceBooleans, TracedCurvesInputGivesTheControlCurvesAnswer)
{
  // Surface Curves has two outputs, Control Curves and Traced Curves; BoolSurf (and Trace
  // Surface Curves) read traced curves as the control curves they were traced from, so either
  // output gives the same region, bit for bit: a Bezier spline and a polygon on a sphere.
  auto sphere = testutils::ToPolyData(boolsurf::MakeIcosphere(3));
  vtkNew<vtkBoolSurfSurfaceCurves> drawing;
  drawing->SetInputData(sphere);
  const double points[][3] = { { 0.6, 0, 0.8 },
    { 0.4, 0.5, 0.77 },
    { -0.1, 0.6, 0.79 },
    { -0.5, 0.2, 0.84 },
    { -0.4, -0.5, 0.77 },
    { 0.2, -0.6, 0.77 },
    { 0.8, 0.3, 0.5 },
    { 0.3, 0.8, 0.5 },
    { 0.0, 0.3, 0.95 } };
  drawing->SetNumberOfPoints(9);
  for (int i = 0; i < 9; ++i)
  {
    drawing->SetPoint(i, points[i][0], points[i][1], points[i][2]);
  }
  drawing->SetNumberOfCurveSizes(2);
  drawing->SetCurveSize(0, 6);
  drawing->SetCurveSize(1, 3);
  drawing->SetNumberOfShapeIds(2);
  drawing->SetShapeId(0, 0);
  drawing->SetShapeId(1, 1);
  drawing->SetNumberOfCurveTypes(2);
  drawing->SetCurveType(0, 1);
  drawing->SetCurveType(1, 0);
  for (int operation = 0; operation < 4; ++operation)
  {
    SCOPED_TRACE("operation " + std::to_string(operation));
    vtkNew<vtkBoolSurf> fromControl, fromTraced, fromTrace;
    vtkNew<vtkBoolSurfTraceCurves> trace;
    trace->SetInputData(0, sphere);
    trace->SetInputConnection(1, drawing->GetOutputPort(0));
    fromControl->SetInputConnection(1, drawing->GetOutputPort(0));
    fromTraced->SetInputConnection(1, drawing->GetOutputPort(1));
    fromTrace->SetInputConnection(1, trace->GetOutputPort(0));
    for (vtkBoolSurf* f : { fromControl.Get(), fromTraced.Get(), fromTrace.Get() })
    {
      f->SetInputData(0, sphere);
      f->SetOperation(operation);
      ASSERT_EQ(testutils::ErrorsOf(f), "");
    }
    const double area = testutils::Area(fromControl->GetOutput());
    ASSERT_GT(area, 0.01);
    EXPECT_EQ(testutils::Area(fromTraced->GetOutput()), area);
    EXPECT_EQ(testutils::Area(fromTrace->GetOutput()), area);
    EXPECT_EQ(
      fromTraced->GetOutput()->GetNumberOfCells(), fromControl->GetOutput()->GetNumberOfCells());
  }
}

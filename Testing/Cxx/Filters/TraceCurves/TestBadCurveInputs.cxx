// Bad curve inputs and Boolean requests get a message naming the problem, the curve and the
// value as given: never a wrapped or clamped value, never a read past an array's end.
#include "FilterTestUtils.h"
#include "vtkBoolSurf.h"
#include "vtkBoolSurfArrangement.h"
#include "vtkBoolSurfBoolean.h"
#include "vtkBoolSurfLabeling.h"
#include "vtkBoolSurfTraceCurves.h"

#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkTriangleFilter.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace
{
using testutils::ControlPolygon;

using testutils::ErrorsOf;

struct Scene
{
  vtkSmartPointer<vtkPolyData> Mesh =
    testutils::ToPolyData(boolsurf::MakeFlatSquare(8, 1.0, 0.0, 1));
  vtkSmartPointer<vtkPolyData> Curves = testutils::ToCurves(
    { ControlPolygon{ { { 0.2, 0.2, 0 }, { 0.8, 0.25, 0 }, { 0.5, 0.8, 0 } }, 0, true } });

  std::string Trace()
  {
    vtkNew<vtkBoolSurfTraceCurves> trace;
    trace->SetInputData(0, this->Mesh);
    trace->SetInputData(1, this->Curves);
    return ErrorsOf(trace);
  }

  // Exact control points: triangle 0 for every point, with the given barycentrics.
  void SetExact(const std::vector<std::array<double, 2>>& uv)
  {
    vtkNew<vtkIdTypeArray> tid;
    tid->SetName("TriangleId");
    vtkNew<vtkDoubleArray> bary;
    bary->SetName("Barycentric");
    bary->SetNumberOfComponents(2);
    for (const auto& p : uv)
    {
      tid->InsertNextValue(0);
      bary->InsertNextTuple(p.data());
    }
    this->Curves->GetPointData()->AddArray(tid);
    this->Curves->GetPointData()->AddArray(bary);
  }
};
} // namespace

TEST(BadCurveInputs, BarycentricsOutsideTheTriangleAreRefused)
{
  for (const std::array<double, 2>& bad :
    { std::array<double, 2>{ 0.8, 0.7 }, { 3.0, 3.0 }, { -0.001, 0.5 } })
  {
    Scene s;
    s.SetExact({ { 0.2, 0.2 }, bad, { 0.1, 0.6 } });
    const std::string errors = s.Trace();
    EXPECT_NE(errors.find("curve 0, control point 1: barycentric coordinates"), std::string::npos)
      << errors;
    EXPECT_NE(errors.find("lie outside triangle 0"), std::string::npos) << errors;
  }
  // On the triangle's edge up to rounding is inside.
  Scene s;
  s.SetExact({ { 0.2, 0.2 }, { 1.3e-16, 0.5 }, { 0.5, 0.5 + 1e-13 } });
  EXPECT_EQ(s.Trace(), "");
}

TEST(BadCurveInputs, ShapeIdsAreCheckedAsGiven)
{
  for (double bad : { 1e12, -1.0, 2.5, std::numeric_limits<double>::quiet_NaN() })
  {
    Scene s;
    vtkNew<vtkDoubleArray> shape;
    shape->SetName("ShapeId");
    shape->InsertNextValue(bad);
    s.Curves->GetCellData()->RemoveArray("ShapeId");
    s.Curves->GetCellData()->AddArray(shape);
    const std::string errors = s.Trace();
    char given[32];
    std::snprintf(given, sizeof(given), "%.17g", bad);
    EXPECT_NE(errors.find(std::string("curve 0: ShapeId ") + given + " is not an integer"),
      std::string::npos)
      << errors;
  }
}

TEST(BadCurveInputs, ShortArraysAreNamedNotReadPastTheirEnd)
{
  Scene s;
  // Two curves, one ShapeId value.
  s.Curves = testutils::ToCurves(
    { ControlPolygon{ { { 0.2, 0.2, 0 }, { 0.8, 0.25, 0 }, { 0.5, 0.8, 0 } }, 0, true },
      ControlPolygon{ { { 0.3, 0.3, 0 }, { 0.7, 0.3, 0 }, { 0.5, 0.6, 0 } }, 1, true } });
  s.Curves->GetCellData()->GetArray("ShapeId")->SetNumberOfTuples(1);
  std::string errors = s.Trace();
  EXPECT_NE(errors.find("cell data ShapeId has 1 value(s) for 2 cells"), std::string::npos)
    << errors;

  Scene t;
  t.SetExact({ { 0.2, 0.2 }, { 0.3, 0.3 } }); // 2 tuples for 3 points
  errors = t.Trace();
  EXPECT_NE(errors.find("point data TriangleId has 2 tuple(s) for 3 points"), std::string::npos)
    << errors;
}

TEST(BadCurveInputs, ShapeBelowMinusOneIsNamedNotClamped)
{
  Scene s;
  vtkNew<vtkBoolSurf> one;
  one->SetInputData(0, s.Mesh);
  one->SetInputData(1, s.Curves);
  one->SetShapeA(-5);
  EXPECT_EQ(one->GetShapeA(), -5);
  const std::string errors = ErrorsOf(one);
  EXPECT_NE(errors.find("ShapeA = -5 is not a shape of the input"), std::string::npos) << errors;
  EXPECT_EQ(one->GetOutput()->GetNumberOfCells(), 0);
}

// Every stage filter empties its outputs when an update fails, so nothing downstream shows the
// previous result as if it were this one.
TEST(BadCurveInputs, FailedStageUpdatesLeaveEmptyOutputs)
{
  Scene s;
  vtkNew<vtkBoolSurfTraceCurves> trace;
  trace->SetInputData(0, s.Mesh);
  trace->SetInputData(1, s.Curves);
  vtkNew<vtkBoolSurfArrangement> arrangement;
  arrangement->SetInputData(0, s.Mesh);
  arrangement->SetInputConnection(1, trace->GetOutputPort());
  vtkNew<vtkBoolSurfLabeling> labeling;
  labeling->SetInputConnection(arrangement->GetOutputPort(0));
  vtkNew<vtkBoolSurfBoolean> boolean;
  boolean->SetInputConnection(labeling->GetOutputPort());
  boolean->SetOperationToExpression();
  boolean->SetExpression("S0");
  boolean->Update();
  ASSERT_GT(boolean->GetOutput()->GetNumberOfCells(), 0);
  ASSERT_GT(arrangement->GetOutput()->GetNumberOfCells(), 0);

  // A malformed expression: the Boolean's outputs are emptied.
  boolean->SetExpression("S0 &");
  EXPECT_NE(ErrorsOf(boolean).find("position"), std::string::npos);
  EXPECT_EQ(boolean->GetOutput(0)->GetNumberOfCells(), 0);
  EXPECT_EQ(boolean->GetOutput(1)->GetNumberOfCells(), 0);
  EXPECT_EQ(boolean->GetOutput(2)->GetNumberOfCells(), 0);
  EXPECT_EQ(boolean->GetOutput(3)->GetNumberOfCells(), 0);

  // The one-step filter too, all four outputs.
  vtkNew<vtkBoolSurf> one;
  one->SetInputData(0, s.Mesh);
  one->SetInputData(1, s.Curves);
  one->SetOperationToExpression();
  one->SetExpression("S0");
  one->Update();
  ASSERT_GT(one->GetOutput(0)->GetNumberOfCells(), 0);
  ASSERT_GT(one->GetOutput(2)->GetNumberOfCells(), 0);
  one->SetExpression("S0 &");
  EXPECT_NE(ErrorsOf(one).find("position"), std::string::npos);
  for (int port = 0; port < 4; ++port)
  {
    EXPECT_EQ(one->GetOutput(port)->GetNumberOfCells(), 0) << "port " << port;
  }

  // Bad curves: tracing fails, and every stage below it ends empty.
  boolean->SetExpression("S0");
  s.SetExact({ { 0.2, 0.2 }, { 3.0, 3.0 }, { 0.1, 0.6 } });
  s.Curves->Modified();
  for (vtkAlgorithm* f : std::initializer_list<vtkAlgorithm*>{ trace, arrangement, labeling })
  {
    ErrorsOf(f);
  }
  ErrorsOf(boolean);
  EXPECT_EQ(trace->GetOutput()->GetNumberOfCells(), 0);
  EXPECT_EQ(arrangement->GetOutput(0)->GetNumberOfCells(), 0);
  EXPECT_EQ(arrangement->GetOutput(1)->GetNumberOfCells(), 0);
  EXPECT_EQ(labeling->GetOutput()->GetNumberOfCells(), 0);
  EXPECT_EQ(boolean->GetOutput(0)->GetNumberOfCells(), 0);
}

// A control point given exactly a rounding error inside a triangle (u or v of 1e-16) is on the
// edge for all purposes: the polygon bounds its area (shoelace), instead of a zero-length
// excursion across the edge making the shape look inconsistent.
TEST(BadCurveInputs, ControlPointsWithinRoundingOfAnEdgeBoundTheirPolygon)
{
  // A 10 x 10 plane cut into triangles by vtkTriangleFilter, on [-0.5, 0.5]^2.
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(10, 10);
  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputConnection(plane->GetOutputPort());
  triangulate->Update();
  vtkPolyData* mesh = triangulate->GetOutput();
  // Exact surface point of (x, y) on the flat mesh: the triangle containing it.
  auto locate = [&](double x, double y, vtkIdType& triangle, double& u, double& v)
  {
    double p[3][3];
    for (vtkIdType t = 0; t < mesh->GetNumberOfCells(); ++t)
    {
      vtkIdType n;
      const vtkIdType* ids;
      mesh->GetCellPoints(t, n, ids);
      for (int k = 0; k < 3; ++k)
        mesh->GetPoint(ids[k], p[k]);
      const double a = p[1][0] - p[0][0], b = p[2][0] - p[0][0];
      const double c = p[1][1] - p[0][1], d = p[2][1] - p[0][1];
      const double det = a * d - b * c;
      u = ((x - p[0][0]) * d - b * (y - p[0][1])) / det;
      v = (a * (y - p[0][1]) - c * (x - p[0][0])) / det;
      if (u >= 0 && v >= 0 && u + v <= 1)
      {
        triangle = t;
        return;
      }
    }
    triangle = -1;
  };
  int checked = 0;
  for (vtkIdType t = 0; t < mesh->GetNumberOfCells(); t += 7)
  {
    for (double eps : { 3e-17, 1.3e-16, 1e-15 })
    {
      for (int side = 0; side < 2; ++side)
      {
        const double u0 = side ? 0.4 : eps, v0 = side ? eps : 0.4;
        vtkIdType n;
        const vtkIdType* ids;
        mesh->GetCellPoints(t, n, ids);
        double p[3][3];
        for (int k = 0; k < 3; ++k)
          mesh->GetPoint(ids[k], p[k]);
        const double x = p[0][0] + u0 * (p[1][0] - p[0][0]) + v0 * (p[2][0] - p[0][0]);
        const double y = p[0][1] + u0 * (p[1][1] - p[0][1]) + v0 * (p[2][1] - p[0][1]);
        const double polygon[4][2] = {
          { x, y }, { x + 0.2, y + 0.05 }, { x + 0.1, y + 0.25 }, { x - 0.15, y + 0.1 }
        };
        if (x - 0.15 < -0.49 || x + 0.2 > 0.49 || y + 0.25 > 0.49)
          continue;
        vtkNew<vtkPoints> points;
        vtkNew<vtkIdTypeArray> tid;
        tid->SetName("TriangleId");
        vtkNew<vtkDoubleArray> bary;
        bary->SetName("Barycentric");
        bary->SetNumberOfComponents(2);
        double area = 0;
        for (int i = 0; i < 4; ++i)
        {
          vtkIdType triangle = t;
          double u = u0, v = v0;
          if (i > 0)
            locate(polygon[i][0], polygon[i][1], triangle, u, v);
          ASSERT_GE(triangle, 0);
          points->InsertNextPoint(polygon[i][0], polygon[i][1], 0);
          tid->InsertNextValue(triangle);
          bary->InsertNextTuple2(u, v);
          const int j = (i + 1) % 4;
          area += 0.5 * (polygon[i][0] * polygon[j][1] - polygon[j][0] * polygon[i][1]);
        }
        vtkNew<vtkPolyData> curves;
        curves->SetPoints(points);
        vtkNew<vtkCellArray> polys;
        polys->InsertNextCell({ 0, 1, 2, 3 });
        curves->SetPolys(polys);
        curves->GetPointData()->AddArray(tid);
        curves->GetPointData()->AddArray(bary);
        vtkNew<vtkBoolSurf> one;
        one->SetInputData(0, mesh);
        one->SetInputData(1, curves);
        one->SetOperationToExpression();
        one->SetExpression("S0");
        EXPECT_EQ(ErrorsOf(one), "") << "triangle " << t << " eps " << eps << " side " << side;
        EXPECT_NEAR(testutils::Area(one->GetOutput()), area, 1e-12)
          << "triangle " << t << " eps " << eps << " side " << side;
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 20);
}

// Control points given by coordinates are projected onto the surface: one far from it (beyond
// the projection tolerance) or with NaN coordinates is named with its curve and point, and one
// just off the surface is projected and traced.
TEST(BadCurveInputs, CoordinatesFarFromTheSurfaceOrNotFiniteAreNamed)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const auto& [point, expected] : { std::pair<std::array<double, 3>, const char*>{
                                           { 0.8, 0.25, 0.5 }, "curve 0, control point 1 is 0.5" },
         { { 0.8, nan, 0.0 }, "curve 0, control point 1: NaN or infinite coordinates" } })
  {
    Scene s;
    s.Curves->GetPoints()->SetPoint(1, point.data());
    const std::string errors = s.Trace();
    EXPECT_NE(errors.find(expected), std::string::npos) << errors;
  }
  Scene s;
  s.Curves->GetPoints()->SetPoint(1, 0.8, 0.25, 1e-3); // 0.07 % of the diagonal above it
  EXPECT_EQ(s.Trace(), "");
}

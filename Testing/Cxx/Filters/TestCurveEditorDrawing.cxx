// The curve editor's drawing (Plugin/pqBoolSurfDrawing): the Surface Curves source's property
// defaults read back, the properties written complete, and the edits a user makes (insert
// after the selected point, a first click starting a curve, deleting a curve's last point).
#include "pqBoolSurfDrawing.h"

#include "FilterTestUtils.h"
#include "Mesh/TriangleMesh.h"
#include "vtkBoolSurfSurfaceCurves.h"

#include <vtkDataArray.h>
#include <vtkPointData.h>

#include <array>
#include <cmath>
#include <vector>

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

TEST(CurveEditorDrawing, MarkersOnTheFarSideOfAClosedSurfaceAreHidden)
{
  // Control points on a sphere, with the facet normals Surface Curves gives (SurfaceNormal):
  // seen from +z, the points of the upper half show, those of the lower half do not; a point
  // whose normal is unknown shows.
  auto sphere = testutils::ToPolyData(boolsurf::MakeIcosphere(3));
  vtkNew<vtkBoolSurfSurfaceCurves> source;
  source->SetInputData(sphere);
  const double points[][3] = { { 0.3, 0.1, 0.95 },
    { -0.2, 0.4, 0.9 },
    { 0.5, 0.5, -0.7 },
    { -0.6, 0.2, -0.77 },
    { 0.9, 0.1, 0.4 },
    { 0.1, 0.9, -0.4 } };
  source->SetNumberOfPoints(6);
  for (int i = 0; i < 6; ++i)
  {
    source->SetPoint(i, points[i][0], points[i][1], points[i][2]);
  }
  source->Update();
  vtkPolyData* out = source->GetOutput();
  vtkDataArray* normals = out->GetPointData()->GetArray("SurfaceNormal");
  ASSERT_NE(normals, nullptr);
  ASSERT_EQ(normals->GetNumberOfTuples(), 6);
  const std::array<double, 3> eye{ { 0, 0, 5 } };
  for (vtkIdType i = 0; i < 6; ++i)
  {
    pqBoolSurfDrawing::Point p;
    out->GetPoint(i, p.Position.data());
    normals->GetTuple(i, p.Normal.data());
    // An outward unit normal of the facet the point is on.
    EXPECT_NEAR(std::hypot(p.Normal[0], p.Normal[1], p.Normal[2]), 1, 1e-12);
    EXPECT_GT(
      p.Normal[0] * p.Position[0] + p.Normal[1] * p.Position[1] + p.Normal[2] * p.Position[2], 0.9);
    // Visible from (0, 0, 5) exactly when the facet faces it: the tangent plane test.
    const bool upper = points[i][2] > 0.3;
    EXPECT_EQ(pqBoolSurfDrawing::FacesEye(p, eye), upper) << "point " << i;
    p.Normal = { 0, 0, 0 };
    EXPECT_TRUE(pqBoolSurfDrawing::FacesEye(p, eye)) << "unknown normal, point " << i;
  }

  // A surface with a boundary may be seen from its back: no normals, every marker shows.
  auto square = testutils::ToPolyData(boolsurf::MakeFlatSquare(8));
  vtkNew<vtkBoolSurfSurfaceCurves> open;
  open->SetInputData(square);
  open->SetNumberOfPoints(2);
  open->SetPoint(0, 0.2, 0.3, 0);
  open->SetPoint(1, 0.7, 0.6, 0);
  open->Update();
  vtkDataArray* none = open->GetOutput()->GetPointData()->GetArray("SurfaceNormal");
  ASSERT_NE(none, nullptr);
  for (vtkIdType i = 0; i < 2; ++i)
  {
    pqBoolSurfDrawing::Point p;
    open->GetOutput()->GetPoint(i, p.Position.data());
    none->GetTuple(i, p.Normal.data());
    EXPECT_TRUE(pqBoolSurfDrawing::FacesEye(p, { { 0, 0, -5 } })) << "seen from below, point " << i;
  }
}

// Points placed by position are snapped in 3D: on the upright facets of a prism (triangles
// with no extent in a coordinate plane's normal direction) the snapped point is the point
// given, and its triangle and weights give it back.
TEST(CurveEditorDrawing, SnapsPointsOnUprightTriangles)
{
  const boolsurf::MeshData prism = boolsurf::MakeOpenCylinder(1.0, 3.0, 48, 16);
  vtkSmartPointer<vtkPolyData> surface = testutils::ToPolyData(prism);
  vtkNew<vtkBoolSurfSurfaceCurves> drawing;
  drawing->SetInputData(surface);
  const int triangles[4] = { 5, 200, 777, 1500 };
  const double weights[4][2] = { { 0.2, 0.3 }, { 0.6, 0.1 }, { 0.25, 0.25 }, { 0.05, 0.9 } };
  std::vector<std::array<double, 3>> given;
  drawing->SetNumberOfPoints(4);
  for (int i = 0; i < 4; ++i)
  {
    const boolsurf::Triangle& t = prism.Triangles[triangles[i]];
    std::array<double, 3> x{};
    const double w[3] = { 1 - weights[i][0] - weights[i][1], weights[i][0], weights[i][1] };
    for (int k = 0; k < 3; ++k)
    {
      x[0] += w[k] * prism.Positions[t[k]].x;
      x[1] += w[k] * prism.Positions[t[k]].y;
      x[2] += w[k] * prism.Positions[t[k]].z;
    }
    given.push_back(x);
    drawing->SetPoint(i, x[0], x[1], x[2]);
  }
  drawing->SetNumberOfCurveSizes(1);
  drawing->SetCurveSize(0, 4);
  drawing->Update();
  ASSERT_EQ(testutils::ErrorsOf(drawing), "");
  vtkPolyData* out = drawing->GetOutput(0);
  ASSERT_EQ(out->GetNumberOfPoints(), 4);
  vtkDataArray* ids = out->GetPointData()->GetArray("TriangleId");
  vtkDataArray* bary = out->GetPointData()->GetArray("Barycentric");
  ASSERT_NE(ids, nullptr);
  ASSERT_NE(bary, nullptr);
  for (int i = 0; i < 4; ++i)
  {
    double x[3];
    out->GetPoint(i, x);
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_NEAR(x[k], given[i][k], 1e-12) << "point " << i;
    }
    // The triangle and weights written give the point back.
    const boolsurf::Triangle& t = prism.Triangles[static_cast<int>(ids->GetComponent(i, 0))];
    const double u = bary->GetComponent(i, 0), v = bary->GetComponent(i, 1);
    const boolsurf::Vec3 back =
      (1 - u - v) * prism.Positions[t[0]] + u * prism.Positions[t[1]] + v * prism.Positions[t[2]];
    EXPECT_NEAR(back.x, given[i][0], 1e-12) << "point " << i;
    EXPECT_NEAR(back.y, given[i][1], 1e-12) << "point " << i;
    EXPECT_NEAR(back.z, given[i][2], 1e-12) << "point " << i;
  }
}

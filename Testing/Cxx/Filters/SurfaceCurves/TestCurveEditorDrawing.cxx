// The curve editor's drawing (Plugin/pqBoolSurfDrawing): the Surface Curves source's property
// defaults read back, the properties written complete, and the edits a user makes (insert
// after the selected point, a first click starting a curve, deleting a curve's last point).
#include "pqBoolSurfDrawing.h"

#include "FilterTestUtils.h"
#include "Mesh/TriangleMesh.h"
#include "vtkBoolSurf.h"
#include "vtkBoolSurfArrangement.h"
#include "vtkBoolSurfBoolean.h"
#include "vtkBoolSurfLabeling.h"
#include "vtkBoolSurfSurfaceCurves.h"
#include "vtkBoolSurfTraceCurves.h"

#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

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
  EXPECT_EQ(d.Curves[0].ShapeId, 7);
  EXPECT_EQ(d.Curves[1].ShapeId, 1);
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
  p->U = 0.25;
  p->V = 0.5;
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
  EXPECT_EQ(again.Curves.at(0).Points.at(1).V, 0.5);
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
  EXPECT_EQ(d.Curves[second].ShapeId, 1); // shape 0 is used
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

TEST(CurveEditorDrawing, MissingPointsFollowEachType)
{
  pqBoolSurfDrawing::Curve c;
  const auto missing = [&](int type, bool closed, int size)
  {
    c.Type = static_cast<boolsurf::CurveType>(type);
    c.Closed = closed;
    c.Points.assign(size, pqBoolSurfDrawing::Point());
    return pqBoolSurfDrawing::MissingPoints(c);
  };
  EXPECT_EQ(missing(0, false, 1), 1);
  EXPECT_EQ(missing(0, true, 2), 0);
  EXPECT_EQ(missing(0, true, 5), 0);
  // Open Bezier: 4, 7, 10, ... points; closed: 3, 6, 9, ...
  const int open[] = { 3, 2, 1, 0, 2, 1, 0, 2 };   // sizes 1..8
  const int closed[] = { 2, 1, 0, 2, 1, 0, 2, 1 }; // sizes 1..8
  for (int size = 1; size <= 8; ++size)
  {
    EXPECT_EQ(missing(1, false, size), open[size - 1]) << size;
    EXPECT_EQ(missing(1, true, size), closed[size - 1]) << size;
  }
}

TEST(CurveEditorDrawing, ReversalKeepsBezierAnchors)
{
  pqBoolSurfDrawing d;
  for (const bool closed : { false, true })
  {
    d.Curves.assign(1, pqBoolSurfDrawing::Curve());
    d.Curves[0].Type = boolsurf::CurveType::CubicBezier;
    d.Curves[0].Closed = closed;
    const int n = closed ? 6 : 7;
    for (int i = 0; i < n; ++i)
    {
      pqBoolSurfDrawing::Point p;
      p.Position = { double(i), 0, 0 };
      d.Curves[0].Points.push_back(p);
    }
    ASSERT_TRUE(d.ReverseCurve(0));
    std::vector<double> order;
    for (const auto& p : d.Curves[0].Points)
    {
      order.push_back(p.Position[0]);
    }
    // Open: the last anchor first; closed: the first anchor stays, the handles swap sides.
    const std::vector<double> expected =
      closed ? std::vector<double>{ 0, 5, 4, 3, 2, 1 } : std::vector<double>{ 6, 5, 4, 3, 2, 1, 0 };
    EXPECT_EQ(order, expected) << (closed ? "closed" : "open");
    // Anchors (0, 3, 6, ...) stay anchors.
    for (size_t k = 0; k < order.size(); k += 3)
    {
      EXPECT_EQ(static_cast<int>(order[k]) % 3, 0) << k;
    }
  }
  EXPECT_FALSE(d.ReverseCurve(5));
}

// A curve being drawn (a Bezier curve between anchors, a curve of one click) is no error: the
// source marks it and says what it needs, its traced output shows its complete part, and a
// BoolSurf downstream leaves it out without a message (each message opened ParaView's Output
// Messages window over the view while the user was clicking).
TEST(CurveEditorDrawing, CurvesBeingDrawnAreNoError)
{
  vtkSmartPointer<vtkPolyData> surface =
    testutils::ToPolyData(boolsurf::MakeFlatSquare(40, 1.0, 0.0, 0));
  // Curve 0: a closed square (complete); curve 1: an open Bezier of 5 points (one segment and
  // one more anchor's first handle); curve 2: a first click.
  const double pts[][3] = { { 0.2, 0.2, 0 },
    { 0.4, 0.2, 0 },
    { 0.4, 0.4, 0 },
    { 0.2, 0.4, 0 },
    { 0.6, 0.6, 0 },
    { 0.7, 0.65, 0 },
    { 0.8, 0.65, 0 },
    { 0.9, 0.6, 0 },
    { 0.9, 0.7, 0 },
    { 0.1, 0.9, 0 } };
  vtkNew<vtkBoolSurfSurfaceCurves> drawing;
  drawing->SetInputData(surface);
  drawing->SetNumberOfPoints(10);
  for (int i = 0; i < 10; ++i)
  {
    drawing->SetPoint(i, pts[i][0], pts[i][1], pts[i][2]);
  }
  const int sizes[] = { 4, 5, 1 }, types[] = { 0, 1, 0 }, closed[] = { 1, 0, 0 };
  drawing->SetNumberOfCurveSizes(3);
  drawing->SetNumberOfCurveTypes(3);
  drawing->SetNumberOfClosedCurves(3);
  for (int c = 0; c < 3; ++c)
  {
    drawing->SetCurveSize(c, sizes[c]);
    drawing->SetCurveType(c, types[c]);
    drawing->SetClosedCurve(c, closed[c]);
  }
  vtkNew<testutils::MessageCatcher> messages;
  drawing->AddObserver(vtkCommand::ErrorEvent, messages);
  drawing->AddObserver(vtkCommand::WarningEvent, messages);
  drawing->Update();
  EXPECT_EQ(messages->Errors + messages->Warnings, "");
  vtkPolyData* controls = drawing->GetOutput(0);
  ASSERT_EQ(controls->GetNumberOfPoints(), 10);
  vtkDataArray* complete = controls->GetCellData()->GetArray("Complete");
  ASSERT_NE(complete, nullptr);
  EXPECT_EQ(complete->GetComponent(0, 0), 1);
  EXPECT_EQ(complete->GetComponent(1, 0), 0);
  EXPECT_EQ(complete->GetComponent(2, 0), 0);
  auto* needs =
    vtkStringArray::SafeDownCast(controls->GetFieldData()->GetAbstractArray("IncompleteCurves"));
  ASSERT_NE(needs, nullptr);
  ASSERT_EQ(needs->GetNumberOfValues(), 2);
  EXPECT_NE(
    needs->GetValue(0).find("curve 1: an open cubic Bezier spline needs 3n+1"), std::string::npos)
    << needs->GetValue(0);
  EXPECT_NE(needs->GetValue(0).find("2 more complete it"), std::string::npos) << needs->GetValue(0);
  EXPECT_NE(needs->GetValue(1).find("curve 2: a geodesic polygon needs 2"), std::string::npos)
    << needs->GetValue(1);
  // Port 1: the square and the Bezier curve's first segment (from (0.6, 0.6) to (0.9, 0.6)).
  vtkPolyData* traced = drawing->GetOutput(1);
  ASSERT_EQ(traced->GetNumberOfCells(), 2);
  vtkDataArray* tracedComplete = traced->GetCellData()->GetArray("Complete");
  ASSERT_NE(tracedComplete, nullptr);
  EXPECT_EQ(tracedComplete->GetComponent(0, 0), 1);
  EXPECT_EQ(tracedComplete->GetComponent(1, 0), 0);
  double last[3];
  traced->GetPoint(traced->GetNumberOfPoints() - 1, last);
  EXPECT_NEAR(last[0], 0.9, 1e-12);
  EXPECT_NEAR(last[1], 0.6, 1e-12);

  // Downstream, from either port: the square's region, without a message.
  for (int port : { 0, 1 })
  {
    vtkNew<vtkBoolSurf> boolsurf;
    boolsurf->SetInputData(0, surface);
    boolsurf->SetInputConnection(1, drawing->GetOutputPort(port));
    boolsurf->SetOperationToExpression();
    boolsurf->SetExpression("S0");
    vtkNew<testutils::MessageCatcher> downstream;
    boolsurf->AddObserver(vtkCommand::ErrorEvent, downstream);
    boolsurf->AddObserver(vtkCommand::WarningEvent, downstream);
    boolsurf->Update();
    EXPECT_EQ(downstream->Errors + downstream->Warnings, "") << "port " << port;
    EXPECT_NEAR(testutils::Area(boolsurf->GetOutput(0)), 0.04, 1e-12) << "port " << port;
  }
}

// The stage chain (Trace Surface Curves, Surface Arrangement, Label Arrangement Cells, Surface
// Boolean) below a drawing that is starting (no point yet; one click) gives no region and no
// message at any stage: each passes the start of the drawing on; once a curve is complete, its
// region.
TEST(CurveEditorDrawing, StageChainIsQuietWhileADrawingStarts)
{
  vtkSmartPointer<vtkPolyData> surface =
    testutils::ToPolyData(boolsurf::MakeFlatSquare(40, 1.0, 0.0, 0));
  vtkNew<vtkBoolSurfSurfaceCurves> drawing;
  drawing->SetInputData(surface);
  vtkNew<vtkBoolSurfTraceCurves> trace;
  trace->SetInputData(0, surface);
  trace->SetInputConnection(1, drawing->GetOutputPort(0));
  vtkNew<vtkBoolSurfArrangement> arrangement;
  arrangement->SetInputData(0, surface);
  arrangement->SetInputConnection(1, trace->GetOutputPort());
  vtkNew<vtkBoolSurfLabeling> labeling;
  labeling->SetInputConnection(arrangement->GetOutputPort(0));
  vtkNew<vtkBoolSurfBoolean> boolean;
  boolean->SetInputConnection(labeling->GetOutputPort(0));
  boolean->SetOperationToExpression();
  boolean->SetExpression("S0");
  vtkNew<testutils::MessageCatcher> messages;
  for (vtkAlgorithm* stage :
    std::vector<vtkAlgorithm*>{ drawing, trace, arrangement, labeling, boolean })
  {
    stage->AddObserver(vtkCommand::ErrorEvent, messages);
    stage->AddObserver(vtkCommand::WarningEvent, messages);
  }
  const double square[][3] = { { 0.2, 0.2, 0 }, { 0.4, 0.2, 0 }, { 0.4, 0.4, 0 }, { 0.2, 0.4, 0 } };
  for (int clicks : { 0, 1, 4 })
  {
    SCOPED_TRACE(std::to_string(clicks) + " click(s)");
    drawing->SetNumberOfPoints(clicks);
    for (int i = 0; i < clicks; ++i)
    {
      drawing->SetPoint(i, square[i][0], square[i][1], square[i][2]);
    }
    boolean->Update();
    EXPECT_EQ(messages->Errors + messages->Warnings, "");
    EXPECT_NEAR(testutils::Area(boolean->GetOutput(0)), clicks == 4 ? 0.04 : 0.0, 1e-12);
  }
}

// Port 1 traces the curves the source holds, without reading port 0 back; it is bit for bit
// what Trace Surface Curves makes of port 0: a closed polygon, an open polygon whose last
// point is its first (read as closed), a closed Bezier spline, exact and snapped points.
TEST(CurveEditorDrawing, PortOneIsTheTraceOfPortZero)
{
  vtkSmartPointer<vtkPolyData> surface =
    testutils::ToPolyData(boolsurf::MakeFlatSquare(12, 1.0, 0.3, 5));
  const double pts[][3] = { { 0.2, 0.2, 0 },
    { 0.45, 0.25, 0 },
    { 0.3, 0.45, 0 },
    { 0.6, 0.1, 0 },
    { 0.85, 0.3, 0 },
    { 0.7, 0.45, 0 },
    { 0.6, 0.1, 0 },
    { 0.2, 0.6, 0 },
    { 0.4, 0.55, 0 },
    { 0.5, 0.75, 0 },
    { 0.45, 0.9, 0 },
    { 0.25, 0.95, 0 },
    { 0.1, 0.8, 0 } };
  const int points = 13;
  vtkNew<vtkBoolSurfSurfaceCurves> drawing;
  drawing->SetInputData(surface);
  drawing->SetGeodesicMethodToExact();
  drawing->SetNumberOfPoints(points);
  for (int i = 0; i < points; ++i)
  {
    drawing->SetPoint(i, pts[i][0], pts[i][1], pts[i][2]);
  }
  const int sizes[] = { 3, 4, 6 }, types[] = { 0, 0, 1 }, closed[] = { 1, 0, 1 };
  drawing->SetNumberOfCurveSizes(3);
  drawing->SetNumberOfCurveTypes(3);
  drawing->SetNumberOfClosedCurves(3);
  for (int c = 0; c < 3; ++c)
  {
    drawing->SetCurveSize(c, sizes[c]);
    drawing->SetCurveType(c, types[c]);
    drawing->SetClosedCurve(c, closed[c]);
  }
  for (bool exact : { false, true })
  {
    SCOPED_TRACE(exact ? "exact points" : "snapped points");
    if (exact)
    {
      // The points as snapped, given exactly (the curve editor's form), the repeated one too.
      drawing->Update();
      vtkDataArray* t = drawing->GetOutput(0)->GetPointData()->GetArray("TriangleId");
      vtkDataArray* b = drawing->GetOutput(0)->GetPointData()->GetArray("Barycentric");
      ASSERT_TRUE(t && b);
      drawing->SetNumberOfTriangleIds(points);
      drawing->SetNumberOfBarycentrics(points);
      for (int i = 0; i < points; ++i)
      {
        drawing->SetTriangleId(i, static_cast<vtkIdType>(t->GetComponent(i, 0)));
        drawing->SetBarycentric(i, b->GetComponent(i, 0), b->GetComponent(i, 1));
      }
    }
    vtkNew<vtkBoolSurfTraceCurves> trace;
    trace->SetInputData(0, surface);
    trace->SetInputConnection(1, drawing->GetOutputPort(0));
    trace->SetGeodesicMethodToExact();
    trace->Update();
    drawing->Update();
    vtkPolyData* held = drawing->GetOutput(1);
    vtkPolyData* read = trace->GetOutput();
    ASSERT_EQ(held->GetNumberOfCells(), 3);
    ASSERT_EQ(held->GetNumberOfPoints(), read->GetNumberOfPoints());
    ASSERT_EQ(held->GetNumberOfCells(), read->GetNumberOfCells());
    for (vtkIdType p = 0; p < held->GetNumberOfPoints(); ++p)
    {
      double a[3], b[3];
      held->GetPoint(p, a);
      read->GetPoint(p, b);
      ASSERT_TRUE(a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) << "point " << p;
    }
    for (vtkIdType c = 0; c < held->GetNumberOfCells(); ++c)
    {
      vtkNew<vtkIdList> a, b;
      held->GetCellPoints(c, a);
      read->GetCellPoints(c, b);
      ASSERT_EQ(a->GetNumberOfIds(), b->GetNumberOfIds()) << "cell " << c;
      for (vtkIdType k = 0; k < a->GetNumberOfIds(); ++k)
      {
        ASSERT_EQ(a->GetId(k), b->GetId(k)) << "cell " << c << " corner " << k;
      }
    }
    for (vtkDataSetAttributes* heldData :
      { static_cast<vtkDataSetAttributes*>(held->GetPointData()),
        static_cast<vtkDataSetAttributes*>(held->GetCellData()) })
    {
      vtkDataSetAttributes* readData = heldData == held->GetPointData()
        ? static_cast<vtkDataSetAttributes*>(read->GetPointData())
        : static_cast<vtkDataSetAttributes*>(read->GetCellData());
      ASSERT_EQ(heldData->GetNumberOfArrays(), readData->GetNumberOfArrays());
      for (int i = 0; i < heldData->GetNumberOfArrays(); ++i)
      {
        vtkDataArray* a = heldData->GetArray(i);
        vtkDataArray* b = a ? readData->GetArray(a->GetName()) : nullptr;
        ASSERT_TRUE(a && b) << "array " << i;
        ASSERT_EQ(a->GetNumberOfValues(), b->GetNumberOfValues()) << a->GetName();
        for (vtkIdType k = 0; k < a->GetNumberOfTuples(); ++k)
        {
          for (int j = 0; j < a->GetNumberOfComponents(); ++j)
          {
            ASSERT_EQ(a->GetComponent(k, j), b->GetComponent(k, j)) << a->GetName() << " " << k;
          }
        }
      }
    }
    // The open polygon whose last point is its first is traced closed.
    EXPECT_EQ(held->GetCellData()->GetArray("Closed")->GetComponent(1, 0), 1);
  }
}

// vtkBoolSurfTraceCurves and vtkBoolSurfArrangement as VTK filters: output arrays, exact
// control points, named errors, the data contract of the arrangement, attribute transfer.
#include "FilterTestUtils.h"
#include "vtkBoolSurf.h"
#include "vtkBoolSurfArrangement.h"
#include "vtkBoolSurfTraceCurves.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

using testutils::ControlPolygon;

namespace
{
std::string TraceErrors(vtkPolyData* pd)
{
  auto* a = vtkStringArray::SafeDownCast(pd->GetFieldData()->GetAbstractArray("TraceErrors"));
  std::string all;
  for (vtkIdType i = 0; a && i < a->GetNumberOfValues(); ++i)
  {
    all += a->GetValue(i) + "\n";
  }
  return all;
}

class Silence : public vtkCommand
{
public:
  static Silence* New() { return new Silence; }
  void Execute(vtkObject*, unsigned long, void*) override {}
};

vtkSmartPointer<vtkPolyData> Trace(vtkPolyData* surface, vtkPolyData* curves, int resolution = 4)
{
  vtkNew<vtkBoolSurfTraceCurves> trace;
  vtkNew<Silence> silence;
  trace->AddObserver(vtkCommand::ErrorEvent, silence);
  trace->AddObserver(vtkCommand::WarningEvent, silence);
  trace->SetInputData(0, surface);
  trace->SetInputData(1, curves);
  trace->SetResolution(resolution);
  trace->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(trace->GetOutput());
  return out;
}
} // namespace

TEST(TraceCurvesFilter, FlatPolygonIsStraightWithOnePointPerEdgeCrossing)
{
  auto mesh = testutils::ToPolyData(boolsurf::MakeFlatSquare(20, 1.0, 0.3, 4));
  ControlPolygon c;
  c.Points = { { 0.1, 0.15, 0 }, { 0.8, 0.3, 0 }, { 0.45, 0.85, 0 } };
  c.ShapeId = 7;
  auto out = Trace(mesh, testutils::ToCurves({ c }));
  ASSERT_EQ(TraceErrors(out), "");
  ASSERT_EQ(out->GetNumberOfCells(), 1);
  auto* length = vtkDoubleArray::SafeDownCast(out->GetCellData()->GetArray("Length"));
  double perimeter = 0;
  for (int i = 0; i < 3; ++i)
  {
    const auto& a = c.Points[i];
    const auto& b = c.Points[(i + 1) % 3];
    perimeter += std::hypot(b[0] - a[0], b[1] - a[1]);
  }
  ASSERT_NE(length, nullptr);
  EXPECT_NEAR(length->GetValue(0), perimeter, 1e-12);
  EXPECT_EQ(vtkIntArray::SafeDownCast(out->GetCellData()->GetArray("ShapeId"))->GetValue(0), 7);
  EXPECT_EQ(vtkIntArray::SafeDownCast(out->GetCellData()->GetArray("Closed"))->GetValue(0), 1);
  // Every traced point carries its surface point, and the 3D point is where it says.
  auto* tri = out->GetPointData()->GetArray("TriangleId");
  auto* bary = out->GetPointData()->GetArray("Barycentric");
  ASSERT_TRUE(tri && bary && out->GetPointData()->GetArray("CurveParameter") &&
    out->GetPointData()->GetArray("ControlPointId"));
  for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
  {
    const vtkIdType t = static_cast<vtkIdType>(tri->GetComponent(p, 0));
    const double u = bary->GetComponent(p, 0), v = bary->GetComponent(p, 1);
    vtkIdType n;
    const vtkIdType* ids;
    mesh->GetCellPoints(t, n, ids);
    double a[3], b[3], cc[3], x[3];
    mesh->GetPoint(ids[0], a);
    mesh->GetPoint(ids[1], b);
    mesh->GetPoint(ids[2], cc);
    out->GetPoint(p, x);
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_NEAR(x[k], (1 - u - v) * a[k] + u * b[k] + v * cc[k], 1e-12);
    }
  }
  EXPECT_GT(out->GetNumberOfPoints(), 3 * 10); // edge crossings of a 20 x 20 mesh
}

TEST(TraceCurvesFilter, ExactSurfacePointsAreUsedAsGiven)
{
  auto mesh = testutils::ToPolyData(boolsurf::MakeFlatSquare(4));
  auto curves = testutils::ToCurves({ ControlPolygon{ { { 0, 0, 5 }, { 0, 0, 5 } }, 0, false } });
  vtkNew<vtkIdTypeArray> tri;
  tri->SetName("TriangleId");
  tri->InsertNextValue(0);
  tri->InsertNextValue(31);
  vtkNew<vtkDoubleArray> bary;
  bary->SetName("Barycentric");
  bary->SetNumberOfComponents(2);
  bary->InsertNextTuple2(0.25, 0.25);
  bary->InsertNextTuple2(0.5, 0.25);
  curves->GetPointData()->AddArray(tri);
  curves->GetPointData()->AddArray(bary);
  auto out = Trace(mesh, curves); // the 3D coordinates (far away) are ignored
  ASSERT_EQ(TraceErrors(out), "");
  auto* outTri = out->GetPointData()->GetArray("TriangleId");
  auto* outBary = out->GetPointData()->GetArray("Barycentric");
  const vtkIdType last = out->GetNumberOfPoints() - 1;
  EXPECT_EQ(outTri->GetComponent(0, 0), 0);
  EXPECT_EQ(outBary->GetComponent(0, 0), 0.25);
  EXPECT_EQ(outBary->GetComponent(0, 1), 0.25);
  EXPECT_EQ(outTri->GetComponent(last, 0), 31);
  EXPECT_EQ(outBary->GetComponent(last, 0), 0.5);
  EXPECT_EQ(outBary->GetComponent(last, 1), 0.25);
}

// Control points given as surface points come back bit for bit in the field data
// ControlTriangleId/ControlBarycentric, for arbitrary doubles, points on edges (v = 1 - u) and on
// vertices; the traced point at their ControlPointId is the same surface point in canonical form
// (exact zeros on edges and vertices), in the user's triangle, and off edges and vertices it is
// the user's numbers bit for bit.
TEST(TraceCurvesFilter, ControlPointsRoundTripExactly)
{
  auto mesh = testutils::ToPolyData(boolsurf::MakeFlatSquare(12, 1.0, 0.3, 5));
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> triangle(0, static_cast<int>(mesh->GetNumberOfCells()) - 1);
  const int n = 12;
  ControlPolygon c;
  c.Closed = false;
  vtkNew<vtkIdTypeArray> tri;
  tri->SetName("TriangleId");
  vtkNew<vtkDoubleArray> bary;
  bary->SetName("Barycentric");
  bary->SetNumberOfComponents(2);
  for (int i = 0; i < n; ++i)
  {
    double u = unit(rng), v = unit(rng) * (1 - u);
    if (i % 4 == 1)
    {
      v = 1 - u; // on the edge opposite corner 0
    }
    else if (i % 4 == 2)
    {
      u = 0; // on the edge from corner 0 to corner 2
    }
    else if (i % 4 == 3)
    {
      u = 1; // on corner 1
      v = 0;
    }
    c.Points.push_back({ 0, 0, 0 });
    tri->InsertNextValue(triangle(rng));
    bary->InsertNextTuple2(u, v);
  }
  auto curves = testutils::ToCurves({ c });
  curves->GetPointData()->AddArray(tri);
  curves->GetPointData()->AddArray(bary);
  auto out = Trace(mesh, curves);
  ASSERT_EQ(TraceErrors(out), "");
  auto* outTri = out->GetPointData()->GetArray("TriangleId");
  auto* outBary = out->GetPointData()->GetArray("Barycentric");
  auto* control = out->GetPointData()->GetArray("ControlPointId");
  int found = 0;
  for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
  {
    const int k = static_cast<int>(control->GetComponent(p, 0));
    if (k < 0)
    {
      continue;
    }
    ++found;
    const double u = outBary->GetComponent(p, 0), v = outBary->GetComponent(p, 1);
    EXPECT_EQ(outTri->GetComponent(p, 0), tri->GetValue(k)) << "control point " << k;
    if (k % 4 == 0)
    {
      EXPECT_EQ(u, bary->GetComponent(k, 0)) << "control point " << k;
      EXPECT_EQ(v, bary->GetComponent(k, 1)) << "control point " << k;
    }
    else
    {
      // On an edge or a vertex: a weight exactly 0 where the user's is (within rounding).
      const double w[3] = { 1 - u - v, u, v };
      const double given[3] = { 1 - bary->GetComponent(k, 0) - bary->GetComponent(k, 1),
        bary->GetComponent(k, 0),
        bary->GetComponent(k, 1) };
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_NEAR(w[c], given[c], 1e-15) << "control point " << k << " corner " << c;
        if (std::abs(given[c]) < 1e-15)
        {
          EXPECT_TRUE(c == 0 ? u + v == 1 : w[c] == 0) << "control point " << k << " corner " << c;
        }
      }
    }
  }
  EXPECT_GE(found, n);
  auto* fieldTri = out->GetFieldData()->GetArray("ControlTriangleId");
  auto* fieldBary = out->GetFieldData()->GetArray("ControlBarycentric");
  ASSERT_NE(fieldTri, nullptr);
  ASSERT_NE(fieldBary, nullptr);
  ASSERT_EQ(fieldTri->GetNumberOfTuples(), n);
  for (int k = 0; k < n; ++k)
  {
    EXPECT_EQ(fieldTri->GetComponent(k, 0), tri->GetValue(k)) << "control point " << k;
    EXPECT_EQ(fieldBary->GetComponent(k, 0), bary->GetComponent(k, 0)) << "control point " << k;
    EXPECT_EQ(fieldBary->GetComponent(k, 1), bary->GetComponent(k, 1)) << "control point " << k;
  }
}

TEST(TraceCurvesFilter, BadInputsAreNamed)
{
  auto mesh = testutils::ToPolyData(boolsurf::MakeFlatSquare(8));
  // Zero-length curves (one point, or one point repeated) are skipped with a warning; the other
  // curves are traced.
  ControlPolygon single{ { { 0.5, 0.5, 0 } }, 0, false };
  ControlPolygon repeated{ { { 0.3, 0.5, 0 }, { 0.3, 0.5, 0 }, { 0.3, 0.5, 0 } }, 1, true };
  ControlPolygon fine{ { { 0.2, 0.2, 0 }, { 0.8, 0.3, 0 }, { 0.5, 0.8, 0 } }, 2, true };
  {
    vtkNew<vtkBoolSurfTraceCurves> trace;
    trace->SetInputData(0, mesh);
    trace->SetInputData(1, testutils::ToCurves({ single, repeated, fine }));
    std::string warnings;
    vtkNew<vtkCallbackCommand> onWarning;
    onWarning->SetClientData(&warnings);
    onWarning->SetCallback([](vtkObject*, unsigned long, void* text, void* data)
      { *static_cast<std::string*>(text) += static_cast<const char*>(data); });
    trace->AddObserver(vtkCommand::WarningEvent, onWarning);
    trace->Update();
    EXPECT_EQ(trace->GetOutput()->GetNumberOfLines(), 1);
    EXPECT_NE(warnings.find("curve 0 has 1 control point(s): skipped"), std::string::npos)
      << warnings;
    EXPECT_NE(warnings.find("has 3 control point(s), all at the same surface point: skipped"),
      std::string::npos)
      << warnings;
  }

  ControlPolygon bezier{
    { { 0.1, 0.1, 0 }, { 0.2, 0.3, 0 }, { 0.4, 0.4, 0 }, { 0.6, 0.6, 0 }, { 0.7, 0.7, 0 } },
    0,
    false,
    1
  };
  EXPECT_NE(TraceErrors(Trace(mesh, testutils::ToCurves({ bezier }))).find("needs 3n+1"),
    std::string::npos);
  bezier.Closed = true; // 5 points, closed: needs 3n
  EXPECT_NE(
    TraceErrors(Trace(mesh, testutils::ToCurves({ bezier }))).find("needs 3n"), std::string::npos);

  ControlPolygon far{ { { 0.1, 0.1, 0 }, { 0.5, 0.5, 0.3 } }, 0, false };
  EXPECT_NE(
    TraceErrors(Trace(mesh, testutils::ToCurves({ far }))).find("curve 0, control point 1 is 0.3"),
    std::string::npos);

  // Two disjoint squares: a curve from one to the other.
  boolsurf::MeshData two = boolsurf::MakeFlatSquare(4);
  boolsurf::MeshData other = boolsurf::MakeFlatSquare(4);
  const int offset = static_cast<int>(two.Positions.size());
  for (auto p : other.Positions)
  {
    two.Positions.push_back({ p.x + 2, p.y, 0 });
  }
  for (auto t : other.Triangles)
  {
    two.Triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
  }
  ControlPolygon across{ { { 0.5, 0.5, 0 }, { 2.5, 0.5, 0 } }, 0, false };
  const std::string errors =
    TraceErrors(Trace(testutils::ToPolyData(two), testutils::ToCurves({ across })));
  EXPECT_NE(errors.find("different connected components"), std::string::npos) << errors;
  EXPECT_NE(errors.find("curve 0"), std::string::npos) << errors;
}

TEST(ArrangementFilter, OutputsFollowTheDataContract)
{
  auto mesh = testutils::ToPolyData(boolsurf::MakeFlatSquare(24, 1.0, 0.3, 9));
  // Two overlapping triangles: 4 cells (outside, A only, B only, both); an open curve that
  // crosses both without separating anything.
  ControlPolygon a{ { { 0.1, 0.1, 0 }, { 0.7, 0.15, 0 }, { 0.3, 0.7, 0 } }, 0, true };
  ControlPolygon b{ { { 0.35, 0.2, 0 }, { 0.9, 0.4, 0 }, { 0.5, 0.9, 0 } }, 1, true };
  ControlPolygon open{ { { 0.05, 0.5, 0 }, { 0.95, 0.55, 0 } }, 2, false };
  vtkNew<vtkBoolSurfTraceCurves> trace;
  trace->SetInputData(0, mesh);
  trace->SetInputData(1, testutils::ToCurves({ a, b, open }));
  vtkNew<vtkBoolSurfArrangement> arrangement;
  arrangement->SetInputData(0, mesh);
  arrangement->SetInputConnection(1, trace->GetOutputPort());
  arrangement->SetNumberOfThreads(1);
  arrangement->Update();
  vtkPolyData* refined = arrangement->GetOutput(0);
  vtkFieldData* fd = refined->GetFieldData();
  ASSERT_NE(fd->GetArray("NumberOfCells"), nullptr);
  EXPECT_EQ(fd->GetArray("NumberOfCells")->GetComponent(0, 0), 4);
  EXPECT_EQ(fd->GetArray("NumberOfShapes")->GetComponent(0, 0), 3);
  ASSERT_NE(fd->GetArray("CellGraphArcs"), nullptr);
  EXPECT_EQ(fd->GetArray("CellGraphArcs")->GetNumberOfComponents(), 2);
  EXPECT_NE(fd->GetArray("StageTimes"), nullptr);
  EXPECT_NEAR(testutils::Area(refined), 1.0, 1e-12);
  ASSERT_NE(refined->GetCellData()->GetArray("ArrangementCell"), nullptr);
  ASSERT_NE(refined->GetCellData()->GetArray("SourceTriangle"), nullptr);
  ASSERT_NE(refined->GetPointData()->GetArray("Barycentric"), nullptr);
  vtkPolyData* patches = arrangement->GetPatchesOutput();
  EXPECT_GT(patches->GetNumberOfLines(), 4);
  for (const char* name : { "PatchId", "ShapeId", "CurveId", "LeftCell", "RightCell", "Length" })
  {
    EXPECT_NE(patches->GetCellData()->GetArray(name), nullptr) << name;
  }
  // The same partition with 2 threads.
  vtkNew<vtkBoolSurfArrangement> threaded;
  threaded->SetInputData(0, mesh);
  threaded->SetInputConnection(1, trace->GetOutputPort());
  threaded->SetNumberOfThreads(2);
  threaded->Update();
  vtkDataArray* c1 = refined->GetCellData()->GetArray("ArrangementCell");
  vtkDataArray* c2 = threaded->GetOutput(0)->GetCellData()->GetArray("ArrangementCell");
  ASSERT_EQ(c1->GetNumberOfTuples(), c2->GetNumberOfTuples());
  for (vtkIdType i = 0; i < c1->GetNumberOfTuples(); ++i)
  {
    ASSERT_EQ(c1->GetComponent(i, 0), c2->GetComponent(i, 0)) << "triangle " << i;
  }
}

TEST(ArrangementFilter, InputArraysAreCarriedToTheResult)
{
  // A linear point field (exactly interpolated) and a cell id field on the input surface.
  auto mesh = testutils::ToPolyData(boolsurf::MakeFlatSquare(16, 1.0, 0.2, 2));
  vtkNew<vtkDoubleArray> field;
  field->SetName("Height");
  for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p)
  {
    double x[3];
    mesh->GetPoint(p, x);
    field->InsertNextValue(2 * x[0] - 3 * x[1] + 1);
  }
  mesh->GetPointData()->AddArray(field);
  vtkNew<vtkIntArray> cellIds;
  cellIds->SetName("InputCell");
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    cellIds->InsertNextValue(static_cast<int>(c));
  }
  mesh->GetCellData()->AddArray(cellIds);
  ControlPolygon a{ { { 0.2, 0.2, 0 }, { 0.8, 0.3, 0 }, { 0.4, 0.8, 0 } }, 0, true };
  vtkNew<vtkBoolSurf> f;
  f->SetInputData(0, mesh);
  f->SetInputData(1, testutils::ToCurves({ a }));
  f->SetOperationToExpression();
  f->SetExpression("S0");
  f->Update();
  vtkPolyData* region = f->GetOutput();
  ASSERT_GT(region->GetNumberOfCells(), 0);
  auto* height = region->GetPointData()->GetArray("Height");
  ASSERT_NE(height, nullptr);
  for (vtkIdType p = 0; p < region->GetNumberOfPoints(); ++p)
  {
    double x[3];
    region->GetPoint(p, x);
    EXPECT_NEAR(height->GetComponent(p, 0), 2 * x[0] - 3 * x[1] + 1, 1e-12);
  }
  auto* input = region->GetCellData()->GetArray("InputCell");
  auto* source = region->GetCellData()->GetArray("SourceTriangle");
  ASSERT_TRUE(input && source);
  for (vtkIdType c = 0; c < region->GetNumberOfCells(); ++c)
  {
    EXPECT_EQ(input->GetComponent(c, 0), source->GetComponent(c, 0));
  }
  // Labels belong to cells (field data CellLabels), never per triangle in the region.
  EXPECT_EQ(region->GetCellData()->GetArray("Labels"), nullptr);
  EXPECT_NE(region->GetFieldData()->GetArray("CellLabels"), nullptr);
  EXPECT_NE(region->GetCellData()->GetArray("ArrangementCell"), nullptr);
  // The boundary is one closed loop with the region on its left (counter-clockwise here).
  vtkPolyData* boundary = f->GetBoundaryOutput();
  ASSERT_EQ(boundary->GetNumberOfLines(), 1);
  double signedArea = 0;
  vtkIdType n;
  const vtkIdType* ids;
  boundary->GetLines()->InitTraversal();
  boundary->GetLines()->GetNextCell(n, ids);
  EXPECT_EQ(ids[0], ids[n - 1]);
  for (vtkIdType i = 0; i + 1 < n; ++i)
  {
    double p[3], q[3];
    boundary->GetPoint(ids[i], p);
    boundary->GetPoint(ids[i + 1], q);
    signedArea += 0.5 * (p[0] * q[1] - q[0] * p[1]);
  }
  EXPECT_NEAR(signedArea, testutils::Area(region), 1e-12);
  EXPECT_NE(boundary->GetPointData()->GetArray("TriangleId"), nullptr);

  // The same through the stage filters: Surface Arrangement's refined surface carries the
  // field at every point, mesh vertices and curve points, on a first update and on an edit
  // (which keeps the vertices' surface points from the update before).
  vtkNew<vtkBoolSurfTraceCurves> trace;
  trace->SetInputData(0, mesh);
  trace->SetInputData(1, testutils::ToCurves({ a }));
  vtkNew<vtkBoolSurfArrangement> arrangement;
  arrangement->SetInputData(0, mesh);
  arrangement->SetInputConnection(1, trace->GetOutputPort());
  ControlPolygon moved{ { { 0.25, 0.2, 0 }, { 0.8, 0.35, 0 }, { 0.4, 0.85, 0 } }, 0, true };
  for (const ControlPolygon& drawn : { a, moved })
  {
    trace->SetInputData(1, testutils::ToCurves({ drawn }));
    arrangement->Update();
    vtkPolyData* refined = arrangement->GetOutput(0);
    ASSERT_GT(refined->GetNumberOfPoints(), mesh->GetNumberOfPoints());
    auto* carried = refined->GetPointData()->GetArray("Height");
    ASSERT_NE(carried, nullptr);
    for (vtkIdType p = 0; p < refined->GetNumberOfPoints(); ++p)
    {
      double x[3];
      refined->GetPoint(p, x);
      ASSERT_NEAR(carried->GetComponent(p, 0), 2 * x[0] - 3 * x[1] + 1, 1e-12) << "point " << p;
    }
  }
}

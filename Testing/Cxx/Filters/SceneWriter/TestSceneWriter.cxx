// vtkBoolSurfSceneWriter: scenes written and read again give the same surface points (bit for
// bit), polygons, shapes, curve types and operations; curves saved and reopened give the same
// Boolean region; bad input is a named error and writes no file. The round trip of every
// reference scene reads ../shared (BOOLSURF_SHARED_DATA) and skips with a message without it.
#include "vtkBoolSurf.h"
#include "vtkBoolSurfResolve.h"
#include "vtkBoolSurfSceneReader.h"
#include "vtkBoolSurfSceneWriter.h"

#include "FilterTestUtils.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPLYReader.h>
#include <vtkPLYWriter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include "Support/ScratchDirectory.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace
{
namespace fs = std::filesystem;

/// A scratch folder per test process, removed at exit.
fs::path Scratch()
{
  static const boolsurf::testing::ScratchDirectory dir("boolsurf-scene-writer-");
  return dir.Path;
}

/// Reads a scene; errors are collected, not printed.
vtkSmartPointer<vtkBoolSurfSceneReader> ReadScene(const fs::path& file, std::string& errors)
{
  auto reader = vtkSmartPointer<vtkBoolSurfSceneReader>::New();
  reader->SetFileName(file.string().c_str());
  vtkNew<testutils::MessageCatcher> catcher;
  reader->AddObserver(vtkCommand::ErrorEvent, catcher);
  reader->AddObserver(vtkCommand::WarningEvent, catcher);
  reader->Update();
  errors = catcher->Errors;
  return reader;
}

/// Writes `curves`; returns the error messages (empty on success).
std::string WriteScene(vtkPolyData* curves, const fs::path& file, const std::string& mesh = "")
{
  vtkNew<vtkBoolSurfSceneWriter> writer;
  writer->SetInputData(curves);
  writer->SetFileName(file.string().c_str());
  if (!mesh.empty())
  {
    writer->SetMeshReference(mesh.c_str());
  }
  vtkNew<testutils::MessageCatcher> catcher;
  writer->AddObserver(vtkCommand::ErrorEvent, catcher);
  writer->Write();
  return catcher->Errors;
}

bool SameBits(double a, double b)
{
  return std::memcmp(&a, &b, sizeof a) == 0;
}

/// Every curve (cell point ids), every surface point (bit for bit), every cell array the reader
/// makes and the operations are the same in `a` and `b`.
void ExpectSameCurves(vtkPolyData* a, vtkPolyData* b, const std::string& what)
{
  SCOPED_TRACE(what);
  ASSERT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints());
  ASSERT_EQ(a->GetNumberOfCells(), b->GetNumberOfCells());
  vtkDataArray* ta = a->GetPointData()->GetArray("TriangleId");
  vtkDataArray* tb = b->GetPointData()->GetArray("TriangleId");
  vtkDataArray* ba = a->GetPointData()->GetArray("Barycentric");
  vtkDataArray* bb = b->GetPointData()->GetArray("Barycentric");
  ASSERT_TRUE(ta && tb && ba && bb);
  int different = 0;
  for (vtkIdType p = 0; p < a->GetNumberOfPoints(); ++p)
  {
    const bool same = ta->GetComponent(p, 0) == tb->GetComponent(p, 0) &&
      SameBits(ba->GetComponent(p, 0), bb->GetComponent(p, 0)) &&
      SameBits(ba->GetComponent(p, 1), bb->GetComponent(p, 1));
    if (!same && different++ < 3)
    {
      ADD_FAILURE() << "point " << p << " differs";
    }
  }
  EXPECT_EQ(different, 0);
  auto ia = vtk::TakeSmartPointer(a->GetLines()->NewIterator());
  auto ib = vtk::TakeSmartPointer(b->GetLines()->NewIterator());
  for (ia->GoToFirstCell(), ib->GoToFirstCell(); !ia->IsDoneWithTraversal();
       ia->GoToNextCell(), ib->GoToNextCell())
  {
    ASSERT_FALSE(ib->IsDoneWithTraversal());
    vtkIdType na, nb;
    const vtkIdType *pa, *pb;
    ia->GetCurrentCell(na, pa);
    ib->GetCurrentCell(nb, pb);
    ASSERT_EQ(std::vector<vtkIdType>(pa, pa + na), std::vector<vtkIdType>(pb, pb + nb))
      << "curve " << ia->GetCurrentCellId();
  }
  for (const char* name : { "CurveId", "ShapeId", "CurveType", "Closed" })
  {
    vtkDataArray* ca = a->GetCellData()->GetArray(name);
    vtkDataArray* cb = b->GetCellData()->GetArray(name);
    ASSERT_TRUE(ca && cb) << name;
    for (vtkIdType c = 0; c < a->GetNumberOfCells(); ++c)
    {
      ASSERT_EQ(ca->GetComponent(c, 0), cb->GetComponent(c, 0)) << name << " of curve " << c;
    }
  }
  for (const char* name : { "OperationA", "OperationB", "OperationType" })
  {
    vtkDataArray* fa = a->GetFieldData()->GetArray(name);
    vtkDataArray* fb = b->GetFieldData()->GetArray(name);
    ASSERT_EQ(fa == nullptr, fb == nullptr) << name;
    if (fa)
    {
      ASSERT_EQ(fa->GetNumberOfTuples(), fb->GetNumberOfTuples()) << name;
      for (vtkIdType i = 0; i < fa->GetNumberOfTuples(); ++i)
      {
        EXPECT_EQ(fa->GetComponent(i, 0), fb->GetComponent(i, 0)) << name << " " << i;
      }
    }
  }
}

std::vector<fs::path> ReferenceScenes()
{
  std::vector<fs::path> scenes;
  const char* data = std::getenv("BOOLSURF_SHARED_DATA");
  if (!data || !*data || !fs::is_directory(fs::path(data) / "boolsurf-scenes"))
  {
    return scenes;
  }
  for (const auto& entry : fs::recursive_directory_iterator(fs::path(data) / "boolsurf-scenes"))
  {
    if (entry.path().extension() == ".json" &&
      entry.path().filename().string().find("_basis") == std::string::npos)
    {
      scenes.push_back(entry.path());
    }
  }
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

/// A flat 4 x 4 grid of 32 triangles on [0, 4]^2 with exact control points on it: two
/// overlapping squares (shape 0 and 1) and, in shape 1, a Bezier curve and an open polyline.
vtkSmartPointer<vtkPolyData> FlatGrid()
{
  return testutils::ToPolyData(boolsurf::MakeFlatSquare(4, 4.0));
}

/// Curves with exact surface points, found by projecting (x, y) on FlatGrid() by hand.
vtkSmartPointer<vtkPolyData> ExactCurves(vtkPolyData* grid,
  const std::vector<std::vector<std::array<double, 2>>>& curves,
  const std::vector<int>& shapes,
  const std::vector<int>& types,
  const std::vector<bool>& closed)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkIdTypeArray> triangle;
  triangle->SetName("TriangleId");
  vtkNew<vtkDoubleArray> bary;
  bary->SetName("Barycentric");
  bary->SetNumberOfComponents(2);
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkIntArray> shape, type;
  shape->SetName("ShapeId");
  type->SetName("CurveType");
  for (std::size_t k = 0; k < curves.size(); ++k)
  {
    std::vector<vtkIdType> ids;
    for (const auto& xy : curves[k])
    {
      // The triangle of grid whose barycentric coordinates of (x, y) are all >= 0.
      for (vtkIdType t = 0; t < grid->GetNumberOfCells(); ++t)
      {
        vtkIdType n;
        const vtkIdType* v;
        grid->GetCellPoints(t, n, v);
        double a[3], b[3], c[3];
        grid->GetPoint(v[0], a);
        grid->GetPoint(v[1], b);
        grid->GetPoint(v[2], c);
        const double det = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
        const double u = ((xy[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (xy[1] - a[1])) / det;
        const double w = ((b[0] - a[0]) * (xy[1] - a[1]) - (xy[0] - a[0]) * (b[1] - a[1])) / det;
        if (u >= -1e-12 && w >= -1e-12 && u + w <= 1 + 1e-12)
        {
          ids.push_back(points->InsertNextPoint(xy[0], xy[1], 0));
          triangle->InsertNextValue(t);
          bary->InsertNextTuple2(u, w);
          break;
        }
      }
    }
    if (closed[k])
    {
      ids.push_back(ids.front());
    }
    lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    shape->InsertNextValue(shapes[k]);
    type->InsertNextValue(types[k]);
  }
  pd->SetPoints(points);
  pd->SetLines(lines);
  pd->GetPointData()->AddArray(triangle);
  pd->GetPointData()->AddArray(bary);
  pd->GetCellData()->AddArray(shape);
  pd->GetCellData()->AddArray(type);
  return pd;
}

vtkSmartPointer<vtkPolyData> SampleCurves(vtkPolyData* grid)
{
  return ExactCurves(grid,
    { { { 0.5, 0.5 }, { 2.5, 0.5 }, { 2.5, 2.5 }, { 0.5, 2.5 } },
      { { 1.3, 1.1 }, { 3.7, 1.1 }, { 3.7, 3.3 }, { 1.3, 3.3 } },
      { { 0.2, 3.0 }, { 0.6, 3.9 }, { 1.4, 3.9 }, { 1.8, 3.0 }, { 1.4, 2.1 }, { 0.6, 2.1 } },
      { { 0.1, 0.1 }, { 3.9, 3.9 } } },
    { 0, 1, 1, 2 },
    { 0, 0, 1, 0 },
    { true, true, true, false });
}

/// Writes the grid as a PLY file for the scenes to name (the default grid's coordinates are
/// exact in float; a jittered one is read back for the surface as the scene will have it).
fs::path WriteGrid(vtkPolyData* grid, const std::string& name = "grid.ply")
{
  const fs::path file = Scratch() / name;
  vtkNew<vtkPLYWriter> writer;
  writer->SetInputData(grid);
  writer->SetFileName(file.string().c_str());
  writer->Write();
  return file;
}

/// The area of the region bounded by `result`'s Boundary Control Curves once written as the
/// scene `file` on `mesh` and reopened: one shape under the non-zero rule (holes are loops
/// turning the other way). NaN, with a failure, when a step reports an error.
double ReopenedBoundaryArea(vtkBoolSurf* result, const fs::path& file, const fs::path& mesh)
{
  const std::string written =
    WriteScene(result->GetBoundaryControlCurvesOutput(), file, mesh.filename().string());
  std::string errors;
  auto reader = ReadScene(file, errors);
  vtkNew<vtkBoolSurf> again;
  again->SetInputConnection(0, reader->GetOutputPort(0));
  again->SetInputConnection(1, reader->GetOutputPort(1));
  again->SetOperationToExpression();
  again->SetExpression("S0");
  again->SetFillRule(0);
  errors += testutils::ErrorsOf(again);
  EXPECT_EQ(written, "");
  EXPECT_EQ(errors, "");
  return written.empty() && errors.empty() ? testutils::Area(again->GetOutput(0)) : std::nan("");
}

} // namespace

TEST(SceneWriter, ReferenceScenesRoundTripBitForBit)
{
  const std::vector<fs::path> scenes = ReferenceScenes();
  if (scenes.empty())
  {
    GTEST_SKIP() << "BOOLSURF_SHARED_DATA is not set or has no boolsurf-scenes/: the round trip "
                    "of the reference scenes needs ../shared/data";
  }
  const fs::path grid = Scratch() / "screenspace-grid.ply";
  int written = 0;
  for (const fs::path& scene : scenes)
  {
    SCOPED_TRACE(scene.filename().string());
    std::string errors;
    auto first = ReadScene(scene, errors);
    vtkPolyData* curves = first->GetCurvesOutput();
    if (curves->GetNumberOfCells() == 0)
    {
      continue; // scenes the reader refuses are TestSceneReader's and TestSceneRegression's
    }
    std::string mesh;
    if (!first->GetResolvedMeshFileName()[0])
    {
      // A screen-space scene has no mesh file: its flat grid is saved for the written scene.
      vtkNew<vtkPLYWriter> ply;
      ply->SetInputData(first->GetOutput(0));
      ply->SetFileName(grid.string().c_str());
      ply->Write();
      mesh = grid.string();
    }
    const fs::path copy = Scratch() / scene.filename();
    ASSERT_EQ(WriteScene(curves, copy, mesh), "");
    auto second = ReadScene(copy, errors);
    ASSERT_EQ(errors.find("ERROR"), std::string::npos) << errors;
    ExpectSameCurves(curves, second->GetCurvesOutput(), scene.filename().string());
    EXPECT_EQ(first->GetOutput(0)->GetNumberOfCells(), second->GetOutput(0)->GetNumberOfCells());
    ++written;
  }
  EXPECT_GE(written, 40) << "too few reference scenes were read";
}

TEST(SceneWriter, BezierOpenCurvesAndOperationsRoundTrip)
{
  auto grid = FlatGrid();
  auto curves = SampleCurves(grid);
  vtkNew<vtkIntArray> a, b, t;
  a->SetName("OperationA");
  b->SetName("OperationB");
  t->SetName("OperationType");
  a->InsertNextValue(0);
  b->InsertNextValue(1);
  t->InsertNextValue(3);
  curves->GetFieldData()->AddArray(a);
  curves->GetFieldData()->AddArray(b);
  curves->GetFieldData()->AddArray(t);
  const fs::path mesh = WriteGrid(grid);
  const fs::path file = Scratch() / "sample.json";
  ASSERT_EQ(WriteScene(curves, file, mesh.string()), "");

  std::string errors;
  auto reader = ReadScene(file, errors);
  ASSERT_EQ(errors, "");
  vtkPolyData* back = reader->GetCurvesOutput();
  ASSERT_EQ(back->GetNumberOfCells(), 4);
  vtkDataArray* curveId = back->GetCellData()->GetArray("CurveId");
  vtkDataArray* shapeId = back->GetCellData()->GetArray("ShapeId");
  vtkDataArray* curveType = back->GetCellData()->GetArray("CurveType");
  vtkDataArray* closed = back->GetCellData()->GetArray("Closed");
  const int expectedShape[] = { 0, 1, 1, 2 }, expectedType[] = { 0, 0, 1, 0 };
  for (vtkIdType c = 0; c < 4; ++c)
  {
    // No CurveId in the input: curve k is polygon k + 1 (polygon 0 is BoolSurf's reserved one).
    EXPECT_EQ(curveId->GetComponent(c, 0), c + 1);
    EXPECT_EQ(shapeId->GetComponent(c, 0), expectedShape[c]);
    EXPECT_EQ(curveType->GetComponent(c, 0), expectedType[c]);
    EXPECT_EQ(closed->GetComponent(c, 0), c < 3 ? 1 : 0);
  }
  vtkDataArray* bary = back->GetPointData()->GetArray("Barycentric");
  vtkDataArray* bary0 = curves->GetPointData()->GetArray("Barycentric");
  for (vtkIdType p = 0; p < curves->GetNumberOfPoints(); ++p)
  {
    ASSERT_TRUE(SameBits(bary->GetComponent(p, 0), bary0->GetComponent(p, 0)));
    ASSERT_TRUE(SameBits(bary->GetComponent(p, 1), bary0->GetComponent(p, 1)));
  }
  ASSERT_NE(back->GetFieldData()->GetArray("OperationType"), nullptr);
  EXPECT_EQ(back->GetFieldData()->GetArray("OperationType")->GetComponent(0, 0), 3);

  // Written again from what was read (now with CurveId): the same file, byte for byte.
  const fs::path again = Scratch() / "sample-again.json";
  ASSERT_EQ(WriteScene(back, again, mesh.string()), "");
  std::ifstream f1(file), f2(again);
  const std::string s1((std::istreambuf_iterator<char>(f1)), {});
  const std::string s2((std::istreambuf_iterator<char>(f2)), {});
  EXPECT_EQ(s1, s2);
}

TEST(SceneWriter, SavedCurvesGiveTheSameRegion)
{
  auto grid = FlatGrid();
  auto curves = SampleCurves(grid);
  const fs::path mesh = WriteGrid(grid);
  const fs::path file = Scratch() / "region.json";
  ASSERT_EQ(WriteScene(curves, file, mesh.string()), "");
  std::string errors;
  auto reader = ReadScene(file, errors);
  ASSERT_EQ(errors, "");

  for (int operation = 0; operation < 4; ++operation)
  {
    vtkNew<vtkBoolSurf> before, after;
    before->SetInputData(0, grid);
    before->SetInputData(1, curves);
    after->SetInputConnection(0, reader->GetOutputPort(0));
    after->SetInputConnection(1, reader->GetOutputPort(1));
    for (vtkBoolSurf* f : { before.GetPointer(), after.GetPointer() })
    {
      f->SetOperation(operation);
      f->SetShapeA(0);
      f->SetShapeB(1);
      ASSERT_EQ(testutils::ErrorsOf(f), "");
    }
    const double area = testutils::Area(before->GetOutput(0));
    EXPECT_GT(area, 0.5) << "operation " << operation;
    EXPECT_NEAR(testutils::Area(after->GetOutput(0)), area, 1e-12) << "operation " << operation;
    EXPECT_EQ(after->GetOutput(0)->GetNumberOfCells(), before->GetOutput(0)->GetNumberOfCells());
  }
}

TEST(SceneWriter, ResolvedShapeSetSavedAndReopened)
{
  // A meridian of a torus (inconsistent: it bounds nothing) made a thin strip by Resolve
  // Inconsistent Shapes, a small loop beside it; the resolved set saved with its mesh reference,
  // reopened, gives the same curves and the same union.
  const double R = 2, r = 0.7, pi = std::acos(-1.0);
  auto torus = testutils::ToPolyData(boolsurf::MakeTorus(R, r, 48, 24));
  const fs::path mesh = Scratch() / "torus.ply";
  {
    vtkNew<vtkPLYWriter> ply;
    ply->SetInputData(torus);
    ply->SetFileName(mesh.string().c_str());
    ply->Write();
  }
  auto at = [&](double u, double v) -> std::array<double, 3>
  {
    return {
      (R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)
    };
  };
  testutils::ControlPolygon meridian, blob;
  for (int k = 0; k < 8; ++k)
  {
    meridian.Points.push_back(at(0.0, 2 * pi * k / 8));
    blob.Points.push_back(at(0.15 + 0.2 * std::cos(pi / 4 * k), 0.3 * std::sin(pi / 4 * k)));
  }
  blob.ShapeId = 1;
  vtkNew<vtkPLYReader> surface; // the mesh as the scene reader will read it (float coordinates)
  surface->SetFileName(mesh.string().c_str());
  vtkNew<vtkBoolSurfResolve> resolve;
  resolve->SetInputConnection(0, surface->GetOutputPort());
  resolve->SetInputData(1, testutils::ToCurves({ meridian, blob }));
  ASSERT_EQ(testutils::ErrorsOf(resolve), "");
  vtkPolyData* resolved = resolve->GetOutput();
  ASSERT_EQ(resolved->GetNumberOfCells(), 3) << "the meridian, its reversed copy, the loop";

  const fs::path file = Scratch() / "resolved.json";
  ASSERT_NE(WriteScene(resolved, file).find("no mesh reference"), std::string::npos);
  ASSERT_EQ(WriteScene(resolved, file, mesh.filename().string()), "");
  std::string errors;
  auto reader = ReadScene(file, errors);
  ASSERT_EQ(errors, "");
  vtkPolyData* back = reader->GetCurvesOutput();
  ASSERT_EQ(back->GetNumberOfCells(), 3);
  vtkDataArray* b0 = resolved->GetPointData()->GetArray("Barycentric");
  vtkDataArray* b1 = back->GetPointData()->GetArray("Barycentric");
  for (vtkIdType p = 0; p < resolved->GetNumberOfPoints(); ++p)
  {
    ASSERT_TRUE(SameBits(b0->GetComponent(p, 0), b1->GetComponent(p, 0)));
    ASSERT_TRUE(SameBits(b0->GetComponent(p, 1), b1->GetComponent(p, 1)));
  }

  vtkNew<vtkBoolSurf> before, after;
  before->SetInputConnection(0, surface->GetOutputPort());
  before->SetInputConnection(1, resolve->GetOutputPort());
  after->SetInputConnection(0, reader->GetOutputPort(0));
  after->SetInputConnection(1, reader->GetOutputPort(1));
  for (vtkBoolSurf* f : { before.GetPointer(), after.GetPointer() })
  {
    f->SetOperationToUnion();
    f->SetShapeA(0);
    f->SetShapeB(1);
    ASSERT_EQ(testutils::ErrorsOf(f), "");
  }
  const double area = testutils::Area(before->GetOutput(0));
  EXPECT_GT(area, 0.0);
  EXPECT_EQ(testutils::Area(after->GetOutput(0)), area);
}

TEST(SceneWriter, SavedBoundaryBoundsTheSameRegion)
{
  // A result's boundary (BoolSurf's Boundary Control Curves) saved as a scene, reopened and
  // taken as one shape under the non-zero rule is the same region, for every operation.
  auto grid = testutils::ToPolyData(boolsurf::MakeFlatSquare(12, 4.0, 0.3, 7));
  auto curves = ExactCurves(grid,
    { { { 0.5, 0.5 }, { 2.5, 0.7 }, { 2.4, 2.5 }, { 0.6, 2.3 } },
      { { 1.3, 1.1 }, { 3.7, 1.2 }, { 3.5, 3.3 }, { 1.6, 3.1 }, { 2.9, 2.2 } } },
    { 0, 1 },
    { 0, 0 },
    { true, true });
  const fs::path mesh = WriteGrid(grid, "jittered.ply");
  vtkNew<vtkPLYReader> surface; // the surface exactly as the reopened scene will have it
  surface->SetFileName(mesh.string().c_str());
  surface->Update();
  for (int operation = 0; operation < 4; ++operation)
  {
    SCOPED_TRACE("operation " + std::to_string(operation));
    vtkNew<vtkBoolSurf> first;
    first->SetInputConnection(0, surface->GetOutputPort());
    first->SetInputData(1, curves);
    first->SetOperation(operation);
    ASSERT_EQ(testutils::ErrorsOf(first), "");
    const double area = testutils::Area(first->GetOutput(0));
    ASSERT_GT(area, 0.1);
    const fs::path file = Scratch() / ("boundary" + std::to_string(operation) + ".json");
    EXPECT_NEAR(ReopenedBoundaryArea(first, file, mesh), area, 1e-9 * area);
  }
}

TEST(SceneWriter, SavedReversedSplineLoopBoundsTheSameRegion)
{
  // A clockwise closed spline meeting no other curve comes out of port 2 whole and reversed;
  // saved and reopened it must bound the same region (it did not while the reversed loop
  // started at a handle).
  auto grid = testutils::ToPolyData(boolsurf::MakeFlatSquare(12, 4.0, 0.3, 7));
  const double r = 0.7, k = 0.5523 * r, x = 1.2, y = 1.3;
  auto curves = ExactCurves(grid,
    { { { x + r, y },
        { x + r, y - k },
        { x + k, y - r },
        { x, y - r },
        { x - k, y - r },
        { x - r, y - k },
        { x - r, y },
        { x - r, y + k },
        { x - k, y + r },
        { x, y + r },
        { x + k, y + r },
        { x + r, y + k } },
      { { 2.6, 2.5 }, { 3.6, 2.6 }, { 3.1, 3.6 } } },
    { 0, 1 },
    { 1, 0 },
    { true, true });
  const fs::path mesh = WriteGrid(grid, "jittered-spline.ply");
  vtkNew<vtkPLYReader> surface;
  surface->SetFileName(mesh.string().c_str());
  surface->Update();
  for (int operation : { 0, 3 }) // union, xor
  {
    SCOPED_TRACE("operation " + std::to_string(operation));
    vtkNew<vtkBoolSurf> first;
    first->SetInputConnection(0, surface->GetOutputPort());
    first->SetInputData(1, curves);
    first->SetOperation(operation);
    ASSERT_EQ(testutils::ErrorsOf(first), "");
    const double area = testutils::Area(first->GetOutput(0));
    ASSERT_GT(area, 1.0);
    vtkDataArray* reversed =
      first->GetBoundaryControlCurvesOutput()->GetCellData()->GetArray("Reversed");
    ASSERT_TRUE(reversed);
    ASSERT_EQ(reversed->GetRange(0)[1], 1) << "the spline loop is not reversed: nothing tested";
    const fs::path file = Scratch() / ("spline-boundary" + std::to_string(operation) + ".json");
    EXPECT_NEAR(ReopenedBoundaryArea(first, file, mesh), area, 1e-9 * area);
  }
}

TEST(SceneWriter, BadInputIsANamedErrorAndWritesNothing)
{
  auto grid = FlatGrid();
  const fs::path mesh = WriteGrid(grid);
  auto expectRefused = [&](vtkPolyData* curves, const std::string& meshRef, const char* words)
  {
    const fs::path file = Scratch() / "refused.json";
    fs::remove(file);
    const std::string errors = WriteScene(curves, file, meshRef);
    EXPECT_NE(errors.find(words), std::string::npos) << errors;
    EXPECT_FALSE(fs::exists(file)) << "a refused write left a file";
    EXPECT_FALSE(fs::exists(file.string() + ".part"));
  };
  // No mesh reference anywhere.
  expectRefused(SampleCurves(grid), "", "no mesh reference");
  // Curves without surface points (3D points only).
  expectRefused(testutils::ToCurves({ { { { 0.5, 0.5, 0 }, { 2, 0.5, 0 }, { 1, 2, 0 } } } }),
    mesh.string(),
    "no surface points");
  // A TriangleId that is not a triangle index, named with its point id.
  {
    auto curves = SampleCurves(grid);
    curves->GetPointData()->GetArray("TriangleId")->SetComponent(2, 0, -1);
    expectRefused(curves, mesh.string(), "point 2: TriangleId -1");
  }
  // Barycentric coordinates outside the triangle.
  {
    auto curves = SampleCurves(grid);
    curves->GetPointData()->GetArray("Barycentric")->SetComponent(5, 0, 1.5);
    expectRefused(curves, mesh.string(), "point 5: Barycentric");
  }
  // A curve of one point, and an unknown curve type, named by cell id.
  {
    auto curves = SampleCurves(grid);
    vtkNew<vtkCellArray> lines;
    lines->InsertNextCell({ 0, 1, 2, 0 });
    lines->InsertNextCell({ 3 });
    curves->SetLines(lines);
    curves->GetCellData()->Initialize();
    expectRefused(curves, mesh.string(), "curve (cell) 1 has 1 point(s)");
  }
  {
    auto curves = SampleCurves(grid);
    curves->GetCellData()->GetArray("CurveType")->SetComponent(1, 0, 7);
    expectRefused(curves, mesh.string(), "curve (cell) 1: CurveType 7");
  }
  // No FileName.
  vtkNew<vtkBoolSurfSceneWriter> writer;
  writer->SetInputData(SampleCurves(grid));
  vtkNew<testutils::MessageCatcher> catcher;
  writer->AddObserver(vtkCommand::ErrorEvent, catcher);
  writer->Write();
  EXPECT_NE(catcher->Errors.find("No FileName"), std::string::npos) << catcher->Errors;
}

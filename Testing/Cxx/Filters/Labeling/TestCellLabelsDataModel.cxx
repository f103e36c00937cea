// Labels belong to cells: the labeling's cells x shapes table against an independent planar
// winding-number oracle, shape ids that are huge or sparse, the one-step filter's labels
// against the stage filters' on the reference scenes, and repeated edits of one filter
// against fresh filters.
#include "FilterTestUtils.h"
#include "vtkBoolSurf.h"
#include "vtkBoolSurfArrangement.h"
#include "vtkBoolSurfBoolean.h"
#include "vtkBoolSurfLabeling.h"
#include "vtkBoolSurfSceneReader.h"
#include "vtkBoolSurfTraceCurves.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>

#include <gtest/gtest.h>

#include <climits>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <random>
#include <string>

namespace
{
using testutils::ControlPolygon;

// Planar winding number of a closed polygon around q (crossings of the upward ray... signed).
int WindingNumber(const ControlPolygon& p, double qx, double qy)
{
  int w = 0;
  const size_t n = p.Points.size();
  for (size_t i = 0; i < n; ++i)
  {
    const auto& a = p.Points[i];
    const auto& b = p.Points[(i + 1) % n];
    const double side = (b[0] - a[0]) * (qy - a[1]) - (qx - a[0]) * (b[1] - a[1]);
    if (a[1] <= qy && b[1] > qy && side > 0)
      ++w;
    else if (a[1] > qy && b[1] <= qy && side < 0)
      --w;
  }
  return w;
}

ControlPolygon RandomPolygon(std::mt19937& rng, int shape)
{
  std::uniform_int_distribution<int> count(3, 7);
  std::uniform_int_distribution<int> grid(205, 3891); // [0.05, 0.95] in 1/4096 steps
  ControlPolygon p;
  p.ShapeId = shape;
  const int n = count(rng);
  for (int i = 0; i < n; ++i)
    p.Points.push_back({ grid(rng) / 4096.0, grid(rng) / 4096.0, 0.0 });
  return p;
}

ControlPolygon Square(double x0, double y0, double x1, double y1, int shape)
{
  return { { { x0, y0, 0 }, { x1, y0, 0 }, { x1, y1, 0 }, { x0, y1, 0 } }, shape, true };
}

struct ErrorText
{
  std::string Text;
  vtkNew<vtkCallbackCommand> Command;
  explicit ErrorText(vtkObject* o)
  {
    this->Command->SetClientData(this);
    this->Command->SetCallback([](vtkObject*, unsigned long, void* self, void* data)
      { static_cast<ErrorText*>(self)->Text += static_cast<const char*>(data); });
    o->AddObserver(vtkCommand::ErrorEvent, this->Command);
  }
};

std::vector<int> Ints(vtkDataArray* a)
{
  std::vector<int> v;
  for (vtkIdType i = 0; a && i < a->GetNumberOfTuples(); ++i)
    for (int k = 0; k < a->GetNumberOfComponents(); ++k)
      v.push_back(static_cast<int>(a->GetComponent(i, k)));
  return v;
}

// Everything a user reads from an output, exactly: points, connectivity, listed arrays.
void ExpectSamePolyData(vtkPolyData* a, vtkPolyData* b, const char* what)
{
  SCOPED_TRACE(what);
  ASSERT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints());
  ASSERT_EQ(a->GetNumberOfCells(), b->GetNumberOfCells());
  for (vtkIdType p = 0; p < a->GetNumberOfPoints(); ++p)
  {
    double x[3], y[3];
    a->GetPoint(p, x);
    b->GetPoint(p, y);
    ASSERT_TRUE(x[0] == y[0] && x[1] == y[1] && x[2] == y[2]) << "point " << p;
  }
  vtkNew<vtkIdList> ia, ib;
  for (vtkIdType c = 0; c < a->GetNumberOfCells(); ++c)
  {
    a->GetCellPoints(c, ia);
    b->GetCellPoints(c, ib);
    ASSERT_EQ(ia->GetNumberOfIds(), ib->GetNumberOfIds());
    for (vtkIdType k = 0; k < ia->GetNumberOfIds(); ++k)
      ASSERT_EQ(ia->GetId(k), ib->GetId(k)) << "cell " << c;
  }
  for (const char* name : { "ArrangementCell", "SourceTriangle" })
    EXPECT_EQ(Ints(a->GetCellData()->GetArray(name)), Ints(b->GetCellData()->GetArray(name)))
      << name;
  EXPECT_EQ(Ints(a->GetPointData()->GetArray("TriangleId")),
    Ints(b->GetPointData()->GetArray("TriangleId")));
  EXPECT_EQ(Ints(a->GetFieldData()->GetArray("CellLabels")),
    Ints(b->GetFieldData()->GetArray("CellLabels")));
}

std::filesystem::path SharedData()
{
  const char* d = std::getenv("BOOLSURF_SHARED_DATA");
  return d && *d ? std::filesystem::path(d) : std::filesystem::path();
}

} // namespace

// Every triangle's labels, read from the cell table by its ArrangementCell, are the planar
// winding numbers of its shape's polygons around the triangle's centroid (flat mesh: geodesic
// polygons are the polygons). Shape ids 7, 1000000 and INT_MAX cost three columns.
TEST(CellLabelsDataModel, CellTableMatchesPlanarWindingNumbers)
{
  vtkSmartPointer<vtkPolyData> mesh =
    testutils::ToPolyData(boolsurf::MakeFlatSquare(30, 1.0, 0.3, 4));
  const int ids[] = { 7, 1000000, INT_MAX };
  for (std::uint32_t seed = 1; seed <= 4; ++seed)
  {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937 rng(seed);
    std::vector<ControlPolygon> polygons;
    for (int k = 0; k < 5; ++k)
      polygons.push_back(RandomPolygon(rng, ids[k % 3]));
    vtkNew<vtkBoolSurfTraceCurves> trace;
    trace->SetInputData(0, mesh);
    trace->SetInputData(1, testutils::ToCurves(polygons));
    vtkNew<vtkBoolSurfArrangement> arrangement;
    arrangement->SetInputData(0, mesh);
    arrangement->SetInputConnection(1, trace->GetOutputPort());
    vtkNew<vtkBoolSurfLabeling> labeling;
    labeling->SetInputConnection(arrangement->GetOutputPort(0));
    labeling->SetColorShape(1000000);
    labeling->SetPerTriangleLabels(true);
    labeling->Update();
    vtkPolyData* out = labeling->GetOutput();
    vtkFieldData* fd = out->GetFieldData();
    EXPECT_EQ(Ints(fd->GetArray("ShapeIds")), (std::vector<int>{ 7, 1000000, INT_MAX }));
    vtkDataArray* table = fd->GetArray("CellLabels");
    ASSERT_NE(table, nullptr);
    const int cells = static_cast<int>(fd->GetArray("NumberOfCells")->GetComponent(0, 0));
    // Memory: cells x shapes, whatever the ids.
    EXPECT_EQ(table->GetNumberOfComponents(), 3);
    EXPECT_EQ(table->GetNumberOfTuples(), cells);
    EXPECT_STREQ(table->GetComponentName(2), "S2147483647");
    vtkDataArray* cellOf = out->GetCellData()->GetArray("ArrangementCell");
    vtkDataArray* perTriangle = out->GetCellData()->GetArray("Labels");
    vtkDataArray* colored = out->GetCellData()->GetArray("ShapeLabel");
    ASSERT_TRUE(cellOf && perTriangle && colored);
    vtkNew<vtkIdList> pts;
    for (vtkIdType t = 0; t < out->GetNumberOfCells(); ++t)
    {
      out->GetCellPoints(t, pts);
      double c[3] = { 0, 0, 0 };
      for (int k = 0; k < 3; ++k)
      {
        double x[3];
        out->GetPoint(pts->GetId(k), x);
        c[0] += x[0] / 3;
        c[1] += x[1] / 3;
      }
      const vtkIdType cell = static_cast<vtkIdType>(cellOf->GetComponent(t, 0));
      for (int s = 0; s < 3; ++s)
      {
        int expected = 0;
        for (const ControlPolygon& p : polygons)
          if (p.ShapeId == ids[s])
            expected += WindingNumber(p, c[0], c[1]);
        ASSERT_EQ(table->GetComponent(cell, s), expected) << "triangle " << t << " shape " << s;
        ASSERT_EQ(perTriangle->GetComponent(t, s), expected);
      }
      ASSERT_EQ(colored->GetComponent(t, 0), table->GetComponent(cell, 1));
    }
    // The default output has no per-triangle label array at all.
    labeling->SetColorShape(-1);
    labeling->SetPerTriangleLabels(false);
    labeling->Update();
    EXPECT_EQ(labeling->GetOutput()->GetCellData()->GetArray("Labels"), nullptr);
    EXPECT_EQ(labeling->GetOutput()->GetCellData()->GetArray("ShapeLabel"), nullptr);
  }
}

// Two squares with ShapeIds 1000000 and INT_MAX: every operation by id, through the one-step
// filter and through the stage filters, gives the exact areas; unknown ids are named errors.
TEST(CellLabelsDataModel, HugeShapeIdsSelectCorrectly)
{
  vtkSmartPointer<vtkPolyData> mesh =
    testutils::ToPolyData(boolsurf::MakeFlatSquare(24, 1.0, 0.25, 8));
  const int a = 1000000, b = INT_MAX;
  vtkSmartPointer<vtkPolyData> curves = testutils::ToCurves(
    { Square(0.125, 0.125, 0.625, 0.625, a), Square(0.375, 0.25, 0.875, 0.875, b) });
  const double areaA = 0.25, areaB = 0.5 * 0.625, both = 0.25 * 0.375;
  const std::map<int, double> expected{
    { 0, areaA + areaB - both }, { 1, both }, { 2, areaA - both }, { 3, areaA + areaB - 2 * both }
  };

  vtkNew<vtkBoolSurf> one;
  one->SetInputData(0, mesh);
  one->SetInputData(1, curves);
  one->SetShapeA(a);
  one->SetShapeB(b);
  vtkNew<vtkBoolSurfTraceCurves> trace;
  trace->SetInputData(0, mesh);
  trace->SetInputData(1, curves);
  vtkNew<vtkBoolSurfArrangement> arrangement;
  arrangement->SetInputData(0, mesh);
  arrangement->SetInputConnection(1, trace->GetOutputPort());
  vtkNew<vtkBoolSurfLabeling> labeling;
  labeling->SetInputConnection(arrangement->GetOutputPort(0));
  vtkNew<vtkBoolSurfBoolean> boolean;
  boolean->SetInputConnection(labeling->GetOutputPort());
  boolean->SetShapeA(a);
  boolean->SetShapeB(b);
  for (const auto& [operation, area] : expected)
  {
    SCOPED_TRACE("operation " + std::to_string(operation));
    one->SetOperation(operation);
    one->Update();
    EXPECT_NEAR(testutils::Area(one->GetOutput()), area, 1e-12);
    boolean->SetOperation(operation);
    boolean->Update();
    EXPECT_NEAR(testutils::Area(boolean->GetOutput()), area, 1e-12);
    for (vtkPolyData* region : { one->GetOutput(), boolean->GetOutput() })
    {
      EXPECT_EQ(region->GetCellData()->GetArray("Labels"), nullptr);
      vtkDataArray* table = region->GetFieldData()->GetArray("CellLabels");
      ASSERT_NE(table, nullptr);
      EXPECT_EQ(table->GetNumberOfComponents(), 2);
      EXPECT_LE(table->GetNumberOfTuples(), 4);
      EXPECT_EQ(Ints(region->GetFieldData()->GetArray("ShapeIds")), (std::vector<int>{ a, b }));
    }
  }
  one->SetOperationToExpression();
  one->SetExpression("S2147483647 - S1000000");
  one->Update();
  EXPECT_NEAR(testutils::Area(one->GetOutput()), areaB - both, 1e-12);

  ErrorText errors(one);
  one->SetOperationToUnion();
  one->SetShapeA(5);
  one->Update();
  EXPECT_NE(errors.Text.find("ShapeA = 5 is not a shape of the input (2 shape(s): S1000000, "
                             "S2147483647"),
    std::string::npos)
    << errors.Text;
  errors.Text.clear();
  one->SetOperationToExpression();
  one->SetExpression("S1000000 | S3");
  one->Update();
  EXPECT_NE(errors.Text.find("unknown shape S3"), std::string::npos) << errors.Text;
  // A refused request leaves empty outputs, not the previous region.
  EXPECT_EQ(one->GetOutput(0)->GetNumberOfCells(), 0);
  EXPECT_EQ(one->GetOutput(1)->GetNumberOfCells(), 0);
}

// One filter driven through curve edits and operation changes gives, after every update, the
// same outputs as a fresh filter on the same inputs (buffers reused, nothing stale).
TEST(CellLabelsDataModel, RepeatedEditsEqualFreshFilters)
{
  vtkSmartPointer<vtkPolyData> mesh =
    testutils::ToPolyData(boolsurf::MakeFlatSquare(36, 1.0, 0.3, 2));
  std::vector<vtkSmartPointer<vtkPolyData>> curveSets;
  for (std::uint32_t seed = 1; seed <= 3; ++seed)
  {
    std::mt19937 rng(40 + seed);
    std::vector<ControlPolygon> polygons;
    for (int k = 0; k < static_cast<int>(2 + seed); ++k)
      polygons.push_back(RandomPolygon(rng, k % 3 == 2 ? 90 : k % 3));
    curveSets.push_back(testutils::ToCurves(polygons));
  }
  const std::pair<int, int> steps[] = {
    { 0, 0 }, { 1, 0 }, { 1, 1 }, { 2, 3 }, { 2, 2 }, { 0, 0 }, { 0, 3 }
  };
  vtkNew<vtkBoolSurf> edited;
  edited->SetInputData(0, mesh);
  edited->SetShapeA(-1);
  edited->SetShapeB(-1);
  vtkNew<vtkBoolSurfArrangement> editedArrangement;
  editedArrangement->SetInputData(0, mesh);
  vtkNew<vtkBoolSurfTraceCurves> trace;
  trace->SetInputData(0, mesh);
  editedArrangement->SetInputConnection(1, trace->GetOutputPort());
  int step = 0;
  for (const auto& [set, operation] : steps)
  {
    SCOPED_TRACE("step " + std::to_string(step++));
    edited->SetInputData(1, curveSets[set]);
    edited->SetOperation(operation);
    edited->Update();
    vtkNew<vtkBoolSurf> fresh;
    fresh->SetInputData(0, mesh);
    fresh->SetInputData(1, curveSets[set]);
    fresh->SetShapeA(-1);
    fresh->SetShapeB(-1);
    fresh->SetOperation(operation);
    fresh->Update();
    ASSERT_GT(fresh->GetOutput()->GetNumberOfCells(), 0);
    ExpectSamePolyData(edited->GetOutput(0), fresh->GetOutput(0), "region");
    ExpectSamePolyData(edited->GetOutput(1), fresh->GetOutput(1), "boundary");

    trace->SetInputData(1, curveSets[set]);
    editedArrangement->Update();
    vtkNew<vtkBoolSurfTraceCurves> freshTrace;
    freshTrace->SetInputData(0, mesh);
    freshTrace->SetInputData(1, curveSets[set]);
    vtkNew<vtkBoolSurfArrangement> freshArrangement;
    freshArrangement->SetInputData(0, mesh);
    freshArrangement->SetInputConnection(1, freshTrace->GetOutputPort());
    freshArrangement->Update();
    ExpectSamePolyData(
      editedArrangement->GetOutput(0), freshArrangement->GetOutput(0), "refined surface");
  }
}

// On the reference scenes, the one-step filter (labels straight from the Core arrangement) and
// the stage filters (labels from the arrangement's field data) give the same cells x shapes
// table, and the opt-in per-triangle labels are its rows.
TEST(CellLabelsDataModel, OneStepAndStageLabelsAgreeOnReferenceScenes)
{
  const std::filesystem::path data = SharedData();
  if (data.empty() || !std::filesystem::is_directory(data / "boolsurf-scenes"))
  {
    GTEST_SKIP() << "BOOLSURF_SHARED_DATA is not set or has no boolsurf-scenes/: this test "
                    "needs ../shared/data";
  }
  for (const char* name : { "tests/bunny2.json",
         "tests/bunny3.json",
         "final_tests/bimba.json",
         "tests/loop2.json",
         "tests/examples/tritorus-5loops.json" })
  {
    SCOPED_TRACE(name);
    vtkNew<vtkBoolSurfSceneReader> reader;
    reader->SetFileName((data / "boolsurf-scenes" / name).string().c_str());
    reader->Update();
    ASSERT_GT(reader->GetOutput(0)->GetNumberOfCells(), 0);
    vtkNew<vtkBoolSurfTraceCurves> trace;
    trace->SetInputConnection(0, reader->GetOutputPort(0));
    trace->SetInputConnection(1, reader->GetOutputPort(1));
    vtkNew<vtkBoolSurfArrangement> arrangement;
    arrangement->SetInputConnection(0, reader->GetOutputPort(0));
    arrangement->SetInputConnection(1, trace->GetOutputPort());
    vtkNew<vtkBoolSurfLabeling> labeling;
    labeling->SetInputConnection(arrangement->GetOutputPort(0));
    labeling->SetPerTriangleLabels(true);
    labeling->Update();
    vtkFieldData* fd = labeling->GetOutput()->GetFieldData();
    const std::vector<int> table = Ints(fd->GetArray("CellLabels"));
    const std::vector<int> ids = Ints(fd->GetArray("ShapeIds"));
    const std::vector<int> consistent = Ints(fd->GetArray("ShapeConsistent"));
    ASSERT_FALSE(ids.empty());
    const size_t ns = ids.size();
    vtkDataArray* cellOf = labeling->GetOutput()->GetCellData()->GetArray("ArrangementCell");
    vtkDataArray* perTriangle = labeling->GetOutput()->GetCellData()->GetArray("Labels");
    for (vtkIdType t = 0; t < cellOf->GetNumberOfTuples(); ++t)
      for (size_t s = 0; s < ns; ++s)
        ASSERT_EQ(perTriangle->GetComponent(t, static_cast<int>(s)),
          table[static_cast<size_t>(cellOf->GetComponent(t, 0)) * ns + s]);

    // The one-step filter needs a consistent operand for its Boolean.
    size_t operand = 0;
    while (operand < ns && !consistent[operand])
      ++operand;
    if (operand == ns)
      continue;
    vtkNew<vtkBoolSurf> one;
    one->SetInputConnection(0, reader->GetOutputPort(0));
    one->SetInputConnection(1, reader->GetOutputPort(1));
    one->SetOperationToExpression();
    one->SetExpression(("S" + std::to_string(ids[operand])).c_str());
    one->Update();
    vtkFieldData* ofd = one->GetOutput()->GetFieldData();
    EXPECT_EQ(Ints(ofd->GetArray("CellLabels")), table);
    EXPECT_EQ(Ints(ofd->GetArray("ShapeIds")), ids);
    EXPECT_EQ(Ints(ofd->GetArray("ShapeConsistent")), consistent);
  }
}

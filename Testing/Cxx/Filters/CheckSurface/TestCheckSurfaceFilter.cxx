// vtkBoolSurfCheckSurface on vtkPolyData inputs: arrays, field data, and every bad-input case
// reported by name without a crash.
#include "FilterTestUtils.h"
#include "vtkBoolSurf.h"
#include "vtkBoolSurfCheckSurface.h"

#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSphereSource.h>
#include <vtkStringArray.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace
{
vtkSmartPointer<vtkPolyData> RunCheck(vtkPolyData* input)
{
  vtkNew<vtkBoolSurfCheckSurface> check;
  check->WarnOnProblemsOff();
  check->SetInputData(input);
  check->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(check->GetOutput());
  return out;
}

int FieldInt(vtkPolyData* pd, const char* name, int index = 0)
{
  auto* a = vtkIntArray::SafeDownCast(pd->GetFieldData()->GetAbstractArray(name));
  EXPECT_NE(a, nullptr) << name;
  return a ? a->GetValue(index) : -999;
}

// The Problems entry that starts with "<level> <kind>:" or an empty string.
std::string Problem(vtkPolyData* pd, const std::string& prefix)
{
  auto* a = vtkStringArray::SafeDownCast(pd->GetFieldData()->GetAbstractArray("Problems"));
  if (!a)
  {
    return "";
  }
  for (vtkIdType i = 0; i < a->GetNumberOfValues(); ++i)
  {
    if (a->GetValue(i).rfind(prefix, 0) == 0)
    {
      return a->GetValue(i);
    }
  }
  return "";
}

vtkSmartPointer<vtkPolyData> TwoTriangles()
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> pts;
  pts->InsertNextPoint(0, 0, 0);
  pts->InsertNextPoint(1, 0, 0);
  pts->InsertNextPoint(1, 1, 0);
  pts->InsertNextPoint(0, 1, 0);
  vtkNew<vtkCellArray> polys;
  polys->InsertNextCell({ 0, 1, 2 });
  polys->InsertNextCell({ 0, 2, 3 });
  pd->SetPoints(pts);
  pd->SetPolys(polys);
  return pd;
}
} // namespace

TEST(CheckSurfaceFilter, SphereIsAValidGenusZeroSurface)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(16);
  sphere->Update();
  auto out = RunCheck(sphere->GetOutput());
  EXPECT_EQ(FieldInt(out, "Components"), 1);
  EXPECT_EQ(FieldInt(out, "Genus"), 0);
  EXPECT_EQ(FieldInt(out, "BoundaryLoops"), 0);
  EXPECT_EQ(FieldInt(out, "EulerCharacteristic"), 2);
  EXPECT_EQ(FieldInt(out, "IsManifold"), 1);
  auto* comp = vtkIntArray::SafeDownCast(out->GetCellData()->GetArray("ComponentId"));
  ASSERT_NE(comp, nullptr);
  EXPECT_EQ(comp->GetNumberOfTuples(), out->GetNumberOfCells());
  EXPECT_EQ(comp->GetRange()[0], 0);
  EXPECT_EQ(comp->GetRange()[1], 0);
  EXPECT_EQ(Problem(out, "Error"), "");
}

TEST(CheckSurfaceFilter, QuadsAreTriangulatedWithAWarning)
{
  vtkNew<vtkPlaneSource> plane; // 4 x 3 quads
  plane->SetResolution(4, 3);
  plane->Update();
  auto out = RunCheck(plane->GetOutput());
  EXPECT_EQ(out->GetNumberOfCells(), 24);
  EXPECT_NE(Problem(out, "Warning Conversion: triangulated 12 non-triangle polygon(s)"), "");
  EXPECT_EQ(FieldInt(out, "BoundaryLoops"), 1);
  EXPECT_EQ(FieldInt(out, "Genus"), 0);
  auto* loop = vtkIntArray::SafeDownCast(out->GetPointData()->GetArray("BoundaryLoopId"));
  ASSERT_NE(loop, nullptr);
  int inside = 0;
  for (vtkIdType i = 0; i < loop->GetNumberOfTuples(); ++i)
  {
    inside += loop->GetValue(i) == -1 ? 1 : 0;
  }
  EXPECT_EQ(inside, 3 * 2); // (4-1) x (3-1) interior points
}

TEST(CheckSurfaceFilter, LinesAndVertsAreIgnoredWithAWarning)
{
  auto pd = TwoTriangles();
  vtkNew<vtkCellArray> lines;
  lines->InsertNextCell({ 0, 2 });
  vtkNew<vtkCellArray> verts;
  verts->InsertNextCell({ 1 });
  pd->SetLines(lines);
  pd->SetVerts(verts);
  auto out = RunCheck(pd);
  EXPECT_EQ(out->GetNumberOfCells(), 2);
  EXPECT_EQ(out->GetNumberOfLines(), 0);
  EXPECT_NE(Problem(out, "Warning Conversion: ignored 1 vertex cell(s) and 1 line cell(s)"), "");
}

TEST(CheckSurfaceFilter, EmptyInputIsNamed)
{
  vtkNew<vtkPolyData> empty;
  auto out = RunCheck(empty);
  EXPECT_NE(Problem(out, "Error EmptyInput"), "");
  EXPECT_EQ(FieldInt(out, "Components"), 0);
  EXPECT_EQ(out->GetFieldData()->GetAbstractArray("Genus"), nullptr);
}

TEST(CheckSurfaceFilter, NaNCoordinatesAreNamed)
{
  auto pd = TwoTriangles();
  pd->GetPoints()->SetPoint(3, std::numeric_limits<double>::quiet_NaN(), 0, 0);
  auto out = RunCheck(pd);
  const std::string p = Problem(out, "Error NonFiniteCoordinates");
  EXPECT_NE(p.find("point ids: 3"), std::string::npos) << p;
}

TEST(CheckSurfaceFilter, NonManifoldEdgeAndOrientation)
{
  auto pd = TwoTriangles();
  pd->GetPoints()->InsertNextPoint(0.5, 0.5, 1.0);
  pd->GetPolys()->InsertNextCell({ 0, 2, 4 });
  auto out = RunCheck(pd);
  EXPECT_NE(Problem(out, "Error NonManifoldEdge").find("(0, 2)"), std::string::npos);
  EXPECT_EQ(FieldInt(out, "IsManifold"), 0);

  auto flipped = TwoTriangles();
  vtkNew<vtkCellArray> polys;
  polys->InsertNextCell({ 0, 1, 2 });
  polys->InsertNextCell({ 0, 3, 2 });
  flipped->SetPolys(polys);
  out = RunCheck(flipped);
  EXPECT_NE(Problem(out, "Error InconsistentOrientation").find("0/1"), std::string::npos);
}

TEST(CheckSurfaceFilter, DegenerateTriangleIsNamed)
{
  auto pd = TwoTriangles();
  pd->GetPoints()->InsertNextPoint(2, 0, 0);
  pd->GetPolys()->InsertNextCell({ 1, 0, 4 });
  auto out = RunCheck(pd);
  EXPECT_NE(Problem(out, "Error DegenerateTriangle").find("triangle ids: 2"), std::string::npos);
}

// Point ids outside the points (2^32 + 1, 10^7, one past the end) in triangles and in quads
// are named with their cell before anything reads them: no triangulation crash, no id wrapped
// to a valid one by a narrowing conversion, no quad dropped silently; the one-step filter
// refuses the surface with the same message.
TEST(CheckSurfaceFilter, InvalidPointIdsAreNamedBeforeTriangulation)
{
  auto pd = TwoTriangles();
  pd->GetPolys()->InsertNextCell({ 0, 1, (vtkIdType(1) << 32) + 1 });
  pd->GetPolys()->InsertNextCell({ 0, 1, 2, 10000000 });
  pd->GetPolys()->InsertNextCell({ 0, 1, 2, 4 });
  auto out = RunCheck(pd);
  const std::string p = Problem(out, "Error InvalidVertexIndex");
  EXPECT_NE(p.find("3 polygon(s) use point ids outside [0, 4)"), std::string::npos) << p;
  EXPECT_NE(p.find("2 (4294967297), 3 (10000000), 4 (4)"), std::string::npos) << p;

  vtkNew<vtkBoolSurf> one;
  one->SetInputData(0, pd);
  one->SetInputData(
    1, testutils::ToCurves({ { { { 0.2, 0.1, 0 }, { 0.9, 0.2, 0 }, { 0.8, 0.7, 0 } }, 0, true } }));
  vtkNew<vtkCallbackCommand> quiet;
  std::string errors;
  quiet->SetClientData(&errors);
  quiet->SetCallback([](vtkObject*, unsigned long, void* text, void* data)
    { *static_cast<std::string*>(text) += static_cast<const char*>(data); });
  one->AddObserver(vtkCommand::ErrorEvent, quiet);
  one->Update();
  EXPECT_NE(errors.find("point ids outside [0, 4)"), std::string::npos) << errors;
  EXPECT_EQ(one->GetOutput()->GetNumberOfCells(), 0);
}

// Problem messages count what they list (the count used to be taken after the list was moved).
TEST(CheckSurfaceFilter, ProblemCountsMatchTheirIds)
{
  auto pd = TwoTriangles();
  pd->GetPoints()->SetPoint(3, std::numeric_limits<double>::quiet_NaN(), 0, 0);
  pd->GetPoints()->SetPoint(1, std::numeric_limits<double>::infinity(), 0, 0);
  auto out = RunCheck(pd);
  const std::string p = Problem(out, "Error NonFiniteCoordinates");
  EXPECT_NE(
    p.find("2 point(s) have NaN or infinite coordinates, point ids: 1, 3"), std::string::npos)
    << p;
}

// vtkBoolSurfSubdivide: curves carried onto VTK's linear subdivision keep their 3D points (to
// 1e-12) and, on a flat mesh, give the same Boolean region; on Loop subdivision points on coarse
// vertices stay on those (moved) vertices and every point lies in a child of its triangle; bad
// input is a named error.
#include "vtkBoolSurf.h"
#include "vtkBoolSurfSubdivide.h"

#include "FilterTestUtils.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkLinearSubdivisionFilter.h>
#include <vtkLoopSubdivisionFilter.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <random>

namespace
{

/// Closed curves of random exact surface points (a few on vertices and edges) on `surface`.
vtkSmartPointer<vtkPolyData> RandomCurves(vtkPolyData* surface, int curves, int perCurve, int seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  std::uniform_int_distribution<vtkIdType> triangle(0, surface->GetNumberOfCells() - 1);
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkIdTypeArray> ids;
  ids->SetName("TriangleId");
  vtkNew<vtkDoubleArray> bary;
  bary->SetName("Barycentric");
  bary->SetNumberOfComponents(2);
  vtkNew<vtkCellArray> lines;
  for (int c = 0; c < curves; ++c)
  {
    lines->InsertNextCell(perCurve + 1); // closed: the first point repeated at the end
    const vtkIdType first = points->GetNumberOfPoints();
    for (int k = 0; k < perCurve; ++k)
    {
      const vtkIdType t = triangle(rng);
      double u = unit(rng), v = unit(rng);
      if (u + v > 1)
      {
        u = 1 - u;
        v = 1 - v;
      }
      if (k % 5 == 1)
      {
        u = v = 0; // on corner 0
      }
      else if (k % 5 == 2)
      {
        v = 0; // on edge (0, 1)
      }
      vtkIdType n;
      const vtkIdType* corner;
      surface->GetCellPoints(t, n, corner);
      double a[3], b[3], cc[3], x[3];
      surface->GetPoint(corner[0], a);
      surface->GetPoint(corner[1], b);
      surface->GetPoint(corner[2], cc);
      for (int j = 0; j < 3; ++j)
      {
        x[j] = (1 - u - v) * a[j] + u * b[j] + v * cc[j];
      }
      lines->InsertCellPoint(points->InsertNextPoint(x));
      ids->InsertNextValue(t);
      bary->InsertNextTuple2(u, v);
    }
    lines->InsertCellPoint(first);
  }
  pd->SetPoints(points);
  pd->SetLines(lines);
  pd->GetPointData()->AddArray(ids);
  pd->GetPointData()->AddArray(bary);
  return pd;
}

/// The curve points' 3D positions recomputed from TriangleId/Barycentric on `surface`.
std::vector<std::array<double, 3>> Evaluate(vtkPolyData* surface, vtkPolyData* curves)
{
  vtkDataArray* ids = curves->GetPointData()->GetArray("TriangleId");
  vtkDataArray* bary = curves->GetPointData()->GetArray("Barycentric");
  std::vector<std::array<double, 3>> out;
  for (vtkIdType p = 0; p < curves->GetNumberOfPoints(); ++p)
  {
    vtkIdType n;
    const vtkIdType* corner;
    surface->GetCellPoints(static_cast<vtkIdType>(ids->GetComponent(p, 0)), n, corner);
    const double u = bary->GetComponent(p, 0), v = bary->GetComponent(p, 1);
    double a[3], b[3], c[3];
    surface->GetPoint(corner[0], a);
    surface->GetPoint(corner[1], b);
    surface->GetPoint(corner[2], c);
    out.push_back({ (1 - u - v) * a[0] + u * b[0] + v * c[0],
      (1 - u - v) * a[1] + u * b[1] + v * c[1],
      (1 - u - v) * a[2] + u * b[2] + v * c[2] });
  }
  return out;
}

} // namespace

TEST(SubdivideFilter, LinearSubdivisionKeepsEveryPoint)
{
  auto sphere = testutils::ToPolyData(boolsurf::MakeIcosphere(2));
  auto curves = RandomCurves(sphere, 6, 20, 11);
  const auto before = Evaluate(sphere, curves);
  vtkNew<vtkBoolSurfSubdivide> subdivide;
  subdivide->SetInputData(0, sphere);
  subdivide->SetInputData(1, curves);
  subdivide->SetNumberOfSubdivisions(3);
  ASSERT_EQ(testutils::ErrorsOf(subdivide), "");
  vtkPolyData* finer = subdivide->GetOutput(0);
  vtkPolyData* moved = subdivide->GetCurvesOutput();
  EXPECT_EQ(finer->GetNumberOfCells(), 64 * sphere->GetNumberOfCells());
  // The output surface is VTK's own linear subdivision.
  vtkNew<vtkLinearSubdivisionFilter> reference;
  reference->SetInputData(sphere);
  reference->SetNumberOfSubdivisions(3);
  reference->Update();
  EXPECT_EQ(reference->GetOutput()->GetNumberOfPoints(), finer->GetNumberOfPoints());
  const auto after = Evaluate(finer, moved);
  ASSERT_EQ(after.size(), before.size());
  for (std::size_t p = 0; p < before.size(); ++p)
  {
    double out[3];
    moved->GetPoint(static_cast<vtkIdType>(p), out);
    EXPECT_LT(std::sqrt(vtkMath::Distance2BetweenPoints(after[p].data(), before[p].data())), 1e-12)
      << "point " << p;
    EXPECT_LT(std::sqrt(vtkMath::Distance2BetweenPoints(out, before[p].data())), 1e-12);
  }
  EXPECT_EQ(moved->GetNumberOfCells(), curves->GetNumberOfCells());
}

TEST(SubdivideFilter, FlatBooleanIsTheSameOnTheFinerSurface)
{
  // Geodesics on a flat mesh are straight segments: the region of a Boolean cannot depend on
  // how finely the square is triangulated.
  auto square = testutils::ToPolyData(boolsurf::MakeFlatSquare(6, 1.0, 0.3, 5));
  auto curves = RandomCurves(square, 3, 5, 4);
  vtkNew<vtkBoolSurfSubdivide> subdivide;
  subdivide->SetInputData(0, square);
  subdivide->SetInputData(1, curves);
  subdivide->SetNumberOfSubdivisions(2);
  ASSERT_EQ(testutils::ErrorsOf(subdivide), "");
  for (int operation = 0; operation < 4; ++operation)
  {
    vtkNew<vtkBoolSurf> coarse, fine;
    coarse->SetInputData(0, square);
    coarse->SetInputData(1, curves);
    fine->SetInputConnection(0, subdivide->GetOutputPort(0));
    fine->SetInputConnection(1, subdivide->GetOutputPort(1));
    for (vtkBoolSurf* f : { coarse.GetPointer(), fine.GetPointer() })
    {
      f->SetOperation(operation);
      f->SetShapeA(0);
      f->SetShapeB(1);
      f->SetFillRule(1); // non-zero: random polygons self-intersect
      ASSERT_EQ(testutils::ErrorsOf(f), "") << "operation " << operation;
    }
    const double area = testutils::Area(coarse->GetOutput(0));
    EXPECT_GT(area, 1e-3) << "operation " << operation;
    EXPECT_NEAR(testutils::Area(fine->GetOutput(0)), area, 1e-9) << "operation " << operation;
  }
}

TEST(SubdivideFilter, LoopSubdivisionMovesPointsWithTheSurface)
{
  auto sphere = testutils::ToPolyData(boolsurf::MakeIcosphere(1));
  auto curves = RandomCurves(sphere, 4, 20, 2);
  vtkNew<vtkBoolSurfSubdivide> subdivide;
  subdivide->SetInputData(0, sphere);
  subdivide->SetInputData(1, curves);
  subdivide->SetSchemeToLoop();
  subdivide->SetNumberOfSubdivisions(2);
  ASSERT_EQ(testutils::ErrorsOf(subdivide), "");
  vtkPolyData* finer = subdivide->GetOutput(0);
  vtkPolyData* moved = subdivide->GetCurvesOutput();
  vtkNew<vtkLoopSubdivisionFilter> reference;
  reference->SetInputData(sphere);
  reference->SetNumberOfSubdivisions(2);
  reference->Update();
  ASSERT_EQ(reference->GetOutput()->GetNumberOfPoints(), finer->GetNumberOfPoints());
  for (vtkIdType v = 0; v < finer->GetNumberOfPoints(); v += 7)
  {
    double a[3], b[3];
    finer->GetPoint(v, a);
    reference->GetOutput()->GetPoint(v, b);
    EXPECT_EQ(vtkMath::Distance2BetweenPoints(a, b), 0.0) << "vertex " << v;
  }
  vtkDataArray* ids0 = curves->GetPointData()->GetArray("TriangleId");
  vtkDataArray* bary0 = curves->GetPointData()->GetArray("Barycentric");
  vtkDataArray* ids = moved->GetPointData()->GetArray("TriangleId");
  vtkDataArray* bary = moved->GetPointData()->GetArray("Barycentric");
  const auto positions = Evaluate(finer, moved);
  for (vtkIdType p = 0; p < moved->GetNumberOfPoints(); ++p)
  {
    const double u = bary->GetComponent(p, 0), v = bary->GetComponent(p, 1);
    ASSERT_TRUE(u >= 0 && v >= 0 && u + v <= 1) << "point " << p;
    vtkIdType n;
    const vtkIdType* coarse;
    sphere->GetCellPoints(static_cast<vtkIdType>(ids0->GetComponent(p, 0)), n, coarse);
    const double u0 = bary0->GetComponent(p, 0), v0 = bary0->GetComponent(p, 1);
    vtkIdType nf;
    const vtkIdType* fine;
    finer->GetCellPoints(static_cast<vtkIdType>(ids->GetComponent(p, 0)), nf, fine);
    // A coarse corner keeps its id and its child at that corner holds the point, at weight 1:
    // the point is exactly the smoothed vertex.
    if (u0 == 0 && v0 == 0)
    {
      double x[3];
      finer->GetPoint(coarse[0], x);
      EXPECT_EQ(vtkMath::Distance2BetweenPoints(x, positions[p].data()), 0.0) << "point " << p;
    }
  }
  // Loop and linear subdivision split alike (VTK numbers the new vertices and triangles the same
  // way), so the points land in the same child triangles at the same parameters: only the
  // surface moved.
  vtkNew<vtkBoolSurfSubdivide> linear;
  linear->SetInputData(0, sphere);
  linear->SetInputData(1, curves);
  linear->SetNumberOfSubdivisions(2);
  ASSERT_EQ(testutils::ErrorsOf(linear), "");
  vtkPolyData* flat = linear->GetCurvesOutput();
  for (vtkIdType p = 0; p < moved->GetNumberOfPoints(); ++p)
  {
    EXPECT_EQ(
      flat->GetPointData()->GetArray("TriangleId")->GetComponent(p, 0), ids->GetComponent(p, 0));
    EXPECT_EQ(
      flat->GetPointData()->GetArray("Barycentric")->GetComponent(p, 0), bary->GetComponent(p, 0));
    EXPECT_EQ(
      flat->GetPointData()->GetArray("Barycentric")->GetComponent(p, 1), bary->GetComponent(p, 1));
  }
}

TEST(SubdivideFilter, BadInputIsANamedError)
{
  auto sphere = testutils::ToPolyData(boolsurf::MakeIcosphere(1));
  auto curves = RandomCurves(sphere, 1, 4, 1);
  {
    vtkNew<vtkBoolSurfSubdivide> f;
    f->SetInputData(0, sphere);
    f->SetInputData(1, testutils::ToCurves({ { { { 0, 0, 1 }, { 0, 1, 0 }, { 1, 0, 0 } } } }));
    EXPECT_NE(testutils::ErrorsOf(f).find("no surface points"), std::string::npos);
    EXPECT_EQ(f->GetOutput(0)->GetNumberOfCells(), 0);
  }
  {
    auto bad = vtkSmartPointer<vtkPolyData>::New();
    bad->DeepCopy(curves);
    bad->GetPointData()->GetArray("TriangleId")->SetComponent(2, 0, 1e6);
    vtkNew<vtkBoolSurfSubdivide> f;
    f->SetInputData(0, sphere);
    f->SetInputData(1, bad);
    EXPECT_NE(testutils::ErrorsOf(f).find("Curve point 2: TriangleId 1e+06"), std::string::npos);
  }
  {
    auto quads = vtkSmartPointer<vtkPolyData>::New();
    quads->DeepCopy(sphere);
    vtkNew<vtkCellArray> polys;
    polys->InsertNextCell({ 0, 1, 2, 3 });
    quads->SetPolys(polys);
    vtkNew<vtkBoolSurfSubdivide> f;
    f->SetInputData(0, quads);
    f->SetInputData(1, curves);
    EXPECT_NE(testutils::ErrorsOf(f).find("surface cell 0 has 4 points"), std::string::npos);
  }
}

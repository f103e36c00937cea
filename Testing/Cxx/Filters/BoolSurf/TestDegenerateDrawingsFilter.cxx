// Degenerate but valid drawings through the product: integer polygons given as 3D control
// points to the one-step vtkBoolSurf filter (projected and traced like a user's curves), on
// random Delaunay meshes and on grids aligned with the lattice (curves through mesh vertices
// and along mesh edges). Every drawing must be answered, with the exact planar area
// (independent sweep over winding numbers), the same on every mesh.
#include "FilterTestUtils.h"
#include "Support/PlanarWinding.h"
#include "vtkBoolSurf.h"

#include <vtkCellArray.h>
#include <vtkDelaunay2D.h>
#include <vtkPoints.h>

#include <gtest/gtest.h>

#include <random>

using namespace boolsurf::testing;

namespace
{

using Points = std::vector<std::array<long long, 2>>;

/// Delaunay triangulation of the square [lo, hi]^2: its corners, points along its sides and
/// random points inside.
vtkSmartPointer<vtkPolyData> RandomDelaunaySquare(double lo, double hi, int inside, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> coord(lo, hi);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  const int side = 8;
  for (int i = 0; i < side; ++i)
  {
    const double s = lo + (hi - lo) * i / side, t = lo + (hi - lo) * (i + 1) / side;
    points->InsertNextPoint(s, lo, 0);
    points->InsertNextPoint(hi, s, 0);
    points->InsertNextPoint(t, hi, 0);
    points->InsertNextPoint(lo, t, 0);
  }
  for (int i = 0; i < inside; ++i)
    points->InsertNextPoint(coord(rng), coord(rng), 0);
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(points);
  vtkNew<vtkDelaunay2D> delaunay;
  delaunay->SetInputData(cloud);
  delaunay->Update();
  // vtkDelaunay2D does not orient its triangles consistently: turn each counter-clockwise
  // (normal +z, like the grids), so that a counter-clockwise polygon bounds winding +1.
  vtkPolyData* out = delaunay->GetOutput();
  vtkNew<vtkCellArray> triangles;
  vtkIdType n;
  const vtkIdType* ids;
  vtkCellArray* polys = out->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    double a[3], b[3], c[3];
    out->GetPoint(ids[0], a);
    out->GetPoint(ids[1], b);
    out->GetPoint(ids[2], c);
    const bool ccw = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) > 0;
    const vtkIdType tri[3] = { ids[0], ccw ? ids[1] : ids[2], ccw ? ids[2] : ids[1] };
    triangles->InsertNextCell(3, tri);
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(out->GetPoints());
  mesh->SetPolys(triangles);
  return mesh;
}

/// A grid over [lo, hi]^2 whose vertices are the multiples of `step` (every lattice line
/// through them runs along mesh edges).
vtkSmartPointer<vtkPolyData> AlignedGrid(double lo, double hi, double step = 1)
{
  const int n = static_cast<int>((hi - lo) / step);
  boolsurf::MeshData d = boolsurf::MakeFlatSquare(n, hi - lo);
  for (auto& p : d.Positions)
  {
    p.x += lo;
    p.y += lo;
  }
  return testutils::ToPolyData(d);
}

vtkSmartPointer<vtkPolyData> CurvesOf(const std::vector<LatticePolygon>& drawing)
{
  std::vector<testutils::ControlPolygon> polygons;
  for (const auto& p : drawing)
  {
    testutils::ControlPolygon c;
    c.ShapeId = p.Shape;
    for (const auto& x : p.Points)
      c.Points.push_back({ double(x[0]), double(x[1]), 0.0 });
    polygons.push_back(c);
  }
  return testutils::ToCurves(polygons);
}

/// Area of the one-step result, or -1 (with the error as a test failure) when refused.
double BooleanArea(vtkPolyData* mesh,
  vtkPolyData* curves,
  int op,
  int rule,
  const char* expr,
  const std::string& what)
{
  vtkNew<vtkBoolSurf> f;
  f->SetInputData(0, mesh);
  f->SetInputData(1, curves);
  f->SetFillRule(rule);
  f->SetNumberOfThreads(1);
  if (expr)
  {
    f->SetOperationToExpression();
    f->SetExpression(expr);
  }
  else
  {
    f->SetOperation(op);
  }
  const std::string errors = testutils::ErrorsOf(f);
  if (!errors.empty())
  {
    ADD_FAILURE() << what << ": refused: " << errors;
    return -1;
  }
  return testutils::Area(f->GetOutput());
}

void ExpectAnswered(const Points& polygon, double expected, double lo, double hi, double step = 1)
{
  const std::vector<LatticePolygon> drawing{ { 0, polygon } };
  const double swept = SweepArea(drawing, 1, [](const std::vector<int>& w) { return w[0] != 0; });
  // The issue quotes areas to two decimals.
  ASSERT_NEAR(swept, expected, 0.005) << "the oracle disagrees with the issue's area";
  vtkSmartPointer<vtkPolyData> curves = CurvesOf(drawing);
  for (int m = 0; m <= 10; ++m)
  {
    vtkSmartPointer<vtkPolyData> mesh =
      m < 10 ? RandomDelaunaySquare(lo, hi, 150, 31 + m) : AlignedGrid(lo, hi, step);
    const std::string what = (m < 10 ? "Delaunay mesh " + std::to_string(m) : "aligned grid");
    const double area = BooleanArea(mesh, curves, 0, 0, "S0", what);
    EXPECT_NEAR(area, swept, 1e-9 * (hi - lo) * (hi - lo)) << what;
  }
}

} // namespace

TEST(DegenerateDrawingsFilter, IssueCasesOnTenDelaunayMeshesAndAnAlignedGrid)
{
  for (const DegenerateCase& c : DegenerateIssueCases())
  {
    SCOPED_TRACE(c.Name);
    ExpectAnswered(c.Points, c.Area, c.Lo, c.Hi, c.Step);
  }
}

TEST(DegenerateDrawingsFilter, SquaresOverlappingAlongPartOfAnEdgeUnion)
{
  // Two 10 x 10 squares, the second shifted by (10, 5): their vertical edges overlap along
  // half their length. Union 200, intersection 0.
  const std::vector<LatticePolygon> drawing{ { 0, { { 0, 0 }, { 10, 0 }, { 10, 10 }, { 0, 10 } } },
    { 1, { { 10, 5 }, { 20, 5 }, { 20, 15 }, { 10, 15 } } } };
  vtkSmartPointer<vtkPolyData> curves = CurvesOf(drawing);
  for (int m = 0; m <= 10; ++m)
  {
    vtkSmartPointer<vtkPolyData> mesh =
      m < 10 ? RandomDelaunaySquare(-2, 22, 150, 71 + m) : AlignedGrid(-2, 22);
    const std::string what = m < 10 ? "Delaunay mesh " + std::to_string(m) : "aligned grid";
    EXPECT_NEAR(BooleanArea(mesh, curves, 0, 0, nullptr, what), 200, 1e-9 * 576) << what;
    EXPECT_NEAR(BooleanArea(mesh, curves, 1, 0, nullptr, what), 0, 1e-9 * 576) << what;
  }
}

// Random lattice drawings through the filter, every operation and fill rule, on a Delaunay
// mesh and an aligned grid, against the exact planar areas.
TEST(DegenerateDrawingsFilter, RandomLatticeDrawingsMatchExactAreas)
{
  std::mt19937 rng(5);
  const int lattice = 6;
  vtkSmartPointer<vtkPolyData> aligned = AlignedGrid(-1, lattice + 1);
  int compared = 0;
  for (int k = 0; k < 40; ++k)
  {
    const std::vector<LatticePolygon> drawing = RandomLatticeDrawing(rng, lattice);
    vtkSmartPointer<vtkPolyData> curves = CurvesOf(drawing);
    vtkSmartPointer<vtkPolyData> delaunay = RandomDelaunaySquare(-1, lattice + 1, 60, rng());
    for (int rule = 0; rule < 4; ++rule)
    {
      for (int op = 0; op < 4; ++op)
      {
        auto in = [rule](int w)
        {
          switch (rule)
          {
            case 1:
              return (w & 1) != 0;
            case 2:
              return w > 0;
            case 3:
              return w < 0;
            default:
              return w != 0;
          }
        };
        const double swept = SweepArea(drawing,
          2,
          [&](const std::vector<int>& w)
          {
            const bool a = in(w[0]), b = in(w[1]);
            return op == 0 ? a || b : op == 1 ? a && b : op == 2 ? a && !b : a != b;
          });
        for (vtkPolyData* mesh : { delaunay.GetPointer(), aligned.GetPointer() })
        {
          const std::string what = std::string(mesh == aligned ? "aligned grid" : "Delaunay") +
            " op " + std::to_string(op) + " rule " + std::to_string(rule) + " " +
            DescribeDrawing(drawing);
          const double area = BooleanArea(mesh, curves, op, rule, nullptr, what);
          ASSERT_NEAR(area, swept, 1e-9 * (lattice + 2) * (lattice + 2)) << what;
          ++compared;
        }
      }
    }
  }
  EXPECT_EQ(compared, 40 * 32);
}

// Crowded triangles (issue 28): dense lattice drawings, with the pattern cases above (repeated
// points, spikes, runs shared with earlier polygons), on a square of two mesh triangles, so that
// about a hundred pieces and hundreds of crossings, many of them through lattice points other
// pieces pass, fall in one triangle. Every operation answers with the exact planar area,
// through the filters. Larger drawings (hundreds of pieces, thousands of crossings per
// triangle) are checked in Core: CrowdedLatticeDrawings.
TEST(DegenerateDrawingsFilter, CrowdedTrianglesMatchExactAreas)
{
  std::mt19937 rng(28);
  const int lattice = 16;
  vtkSmartPointer<vtkPolyData> twoTriangles = AlignedGrid(-1, lattice + 1, lattice + 2);
  ASSERT_EQ(twoTriangles->GetNumberOfCells(), 2);
  for (int k = 0; k < 3; ++k)
  {
    std::vector<LatticePolygon> drawing;
    const int polygons = 10 + 5 * k;
    for (int p = 0; p < polygons; ++p)
    {
      drawing.push_back({ p % 2, LatticePolygonPoints(rng, lattice, drawing) });
    }
    std::size_t segments = 0;
    for (const LatticePolygon& polygon : drawing)
    {
      segments += polygon.Points.size();
    }
    vtkSmartPointer<vtkPolyData> curves = CurvesOf(drawing);
    for (int op = 0; op < 4; ++op)
    {
      const double swept = SweepArea(drawing,
        2,
        [&](const std::vector<int>& w)
        {
          const bool a = w[0] != 0, b = w[1] != 0;
          return op == 0 ? a || b : op == 1 ? a && b : op == 2 ? a && !b : a != b;
        });
      const std::string what = "drawing " + std::to_string(k) + " (" + std::to_string(segments) +
        " segments) op " + std::to_string(op);
      const double area = BooleanArea(twoTriangles, curves, op, 0, nullptr, what);
      ASSERT_NEAR(area, swept, 1e-9 * (lattice + 2) * (lattice + 2)) << what;
    }
  }
}

// Degenerate drawings on curved surfaces: control points on mesh vertices, shapes sharing a
// geodesic leg (same or opposite direction), a curve with its exact reverse, a spike. Every
// shape must be consistent and the one-step filter's areas must satisfy inclusion-exclusion
// and complement to 1e-9 of the surface area, on an icosphere and (with ../shared) on a scan.
#include "FilterTestUtils.h"
#include "vtkBoolSurf.h"

#include <vtkPLYReader.h>
#include <vtkTriangleFilter.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace
{

using Point3 = std::array<double, 3>;

/// The mesh vertex nearest to `p`.
Point3 NearestVertex(vtkPolyData* mesh, const Point3& p)
{
  double best = 1e300;
  Point3 q{};
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double x[3];
    mesh->GetPoint(i, x);
    const double d = vtkMath::Distance2BetweenPoints(x, p.data());
    if (d < best)
    {
      best = d;
      q = { x[0], x[1], x[2] };
    }
  }
  return q;
}

double AreaOf(vtkPolyData* mesh, vtkPolyData* curves, const char* expression)
{
  vtkNew<vtkBoolSurf> f;
  f->SetInputData(0, mesh);
  f->SetInputData(1, curves);
  f->SetOperationToExpression();
  f->SetExpression(expression);
  const std::string errors = testutils::ErrorsOf(f);
  EXPECT_TRUE(errors.empty()) << expression << ": " << errors;
  return errors.empty() ? testutils::Area(f->GetOutput()) : -1;
}

/// Shapes 0 and 1 (several curves each, maybe sharing legs): consistent, and
/// |A u B| + |A n B| = |A| + |B|, |A| + |~A| = total, |A - B| + |A n B| = |A|.
void ExpectInclusionExclusion(vtkPolyData* mesh, const std::vector<testutils::ControlPolygon>& c)
{
  vtkSmartPointer<vtkPolyData> curves = testutils::ToCurves(c);
  const double total = testutils::Area(mesh);
  const double a = AreaOf(mesh, curves, "S0"), b = AreaOf(mesh, curves, "S1");
  const double u = AreaOf(mesh, curves, "S0 | S1"), i = AreaOf(mesh, curves, "S0 & S1");
  const double notA = AreaOf(mesh, curves, "~S0"), d = AreaOf(mesh, curves, "S0 - S1");
  EXPECT_GT(a, 1e-4 * total); // a region of many triangles, not a sliver
  EXPECT_NEAR(u + i, a + b, 1e-9 * total);
  EXPECT_NEAR(a + notA, total, 1e-9 * total);
  EXPECT_NEAR(d + i, a, 1e-9 * total);
}

/// Polygons on `mesh` through the mesh vertices nearest to points of a small "window" around
/// the unit direction `center` (scaled to reach the surface): A is a quadrilateral, B the
/// quadrilateral next to it sharing A's leg (1, 2) in the opposite direction.
struct Window
{
  Point3 A[4], B[4];
  Point3 EdgeMidpoint; ///< the midpoint of a mesh edge at A[0] (a control point on an edge)
  Point3 Below;        ///< a vertex beyond A's leg (0, 1)
};

/// The midpoint of a mesh edge from vertex p (the first triangle holding p).
Point3 EdgeMidpointAt(vtkPolyData* mesh, const Point3& p)
{
  vtkIdType n;
  const vtkIdType* ids;
  vtkCellArray* polys = mesh->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    for (int k = 0; k < n; ++k)
    {
      double x[3], y[3];
      mesh->GetPoint(ids[k], x);
      if (x[0] != p[0] || x[1] != p[1] || x[2] != p[2])
        continue;
      mesh->GetPoint(ids[(k + 1) % n], y);
      return { (x[0] + y[0]) / 2, (x[1] + y[1]) / 2, (x[2] + y[2]) / 2 };
    }
  }
  return p;
}

Window MakeWindow(vtkPolyData* mesh, const Point3& center, double size)
{
  double bounds[6];
  mesh->GetBounds(bounds);
  const Point3 mid{
    (bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2, (bounds[4] + bounds[5]) / 2
  };
  const double reach =
    std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
  // Two tangent directions.
  Point3 t1{ -center[1], center[0], 0 };
  if (std::abs(center[2]) > 0.9)
    t1 = { 1, 0, 0 };
  double n1 = vtkMath::Norm(t1.data());
  for (double& x : t1)
    x /= n1;
  Point3 t2;
  vtkMath::Cross(center.data(), t1.data(), t2.data());
  auto at = [&](double s, double t)
  {
    Point3 p;
    for (int k = 0; k < 3; ++k)
      p[k] = mid[k] + reach * (center[k] + size * (s * t1[k] + t * t2[k]));
    // Nearest vertex to the ray's far point: on a star-shaped surface, near the surface.
    return NearestVertex(mesh, p);
  };
  Window w;
  // Counter-clockwise seen from outside (center points outwards, t1 x t2 = center).
  w.A[0] = at(-1, -1);
  w.A[1] = at(1, -1);
  w.A[2] = at(1, 1);
  w.A[3] = at(-1, 1);
  w.B[0] = at(1, -1);
  w.B[1] = at(3, -1);
  w.B[2] = at(3, 1);
  w.B[3] = at(1, 1);
  w.EdgeMidpoint = EdgeMidpointAt(mesh, w.A[0]);
  w.Below = at(0, -3);
  return w;
}

void RunWindowCases(vtkPolyData* mesh, const Point3& center, double size)
{
  const Window w = MakeWindow(mesh, center, size);
  using testutils::ControlPolygon;
  auto poly = [](std::initializer_list<Point3> pts, int shape)
  {
    ControlPolygon c;
    c.Points.assign(pts.begin(), pts.end());
    c.ShapeId = shape;
    return c;
  };
  {
    SCOPED_TRACE("B shares A's leg in the opposite direction");
    ExpectInclusionExclusion(mesh,
      { poly({ w.A[0], w.A[1], w.A[2], w.A[3] }, 0), poly({ w.B[0], w.B[1], w.B[2], w.B[3] }, 1) });
  }
  {
    SCOPED_TRACE("B is A's leg and back plus B: a curve retracing a shared leg");
    ExpectInclusionExclusion(mesh,
      { poly({ w.A[0], w.A[1], w.A[2], w.A[3] }, 0),
        poly({ w.A[1], w.A[2], w.A[1], w.B[1], w.B[2], w.B[3] }, 1) });
  }
  {
    SCOPED_TRACE("B equals A; A has a spike out along B's far leg and back");
    ExpectInclusionExclusion(mesh,
      { poly({ w.A[0], w.A[1], w.B[1], w.A[1], w.A[2], w.A[3] }, 0),
        poly({ w.A[0], w.A[1], w.A[2], w.A[3] }, 1) });
  }
  {
    SCOPED_TRACE("a control point on a mesh edge, on a leg both shapes share");
    ExpectInclusionExclusion(mesh,
      { poly({ w.EdgeMidpoint, w.A[1], w.A[2], w.A[3] }, 0),
        poly({ w.A[1], w.EdgeMidpoint, w.Below }, 1) });
  }
  {
    SCOPED_TRACE("shape 1 holds a curve and its exact reverse next to B");
    vtkSmartPointer<vtkPolyData> curves =
      testutils::ToCurves({ poly({ w.A[0], w.A[1], w.A[2], w.A[3] }, 0),
        poly({ w.B[0], w.B[1], w.B[2], w.B[3] }, 1),
        poly({ w.B[3], w.B[2], w.B[1], w.B[0] }, 1) });
    EXPECT_NEAR(AreaOf(mesh, curves, "S1"), 0.0, 1e-12);
    const double a = AreaOf(mesh, curves, "S0");
    EXPECT_NEAR(AreaOf(mesh, curves, "S0 | S1"), a, 1e-9 * testutils::Area(mesh));
  }
}

} // namespace

TEST(SharedLegsOnCurvedSurfaces, Icosphere)
{
  vtkSmartPointer<vtkPolyData> sphere = testutils::ToPolyData(boolsurf::MakeIcosphere(4));
  RunWindowCases(sphere, { 0, 0, 1 }, 0.12);
  RunWindowCases(sphere, { 0.6, 0.0, 0.8 }, 0.2);
}

TEST(SharedLegsOnCurvedSurfaces, SharedScan)
{
  const char* d = std::getenv("BOOLSURF_SHARED_DATA");
  const std::filesystem::path file =
    d && *d ? std::filesystem::path(d) / "meshes" / "spot.ply" : std::filesystem::path();
  if (file.empty() || !std::filesystem::exists(file))
  {
    GTEST_SKIP() << "BOOLSURF_SHARED_DATA is not set or has no meshes/spot.ply: this test "
                    "needs ../shared/data";
  }
  vtkNew<vtkPLYReader> reader;
  reader->SetFileName(file.string().c_str());
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(reader->GetOutputPort());
  triangles->Update();
  vtkPolyData* mesh = triangles->GetOutput();
  RunWindowCases(mesh, { 0.0, 0.0, 1.0 }, 0.2);
  RunWindowCases(mesh, { 0.0, 1.0, 0.0 }, 0.2);
}

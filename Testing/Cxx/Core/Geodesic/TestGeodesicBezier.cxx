// Geodesic Bezier splines: on a flat mesh they are planar cubic Beziers; on curved meshes they
// interpolate their anchors, close when closed, and keep the tracing invariants.
#include "Geodesic/CurveTracer.h"
#include "Geodesic/GeodesicBezier.h"
#include "Mesh/ProceduralMeshes.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace boolsurf;

namespace
{
/// The message of the last failed trace or path (a test reads it only after a failure).
std::string traceError;
}

namespace
{
/// Canonical point at planar (x, y) of a flat z = 0 mesh (brute force: tests only).
CanonicalPoint Locate(const TriangleMesh& mesh, double x, double y)
{
  for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    const Vec3 a = mesh.GetCornerPosition(t, 0), b = mesh.GetCornerPosition(t, 1),
               c = mesh.GetCornerPosition(t, 2);
    const Vec3 p{ x, y, 0 };
    const double area = Cross(b - a, c - a).z;
    const double u = Cross(p - a, c - a).z / area, v = Cross(b - a, p - a).z / area;
    if (u >= 0 && v >= 0 && u + v <= 1)
    {
      return Canonicalize(mesh, SurfacePoint{ t, u, v }, 0.0);
    }
  }
  ADD_FAILURE() << "no triangle holds (" << x << ", " << y << ")";
  return {};
}

Vec3 PlanarBezier(const Vec3 p[4], double t)
{
  const double s = 1 - t;
  return (s * s * s) * p[0] + (3 * s * s * t) * p[1] + (3 * s * t * t) * p[2] + (t * t * t) * p[3];
}
} // namespace

TEST(GeodesicBezier, FlatSplineIsThePlanarBezier)
{
  const TriangleMesh mesh = []
  {
    MeshData d = MakeFlatSquare(16, 1.0, 0.3, 5);
    return TriangleMesh(d.Positions, d.Triangles);
  }();
  const double xy[7][2] = { { 0.1, 0.1 },
    { 0.3, 0.8 },
    { 0.6, 0.9 },
    { 0.7, 0.5 },
    { 0.8, 0.1 },
    { 0.95, 0.3 },
    { 0.9, 0.9 } };
  std::vector<CanonicalPoint> controls;
  Vec3 planar[7];
  for (int i = 0; i < 7; ++i)
  {
    controls.push_back(Locate(mesh, xy[i][0], xy[i][1]));
    planar[i] = PositionOf(mesh, controls.back());
  }
  CurveTracer tracer(mesh);
  tracer.SetResolution(8);
  CurveTrace trace;
  ASSERT_TRUE(tracer.TraceBezierSpline(controls, false, trace, traceError, 3));
  const std::vector<CanonicalPoint>& pts = trace.Curve.Points;
  ASSERT_GT(pts.size(), 2u * 256u);
  ASSERT_EQ(trace.Parameter.size(), pts.size());
  EXPECT_TRUE(pts.front() == controls.front());
  EXPECT_TRUE(pts.back() == controls.back());
  EXPECT_EQ(trace.ControlPoint.front(), 0);
  EXPECT_EQ(trace.ControlPoint.back(), 6);
  EXPECT_DOUBLE_EQ(trace.Parameter.back(), 2.0);
  int anchors = 0;
  for (size_t k = 0; k < pts.size(); ++k)
  {
    if (k > 0)
    {
      EXPECT_GE(trace.Parameter[k], trace.Parameter[k - 1]);
      EXPECT_GE(SharedTriangle(mesh, pts[k - 1], pts[k]), 0);
    }
    // A joint between segments keeps the segment it ends (parameter = segment + 1).
    const int segment = trace.Segment[k];
    ASSERT_TRUE(segment == 0 || segment == 1);
    EXPECT_GE(trace.Parameter[k], segment);
    EXPECT_LE(trace.Parameter[k], segment + 1);
    const Vec3 exact = PlanarBezier(planar + 3 * segment, trace.Parameter[k] - segment);
    if (trace.OnCurve[k])
    {
      ++anchors;
      EXPECT_LT(Distance(PositionOf(mesh, pts[k]), exact), 1e-9)
        << "parameter " << trace.Parameter[k];
    }
    else
    {
      // The refined control polygon converges like 4^-levels: close, though not on it.
      EXPECT_LT(Distance(PositionOf(mesh, pts[k]), exact), 5e-3);
    }
    if (trace.ControlPoint[k] >= 0)
    {
      EXPECT_EQ(trace.ControlPoint[k] % 3, 0);
      EXPECT_DOUBLE_EQ(trace.Parameter[k], trace.ControlPoint[k] / 3);
    }
  }
  EXPECT_EQ(anchors, 2 * 256 + 1);
}

TEST(GeodesicBezier, ClosedSplineOnSphereCloses)
{
  MeshData d = MakeIcosphere(3);
  const TriangleMesh mesh(d.Positions, d.Triangles);
  CurveTracer tracer(mesh);
  tracer.SetResolution(3);
  std::vector<CanonicalPoint> controls;
  for (int t : { 10, 40, 90, 200, 300, 500, 700, 900, 1100 })
  {
    controls.push_back(Canonicalize(mesh, SurfacePoint{ t, 0.3, 0.3 }));
  }
  CurveTrace trace;
  ASSERT_TRUE(tracer.TraceBezierSpline(controls, true, trace, traceError));
  const std::vector<CanonicalPoint>& pts = trace.Curve.Points;
  EXPECT_TRUE(trace.Curve.Closed);
  EXPECT_TRUE(pts.front() == controls.front());
  EXPECT_FALSE(pts.back() == pts.front()); // closed curves do not repeat the first point
  for (size_t k = 0; k < pts.size(); ++k)
  {
    EXPECT_GE(SharedTriangle(mesh, pts[k], pts[(k + 1) % pts.size()]), 0)
      << "points " << k << " and " << (k + 1) % pts.size();
  }
  // Every anchor is interpolated, at its spline parameter.
  for (int anchor : { 0, 3, 6 })
  {
    bool found = false;
    for (size_t k = 0; k < pts.size(); ++k)
    {
      if (trace.ControlPoint[k] == anchor)
      {
        found = true;
        EXPECT_TRUE(pts[k] == controls[anchor]);
        EXPECT_DOUBLE_EQ(trace.Parameter[k], anchor / 3);
      }
    }
    EXPECT_TRUE(found) << "anchor " << anchor;
  }
  EXPECT_LT(trace.Parameter.back(), 3.0);
  EXPECT_GT(trace.Parameter.back(), 2.0);
}

TEST(GeodesicBezier, MidpointIsEquidistant)
{
  MeshData d = MakeIcosphere(4);
  const TriangleMesh mesh(d.Positions, d.Triangles);
  GeodesicPathSolver solver(mesh);
  const CanonicalPoint a = Canonicalize(mesh, SurfacePoint{ 17, 0.2, 0.3 });
  const CanonicalPoint b = Canonicalize(mesh, SurfacePoint{ 2000, 0.4, 0.1 });
  CanonicalPoint mid;
  ASSERT_TRUE(GeodesicMidpoint(solver, a, b, mid, traceError));
  GeodesicPath whole, first, second;
  ASSERT_TRUE(solver.Compute(a, b, whole, traceError));
  ASSERT_TRUE(solver.Compute(a, mid, first, traceError));
  ASSERT_TRUE(solver.Compute(mid, b, second, traceError));
  EXPECT_NEAR(first.Length, 0.5 * whole.Length, 1e-9);
  EXPECT_NEAR(second.Length, 0.5 * whole.Length, 1e-9);
}

TEST(GeodesicBezier, SubdivisionSizes)
{
  MeshData d = MakeFlatSquare(4);
  const TriangleMesh mesh(d.Positions, d.Triangles);
  GeodesicPathSolver solver(mesh);
  const std::array<CanonicalPoint, 4> segment{ Canonicalize(mesh, { 0, 0.2, 0.2 }),
    Canonicalize(mesh, { 5, 0.2, 0.2 }),
    Canonicalize(mesh, { 20, 0.2, 0.2 }),
    Canonicalize(mesh, { 30, 0.2, 0.2 }) };
  std::vector<CanonicalPoint> polygon;
  ASSERT_TRUE(SubdivideGeodesicBezier(solver, segment, 0, polygon, traceError));
  EXPECT_EQ(polygon.size(), 4u);
  ASSERT_TRUE(SubdivideGeodesicBezier(solver, segment, 3, polygon, traceError));
  EXPECT_EQ(polygon.size(), 3u * 8u + 1u);
  EXPECT_TRUE(polygon.front() == segment[0]);
  EXPECT_TRUE(polygon.back() == segment[3]);
}

// Curve tracing: geodesic polygons with provenance, and the named errors users see.
#include "Geodesic/CurveTracer.h"
#include "Geodesic/WrittenCurvePoints.h"
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
TriangleMesh FlatMesh()
{
  MeshData d = MakeFlatSquare(12, 1.0, 0.3, 4);
  return TriangleMesh(d.Positions, d.Triangles);
}
} // namespace

TEST(CurveTracer, OpenPolygonOnFlatMesh)
{
  const TriangleMesh mesh = FlatMesh();
  CurveTracer tracer(mesh);
  const std::vector<SurfacePoint> controls{
    { 3, 0.2, 0.3 }, { 100, 0.1, 0.1 }, { 250, 0.5, 0.25 }, { 40, 0.3, 0.3 }
  };
  CurveTrace trace;
  ASSERT_TRUE(tracer.Trace(controls, CurveType::GeodesicPolygon, false, trace, traceError, 5));
  const std::vector<CanonicalPoint>& pts = trace.Curve.Points;
  EXPECT_EQ(trace.Curve.CurveId, 5);
  EXPECT_FALSE(trace.Curve.Closed);
  double expectedLength = 0;
  for (size_t i = 0; i + 1 < controls.size(); ++i)
  {
    expectedLength += Distance(mesh.Evaluate(controls[i].Triangle, controls[i].U, controls[i].V),
      mesh.Evaluate(controls[i + 1].Triangle, controls[i + 1].U, controls[i + 1].V));
  }
  EXPECT_NEAR(trace.Length, expectedLength, 1e-12);
  int seen = 0;
  for (size_t k = 0; k < pts.size(); ++k)
  {
    if (k > 0)
    {
      EXPECT_GE(SharedTriangle(mesh, pts[k - 1], pts[k]), 0);
      EXPECT_GT(trace.Parameter[k], trace.Parameter[k - 1]);
    }
    EXPECT_TRUE(trace.OnCurve[k]);
    const int segment = trace.Segment[k];
    ASSERT_GE(segment, 0);
    ASSERT_LE(segment, 2);
    // The point sits at its parameter's fraction of the straight segment.
    const Vec3 a =
      mesh.Evaluate(controls[segment].Triangle, controls[segment].U, controls[segment].V);
    const Vec3 b = mesh.Evaluate(
      controls[segment + 1].Triangle, controls[segment + 1].U, controls[segment + 1].V);
    const double f = trace.Parameter[k] - segment;
    EXPECT_LT(Distance(PositionOf(mesh, pts[k]), (1 - f) * a + f * b), 1e-12);
    if (trace.ControlPoint[k] >= 0)
    {
      EXPECT_EQ(trace.ControlPoint[k], seen);
      EXPECT_DOUBLE_EQ(trace.Parameter[k], seen);
      ++seen;
    }
  }
  EXPECT_EQ(seen, 4);
}

TEST(CurveTracer, ClosedPolygonOnTorus)
{
  MeshData d = MakeTorus(2.0, 0.6, 40, 20);
  const TriangleMesh mesh(d.Positions, d.Triangles);
  CurveTracer tracer(mesh);
  const std::vector<SurfacePoint> controls{
    { 10, 0.3, 0.3 }, { 300, 0.3, 0.3 }, { 900, 0.3, 0.3 }
  };
  CurveTrace trace;
  ASSERT_TRUE(tracer.Trace(controls, CurveType::GeodesicPolygon, true, trace, traceError));
  const std::vector<CanonicalPoint>& pts = trace.Curve.Points;
  EXPECT_TRUE(trace.Curve.Closed);
  EXPECT_FALSE(pts.back() == pts.front());
  for (size_t k = 0; k < pts.size(); ++k)
  {
    EXPECT_GE(SharedTriangle(mesh, pts[k], pts[(k + 1) % pts.size()]), 0);
  }
  EXPECT_GT(trace.Parameter.back(), 2.0);
  EXPECT_LT(trace.Parameter.back(), 3.0);
  EXPECT_NEAR(PolylineLength(mesh, pts) +
      Distance(PositionOf(mesh, pts.back()), PositionOf(mesh, pts.front())),
    trace.Length,
    1e-9);
}

TEST(CurveTracer, NamedErrors)
{
  const TriangleMesh mesh = FlatMesh();
  CurveTracer tracer(mesh);
  CurveTrace trace;
  bool s =
    tracer.Trace({ { 1, 0.2, 0.2 } }, CurveType::GeodesicPolygon, false, trace, traceError, 4);
  EXPECT_FALSE(s);
  EXPECT_EQ(traceError, "curve 4: a geodesic polygon needs at least 2 control points, got 1");

  std::vector<SurfacePoint> five(5, SurfacePoint{ 1, 0.2, 0.2 });
  s = tracer.Trace(five, CurveType::CubicBezier, false, trace, traceError, 2);
  EXPECT_EQ(traceError,
    "curve 2: an open cubic Bezier spline needs 3n+1 control points (anchor, handle, handle, "
    "anchor, ...), got 5");
  std::vector<SurfacePoint> four(4, SurfacePoint{ 1, 0.2, 0.2 });
  s = tracer.Trace(four, CurveType::CubicBezier, true, trace, traceError, 2);
  EXPECT_EQ(traceError,
    "curve 2: a closed cubic Bezier spline needs 3n control points (anchor, handle, handle, "
    "anchor, ...), got 4");

  s = tracer.Trace({ { 1, 0.2, 0.2 }, { 2, std::nan(""), 0.1 } },
    CurveType::GeodesicPolygon,
    false,
    trace,
    traceError,
    7);
  EXPECT_FALSE(s);
  EXPECT_EQ(traceError.rfind("curve 7, control point 1: barycentric coordinates", 0), 0u)
    << traceError;
  s = tracer.Trace(
    { { 1, 0.2, 0.2 }, { 100000, 0.1, 0.1 } }, CurveType::CubicBezier, false, trace, traceError, 0);
  EXPECT_EQ(traceError, "curve 0, control point 1: triangle id 100000 is out of range [0, 288)");
  EXPECT_TRUE(trace.Curve.Points.empty());
}

TEST(CurveTracer, DifferentComponentsNamesCurveAndSegment)
{
  MeshData a = MakeFlatSquare(3);
  const int offset = static_cast<int>(a.Positions.size());
  const MeshData b = MakeFlatSquare(3);
  for (Vec3 p : b.Positions)
  {
    a.Positions.push_back(p + Vec3{ 3, 0, 0 });
  }
  for (auto tri : b.Triangles)
  {
    a.Triangles.push_back({ tri[0] + offset, tri[1] + offset, tri[2] + offset });
  }
  const TriangleMesh mesh(a.Positions, a.Triangles);
  CurveTracer tracer(mesh);
  CurveTrace trace;
  const bool s = tracer.Trace({ { 0, 0.2, 0.2 }, { 1, 0.2, 0.2 }, { 20, 0.2, 0.2 } },
    CurveType::GeodesicPolygon,
    false,
    trace,
    traceError,
    9);
  EXPECT_FALSE(s);
  EXPECT_EQ(traceError.rfind("curve 9, segment 1 (control points 1 and 2): start point", 0), 0u)
    << traceError;
  EXPECT_NE(traceError.find("different connected components"), std::string::npos);
}

// The tracer remembers traced curves: the same control points, type, closure, resolution and
// method give the same trace without tracing (curve id updated); anything else traces; curves
// not used during a whole pass are forgotten at the next StartPass.
TEST(CurveTracer, RemembersTracedCurves)
{
  const TriangleMesh mesh = FlatMesh();
  CurveTracer tracer(mesh);
  const std::vector<SurfacePoint> polygon{ { 3, 0.2, 0.3 }, { 100, 0.1, 0.1 }, { 250, 0.5, 0.25 } };
  const std::vector<SurfacePoint> spline{
    { 3, 0.2, 0.3 }, { 100, 0.1, 0.1 }, { 250, 0.5, 0.25 }, { 40, 0.3, 0.3 }
  };
  CurveTrace first, again;
  tracer.StartPass();
  ASSERT_TRUE(tracer.Trace(polygon, CurveType::GeodesicPolygon, true, first, traceError, 1));
  ASSERT_TRUE(tracer.Trace(polygon, CurveType::GeodesicPolygon, true, again, traceError, 7));
  EXPECT_EQ(tracer.GetRecalledCurves(), 1u);
  EXPECT_TRUE(again.Curve.Points == first.Curve.Points);
  EXPECT_EQ(again.Parameter, first.Parameter);
  EXPECT_EQ(again.Length, first.Length);
  EXPECT_EQ(again.Curve.CurveId, 7);
  // Open instead of closed, a Bezier, another resolution, another method: traced.
  ASSERT_TRUE(tracer.Trace(polygon, CurveType::GeodesicPolygon, false, again, traceError));
  ASSERT_TRUE(tracer.Trace(spline, CurveType::CubicBezier, false, again, traceError));
  tracer.SetResolution(2);
  ASSERT_TRUE(tracer.Trace(spline, CurveType::CubicBezier, false, again, traceError));
  GeodesicPathOptions options;
  options.Method = GeodesicMethod::LocallyShortest;
  tracer.GetPathSolver().SetOptions(options);
  ASSERT_TRUE(tracer.Trace(polygon, CurveType::GeodesicPolygon, true, again, traceError));
  EXPECT_EQ(tracer.GetRecalledCurves(), 1u);
  options.Method = GeodesicMethod::Bounded;
  tracer.GetPathSolver().SetOptions(options);
  tracer.SetResolution(4);
  // Any other setting of the solver is another trace too (filters share a tracer, each with
  // its own settings): a smaller window budget, no corridor refinement.
  GeodesicPathOptions budget = options;
  budget.BoundedWindows = 1 << 10;
  tracer.GetPathSolver().SetOptions(budget);
  ASSERT_TRUE(tracer.Trace(polygon, CurveType::GeodesicPolygon, true, again, traceError));
  GeodesicPathOptions corridor = options;
  corridor.CorridorRefinement = false;
  tracer.GetPathSolver().SetOptions(corridor);
  ASSERT_TRUE(tracer.Trace(polygon, CurveType::GeodesicPolygon, true, again, traceError));
  EXPECT_EQ(tracer.GetRecalledCurves(), 1u);
  tracer.GetPathSolver().SetOptions(options);
  // A control point moved by one ulp is another curve.
  std::vector<SurfacePoint> moved = polygon;
  moved[1].U = std::nextafter(moved[1].U, 1.0);
  ASSERT_TRUE(tracer.Trace(moved, CurveType::GeodesicPolygon, true, again, traceError));
  EXPECT_EQ(tracer.GetRecalledCurves(), 1u);
  // Passes: used in the last pass, kept; unused for a whole pass, forgotten.
  tracer.StartPass();
  ASSERT_TRUE(tracer.Trace(polygon, CurveType::GeodesicPolygon, true, again, traceError));
  EXPECT_EQ(tracer.GetRecalledCurves(), 2u);
  tracer.StartPass(); // polygon was used during the pass that ends: kept
  tracer.StartPass(); // not used during this one: forgotten
  ASSERT_TRUE(tracer.Trace(polygon, CurveType::GeodesicPolygon, true, again, traceError));
  EXPECT_EQ(tracer.GetRecalledCurves(), 2u);
  EXPECT_TRUE(again.Curve.Points == first.Curve.Points); // traced again: the same result
}

// With written forms kept, a traced curve carries each point's position and output form, equal
// to what WrittenCurvePoint and PositionOf give (a fresh trace, a recalled one, and one
// remembered before the forms were kept); without them it carries none.
TEST(CurveTracer, KeepsWrittenForms)
{
  const MeshData d = MakeTorus(1.0, 0.4, 24, 12);
  const TriangleMesh mesh(d.Positions, d.Triangles);
  CurveTracer tracer(mesh);
  const std::vector<SurfacePoint> polygon{ { 3, 0.2, 0.3 }, { 100, 0.0, 0.5 }, { 250, 1.0, 0.0 } };
  const std::vector<SurfacePoint> spline{
    { 7, 0.2, 0.3 }, { 90, 0.5, 0.5 }, { 200, 0.25, 0.25 }, { 401, 0.3, 0.0 }
  };
  const auto expectForms = [&mesh](const CurveTrace& trace)
  {
    const std::size_t n = trace.Curve.Points.size();
    ASSERT_EQ(trace.Positions.size(), n);
    ASSERT_EQ(trace.Written.size(), n);
    for (std::size_t i = 0; i < n; ++i)
    {
      const SurfacePoint w = WrittenCurvePoint(mesh, trace.Curve, i);
      EXPECT_EQ(trace.Written[i].Triangle, w.Triangle) << i;
      EXPECT_EQ(trace.Written[i].U, w.U) << i;
      EXPECT_EQ(trace.Written[i].V, w.V) << i;
      // Read back where it was traced (bit for bit but for an edge point whose parameter
      // sits on the implicit corner in both triangles: WriteSurfacePoint).
      const CanonicalPoint back = LocateSurfacePoint(mesh, w);
      EXPECT_EQ(back.Location, trace.Curve.Points[i].Location) << i;
      EXPECT_EQ(back.Id, trace.Curve.Points[i].Id) << i;
      EXPECT_NEAR(back.T, trace.Curve.Points[i].T, 1e-15) << i;
      const std::size_t next = i + 1 < n ? i + 1 : (trace.Curve.Closed ? 0 : i - 1);
      if (trace.Curve.Points[i].Location != PointLocation::Face)
      {
        EXPECT_TRUE(TriangleContains(mesh, trace.Curve.Points[next], w.Triangle)) << i;
      }
      const Vec3 x = PositionOf(mesh, trace.Curve.Points[i]);
      EXPECT_EQ(trace.Positions[i].x, x.x);
      EXPECT_EQ(trace.Positions[i].y, x.y);
      EXPECT_EQ(trace.Positions[i].z, x.z);
    }
  };
  CurveTrace trace;
  tracer.StartPass();
  ASSERT_TRUE(tracer.Trace(polygon, CurveType::GeodesicPolygon, true, trace, traceError));
  EXPECT_TRUE(trace.Written.empty());
  tracer.SetKeepWrittenForms(true);
  ASSERT_TRUE(
    tracer.Trace(polygon, CurveType::GeodesicPolygon, true, trace, traceError)); // recalled
  EXPECT_EQ(tracer.GetRecalledCurves(), 1u);
  expectForms(trace);
  ASSERT_TRUE(tracer.Trace(spline, CurveType::CubicBezier, false, trace, traceError)); // fresh
  expectForms(trace);
  ASSERT_TRUE(tracer.Trace(spline, CurveType::CubicBezier, false, trace, traceError)); // recalled
  EXPECT_EQ(tracer.GetRecalledCurves(), 2u);
  expectForms(trace);
  tracer.SetKeepWrittenForms(false);
  ASSERT_TRUE(tracer.Trace(spline, CurveType::CubicBezier, false, trace, traceError));
  EXPECT_TRUE(trace.Written.empty() && trace.Positions.empty());
}

// CurveTracer::TraceCurves: many curves traced on several threads give, curve by curve, what
// Trace() gives one curve at a time on one thread, bit for bit (polygons and Bezier splines,
// short exact legs and far routed ones), with each failure at its own curve, and the curves
// remembered for the next update as Trace() remembers them.
#include "Geodesic/CurveTracer.h"
#include "Mesh/ProceduralMeshes.h"

#include <gtest/gtest.h>

#include <random>

using namespace boolsurf;

namespace
{
SurfacePoint RandomPoint(const TriangleMesh& mesh, std::mt19937& rng)
{
  std::uniform_real_distribution<double> unit(0.05, 0.45);
  return { static_cast<int>(rng() % mesh.GetNumberOfTriangles()), unit(rng), unit(rng) };
}

struct Drawing
{
  std::vector<ControlCurve> Curves;
  std::vector<const ControlCurve*> Requests;
};

/// `n` curves: polygons of 3-6 random points (far apart on the torus, so many legs are routed)
/// and closed Bezier splines of 2 segments; curve `broken` (if any) has a point in a triangle
/// that does not exist.
Drawing RandomDrawing(const TriangleMesh& mesh, int n, std::uint32_t seed, int broken = -1)
{
  std::mt19937 rng(seed);
  Drawing d;
  d.Curves.resize(n);
  for (int c = 0; c < n; ++c)
  {
    const bool bezier = c % 3 == 2;
    const int count = bezier ? 6 : 3 + static_cast<int>(rng() % 4);
    for (int k = 0; k < count; ++k)
    {
      d.Curves[c].Points.push_back(RandomPoint(mesh, rng));
    }
    if (c == broken)
    {
      d.Curves[c].Points[1].Triangle = mesh.GetNumberOfTriangles() + 5;
    }
  }
  for (int c = 0; c < n; ++c)
  {
    const bool bezier = c % 3 == 2;
    ControlCurve& curve = d.Curves[c];
    curve.Type = bezier ? CurveType::CubicBezier : CurveType::GeodesicPolygon;
    curve.Closed = c % 2 == 0 || bezier;
    curve.CurveId = 100 + c;
    d.Requests.push_back(&curve);
  }
  return d;
}

void ExpectSameTrace(const CurveTrace& a, const CurveTrace& b, int c)
{
  ASSERT_EQ(a.Curve.Points.size(), b.Curve.Points.size()) << "curve " << c;
  for (std::size_t i = 0; i < a.Curve.Points.size(); ++i)
  {
    ASSERT_EQ(a.Curve.Points[i], b.Curve.Points[i]) << "curve " << c << " point " << i;
  }
  EXPECT_EQ(a.Curve.Closed, b.Curve.Closed);
  EXPECT_EQ(a.Curve.CurveId, b.Curve.CurveId);
  EXPECT_EQ(a.Segment, b.Segment);
  EXPECT_EQ(a.ControlPoint, b.ControlPoint);
  EXPECT_EQ(a.Parameter, b.Parameter);
  EXPECT_EQ(a.OnCurve, b.OnCurve);
  EXPECT_EQ(a.Length, b.Length);
}
} // namespace

TEST(ParallelTracing, SameCurvesAsOneByOne)
{
  const MeshData torus = MakeTorus(1.0, 0.35, 96, 40);
  const TriangleMesh mesh(torus.Positions, torus.Triangles);
  const Drawing drawing = RandomDrawing(mesh, 24, 7, 10);
  for (GeodesicMethod method : { GeodesicMethod::Bounded, GeodesicMethod::Exact })
  {
    // One by one: the reference. A small window budget, so that far legs are routed.
    CurveTracer single(mesh);
    GeodesicPathOptions options;
    options.Method = method;
    options.BoundedWindows = 1 << 10;
    single.GetPathSolver().SetOptions(options);
    single.SetKeepWrittenForms(true);
    std::vector<CurveTrace> expected(drawing.Requests.size());
    std::vector<std::string> expectedErrors(drawing.Requests.size());
    int routed = 0;
    for (std::size_t c = 0; c < drawing.Requests.size(); ++c)
    {
      const ControlCurve& r = *drawing.Requests[c];
      single.Trace(r.Points, r.Type, r.Closed, expected[c], expectedErrors[c], r.CurveId);
      routed += single.GetPathSolver().GetLastStatistics().Routed;
    }
    ASSERT_FALSE(expectedErrors[10].empty());
    if (method == GeodesicMethod::Bounded)
    {
      EXPECT_GT(routed, 0) << "no curve's last leg was routed: the budget is too large";
    }
    for (int threads : { 1, 2, 4 })
    {
      CurveTracer parallel(mesh);
      parallel.GetPathSolver().SetOptions(options);
      parallel.SetKeepWrittenForms(true);
      std::vector<CurveTrace> traces;
      std::vector<std::string> errors;
      int calls = 0;
      parallel.TraceCurves(drawing.Requests,
        threads,
        traces,
        errors,
        [&](double fraction)
        {
          EXPECT_GT(fraction, 0.0);
          EXPECT_LE(fraction, 1.0);
          ++calls;
          return true;
        });
      EXPECT_GT(calls, 0);
      ASSERT_EQ(traces.size(), expected.size());
      for (std::size_t c = 0; c < expected.size(); ++c)
      {
        ASSERT_EQ(errors[c].empty(), expectedErrors[c].empty()) << "curve " << c;
        EXPECT_EQ(errors[c], expectedErrors[c]);
        ExpectSameTrace(traces[c], expected[c], static_cast<int>(c));
        EXPECT_EQ(traces[c].Written.size(), expected[c].Written.size());
      }
      // The next update recalls every curve traced, and traces the broken one again.
      parallel.StartPass();
      std::vector<CurveTrace> again;
      parallel.TraceCurves(drawing.Requests, threads, again, errors);
      EXPECT_EQ(parallel.GetRecalledCurves(), drawing.Requests.size() - 1);
      EXPECT_FALSE(errors[10].empty());
      for (std::size_t c = 0; c < expected.size(); ++c)
      {
        ExpectSameTrace(again[c], expected[c], static_cast<int>(c));
      }
    }
  }
}

TEST(ParallelTracing, StopsWhenAsked)
{
  const MeshData sphere = MakeIcosphere(4);
  const TriangleMesh mesh(sphere.Positions, sphere.Triangles);
  const Drawing drawing = RandomDrawing(mesh, 12, 3);
  CurveTracer tracer(mesh);
  std::vector<CurveTrace> traces;
  std::vector<std::string> errors;
  tracer.TraceCurves(drawing.Requests, 1, traces, errors, [](double) { return false; });
  // The first curve is traced, then the tracing stops: the others fail, named.
  EXPECT_TRUE(errors[0].empty());
  for (std::size_t c = 1; c < errors.size(); ++c)
  {
    EXPECT_FALSE(errors[c].empty());
    EXPECT_NE(errors[c].find("curve " + std::to_string(100 + c)), std::string::npos) << errors[c];
  }
}

// One long curve (a polygon of 40 far-apart points, a closed Bezier spline of 8 segments) is
// shared between threads piece by piece: each is still, bit for bit, the curve one thread
// traces.
TEST(ParallelTracing, OneLongCurveOnEveryThread)
{
  const MeshData torus = MakeTorus(1.0, 0.35, 96, 40);
  const TriangleMesh mesh(torus.Positions, torus.Triangles);
  std::mt19937 rng(11);
  std::vector<ControlCurve> curves(2);
  for (int k = 0; k < 40; ++k)
  {
    curves[0].Points.push_back(RandomPoint(mesh, rng));
  }
  for (int k = 0; k < 24; ++k)
  {
    curves[1].Points.push_back(RandomPoint(mesh, rng));
  }
  curves[0].Type = CurveType::GeodesicPolygon;
  curves[1].Type = CurveType::CubicBezier;
  for (int c = 0; c < 2; ++c)
  {
    curves[c].Closed = true;
    curves[c].CurveId = c;
    CurveTracer single(mesh);
    CurveTrace expected;
    std::string expectedError;
    ASSERT_TRUE(single.Trace(curves[c].Points,
      curves[c].Type,
      curves[c].Closed,
      expected,
      expectedError,
      curves[c].CurveId))
      << expectedError;
    for (int threads : { 2, 4 })
    {
      CurveTracer parallel(mesh);
      std::vector<CurveTrace> traces;
      std::vector<std::string> errors;
      parallel.TraceCurves({ &curves[c] }, threads, traces, errors);
      ASSERT_TRUE(errors[0].empty()) << errors[0];
      ExpectSameTrace(traces[0], expected, c);
    }
  }
}

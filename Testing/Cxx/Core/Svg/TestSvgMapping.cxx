// SVG drawings: parsing (every path command, shapes, transforms, fill-rule; the shared SVGs),
// and the exponential map: the identity up to scale and rotation on a flat mesh (1e-9),
// geodesic distances from the center and angles at it kept on a sphere, converging under
// refinement; named errors for bad input.
#include "Geodesic/StraightestGeodesic.h"
#include "Mesh/ProceduralMeshes.h"
#include "Svg/SvgDrawing.h"
#include "Svg/SvgSurfaceMap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace
{
using namespace boolsurf;

TriangleMesh ToMesh(const MeshData& data)
{
  return TriangleMesh(data.Positions, data.Triangles);
}

std::string Svg(const std::string& body)
{
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 100 100\">" + body + "</svg>";
}

/// The surface point of (x, y) on a flat mesh in z = 0.
SurfacePoint Locate(const TriangleMesh& mesh, double x, double y)
{
  for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    const Vec3 a = mesh.GetCornerPosition(t, 0), b = mesh.GetCornerPosition(t, 1),
               c = mesh.GetCornerPosition(t, 2);
    const double det = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    const double u = ((x - a.x) * (c.y - a.y) - (c.x - a.x) * (y - a.y)) / det;
    const double v = ((b.x - a.x) * (y - a.y) - (x - a.x) * (b.y - a.y)) / det;
    if (u >= 0 && v >= 0 && u + v <= 1)
    {
      return { t, u, v };
    }
  }
  return {};
}
} // namespace

TEST(SvgDrawing, PathCommandsShapesTransformsAndFillRule)
{
  SvgDrawing d;
  std::string error;
  // Relative and absolute commands; a quadratic and an arc become cubics; H/V/Z.
  ASSERT_TRUE(ParseSvg(Svg("<path d='M10 10 h20 v20 H10 Z m40 0 l10 0 q5 5 0 10 "
                           "c-5 0 -5 -5 -10 -10 z M70 70 a10 10 0 0 1 20 0 s0 10 -10 10 "
                           "t-10 -10 Z'/>"),
    d,
    error))
    << error;
  ASSERT_EQ(d.Paths.size(), 1u);
  ASSERT_EQ(d.Paths[0].Subpaths.size(), 3u);
  const SvgSubpath& square = d.Paths[0].Subpaths[0];
  EXPECT_TRUE(square.Closed);
  ASSERT_EQ(square.Points.size(), 12u); // 4 straight sides, 3 control points each
  EXPECT_DOUBLE_EQ(square.Points[3].x, 30);
  EXPECT_DOUBLE_EQ(square.Points[6].y, 30);
  EXPECT_DOUBLE_EQ(square.Points[1].x, 10 + 20.0 / 3); // a line's handle at a third
  // The relative move after Z starts from the closed subpath's start (10, 10).
  EXPECT_DOUBLE_EQ(d.Paths[0].Subpaths[1].Points[0].x, 50);
  EXPECT_EQ(d.Paths[0].Subpaths[2].Points.size() % 3, 0u);
  EXPECT_FALSE(d.Paths[0].EvenOdd);

  // Basic shapes as paths; transforms of groups and elements compose; fill-rule inherited.
  ASSERT_TRUE(ParseSvg(Svg("<g transform='translate(10 20)' style='fill-rule:evenodd'>"
                           "<rect x='0' y='0' width='10' height='5' transform='scale(2)'/>"
                           "<circle cx='0' cy='0' r='3'/></g>"
                           "<polygon points='0,0 5,0 5,5'/><polyline points='0,0 1,1 2,0'/>"),
    d,
    error))
    << error;
  ASSERT_EQ(d.Paths.size(), 4u);
  EXPECT_TRUE(d.Paths[0].EvenOdd);
  EXPECT_TRUE(d.Paths[1].EvenOdd);
  EXPECT_FALSE(d.Paths[2].EvenOdd);
  // The rect's corner (10, 5) scaled by 2 then translated: (30, 30).
  bool corner = false;
  for (const Vec2& p : d.Paths[0].Subpaths[0].Points)
  {
    corner = corner || (std::abs(p.x - 30) < 1e-12 && std::abs(p.y - 30) < 1e-12);
  }
  EXPECT_TRUE(corner);
  // The circle (4 arcs as cubics) stays within 3 of (10, 20), and reaches it.
  double farthest = 0;
  for (const Vec2& p : d.Paths[1].Subpaths[0].Points)
  {
    farthest = std::max(farthest, std::hypot(p.x - 10, p.y - 20));
  }
  EXPECT_NEAR(farthest, 3 * 1.0, 0.6); // handles of a circle's cubics stick out by ~0.55 r
  EXPECT_TRUE(d.Paths[1].Subpaths[0].Closed);
  EXPECT_FALSE(d.Paths[3].Subpaths[0].Closed);
  EXPECT_EQ(d.Paths[3].Subpaths[0].Points.size(), 7u); // two straight pieces, open

  // Unknown attributes are skipped and named.
  ASSERT_TRUE(ParseSvg(Svg("<path data-name='x' d='M0 0 L1 0 L1 1 Z'/>"), d, error)) << error;
  ASSERT_FALSE(d.Warnings.empty());
  EXPECT_NE(d.Warnings[0].find("data-name"), std::string::npos);
}

TEST(SvgDrawing, BadInputIsNamed)
{
  SvgDrawing d;
  std::string error;
  EXPECT_FALSE(LoadSvg("no/such/file.svg", d, error));
  EXPECT_NE(error.find("cannot open no/such/file.svg"), std::string::npos) << error;
  EXPECT_FALSE(ParseSvg("<svg><path d='M0 0 L1 1'", d, error));
  EXPECT_NE(error.find("malformed XML"), std::string::npos) << error;
  EXPECT_FALSE(ParseSvg(Svg(""), d, error));
  EXPECT_NE(error.find("no path"), std::string::npos) << error;
  EXPECT_FALSE(ParseSvg(Svg("<path d='M0 0 L1 0 L1 1 Z' transform='scale(1e400)'/>"), d, error));
}

TEST(SvgDrawing, EverySharedSvgParses)
{
  const char* data = std::getenv("BOOLSURF_SHARED_DATA");
  const std::filesystem::path folder =
    data ? std::filesystem::path(data) / "boolsurf-scenes" / "svgs" : std::filesystem::path();
  if (!data || !std::filesystem::is_directory(folder))
  {
    GTEST_SKIP() << "BOOLSURF_SHARED_DATA is not set or has no boolsurf-scenes/svgs";
  }
  int files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder))
  {
    if (entry.path().extension() != ".svg")
    {
      continue;
    }
    SvgDrawing d;
    std::string error;
    EXPECT_TRUE(LoadSvg(entry.path().string(), d, error)) << error;
    EXPECT_GT(d.Paths.size(), 0u) << entry.path();
    ++files;
  }
  EXPECT_GE(files, 36);
}

TEST(SvgSurfaceMap, FlatMeshIsTheAffineMap)
{
  const TriangleMesh mesh = ToMesh(MakeFlatSquare(20, 10.0, 0.3, 3));
  SvgDrawing d;
  std::string error;
  ASSERT_TRUE(ParseSvg(Svg("<path d='M20 20 C40 10 60 30 80 20 L80 80 Q50 90 20 80 Z'/>"
                           "<circle cx='50' cy='50' r='10'/>"),
    d,
    error))
    << error;
  SvgMapOptions options;
  options.Center = Locate(mesh, 5.3, 4.7);
  options.Scale = 0.05;
  options.Rotation = 30;
  std::vector<MappedSvgCurve> curves;
  std::vector<std::string> warnings;
  ASSERT_TRUE(MapSvgOntoSurface(mesh, d, options, curves, warnings, error)) << error;
  // Expected: the center triangle's first edge is the x direction of the drawing.
  const int t = options.Center.Triangle;
  Vec3 e1 = mesh.GetCornerPosition(t, 1) - mesh.GetCornerPosition(t, 0);
  e1 = (1.0 / std::sqrt(Dot(e1, e1))) * e1;
  const double frame = std::atan2(e1.y, e1.x) + 30 * std::acos(-1.0) / 180;
  const Vec3 center = mesh.Evaluate(t, options.Center.U, options.Center.V);
  const double cx = 0.5 * (d.Min[0] + d.Max[0]), cy = 0.5 * (d.Min[1] + d.Max[1]);
  int checked = 0;
  ASSERT_EQ(curves.size(), 2u);
  for (std::size_t c = 0; c < curves.size(); ++c)
  {
    const SvgSubpath& source = d.Paths[c].Subpaths[0];
    ASSERT_EQ(curves[c].Points.size(), source.Points.size());
    for (std::size_t i = 0; i < source.Points.size(); ++i)
    {
      // Orientation may have been reversed (keeping the first anchor): find the source point.
      const double x = (source.Points[i].x - cx) * 0.05, y = -(source.Points[i].y - cy) * 0.05;
      const Vec3 expected{ center.x + std::cos(frame) * x - std::sin(frame) * y,
        center.y + std::sin(frame) * x + std::cos(frame) * y,
        0 };
      double best = 1e300;
      for (const SurfacePoint& p : curves[c].Points)
      {
        best = std::min(best, Distance(mesh.Evaluate(p.Triangle, p.U, p.V), expected));
      }
      EXPECT_LT(best, 1e-9) << "curve " << c << " point " << i;
      ++checked;
    }
  }
  EXPECT_GT(checked, 20);
  EXPECT_TRUE(warnings.empty());
}

TEST(SvgSurfaceMap, SphereKeepsDistancesAndAnglesAtTheCenter)
{
  // Points at SVG distance r from the drawing's center land at geodesic distance r * scale
  // (the sphere's arc), up to the polyhedral error, which shrinks as the sphere is refined.
  SvgDrawing d;
  std::string error;
  ASSERT_TRUE(ParseSvg(Svg("<polygon points='50,10 90,50 50,90 10,50'/>"
                           "<polygon points='50,30 70,50 50,70 30,50'/>"),
    d,
    error))
    << error;
  double previous = 1e300;
  for (int level : { 3, 4, 5 })
  {
    const TriangleMesh mesh = ToMesh(MakeIcosphere(level));
    SvgMapOptions options;
    options.Center = { 7, 0.3, 0.3 };
    options.Scale = 0.02; // 40 SVG units = 0.8 radians of arc
    std::vector<MappedSvgCurve> curves;
    std::vector<std::string> warnings;
    ASSERT_TRUE(MapSvgOntoSurface(mesh, d, options, curves, warnings, error)) << error;
    const Vec3 c = mesh.Evaluate(7, 0.3, 0.3);
    const Vec3 cn = (1.0 / std::sqrt(Dot(c, c))) * c;
    double worst = 0;
    for (std::size_t k = 0; k < curves.size(); ++k)
    {
      for (std::size_t i = 0; i < curves[k].Points.size(); i += 3) // the anchors
      {
        const SurfacePoint& p = curves[k].Points[i];
        const Vec3 x = mesh.Evaluate(p.Triangle, p.U, p.V);
        const double arc = std::acos(std::min(1.0, Dot(cn, (1.0 / std::sqrt(Dot(x, x))) * x)));
        const double expected = (k == 0 ? 40 : 20) * 0.02;
        worst = std::max(worst, std::abs(arc - expected));
      }
    }
    EXPECT_LT(worst, 0.05) << "level " << level;
    RecordProperty("DistanceErrorLevel" + std::to_string(level), std::to_string(worst));
    EXPECT_LT(worst, previous) << "no convergence at level " << level;
    previous = worst;
    // Angles at the center: the anchors of the outer square are a quarter turn apart.
    const Vec3 ref =
      mesh.Evaluate(curves[0].Points[0].Triangle, curves[0].Points[0].U, curves[0].Points[0].V) - c;
    const Vec3 next =
      mesh.Evaluate(curves[0].Points[3].Triangle, curves[0].Points[3].U, curves[0].Points[3].V) - c;
    const Vec3 a = ref - Dot(ref, cn) * cn, b = next - Dot(next, cn) * cn;
    const double angle = std::acos(Dot(a, b) / std::sqrt(Dot(a, a) * Dot(b, b)));
    EXPECT_NEAR(angle, std::acos(-1.0) / 2, 0.05) << "level " << level;
  }
}

TEST(SvgSurfaceMap, BoundaryAndBadCenterAreNamed)
{
  const TriangleMesh mesh = ToMesh(MakeFlatSquare(4, 1.0));
  SvgDrawing d;
  std::string error;
  ASSERT_TRUE(ParseSvg(Svg("<rect x='0' y='0' width='100' height='100'/>"), d, error)) << error;
  SvgMapOptions options;
  options.Center = Locate(mesh, 0.5, 0.5);
  options.Scale = 0.02; // 2 x 2: beyond the unit square
  std::vector<MappedSvgCurve> curves;
  std::vector<std::string> warnings;
  ASSERT_TRUE(MapSvgOntoSurface(mesh, d, options, curves, warnings, error)) << error;
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("beyond an open boundary"), std::string::npos);
  options.Center = { 99, 0.1, 0.1 };
  EXPECT_FALSE(MapSvgOntoSurface(mesh, d, options, curves, warnings, error));
  EXPECT_NE(error.find("triangle 99"), std::string::npos) << error;
}

TEST(SvgDrawing, CircleAndEllipseAreFourCubicSegments)
{
  // A circle is four quarter arcs: 12 control points of a closed spline, its anchors on the
  // circle at 90 degrees from each other and no segment of zero length (svgpp draws the
  // circle from a move to its first point, a zero-length line and arcs).
  using namespace boolsurf;
  for (const char* element :
    { "<circle cx='5' cy='7' r='3'/>", "<ellipse cx='5' cy='7' rx='3' ry='3'/>" })
  {
    SCOPED_TRACE(element);
    SvgDrawing d;
    std::string error;
    ASSERT_TRUE(ParseSvg(Svg(element), d, error)) << error;
    ASSERT_EQ(d.Paths.size(), 1u);
    ASSERT_EQ(d.Paths[0].Subpaths.size(), 1u);
    const SvgSubpath& s = d.Paths[0].Subpaths[0];
    EXPECT_TRUE(s.Closed);
    ASSERT_EQ(s.Points.size(), 12u);
    for (std::size_t k = 0; k < 12; ++k)
    {
      const Vec2& p = s.Points[k];
      const Vec2& q = s.Points[(k + 1) % 12];
      EXPECT_GT(std::hypot(p.x - q.x, p.y - q.y), 1.0) << "control points " << k << ", " << k + 1;
      if (k % 3 == 0)
      {
        EXPECT_NEAR(std::hypot(p.x - 5, p.y - 7), 3, 1e-12) << "anchor " << k / 3;
      }
    }
  }
  // Two half arcs closed by Z end within rounding of their start: no closing sliver.
  SvgDrawing d;
  std::string error;
  ASSERT_TRUE(ParseSvg(Svg("<path d='M8 7 A3 3 0 0 1 2 7 A3 3 0 0 1 8 7 Z'/>"), d, error)) << error;
  const SvgSubpath& s = d.Paths.at(0).Subpaths.at(0);
  const std::size_t n = s.Points.size();
  ASSERT_EQ(n % 3, 0u);
  EXPECT_EQ(n / 3, 4u) << "a full turn of arcs is four quarter-turn pieces";
  for (std::size_t k = 0; k < n; ++k)
  {
    const Vec2& p = s.Points[k];
    const Vec2& q = s.Points[(k + 1) % n];
    EXPECT_GT(std::hypot(p.x - q.x, p.y - q.y), 1e-3) << "control points " << k << ", " << k + 1;
  }
  // Each piece stays on the circle of radius 3 around (5, 7) (a quarter-turn cubic is off by
  // at most 2.7e-4 of the radius).
  for (std::size_t k = 0; k < n; k += 3)
  {
    const Vec2 &a = s.Points[k], &b = s.Points[k + 1], &c = s.Points[k + 2],
               &e = s.Points[(k + 3) % n];
    for (double t : { 0.25, 0.5, 0.75 })
    {
      const double u = 1 - t;
      const double x =
        u * u * u * a.x + 3 * u * u * t * b.x + 3 * u * t * t * c.x + t * t * t * e.x;
      const double y =
        u * u * u * a.y + 3 * u * u * t * b.y + 3 * u * t * t * c.y + t * t * t * e.y;
      EXPECT_NEAR(std::hypot(x - 5, y - 7), 3, 3 * 3e-4) << "piece " << k / 3 << " at " << t;
    }
  }
}

TEST(SvgDrawing, NoSegmentOfNoLength)
{
  // Lines to where the path already is, and the straight sides of a rect whose rounded corners
  // take the whole side (a pill), are segments of no length: dropped. What is left is the
  // shape, every segment of some length.
  using namespace boolsurf;
  struct Case
  {
    const char* Element;
    std::size_t Segments;
  };
  for (const Case& c : { Case{ "<path d='M0 0 L0 0 L5 0 L5 0 L5 5 Z'/>", 3 },
         Case{ "<rect x='0' y='0' width='10' height='4' rx='2' ry='2'/>", 0 } })
  {
    SCOPED_TRACE(c.Element);
    SvgDrawing d;
    std::string error;
    ASSERT_TRUE(ParseSvg(Svg(c.Element), d, error)) << error;
    const SvgSubpath& s = d.Paths.at(0).Subpaths.at(0);
    ASSERT_TRUE(s.Closed);
    const std::size_t n = s.Points.size();
    ASSERT_EQ(n % 3, 0u);
    if (c.Segments > 0)
    {
      EXPECT_EQ(n / 3, c.Segments);
    }
    for (std::size_t k = 0; k < n; k += 3)
    {
      double length = 0;
      for (std::size_t i = 0; i < 3; ++i)
      {
        const Vec2& a = s.Points[k + i];
        const Vec2& b = s.Points[(k + i + 1) % n];
        length += std::hypot(a.x - b.x, a.y - b.y);
      }
      EXPECT_GT(length, 1e-3) << "segment " << k / 3 << " of " << n / 3;
    }
  }
}

TEST(SvgSurfaceMap, SamePointsOnOneThreadAndOnEvery)
{
  // Enough control points (circles of 12, a path) for the walks to run in parallel: the
  // mapped curves are those of one thread bit for bit.
  const TriangleMesh mesh = ToMesh(MakeTorus(1.0, 0.4, 64, 32));
  std::string body = "<path d='M10 10 C30 5 60 40 90 10 L90 90 Q50 70 10 90 Z'/>";
  for (int k = 0; k < 12; ++k)
  {
    body += "<circle cx='" + std::to_string(10 + 7 * k) + "' cy='" + std::to_string(15 + 6 * k) +
      "' r='" + std::to_string(3 + k) + "'/>";
  }
  SvgDrawing d;
  std::string error;
  ASSERT_TRUE(ParseSvg(Svg(body), d, error)) << error;
  SvgMapOptions options;
  options.Center = { 17, 0.25, 0.3 };
  options.Scale = 0.03;
  options.Rotation = 40;
  std::vector<std::vector<MappedSvgCurve>> byThreads;
  for (int threads : { 1, 2, 0 })
  {
    options.Threads = threads;
    std::vector<MappedSvgCurve> curves;
    std::vector<std::string> warnings;
    ASSERT_TRUE(MapSvgOntoSurface(mesh, d, options, curves, warnings, error)) << error;
    byThreads.push_back(std::move(curves));
  }
  std::size_t points = 0;
  for (const MappedSvgCurve& c : byThreads[0])
  {
    points += c.Points.size();
  }
  ASSERT_GE(points, 64u); // the parallel path is taken
  for (std::size_t run = 1; run < byThreads.size(); ++run)
  {
    ASSERT_EQ(byThreads[run].size(), byThreads[0].size());
    for (std::size_t c = 0; c < byThreads[0].size(); ++c)
    {
      const std::vector<SurfacePoint>& a = byThreads[0][c].Points;
      const std::vector<SurfacePoint>& b = byThreads[run][c].Points;
      ASSERT_EQ(a.size(), b.size());
      for (std::size_t i = 0; i < a.size(); ++i)
      {
        EXPECT_EQ(a[i].Triangle, b[i].Triangle);
        EXPECT_EQ(a[i].U, b[i].U); // bit for bit
        EXPECT_EQ(a[i].V, b[i].V);
      }
    }
  }
}

// Surface winding numbers (Winding/SurfaceWinding.h): closed curves against the exact labels,
// broken, open and overshooting curves against their closed originals, a curve that bounds
// nothing, the planar generalized winding number far from a flat mesh's boundary, bad input.
#include "Labeling/ArrangementLabelingInput.h"
#include "Mesh/MeshTopology.h"
#include "Mesh/PlyReader.h"
#include "Mesh/ProceduralMeshes.h"
#include "Support/SourceTree.h"
#include "Support/SyntheticCurves.h"
#include "Winding/SurfaceWinding.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>

namespace boolsurf
{
namespace
{

constexpr double Pi = 3.14159265358979323846;

TriangleMesh MeshOf(const MeshData& d)
{
  return TriangleMesh(d.Positions, d.Triangles);
}

Arrangement Arrange(const TriangleMesh& mesh, const std::vector<TracedCurve>& curves)
{
  Arrangement arr;
  std::string error;
  ArrangementOptions options;
  options.Threads = 1;
  EXPECT_TRUE(ComputeArrangement(mesh, curves, options, arr, error)) << error;
  return arr;
}

double TriangleArea(const TriangleMesh& mesh, const Arrangement& arr, int r)
{
  const Triangle t = arr.GetTriangle(mesh, r);
  return 0.5 *
    Length(Cross(arr.GetPosition(mesh, t[1]) - arr.GetPosition(mesh, t[0]),
      arr.GetPosition(mesh, t[2]) - arr.GetPosition(mesh, t[0])));
}

/// Largest difference between w at every corner of every refined triangle and the exact
/// label of the triangle's cell, per shape.
double LargestLabelError(const TriangleMesh& mesh,
  const std::vector<TracedCurve>& curves,
  const Arrangement& arr,
  const WindingResult& w)
{
  const MeshTopology topology = MeshTopology::Compute(mesh);
  const LabelingResult labels = LabelCells(MakeLabelingInput(mesh, topology, curves, arr));
  double worst = 0;
  for (int s = 0; s < w.GetNumberOfShapes(); ++s)
  {
    EXPECT_TRUE(labels.ShapeConsistent[s]);
    EXPECT_EQ(labels.ShapeIdOf(s), w.ShapeIds[s]);
    for (int r = 0; r < arr.GetNumberOfTriangles(); ++r)
    {
      const int cell = arr.CellOfTriangle(r);
      if (cell < 0 || TriangleArea(mesh, arr, r) == 0.0)
      {
        continue; // (a curve retracing itself may leave cells of no area, labeled as sides)
      }
      for (int k = 0; k < 3; ++k)
      {
        worst = std::max(worst, std::abs(w.Corner(arr, mesh, s, r, k) - labels.GetLabel(cell, s)));
      }
    }
  }
  return worst;
}

WindingResult Wind(const TriangleMesh& mesh,
  const Arrangement& arr,
  const std::vector<TracedCurve>& curves,
  WindingOptions options = WindingOptions(),
  SurfaceWinding* kept = nullptr)
{
  SurfaceWinding fresh;
  SurfaceWinding& winding = kept ? *kept : fresh;
  WindingResult w;
  std::string error;
  options.Threads = 1;
  EXPECT_TRUE(winding.Compute(mesh, arr, curves, options, w, error)) << error;
  return w;
}

/// meshes/ of the shared collection (BOOLSURF_SHARED_DATA), empty when it is not there.
std::filesystem::path SharedMeshFolder()
{
  const char* shared = std::getenv("BOOLSURF_SHARED_DATA");
  const std::filesystem::path folder =
    shared ? std::filesystem::path(shared) / "meshes" : std::filesystem::path();
  return shared && std::filesystem::exists(folder) ? folder : std::filesystem::path();
}

/// Mesh `name` of the shared collection; a failure names the file and the reason.
::testing::AssertionResult ReadSharedMesh(const char* name, MeshData& out)
{
  std::string error;
  if (ReadPly((SharedMeshFolder() / name).string(), out, error))
  {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << error;
}

/// Corners of the axis-aligned box of `points`.
void BoundingBox(const std::vector<Vec3>& points, Vec3& lo, Vec3& hi)
{
  lo = { 1e300, 1e300, 1e300 };
  hi = { -1e300, -1e300, -1e300 };
  for (const Vec3& p : points)
  {
    lo = { std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z) };
    hi = { std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z) };
  }
}

/// Reverses `curve` unless the side dot(normal, x) > offset is on its left (plane sections
/// follow the mesh, not the plane's side).
void PositiveSideOnTheLeft(const TriangleMesh& mesh, Vec3 normal, TracedCurve& curve)
{
  const size_t n = curve.Points.size();
  for (size_t i = 0; i < n; ++i)
  {
    const CanonicalPoint& a = curve.Points[i];
    const CanonicalPoint& b = curve.Points[(i + 1) % n];
    const int t = SharedTriangle(mesh, a, b);
    const Vec3 d = PositionOf(mesh, b) - PositionOf(mesh, a);
    if (t < 0 || Length(d) == 0.0)
    {
      continue;
    }
    const Triangle& tri = mesh.GetTriangle(t);
    const Vec3 faceNormal = Cross(mesh.GetPosition(tri[1]) - mesh.GetPosition(tri[0]),
      mesh.GetPosition(tri[2]) - mesh.GetPosition(tri[0]));
    if (Dot(normal, Cross(faceNormal, d)) < 0)
    {
      std::reverse(curve.Points.begin(), curve.Points.end());
    }
    return;
  }
}

/// Points of a circle polygon of n vertices.
std::vector<Vec2> Circle(Vec2 center, double radius, int n, double phase = 0.1)
{
  std::vector<Vec2> points;
  for (int i = 0; i < n; ++i)
  {
    const double a = phase + 2 * Pi * i / n;
    points.push_back({ center.x + radius * std::cos(a), center.y + radius * std::sin(a) });
  }
  return points;
}

bool InsidePolygon(const std::vector<Vec2>& polygon, Vec2 p)
{
  bool inside = false;
  for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
  {
    const Vec2 a = polygon[i], b = polygon[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x)
    {
      inside = !inside;
    }
  }
  return inside;
}

/// The circle cut into `gaps` pieces with `gapFraction` of its vertices left out in total
/// (evenly), each piece an open curve of shape 0. `overshoot` > 0 extends every piece past the
/// next one's start by that many vertices instead.
std::vector<TracedCurve> BrokenCircle(const TriangleMesh& mesh,
  const std::vector<Vec2>& circle,
  int gaps,
  double gapFraction,
  int overshoot = 0)
{
  const int n = static_cast<int>(circle.size());
  const int gapVertices = static_cast<int>(std::lround(gapFraction * n / gaps));
  FlatPolygonTracer tracer(mesh);
  std::vector<TracedCurve> curves;
  for (int g = 0; g < gaps; ++g)
  {
    const int first = g * n / gaps;
    const int last = (g + 1) * n / gaps - gapVertices + overshoot;
    std::vector<Vec2> piece;
    for (int i = first; i <= last; ++i)
    {
      piece.push_back(circle[i % n]);
    }
    TracedCurve c;
    EXPECT_TRUE(tracer.Trace(piece, false, 0, g, c));
    curves.push_back(c);
  }
  return curves;
}

/// Area of {w >= 1/2} by refined triangles (centroid value) and its symmetric difference with
/// the inside of `polygon` (by centroid).
void RegionAgainstPolygon(const TriangleMesh& mesh,
  const Arrangement& arr,
  const WindingResult& w,
  const std::vector<Vec2>& polygon,
  double& area,
  double& difference)
{
  area = difference = 0;
  for (int r = 0; r < arr.GetNumberOfTriangles(); ++r)
  {
    const Triangle t = arr.GetTriangle(mesh, r);
    const Vec3 c = (1.0 / 3.0) *
      (arr.GetPosition(mesh, t[0]) + arr.GetPosition(mesh, t[1]) + arr.GetPosition(mesh, t[2]));
    const bool in = w.Triangle(arr, mesh, 0, r) >= 0.5;
    const double a = TriangleArea(mesh, arr, r);
    area += in ? a : 0.0;
    difference += in != InsidePolygon(polygon, { c.x, c.y }) ? a : 0.0;
  }
}

double PolygonArea(const std::vector<Vec2>& p)
{
  double a = 0;
  for (size_t i = 0; i < p.size(); ++i)
  {
    const Vec2 u = p[i], v = p[(i + 1) % p.size()];
    a += u.x * v.y - v.x * u.y;
  }
  return 0.5 * a;
}

TEST(SurfaceWinding, ClosedPolygonsOnAFlatMeshEqualTheLabels)
{
  const TriangleMesh mesh = MeshOf(MakeFlatSquare(30, 10.0, 0.45, 7));
  FlatPolygonTracer tracer(mesh);
  std::vector<TracedCurve> curves(4);
  // Shape 0: a counter-clockwise circle and a clockwise square crossing it (labels 1, 0, -1);
  // shape 1: nested circles (labels 1 and 2); a polygon with a side along the boundary.
  ASSERT_TRUE(tracer.Trace(Circle({ 4.0, 4.5 }, 2.5, 40), true, 0, 0, curves[0]));
  ASSERT_TRUE(tracer.Trace(
    { { 5.1, 3.2 }, { 5.1, 7.7 }, { 8.3, 7.7 }, { 8.3, 3.2 } }, true, 0, 1, curves[1]));
  ASSERT_TRUE(tracer.Trace(Circle({ 6.0, 6.0 }, 3.0, 33, 0.3), true, 1, 0, curves[2]));
  ASSERT_TRUE(tracer.Trace(Circle({ 6.3, 6.2 }, 1.1, 17, 0.7), true, 1, 1, curves[3]));
  TracedCurve along;
  ASSERT_TRUE(
    tracer.Trace({ { 0.0, 1.0 }, { 0.0, 0.0 }, { 3.7, 0.0 }, { 2.2, 1.9 } }, true, 2, 0, along));
  curves.push_back(along);
  const Arrangement arr = Arrange(mesh, curves);
  const WindingResult w = Wind(mesh, arr, curves);
  ASSERT_EQ(w.GetNumberOfShapes(), 3);
  EXPECT_LT(LargestLabelError(mesh, curves, arr, w), 1e-8);
  for (const WindingCurveReport& report : w.Curves)
  {
    EXPECT_TRUE(report.Bounds);
  }
  // Closed curves that bound their region exactly have no residual where they are alone.
  EXPECT_LT(w.Curves[4].Residual, 1e-9);
}

/// One closed polygon of shape 0 on a flat mesh: w equals its labels, nothing dropped.
void ExpectOneClosedPolygonKeptAsLabeled(const TriangleMesh& mesh, const std::vector<Vec2>& polygon)
{
  FlatPolygonTracer tracer(mesh);
  std::vector<TracedCurve> curves(1);
  ASSERT_TRUE(tracer.Trace(polygon, true, 0, 0, curves[0]));
  const Arrangement arr = Arrange(mesh, curves);
  const WindingResult w = Wind(mesh, arr, curves);
  EXPECT_LT(LargestLabelError(mesh, curves, arr, w), 1e-8);
  EXPECT_TRUE(w.Curves[0].Bounds);
  EXPECT_EQ(w.Times.DroppedEdges, 0);
}

TEST(SurfaceWinding, ARetracedSpikeIsNotDroppedWithItsLoop)
{
  // Found by fuzzing: a closed curve that runs out along a line, round a loop and back along
  // the same line. Its retraced stretches cancel (no jump, no say in whether it bounds); it
  // bounds its loop, and was dropped as a whole when they counted as bounding nothing.
  ExpectOneClosedPolygonKeptAsLabeled(MeshOf(MakeFlatSquare(20, 10.0, 0.45, 17)),
    { { 1.2, 5.1 }, { 5.3, 5.1 }, { 6.2, 3.9 }, { 7.6, 5.0 }, { 6.1, 6.4 }, { 5.3, 5.1 } });
}

TEST(SurfaceWinding, ClockwiseAlongTheBoundaryIsNotDropped)
{
  // Found by fuzzing: a curve running along the open boundary with the surface on its right
  // (clockwise round a corner region) has no refined triangle on its left there; its degree was
  // read as 0 and the whole curve dropped.
  ExpectOneClosedPolygonKeptAsLabeled(MeshOf(MakeFlatSquare(10, 10.0, 0.0)),
    { { 0.0, 0.0 }, { 0.0, 4.0 }, { 0.0, 6.0 }, { 0.0, 4.0 }, { 3.3, 2.7 }, { 5.0, 0.0 } });
}

TEST(SurfaceWinding, LatitudeOnASphereEqualsTheLabels)
{
  const TriangleMesh mesh = MeshOf(MakeIcosphere(4));
  std::vector<TracedCurve> curves = PlaneSectionCurves(mesh, { 0.1, 0.2, 1.0 }, 0.31, 0);
  const std::vector<TracedCurve> second = PlaneSectionCurves(mesh, { 1.0, -0.3, 0.1 }, 0.17, 1);
  curves.insert(curves.end(), second.begin(), second.end());
  ASSERT_EQ(curves.size(), 2u);
  const Arrangement arr = Arrange(mesh, curves);
  const WindingResult w = Wind(mesh, arr, curves);
  EXPECT_LT(LargestLabelError(mesh, curves, arr, w), 1e-8);
  EXPECT_LT(w.Curves[0].Residual, 1e-9);
}

TEST(SurfaceWinding, BoundingCurvesOnATorusEqualTheLabels)
{
  const TriangleMesh mesh = MeshOf(MakeTorus(2.0, 0.7, 48, 24));
  // A small loop around the outer equator, and the two longitudes a plane above the centre
  // cuts (they bound the band between them together).
  std::vector<TracedCurve> curves = PlaneSectionCurves(mesh, { 1.0, 0.05, 0.02 }, 2.45, 0);
  ASSERT_EQ(curves.size(), 1u);
  std::vector<TracedCurve> band = PlaneSectionCurves(mesh, { 0.01, 0.02, 1.0 }, 0.45, 1);
  ASSERT_EQ(band.size(), 2u);
  // A plane section runs both longitudes the same way round the axis: reverse one so that
  // they bound the band between them.
  std::reverse(band[1].Points.begin(), band[1].Points.end());
  curves.insert(curves.end(), band.begin(), band.end());
  const Arrangement arr = Arrange(mesh, curves);
  const WindingResult w = Wind(mesh, arr, curves);
  EXPECT_LT(LargestLabelError(mesh, curves, arr, w), 1e-8);
  for (const WindingCurveReport& report : w.Curves)
  {
    EXPECT_TRUE(report.Bounds) << "curve " << report.Curve;
    ASSERT_EQ(report.Homology.size(), 2u);
  }
  // The longitudes carry opposite integer classes, not zero; the small loop none.
  double norm = 0;
  for (int g = 0; g < 2; ++g)
  {
    EXPECT_NEAR(w.Curves[1].Homology[g], std::round(w.Curves[1].Homology[g]), 1e-6);
    norm += std::abs(w.Curves[1].Homology[g]);
    EXPECT_NEAR(w.Curves[0].Homology[g], 0.0, 1e-6);
    EXPECT_NEAR(w.Curves[1].Homology[g] + w.Curves[2].Homology[g], 0.0, 1e-6);
  }
  EXPECT_GT(norm, 0.9);
}

TEST(SurfaceWinding, TorusMeridianBoundsNothing)
{
  const TriangleMesh mesh = MeshOf(MakeTorus(2.0, 0.7, 48, 24));
  // The plane x = 0 cuts two meridians; keep one, and add a small bounding loop to its shape.
  std::vector<TracedCurve> meridians = PlaneSectionCurves(mesh, { 1.0, 0.03, 0.0 }, 0.013, 0);
  ASSERT_EQ(meridians.size(), 2u);
  std::vector<TracedCurve> curves = { meridians[0] };
  std::vector<TracedCurve> loop = PlaneSectionCurves(mesh, { 0.02, 1.0, 0.05 }, 2.45, 0, 1);
  ASSERT_EQ(loop.size(), 1u);
  curves.push_back(loop[0]);
  const Arrangement arr = Arrange(mesh, curves);
  const WindingResult w = Wind(mesh, arr, curves);
  ASSERT_EQ(w.Curves.size(), 2u);
  EXPECT_FALSE(w.Curves[0].Bounds);
  EXPECT_EQ(w.Curves[0].Residual, 1.0);
  EXPECT_TRUE(w.Curves[1].Bounds);
  EXPECT_LT(w.Curves[1].Residual, 1e-9);
  // What is left is the loop's region exactly: w is the labels of the loop alone.
  const std::vector<TracedCurve> alone = { loop[0] };
  const Arrangement arrAlone = Arrange(mesh, alone);
  const WindingResult wAlone = Wind(mesh, arrAlone, alone);
  EXPECT_LT(LargestLabelError(mesh, alone, arrAlone, wAlone), 1e-8);
  double inside = 0, insideAlone = 0;
  for (int r = 0; r < arr.GetNumberOfTriangles(); ++r)
  {
    inside += w.Triangle(arr, mesh, 0, r) >= 0.5 ? TriangleArea(mesh, arr, r) : 0.0;
  }
  for (int r = 0; r < arrAlone.GetNumberOfTriangles(); ++r)
  {
    insideAlone +=
      wAlone.Triangle(arrAlone, mesh, 0, r) >= 0.5 ? TriangleArea(mesh, arrAlone, r) : 0.0;
  }
  EXPECT_NEAR(inside, insideAlone, 1e-9 * insideAlone);
  // Without the correction the meridian's ramp reaches every value between its sides.
  WindingOptions raw;
  raw.RemoveNonBounding = false;
  const WindingResult ramp = Wind(mesh, arr, curves, raw);
  EXPECT_TRUE(ramp.Curves[0].Bounds);
  double lo = 1e300, hi = -1e300;
  for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
    lo = std::min(lo, ramp.Point(0, v));
    hi = std::max(hi, ramp.Point(0, v));
  }
  EXPECT_GT(hi - lo, 0.9);
}

TEST(SurfaceWinding, GenusTwoCapEqualsTheLabels)
{
  MeshData d;
  std::string error;
  ASSERT_TRUE(ReadPly((testing::SourceTree() / "Data" / "eight.ply").string(), d, error)) << error;
  const TriangleMesh mesh = MeshOf(d);
  // A cap cut near one end of the longest axis.
  Vec3 lo, hi;
  BoundingBox(d.Positions, lo, hi);
  const Vec3 extent = hi - lo;
  const int axis =
    extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  Vec3 normal{ 0.013, 0.021, 0.017 };
  normal = normal + Vec3{ axis == 0 ? 1.0 : 0.0, axis == 1 ? 1.0 : 0.0, axis == 2 ? 1.0 : 0.0 };
  const double offset = Dot(normal, hi) - 0.12 * extent[axis];
  std::vector<TracedCurve> curves = PlaneSectionCurves(mesh, normal, offset, 0);
  ASSERT_EQ(curves.size(), 1u);
  const Arrangement arr = Arrange(mesh, curves);
  const WindingResult w = Wind(mesh, arr, curves);
  EXPECT_LT(LargestLabelError(mesh, curves, arr, w), 1e-8);
  EXPECT_TRUE(w.Curves[0].Bounds);
  for (double a : w.Curves[0].Homology)
  {
    EXPECT_NEAR(a, 0.0, 1e-6);
  }
}

TEST(SurfaceWinding, BrokenCircleGivesTheClosedRegion)
{
  const TriangleMesh mesh = MeshOf(MakeFlatSquare(48, 10.0, 0.45, 3));
  const std::vector<Vec2> circle = Circle({ 5.1, 4.9 }, 3.0, 240);
  const double area = std::abs(PolygonArea(circle));
  for (int gaps = 1; gaps <= 4; ++gaps)
  {
    for (double fraction : { 0.01, 0.03, 0.05, 0.10 })
    {
      const std::vector<TracedCurve> curves = BrokenCircle(mesh, circle, gaps, fraction);
      const Arrangement arr = Arrange(mesh, curves);
      const WindingResult w = Wind(mesh, arr, curves);
      double region, difference;
      RegionAgainstPolygon(mesh, arr, w, circle, region, difference);
      if (fraction <= 0.05)
      {
        EXPECT_LE(difference, 0.01 * area) << gaps << " gaps, " << fraction;
      }
      else
      {
        EXPECT_LE(difference, 0.05 * area) << gaps << " gaps, " << fraction;
      }
      for (const WindingCurveReport& report : w.Curves)
      {
        EXPECT_LT(report.Residual, 0.5) << gaps << " gaps, " << fraction;
      }
    }
  }
}

TEST(SurfaceWinding, OvershootsAndSpursLeaveTheRegion)
{
  const TriangleMesh mesh = MeshOf(MakeFlatSquare(48, 10.0, 0.45, 5));
  const std::vector<Vec2> circle = Circle({ 4.9, 5.2 }, 3.1, 200);
  const double area = std::abs(PolygonArea(circle));
  FlatPolygonTracer tracer(mesh);
  // Overshooting pieces: each runs 4 vertices past the next one's start.
  {
    const std::vector<TracedCurve> curves = BrokenCircle(mesh, circle, 3, 0.0, 4);
    const Arrangement arr = Arrange(mesh, curves);
    const WindingResult w = Wind(mesh, arr, curves);
    double region, difference;
    RegionAgainstPolygon(mesh, arr, w, circle, region, difference);
    EXPECT_LE(difference, 0.01 * area);
  }
  // One stroke round the circle that runs on past its start and out, a tail of about a tenth
  // of its length.
  {
    std::vector<Vec2> stroke(circle.begin(), circle.end());
    stroke.push_back(circle[0]);
    for (int i = 1; i <= 10; ++i)
    {
      stroke.push_back({ circle[0].x + 0.12 * i, circle[0].y + 0.05 * i });
    }
    std::vector<TracedCurve> curves(1);
    ASSERT_TRUE(tracer.Trace(stroke, false, 0, 0, curves[0]));
    const Arrangement arr = Arrange(mesh, curves);
    const WindingResult w = Wind(mesh, arr, curves);
    double region, difference;
    RegionAgainstPolygon(mesh, arr, w, circle, region, difference);
    EXPECT_LE(difference, 0.01 * area);
    EXPECT_GT(w.Times.DroppedEdges, 0);
    EXPECT_TRUE(w.Curves[0].Bounds);
  }
  // A closed circle with a spur dangling inside and one sticking out.
  {
    std::vector<TracedCurve> curves(3);
    ASSERT_TRUE(tracer.Trace(circle, true, 0, 0, curves[0]));
    ASSERT_TRUE(tracer.Trace({ { 4.9, 5.2 }, { 6.1, 6.3 }, { 7.0, 5.9 } }, false, 0, 1, curves[1]));
    ASSERT_TRUE(tracer.Trace({ { 7.3, 5.0 }, { 9.1, 4.2 } }, false, 0, 2, curves[2]));
    const Arrangement arr = Arrange(mesh, curves);
    const WindingResult w = Wind(mesh, arr, curves);
    double region, difference;
    RegionAgainstPolygon(mesh, arr, w, circle, region, difference);
    EXPECT_LE(difference, 0.01 * area);
    // The spurs bound nothing: almost all of their length is off the level set.
    EXPECT_GT(w.Curves[1].Residual, 0.9);
    EXPECT_GT(w.Curves[2].Residual, 0.5);
    EXPECT_LT(w.Curves[0].Residual, 0.05);
  }
}

/// Symmetric difference, per mesh triangle, between {w >= 1/2} of a closed loop and of the same
/// loop broken into `pieces` open curves with `gapFraction` of its points left out, relative
/// to the closed loop's region. 3 to 1 pieces, gaps of 1 to 5 %.
double BrokenLoopDifference(const TriangleMesh& mesh,
  const TracedCurve& loop,
  int pieces,
  double gapFraction,
  SurfaceWinding& winding,
  double* regionArea = nullptr)
{
  const std::vector<TracedCurve> closed = { loop };
  const Arrangement arrClosed = Arrange(mesh, closed);
  const WindingResult wClosed = Wind(mesh, arrClosed, closed, WindingOptions(), &winding);
  if (!wClosed.Curves[0].Bounds)
  {
    return -1.0; // a loop around a handle: nothing to recover
  }
  const std::vector<CanonicalPoint>& points = loop.Points;
  const int n = static_cast<int>(points.size());
  const int gap = std::max(1, static_cast<int>(std::lround(gapFraction * n / pieces)));
  std::vector<TracedCurve> broken;
  for (int g = 0; g < pieces; ++g)
  {
    TracedCurve c;
    c.Closed = false;
    c.ShapeId = loop.ShapeId;
    c.CurveId = g;
    for (int i = g * n / pieces; i <= (g + 1) * n / pieces - gap; ++i)
    {
      c.Points.push_back(points[i % n]);
    }
    broken.push_back(c);
  }
  const Arrangement arr = Arrange(mesh, broken);
  const WindingResult w = Wind(mesh, arr, broken, WindingOptions(), &winding);
  auto insideShare = [&](const Arrangement& a, const WindingResult& ww)
  {
    std::vector<double> share(mesh.GetNumberOfTriangles(), 0.0);
    for (int r = 0; r < a.GetNumberOfTriangles(); ++r)
    {
      if (a.GetSourceTriangle(mesh, r) >= 0 && ww.Triangle(a, mesh, 0, r) >= 0.5)
      {
        share[a.GetSourceTriangle(mesh, r)] += TriangleArea(mesh, a, r);
      }
    }
    return share;
  };
  const std::vector<double> x = insideShare(arrClosed, wClosed), y = insideShare(arr, w);
  double region = 0, difference = 0;
  for (size_t t = 0; t < x.size(); ++t)
  {
    region += x[t];
    difference += std::abs(x[t] - y[t]);
  }
  if (regionArea)
  {
    *regionArea = region;
  }
  return region > 0 ? difference / region : 1.0;
}

TEST(SurfaceWinding, BrokenLoopsOnASphereATorusAndScans)
{
  {
    const TriangleMesh mesh = MeshOf(MakeIcosphere(5));
    const std::vector<TracedCurve> loop = PlaneSectionCurves(mesh, { 0.1, 0.2, 1.0 }, 0.45, 0);
    ASSERT_EQ(loop.size(), 1u);
    SurfaceWinding winding;
    for (int pieces = 1; pieces <= 3; ++pieces)
    {
      double area = 0;
      EXPECT_LE(BrokenLoopDifference(mesh, loop[0], pieces, 0.03, winding, &area), 0.01) << pieces;
      EXPECT_GT(area, 0.1);
    }
  }
  {
    // A contractible loop on the outer side of a torus (genus 1: the homology correction runs
    // and must leave a broken bounding loop alone).
    const TriangleMesh mesh = MeshOf(MakeTorus(2.0, 0.7, 96, 48));
    const std::vector<TracedCurve> loop = PlaneSectionCurves(mesh, { 1.0, 0.05, 0.02 }, 2.2, 0);
    ASSERT_EQ(loop.size(), 1u);
    SurfaceWinding winding;
    for (int pieces = 1; pieces <= 3; ++pieces)
    {
      EXPECT_LE(BrokenLoopDifference(mesh, loop[0], pieces, 0.04, winding), 0.01) << pieces;
    }
  }
  if (SharedMeshFolder().empty())
  {
    GTEST_SKIP() << "BOOLSURF_SHARED_DATA (../shared/data) is not available: scans skipped";
  }
  for (const char* name : { "kitten.ply", "spot.ply", "fertility.ply" })
  {
    MeshData d;
    ASSERT_TRUE(ReadSharedMesh(name, d));
    const TriangleMesh mesh = MeshOf(d);
    Vec3 lo, hi;
    BoundingBox(d.Positions, lo, hi);
    // Loops that bound, cut near one end of two axes (sections of one closed loop; a loop
    // around a handle is skipped).
    int tested = 0;
    SurfaceWinding winding;
    for (const Vec3 normal : { Vec3{ 1.0, 0.04, 0.03 }, Vec3{ 0.02, 1.0, 0.05 } })
    {
      for (double f : { 0.8, 0.75, 0.85, 0.7, 0.9, 0.65 })
      {
        std::vector<TracedCurve> loop =
          PlaneSectionCurves(mesh, normal, Dot(normal, lo + f * (hi - lo)), 0);
        if (loop.size() != 1 || !loop[0].Closed)
        {
          continue;
        }
        PositiveSideOnTheLeft(mesh, normal, loop[0]); // the cap beyond the plane inside
        if (BrokenLoopDifference(mesh, loop[0], 1, 0.0, winding) < 0)
        {
          continue;
        }
        for (int pieces = 1; pieces <= 3; ++pieces)
        {
          EXPECT_LE(BrokenLoopDifference(mesh, loop[0], pieces, 0.03, winding), 0.01)
            << name << ", " << pieces << " pieces";
        }
        ++tested;
        break;
      }
    }
    EXPECT_GE(tested, 1) << name; // sections of many loops are left out
  }
}

TEST(SurfaceWinding, OpenArcFollowsThePlanarGeneralizedWindingNumber)
{
  // Far from the boundary of a large flat mesh, w of an open arc is the planar generalized
  // winding number (the angle it subtends over 2 pi), up to a constant.
  const TriangleMesh mesh = MeshOf(MakeFlatSquare(160, 60.0, 0.3, 11));
  std::vector<Vec2> arc;
  for (int i = 0; i <= 60; ++i)
  {
    const double a = 0.2 + 1.5 * Pi * i / 60;
    arc.push_back({ 30.0 + 2.0 * std::cos(a), 30.0 + 2.0 * std::sin(a) });
  }
  FlatPolygonTracer tracer(mesh);
  std::vector<TracedCurve> curves(1);
  ASSERT_TRUE(tracer.Trace(arc, false, 0, 0, curves[0]));
  const Arrangement arr = Arrange(mesh, curves);
  WindingOptions raw;
  raw.RemoveNonBounding = false;
  const WindingResult w = Wind(mesh, arr, curves, raw);
  auto planar = [&](Vec2 p)
  {
    double angle = 0;
    for (size_t i = 0; i + 1 < arc.size(); ++i)
    {
      const Vec2 a = arc[i] - p, b = arc[i + 1] - p;
      angle += std::atan2(Cross(a, b), Dot(a, b));
    }
    return angle / (2 * Pi);
  };
  std::vector<double> difference;
  for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
    const Vec3 x = mesh.GetPosition(v);
    const double r = std::hypot(x.x - 30.0, x.y - 30.0);
    if (r > 3.0 && r < 8.0)
    {
      difference.push_back(w.Point(0, v) - planar({ x.x, x.y }));
    }
  }
  ASSERT_GT(difference.size(), 100u);
  double mean = 0;
  for (double d : difference)
  {
    mean += d;
  }
  mean /= difference.size();
  double worst = 0;
  for (double d : difference)
  {
    worst = std::max(worst, std::abs(d - mean));
  }
  EXPECT_LT(worst, 0.02);
}

TEST(SurfaceWinding, EditsReuseTheFactorizationWithTheSameResult)
{
  const TriangleMesh mesh = MeshOf(MakeFlatSquare(30, 10.0, 0.45, 9));
  SurfaceWinding kept;
  std::string error;
  for (double shift : { 0.0, 0.37, 1.1 })
  {
    const std::vector<TracedCurve> curves =
      BrokenCircle(mesh, Circle({ 4.0 + shift, 5.0 }, 2.0, 90), 2, 0.04);
    const Arrangement arr = Arrange(mesh, curves);
    WindingResult reused, fresh;
    ASSERT_TRUE(kept.Compute(mesh, arr, curves, WindingOptions(), reused, error)) << error;
    SurfaceWinding once;
    ASSERT_TRUE(once.Compute(mesh, arr, curves, WindingOptions(), fresh, error)) << error;
    EXPECT_EQ(reused.CornerLift, fresh.CornerLift);
    for (int p = 0; p < arr.GetNumberOfPoints(); ++p)
    {
      ASSERT_EQ(reused.Point(0, p), fresh.Point(0, p)) << "point " << p;
    }
  }
}

TEST(SurfaceWinding, CurveFromBoundaryToBoundaryBoundsWithTheBoundary)
{
  // Zero normal derivative on the open boundary: the boundary completes a curve that ends on
  // it, so a line across the square gives exactly 1 on its left and 0 on its right.
  const TriangleMesh mesh = MeshOf(MakeFlatSquare(25, 10.0, 0.45, 13));
  FlatPolygonTracer tracer(mesh);
  std::vector<TracedCurve> curves(1);
  ASSERT_TRUE(tracer.Trace({ { 3.0, 0.0 }, { 4.1, 5.2 }, { 7.2, 10.0 } }, false, 0, 0, curves[0]));
  const Arrangement arr = Arrange(mesh, curves);
  const WindingResult w = Wind(mesh, arr, curves);
  auto leftOfLine = [](Vec3 p)
  {
    const Vec2 a = p.y <= 5.2 ? Vec2{ 3.0, 0.0 } : Vec2{ 4.1, 5.2 };
    const Vec2 b = p.y <= 5.2 ? Vec2{ 4.1, 5.2 } : Vec2{ 7.2, 10.0 };
    return Cross(b - a, Vec2{ p.x, p.y } - a) > 0;
  };
  double worst = 0;
  for (int r = 0; r < arr.GetNumberOfTriangles(); ++r)
  {
    const Triangle t = arr.GetTriangle(mesh, r);
    const Vec3 c = (1.0 / 3.0) *
      (arr.GetPosition(mesh, t[0]) + arr.GetPosition(mesh, t[1]) + arr.GetPosition(mesh, t[2]));
    for (int k = 0; k < 3; ++k)
    {
      worst = std::max(worst, std::abs(w.Corner(arr, mesh, 0, r, k) - (leftOfLine(c) ? 1 : 0)));
    }
  }
  EXPECT_LT(worst, 1e-8);
  EXPECT_LT(w.Curves[0].Residual, 1e-9);
}

TEST(SurfaceWinding, OpenCylinderBandEqualsTheLabels)
{
  // Two boundary loops; two tilted loops around the cylinder (each homologous to a boundary
  // loop, so bounding with the loops capped), one shape each.
  const TriangleMesh mesh = MeshOf(MakeOpenCylinder(1.0, 3.0, 40, 24));
  Vec3 lo, hi;
  BoundingBox(mesh.GetPositions(), lo, hi);
  const Vec3 extent = hi - lo;
  const int axis =
    extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  Vec3 along{ axis == 0 ? 1.0 : 0.0, axis == 1 ? 1.0 : 0.0, axis == 2 ? 1.0 : 0.0 };
  const Vec3 n0 = along + Vec3{ 0.11, 0.07, 0.09 }, n1 = along + Vec3{ -0.2, 0.13, -0.17 };
  std::vector<TracedCurve> curves = PlaneSectionCurves(mesh, n0, Dot(n0, lo + 0.4 * extent), 0);
  const std::vector<TracedCurve> side =
    PlaneSectionCurves(mesh, n1, Dot(n1, lo + 0.62 * extent), 1);
  curves.insert(curves.end(), side.begin(), side.end());
  ASSERT_EQ(curves.size(), 2u);
  for (const TracedCurve& c : curves)
  {
    ASSERT_TRUE(c.Closed);
  }
  const Arrangement arr = Arrange(mesh, curves);
  const WindingResult w = Wind(mesh, arr, curves);
  EXPECT_LT(LargestLabelError(mesh, curves, arr, w), 1e-8);
}

TEST(SurfaceWinding, SharedScansEqualTheLabels)
{
  if (SharedMeshFolder().empty())
  {
    GTEST_SKIP() << "BOOLSURF_SHARED_DATA (../shared/data) is not available";
  }
  for (const char* name : { "stanford-bunny.ply", "kitten.ply", "fertility.ply" })
  {
    MeshData d;
    ASSERT_TRUE(ReadSharedMesh(name, d));
    const TriangleMesh mesh = MeshOf(d);
    Vec3 lo, hi;
    BoundingBox(d.Positions, lo, hi);
    // Sections of three planes, one shape each, at the first offset whose loops are all closed
    // (a section that meets a hole is skipped): together they bound the part on one side.
    std::vector<TracedCurve> curves;
    const Vec3 normals[3] = { { 1.0, 0.03, 0.02 }, { 0.02, 1.0, 0.04 }, { 0.03, 0.01, 1.0 } };
    for (int s = 0; s < 3; ++s)
    {
      for (double f : { 0.5, 0.35, 0.65, 0.2, 0.8 })
      {
        const double offset = Dot(normals[s], lo + f * (hi - lo));
        const std::vector<TracedCurve> section =
          PlaneSectionCurves(mesh, normals[s], offset, s, 100 * s);
        if (!section.empty() &&
          std::all_of(
            section.begin(), section.end(), [](const TracedCurve& c) { return c.Closed; }))
        {
          for (TracedCurve c : section)
          {
            PositiveSideOnTheLeft(mesh, normals[s], c);
            curves.push_back(c);
          }
          break;
        }
      }
    }
    ASSERT_GE(curves.size(), 3u) << name;
    const Arrangement arr = Arrange(mesh, curves);
    const WindingResult w = Wind(mesh, arr, curves);
    // Plane sections bound (the half of the surface on one side), whatever the genus.
    EXPECT_LT(LargestLabelError(mesh, curves, arr, w), 1e-8) << name;
  }
}

TEST(SurfaceWinding, BadInputIsNamed)
{
  const TriangleMesh mesh = MeshOf(MakeFlatSquare(8, 1.0));
  SurfaceWinding winding;
  WindingResult w;
  std::string error;
  Arrangement empty;
  EXPECT_FALSE(winding.Compute(mesh, empty, {}, WindingOptions(), w, error));
  EXPECT_NE(error.find("no curves"), std::string::npos) << error;

  FlatPolygonTracer tracer(mesh);
  std::vector<TracedCurve> curves(1);
  ASSERT_TRUE(tracer.Trace({ { 0.2, 0.2 }, { 0.7, 0.3 }, { 0.4, 0.8 } }, true, 3, 5, curves[0]));
  Arrangement arr = Arrange(mesh, curves);
  WindingOptions options;
  options.Shapes = { 4 };
  EXPECT_FALSE(winding.Compute(mesh, arr, curves, options, w, error));
  EXPECT_NE(error.find("shape 4 has no curve"), std::string::npos) << error;

  std::vector<TracedCurve> onePoint = curves;
  onePoint[0].Points.resize(1);
  EXPECT_FALSE(winding.Compute(mesh, arr, onePoint, WindingOptions(), w, error));
  EXPECT_NE(error.find("curve 5 of shape 3 has 1 point"), std::string::npos) << error;

  std::vector<TracedCurve> notFinite = curves;
  notFinite[0].Points[1].Location = PointLocation::Face;
  notFinite[0].Points[1].Id = 0;
  notFinite[0].Points[1].U = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(winding.Compute(mesh, arr, notFinite, WindingOptions(), w, error));
  EXPECT_NE(error.find("point 1 of curve 5 of shape 3"), std::string::npos) << error;
}

} // namespace
} // namespace boolsurf

// The result as vector curves (vtkBoolSurf ports 2 and 3), against independent oracles:
// - flat meshes: the control points of each boundary loop are exactly the vertices of a
//   Clipper result polygon (intersection points included), for every operation;
// - tracing the boundary control curves again gives the boundary polyline, point for point on a
//   flat mesh, within 1e-6 of the diagonal on a shared scan;
// - open curves are clipped like Clipper clips open paths (same total length), each piece
//   starting and ending on the region's boundary or at the curve's own end;
// - Bezier pieces split by geodesic de Casteljau insertion are, on a flat mesh, exactly the
//   pieces of the planar Bezier curve; on a sphere their traces stay on the original trace.
#include "ClipperOracle.h"
#include "FilterTestUtils.h"
#include "vtkBoolSurf.h"
#include "vtkBoolSurfArrangement.h"
#include "vtkBoolSurfBSC.h"
#include "vtkBoolSurfBoolean.h"
#include "vtkBoolSurfLabeling.h"
#include "vtkBoolSurfTraceCurves.h"

#include <vtkCellArrayIterator.h>
#include <vtkDoubleArray.h>
#include <vtkLine.h>
#include <vtkMath.h>
#include <vtkPLYReader.h>
#include <vtkPointData.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <random>
#include <sstream>

namespace
{
using testutils::ControlPolygon;
using Point2 = std::array<double, 2>;

ControlPolygon RandomPolygon(std::mt19937& rng, int shape, bool closed = true)
{
  return testutils::RandomGridPolygon(rng, shape, closed);
}

/// Points of each cell of `pd`, grouped by the cell data `group`, without repeats (1e-9).
std::map<int, std::vector<Point2>> PointsByGroup(vtkPolyData* pd, const char* group)
{
  std::map<int, std::vector<Point2>> out;
  vtkDataArray* g = pd->GetCellData()->GetArray(group);
  auto it = vtk::TakeSmartPointer(pd->GetLines()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    std::vector<Point2>& points = out[static_cast<int>(g->GetComponent(it->GetCurrentCellId(), 0))];
    for (vtkIdType i = 0; i < n; ++i)
    {
      double x[3];
      pd->GetPoint(ids[i], x);
      bool known = false;
      for (const Point2& p : points)
      {
        known = known || (std::abs(p[0] - x[0]) <= 1e-9 && std::abs(p[1] - x[1]) <= 1e-9);
      }
      if (!known)
      {
        points.push_back({ x[0], x[1] });
      }
    }
  }
  return out;
}

/// Whether every point of `a` has one of `b` within `tolerance` and the other way round.
bool SameSets(const std::vector<Point2>& a, const std::vector<Point2>& b, double tolerance)
{
  auto covered = [tolerance](const std::vector<Point2>& from, const std::vector<Point2>& to)
  {
    for (const Point2& p : from)
    {
      bool found = false;
      for (const Point2& q : to)
      {
        found = found || (std::abs(p[0] - q[0]) <= tolerance && std::abs(p[1] - q[1]) <= tolerance);
      }
      if (!found)
      {
        return false;
      }
    }
    return true;
  };
  return covered(a, b) && covered(b, a);
}

/// Loops that share a vertex merged into one point set. Where a region touches itself at a
/// point, Clipper may give one polygon passing the point twice where we give two loops (or the
/// other way round): both describe the same boundary, so they are compared merged.
std::vector<std::vector<Point2>> MergeTouching(std::vector<std::vector<Point2>> sets)
{
  bool merged = true;
  while (merged)
  {
    merged = false;
    for (std::size_t i = 0; i < sets.size() && !merged; ++i)
    {
      for (std::size_t j = i + 1; j < sets.size() && !merged; ++j)
      {
        bool touch = false;
        for (const Point2& p : sets[i])
        {
          for (const Point2& q : sets[j])
          {
            touch = touch || (std::abs(p[0] - q[0]) <= 1e-9 && std::abs(p[1] - q[1]) <= 1e-9);
          }
        }
        if (touch)
        {
          for (const Point2& q : sets[j])
          {
            bool known = false;
            for (const Point2& p : sets[i])
            {
              known = known || (std::abs(p[0] - q[0]) <= 1e-9 && std::abs(p[1] - q[1]) <= 1e-9);
            }
            if (!known)
            {
              sets[i].push_back(q);
            }
          }
          sets.erase(sets.begin() + static_cast<long>(j));
          merged = true;
        }
      }
    }
  }
  return sets;
}

/// Calls visit(a, b) for every segment of the lines of `pd`.
template <class Visit>
void ForEachSegment(vtkPolyData* pd, Visit visit)
{
  auto it = vtk::TakeSmartPointer(pd->GetLines()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    for (vtkIdType i = 0; i + 1 < n; ++i)
    {
      double a[3], b[3];
      pd->GetPoint(ids[i], a);
      pd->GetPoint(ids[i + 1], b);
      visit(a, b);
    }
  }
}

double PolylineLength(vtkPolyData* pd)
{
  double length = 0;
  ForEachSegment(pd,
    [&](const double a[3], const double b[3])
    { length += std::sqrt(vtkMath::Distance2BetweenPoints(a, b)); });
  return length;
}

/// Distance from x to the nearest segment of the lines of `pd`.
double DistanceToLines(vtkPolyData* pd, const double x[3])
{
  double best = VTK_DOUBLE_MAX;
  ForEachSegment(pd,
    [&](const double a[3], const double b[3])
    {
      double t, closest[3];
      best = std::min(best, std::sqrt(vtkLine::DistanceToLine(x, a, b, t, closest)));
    });
  return best;
}

/// Largest distance from a point of `from` to the lines of `to`.
double OneSidedHausdorff(vtkPolyData* from, vtkPolyData* to)
{
  double worst = 0;
  for (vtkIdType p = 0; p < from->GetNumberOfPoints(); ++p)
  {
    double x[3];
    from->GetPoint(p, x);
    worst = std::max(worst, DistanceToLines(to, x));
  }
  return worst;
}

vtkSmartPointer<vtkPolyData> Retrace(vtkPolyData* surface, vtkPolyData* controls, int resolution)
{
  vtkNew<vtkBoolSurfTraceCurves> trace;
  trace->SetInputData(0, surface);
  trace->SetInputData(1, controls);
  trace->SetResolution(resolution);
  EXPECT_EQ(testutils::ErrorsOf(trace), "");
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(trace->GetOutput());
  return out;
}

/// Planar cubic Bezier spline point: segment s of `control` (3n+1 or closed 3n) at t.
Point2 Bezier(const std::vector<Point2>& c, bool closed, double parameter)
{
  const int n = static_cast<int>(c.size());
  const int segments = closed ? n / 3 : (n - 1) / 3;
  // Closed splines wrap (a parameter past the end is the next turn); open ones end at their
  // last anchor.
  int s = static_cast<int>(std::floor(parameter));
  if (!closed)
  {
    s = std::min(s, segments - 1);
  }
  const double t = parameter - s;
  s = ((s % segments) + segments) % segments;
  const Point2& p0 = c[3 * s];
  const Point2& p1 = c[3 * s + 1];
  const Point2& p2 = c[3 * s + 2];
  const Point2& p3 = c[(3 * s + 3) % n];
  const double u = 1 - t;
  Point2 x;
  for (int k = 0; k < 2; ++k)
  {
    x[k] = u * u * u * p0[k] + 3 * u * u * t * p1[k] + 3 * u * t * t * p2[k] + t * t * t * p3[k];
  }
  return x;
}

} // namespace

TEST(BoundaryControlCurves, LoopsAreClipperPolygonsOnAFlatMesh)
{
  vtkSmartPointer<vtkPolyData> mesh =
    testutils::ToPolyData(boolsurf::MakeFlatSquare(32, 1.0, 0.3, 17));
  std::mt19937 rng(77);
  const ClipperLib::ClipType clipperOps[] = {
    ClipperLib::ctUnion, ClipperLib::ctIntersection, ClipperLib::ctDifference, ClipperLib::ctXor
  };
  int loops = 0, intersections = 0;
  for (int trial = 0; trial < 10; ++trial)
  {
    const auto a = RandomPolygon(rng, 0), b = RandomPolygon(rng, 1);
    vtkNew<vtkBoolSurf> f;
    f->SetInputData(0, mesh);
    f->SetInputData(1, testutils::ToCurves({ a, b }));
    for (int op = 0; op < 4; ++op)
    {
      SCOPED_TRACE("trial " + std::to_string(trial) + " operation " + std::to_string(op));
      f->SetOperation(op);
      f->SetFillRule(0); // non-zero
      ASSERT_EQ(testutils::ErrorsOf(f), "");
      ClipperLib::Clipper clipper;
      clipper.AddPath(testutils::ToClipper(a), ClipperLib::ptSubject, true);
      clipper.AddPath(testutils::ToClipper(b), ClipperLib::ptClip, true);
      ClipperLib::Paths solution;
      ASSERT_TRUE(
        clipper.Execute(clipperOps[op], solution, ClipperLib::pftNonZero, ClipperLib::pftNonZero));
      std::vector<std::vector<Point2>> ours, theirs;
      for (auto& loop : PointsByGroup(f->GetBoundaryControlCurvesOutput(), "BoundaryLoop"))
      {
        ours.push_back(loop.second);
      }
      for (const ClipperLib::Path& path : solution)
      {
        std::vector<Point2> points;
        for (const ClipperLib::IntPoint& q : path)
        {
          points.push_back({ q.X / testutils::ClipperScale, q.Y / testutils::ClipperScale });
        }
        theirs.push_back(points);
      }
      ours = MergeTouching(ours);
      theirs = MergeTouching(theirs);
      EXPECT_EQ(ours.size(), theirs.size());
      // Every Clipper polygon is one of our loops, vertex for vertex.
      for (const std::vector<Point2>& expected : theirs)
      {
        bool matched = false;
        for (const auto& loop : ours)
        {
          matched = matched || SameSets(loop, expected, 1e-9);
        }
        EXPECT_TRUE(matched) << "a Clipper polygon of " << expected.size()
                             << " vertices has no loop with the same control points";
        ++loops;
        // Intersection points are vertices of neither input polygon.
        for (const Point2& p : expected)
        {
          bool input = false;
          for (const auto* polygon : { &a, &b })
          {
            for (const auto& v : polygon->Points)
            {
              input = input || (std::abs(v[0] - p[0]) < 1e-9 && std::abs(v[1] - p[1]) < 1e-9);
            }
          }
          intersections += input ? 0 : 1;
        }
      }
    }
  }
  EXPECT_GT(loops, 30);
  EXPECT_GT(intersections, 50) << "the loops hardly meet: the test would not see intersections";
}

TEST(BoundaryControlCurves, TracingThemAgainGivesTheBoundary)
{
  vtkSmartPointer<vtkPolyData> mesh =
    testutils::ToPolyData(boolsurf::MakeFlatSquare(24, 1.0, 0.3, 5));
  std::mt19937 rng(5);
  for (int trial = 0; trial < 6; ++trial)
  {
    vtkNew<vtkBoolSurf> f;
    f->SetInputData(0, mesh);
    f->SetInputData(1, testutils::ToCurves({ RandomPolygon(rng, 0), RandomPolygon(rng, 1) }));
    f->SetOperation(trial % 4);
    f->SetFillRule(0); // non-zero
    ASSERT_EQ(testutils::ErrorsOf(f), "");
    vtkPolyData* boundary = f->GetBoundaryOutput();
    auto again = Retrace(mesh, f->GetBoundaryControlCurvesOutput(), 4);
    // Point for point: the retraced pieces' points are the boundary's points (as sets).
    std::vector<Point2> a, b;
    for (vtkIdType p = 0; p < boundary->GetNumberOfPoints(); ++p)
    {
      a.push_back({ boundary->GetPoint(p)[0], boundary->GetPoint(p)[1] });
    }
    for (vtkIdType p = 0; p < again->GetNumberOfPoints(); ++p)
    {
      b.push_back({ again->GetPoint(p)[0], again->GetPoint(p)[1] });
    }
    EXPECT_TRUE(SameSets(a, b, 1e-9)) << "trial " << trial;
    EXPECT_NEAR(PolylineLength(again), PolylineLength(boundary), 1e-9);
  }
}

TEST(BoundaryControlCurves, OpenCurvesAreClippedLikeClipperClipsOpenPaths)
{
  vtkSmartPointer<vtkPolyData> mesh =
    testutils::ToPolyData(boolsurf::MakeFlatSquare(32, 1.0, 0.3, 3));
  std::mt19937 rng(31);
  int pieces = 0;
  for (int trial = 0; trial < 8; ++trial)
  {
    const auto a = RandomPolygon(rng, 0), b = RandomPolygon(rng, 1);
    const auto line = RandomPolygon(rng, 2, false);
    vtkNew<vtkBoolSurf> f;
    f->SetInputData(0, mesh);
    f->SetInputData(1, testutils::ToCurves({ a, b, line }));
    f->SetOperation(trial % 4);
    f->SetFillRule(0); // non-zero
    ASSERT_EQ(testutils::ErrorsOf(f), "");
    // Clipper: the region's polygons, then the open path clipped by them.
    ClipperLib::Clipper region;
    region.AddPath(testutils::ToClipper(a), ClipperLib::ptSubject, true);
    region.AddPath(testutils::ToClipper(b), ClipperLib::ptClip, true);
    const ClipperLib::ClipType ops[] = {
      ClipperLib::ctUnion, ClipperLib::ctIntersection, ClipperLib::ctDifference, ClipperLib::ctXor
    };
    ClipperLib::Paths solution;
    region.Execute(ops[trial % 4], solution, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    ClipperLib::Clipper clip;
    clip.AddPath(testutils::ToClipper(line), ClipperLib::ptSubject, false);
    clip.AddPaths(solution, ClipperLib::ptClip, true);
    ClipperLib::PolyTree tree;
    clip.Execute(ClipperLib::ctIntersection, tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    ClipperLib::Paths open;
    ClipperLib::OpenPathsFromPolyTree(tree, open);
    double expected = 0;
    for (const auto& path : open)
    {
      for (std::size_t i = 0; i + 1 < path.size(); ++i)
      {
        expected += std::hypot(static_cast<double>(path[i + 1].X - path[i].X),
                      static_cast<double>(path[i + 1].Y - path[i].Y)) /
          testutils::ClipperScale;
      }
    }
    vtkPolyData* clipped = f->GetClippedCurvesOutput();
    // On a flat mesh a polygon's legs are straight: its control polyline is the curve.
    EXPECT_NEAR(PolylineLength(clipped), expected, 1e-9) << "trial " << trial;
    EXPECT_EQ(clipped->GetNumberOfCells(), static_cast<vtkIdType>(open.size()))
      << "trial " << trial;
    // Every piece starts and ends on the region's boundary, or at an end of the line.
    vtkPolyData* boundary = f->GetBoundaryOutput();
    auto it = vtk::TakeSmartPointer(clipped->GetLines()->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      for (vtkIdType end : { ids[0], ids[n - 1] })
      {
        double x[3];
        clipped->GetPoint(end, x);
        const auto& first = line.Points.front();
        const auto& last = line.Points.back();
        const bool lineEnd = (std::abs(x[0] - first[0]) + std::abs(x[1] - first[1]) < 1e-12) ||
          (std::abs(x[0] - last[0]) + std::abs(x[1] - last[1]) < 1e-12);
        EXPECT_TRUE(lineEnd || DistanceToLines(boundary, x) < 1e-9)
          << "trial " << trial << ": a piece ends off the boundary";
      }
      ++pieces;
    }
  }
  EXPECT_GT(pieces, 4);
}

/// A closed cubic spline of two segments on the unit square, and its control polygon.
ControlPolygon TwoSegmentSpline(std::vector<Point2>& c)
{
  c = { { 0.2, 0.5 }, { 0.2, 0.9 }, { 0.8, 0.9 }, { 0.8, 0.5 }, { 0.8, 0.1 }, { 0.2, 0.1 } };
  ControlPolygon spline;
  spline.ShapeId = 0;
  spline.Type = 1;
  for (const Point2& p : c)
  {
    spline.Points.push_back({ p[0], p[1], 0.0 });
  }
  return spline;
}

/// Every Bezier piece of the boundary control curves of TwoSegmentSpline and `other` under
/// each operation, on a jittered flat square, against the planar spline between the piece's
/// parameters (on a flat mesh geodesic de Casteljau is the planar one, so they agree to
/// rounding). Returns the number of points compared and, in `pieces`, the number of Bezier
/// pieces seen.
int CheckPlanarBezierPieces(const ControlPolygon& other, int& pieces)
{
  vtkSmartPointer<vtkPolyData> mesh =
    testutils::ToPolyData(boolsurf::MakeFlatSquare(32, 1.0, 0.3, 8));
  std::vector<Point2> c;
  const ControlPolygon spline = TwoSegmentSpline(c);
  int checked = 0;
  pieces = 0;
  for (int op = 0; op < 4; ++op)
  {
    vtkNew<vtkBoolSurf> f;
    f->SetInputData(0, mesh);
    f->SetInputData(1, testutils::ToCurves({ spline, other }));
    f->SetOperation(op);
    EXPECT_EQ(testutils::ErrorsOf(f), "");
    vtkPolyData* out = f->GetBoundaryControlCurvesOutput();
    vtkDataArray* type = out->GetCellData()->GetArray("CurveType");
    vtkDataArray* range = out->GetCellData()->GetArray("ParameterRange");
    vtkDataArray* reversed = out->GetCellData()->GetArray("Reversed");
    if (!type || !range || !reversed)
    {
      ADD_FAILURE() << "operation " << op << ": no control curves";
      continue;
    }
    auto it = vtk::TakeSmartPointer(out->GetLines()->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      const vtkIdType cell = it->GetCurrentCellId();
      if (type->GetComponent(cell, 0) != 1)
      {
        continue;
      }
      ++pieces;
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      std::vector<Point2> piece;
      for (vtkIdType i = 0; i < n; ++i)
      {
        piece.push_back({ out->GetPoint(ids[i])[0], out->GetPoint(ids[i])[1] });
      }
      if (reversed->GetComponent(cell, 0) != 0)
      {
        std::reverse(piece.begin(), piece.end());
      }
      EXPECT_EQ(piece.size() % 3, 1u) << "an open spline piece has 3k + 1 control points";
      // Breakpoints of the piece's segments: T0, the integers between, T1.
      const double t0 = range->GetComponent(cell, 0), t1 = range->GetComponent(cell, 1);
      std::vector<double> breaks = { t0 };
      for (double k = std::floor(t0 + 1e-9) + 1; k < t1 - 1e-9; ++k)
      {
        breaks.push_back(k);
      }
      breaks.push_back(t1);
      if (breaks.size() - 1 != (piece.size() - 1) / 3)
      {
        ADD_FAILURE() << "piece [" << t0 << ", " << t1 << "] has " << piece.size()
                      << " control points";
        continue;
      }
      for (std::size_t s = 0; s + 1 < breaks.size(); ++s)
      {
        for (double u : { 0.0, 0.1, 0.37, 0.5, 0.81, 1.0 })
        {
          const Point2 x = Bezier(piece, false, s + u);
          const Point2 y = Bezier(c, true, breaks[s] + u * (breaks[s + 1] - breaks[s]));
          EXPECT_NEAR(x[0], y[0], 1e-9) << "piece [" << t0 << ", " << t1 << "] at " << u;
          EXPECT_NEAR(x[1], y[1], 1e-9) << "piece [" << t0 << ", " << t1 << "] at " << u;
          ++checked;
        }
      }
    }
  }
  return checked;
}

TEST(BoundaryControlCurves, BezierPiecesArePiecesOfThePlanarCurve)
{
  // A closed cubic spline (two segments) crossed by a square; each piece's control points give
  // exactly the original curve between the piece's parameters.
  ControlPolygon square;
  square.ShapeId = 1;
  square.Points = { { 0.45, 0.3, 0 }, { 0.95, 0.3, 0 }, { 0.95, 0.95, 0 }, { 0.45, 0.95, 0 } };
  int pieces = 0;
  EXPECT_GT(CheckPlanarBezierPieces(square, pieces), 20);
}

TEST(BoundaryControlCurves, BezierSegmentCutManyTimes)
{
  // A comb whose 30 teeth cross the spline's upper segment 60 times: that segment is cut into
  // 61 pieces (split by halving, BezierPieces::SplitAtCuts), each of which must still be
  // exactly the original curve between its parameters.
  ControlPolygon comb;
  comb.ShapeId = 1;
  const int teeth = 30;
  const double left = 0.26, pitch = 0.016, width = 0.008;
  comb.Points.push_back({ left, 0.97, 0 });
  for (int k = 0; k < teeth; ++k)
  {
    const double x = left + k * pitch;
    comb.Points.push_back({ x, 0.6, 0 });
    comb.Points.push_back({ x + width, 0.6, 0 });
    comb.Points.push_back({ x + width, k + 1 < teeth ? 0.93 : 0.97, 0 });
    if (k + 1 < teeth)
    {
      comb.Points.push_back({ x + pitch, 0.93, 0 });
    }
  }
  int pieces = 0;
  const int checked = CheckPlanarBezierPieces(comb, pieces);
  // Each operation's boundary holds the teeth's pieces of the upper segment (about half of the
  // 61 pieces, alternately inside and outside a tooth).
  EXPECT_GT(pieces, 4 * 25);
  EXPECT_GT(checked, 6 * pieces - 1);
}

TEST(BoundaryControlCurves, BezierPiecesStayOnTheCurveOnASphere)
{
  // On a curved surface geodesic de Casteljau at another parameter is another curve, close to
  // the original: the retraced pieces stay within the tracing tolerance of its trace.
  auto sphere = testutils::ToPolyData(boolsurf::MakeIcosphere(4));
  auto at = [](double theta, double phi) -> std::array<double, 3> {
    return { std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta) };
  };
  ControlPolygon spline, polygon;
  spline.Type = 1;
  spline.ShapeId = 0;
  for (int k = 0; k < 6; ++k)
  {
    spline.Points.push_back(at(0.6 + 0.25 * (k % 2), 2 * 3.14159265358979 * k / 6));
  }
  polygon.ShapeId = 1;
  for (int k = 0; k < 4; ++k)
  {
    polygon.Points.push_back(at(0.45 + 0.45 * (k == 1 || k == 2), 0.3 + 0.9 * (k >= 2)));
  }
  vtkNew<vtkBoolSurf> f;
  f->SetInputData(0, sphere);
  f->SetInputData(1, testutils::ToCurves({ spline, polygon }));
  f->SetOperation(0);
  ASSERT_EQ(testutils::ErrorsOf(f), "");
  vtkPolyData* pieces = f->GetBoundaryControlCurvesOutput();
  vtkDataArray* type = pieces->GetCellData()->GetArray("CurveType");
  int bezierPieces = 0;
  for (vtkIdType c = 0; c < pieces->GetNumberOfCells(); ++c)
  {
    // Pieces, not the whole spline: the polygon crosses it.
    bezierPieces += type->GetComponent(c, 0) == 1 &&
        pieces->GetCellData()->GetArray("Closed")->GetComponent(c, 0) == 0
      ? 1
      : 0;
  }
  ASSERT_GE(bezierPieces, 1);
  auto original = Retrace(sphere, testutils::ToCurves({ spline }), 4);
  auto retraced = Retrace(sphere, pieces, 4);
  // Only the Bezier pieces: the polygon's legs are checked by the other tests.
  double worst = 0;
  vtkDataArray* tracedType = retraced->GetCellData()->GetArray("CurveType");
  auto it = vtk::TakeSmartPointer(retraced->GetLines()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    if (tracedType->GetComponent(it->GetCurrentCellId(), 0) != 1)
    {
      continue;
    }
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    for (vtkIdType i = 0; i < n; ++i)
    {
      worst = std::max(worst, DistanceToLines(original, retraced->GetPoint(ids[i])));
    }
  }
  // The tracing tolerance: 5% of the mean edge (0.055); measured 1.5e-3 (Resolution 4).
  EXPECT_LT(worst, 3e-3) << "retraced Bezier pieces leave the original trace by " << worst;
  std::ostringstream text;
  text << std::scientific << worst;
  RecordProperty("BezierPieceDistance", text.str());
}

TEST(BoundaryControlCurves, RetracedOnASharedScan)
{
  const char* data = std::getenv("BOOLSURF_SHARED_DATA");
  const std::filesystem::path file =
    data ? std::filesystem::path(data) / "meshes" / "spot.ply" : std::filesystem::path();
  if (!data || !std::filesystem::exists(file))
  {
    GTEST_SKIP() << "BOOLSURF_SHARED_DATA is not set or has no meshes/spot.ply: the shared-scan "
                    "check needs ../shared/data";
  }
  vtkNew<vtkPLYReader> reader;
  reader->SetFileName(file.string().c_str());
  reader->Update();
  vtkPolyData* spot = reader->GetOutput();
  double b[6];
  spot->GetBounds(b);
  const double diagonal = std::sqrt(
    (b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) + (b[5] - b[4]) * (b[5] - b[4]));
  // Two overlapping pentagons: vertices at a fixed rank of distance from a seed vertex, in
  // angular order around the seed (in the plane across the direction from the centre).
  double centre[3];
  spot->GetCenter(centre);
  auto ringAround = [&](vtkIdType seed, std::size_t rank, int shape)
  {
    double s[3];
    spot->GetPoint(seed, s);
    double n[3] = { s[0] - centre[0], s[1] - centre[1], s[2] - centre[2] };
    vtkMath::Normalize(n);
    double u[3], w[3];
    vtkMath::Perpendiculars(n, u, w, 0);
    std::vector<std::pair<double, vtkIdType>> near;
    for (vtkIdType v = 0; v < spot->GetNumberOfPoints(); ++v)
    {
      double x[3];
      spot->GetPoint(v, x);
      near.push_back({ vtkMath::Distance2BetweenPoints(x, s), v });
    }
    std::sort(near.begin(), near.end());
    std::vector<std::pair<double, vtkIdType>> ring; // (angle, vertex) of the rank-th band
    for (std::size_t k = rank; k < rank + 40 && k < near.size(); ++k)
    {
      double x[3];
      spot->GetPoint(near[k].second, x);
      const double d[3] = { x[0] - s[0], x[1] - s[1], x[2] - s[2] };
      ring.push_back({ std::atan2(vtkMath::Dot(d, w), vtkMath::Dot(d, u)), near[k].second });
    }
    std::sort(ring.begin(), ring.end());
    ControlPolygon p;
    p.ShapeId = shape;
    for (int k = 0; k < 5; ++k)
    {
      double x[3];
      spot->GetPoint(ring[k * ring.size() / 5].second, x);
      p.Points.push_back({ x[0], x[1], x[2] });
    }
    return std::make_pair(p, near);
  };
  const vtkIdType seed = spot->GetNumberOfPoints() / 3;
  auto [a, near] = ringAround(seed, 120, 0);
  ControlPolygon c = ringAround(near[60].second, 120, 1).first;
  vtkNew<vtkBoolSurf> f;
  f->SetInputData(0, spot);
  f->SetInputData(1, testutils::ToCurves({ a, c }));
  f->SetOperation(0);
  f->SetFillRule(0); // non-zero
  const std::string errors = testutils::ErrorsOf(f);
  ASSERT_EQ(errors, "");
  vtkPolyData* boundary = f->GetBoundaryOutput();
  ASSERT_GT(boundary->GetNumberOfPoints(), 0);
  auto again = Retrace(spot, f->GetBoundaryControlCurvesOutput(), 4);
  const double d = std::max(OneSidedHausdorff(again, boundary), OneSidedHausdorff(boundary, again));
  EXPECT_LE(d, 1e-6 * diagonal) << "Hausdorff distance " << d << " of diagonal " << diagonal;
  std::ostringstream ratio;
  ratio << std::scientific << d / diagonal;
  RecordProperty("HausdorffOverDiagonal", ratio.str());
}

namespace
{
/// Cells of `a` and `b` hold the same points in the same order (to 1e-12), cell by cell.
void ExpectSameCurves(vtkPolyData* a, vtkPolyData* b)
{
  ASSERT_EQ(a->GetNumberOfCells(), b->GetNumberOfCells());
  auto ia = vtk::TakeSmartPointer(a->GetLines()->NewIterator());
  auto ib = vtk::TakeSmartPointer(b->GetLines()->NewIterator());
  for (ia->GoToFirstCell(), ib->GoToFirstCell(); !ia->IsDoneWithTraversal();
       ia->GoToNextCell(), ib->GoToNextCell())
  {
    vtkIdType na, nb;
    const vtkIdType *pa, *pb;
    ia->GetCurrentCell(na, pa);
    ib->GetCurrentCell(nb, pb);
    ASSERT_EQ(na, nb);
    for (vtkIdType i = 0; i < na; ++i)
    {
      EXPECT_LT(vtkMath::Distance2BetweenPoints(a->GetPoint(pa[i]), b->GetPoint(pb[i])), 1e-24);
    }
  }
}
} // namespace

TEST(BoundaryControlCurves, StageFiltersGiveTheOneStepAnswer)
{
  // Trace -> Arrangement -> Label -> Surface Boolean (and Boundary Sampled Curves) give the
  // control-point outputs of the one-step filter, piece for piece.
  vtkSmartPointer<vtkPolyData> mesh =
    testutils::ToPolyData(boolsurf::MakeFlatSquare(24, 1.0, 0.3, 9));
  std::mt19937 rng(12);
  for (int trial = 0; trial < 4; ++trial)
  {
    SCOPED_TRACE("trial " + std::to_string(trial));
    auto curves = testutils::ToCurves(
      { RandomPolygon(rng, 0), RandomPolygon(rng, 1), RandomPolygon(rng, 2, false) });
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
    boolean->SetOperation(trial);
    boolean->SetShapeA(0);
    boolean->SetShapeB(1);
    vtkNew<vtkBoolSurf> oneStep;
    oneStep->SetInputData(0, mesh);
    oneStep->SetInputData(1, curves);
    oneStep->SetOperation(trial);
    ASSERT_EQ(testutils::ErrorsOf(boolean), "");
    ASSERT_EQ(testutils::ErrorsOf(oneStep), "");
    ASSERT_GT(oneStep->GetBoundaryControlCurvesOutput()->GetNumberOfCells(), 0);
    ExpectSameCurves(
      boolean->GetBoundaryControlCurvesOutput(), oneStep->GetBoundaryControlCurvesOutput());
    ExpectSameCurves(boolean->GetClippedCurvesOutput(), oneStep->GetClippedCurvesOutput());
  }

  // BSC: one sample inside the bottom edge of a square, pointing into it, selects the square.
  testutils::ControlPolygon square, other;
  square.ShapeId = 0;
  square.Points = { { 0.2, 0.2, 0 }, { 0.6, 0.2, 0 }, { 0.6, 0.6, 0 }, { 0.2, 0.6, 0 } };
  other.ShapeId = 1;
  other.Points = { { 0.4, 0.4, 0 }, { 0.8, 0.4, 0 }, { 0.8, 0.8, 0 }, { 0.4, 0.8, 0 } };
  auto curves = testutils::ToCurves({ square, other });
  vtkNew<vtkPolyData> samples;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0.3, 0.2, 0);
  vtkNew<vtkDoubleArray> direction;
  direction->SetName("Direction");
  direction->SetNumberOfComponents(3);
  direction->InsertNextTuple3(0, 1, 0);
  samples->SetPoints(points);
  samples->GetPointData()->AddArray(direction);
  vtkNew<vtkBoolSurfTraceCurves> trace;
  trace->SetInputData(0, mesh);
  trace->SetInputData(1, curves);
  vtkNew<vtkBoolSurfArrangement> arrangement;
  arrangement->SetInputData(0, mesh);
  arrangement->SetInputConnection(1, trace->GetOutputPort());
  vtkNew<vtkBoolSurfBSC> bsc;
  bsc->SetInputConnection(0, arrangement->GetOutputPort(0));
  bsc->SetInputData(1, samples);
  vtkNew<vtkBoolSurf> oneStep;
  oneStep->SetInputData(0, mesh);
  oneStep->SetInputData(1, curves);
  oneStep->SetInputData(2, samples);
  oneStep->SetSelectionToBSC();
  ASSERT_EQ(testutils::ErrorsOf(bsc), "");
  ASSERT_EQ(testutils::ErrorsOf(oneStep), "");
  ASSERT_GT(bsc->GetBoundaryControlCurvesOutput()->GetNumberOfCells(), 0);
  ExpectSameCurves(
    bsc->GetBoundaryControlCurvesOutput(), oneStep->GetBoundaryControlCurvesOutput());
}

TEST(BoundaryControlCurves, ReversedWholeSplineLoopStartsAtAnAnchor)
{
  // A clockwise closed spline that meets no other curve bounds its region on its right: port 2
  // gives it whole and reversed. Its points must still read anchor, handle, handle, anchor,
  // ... from the spline's first anchor, so that tracing them again gives the region's
  // boundary (starting at a handle, they were another curve, 0.028 away).
  vtkSmartPointer<vtkPolyData> mesh = testutils::ToPolyData(boolsurf::MakeFlatSquare(20));
  ControlPolygon spline;
  spline.ShapeId = 0;
  spline.Type = 1;
  const double r = 0.2, k = 0.5523 * r; // four cubic segments close to a circle
  const Point2 o = { 0.35, 0.4 };
  // Clockwise: anchors at 0, -90, -180, -270 degrees, each followed by its two handles.
  const std::vector<Point2> c = { { o[0] + r, o[1] },
    { o[0] + r, o[1] - k },
    { o[0] + k, o[1] - r },
    { o[0], o[1] - r },
    { o[0] - k, o[1] - r },
    { o[0] - r, o[1] - k },
    { o[0] - r, o[1] },
    { o[0] - r, o[1] + k },
    { o[0] - k, o[1] + r },
    { o[0], o[1] + r },
    { o[0] + k, o[1] + r },
    { o[0] + r, o[1] + k } };
  for (const Point2& p : c)
  {
    spline.Points.push_back({ p[0], p[1], 0.0 });
  }
  ControlPolygon triangle;
  triangle.ShapeId = 1;
  triangle.Points = { { 0.65, 0.6, 0 }, { 0.9, 0.6, 0 }, { 0.8, 0.85, 0 } };
  for (int fillRule : { 0, 1 })
  {
    SCOPED_TRACE("fill rule " + std::to_string(fillRule));
    vtkNew<vtkBoolSurf> f;
    f->SetInputData(0, mesh);
    f->SetInputData(1, testutils::ToCurves({ spline, triangle }));
    f->SetOperation(0); // union
    f->SetFillRule(fillRule);
    ASSERT_EQ(testutils::ErrorsOf(f), "");
    vtkPolyData* out = f->GetBoundaryControlCurvesOutput();
    vtkDataArray* type = out->GetCellData()->GetArray("CurveType");
    vtkDataArray* reversed = out->GetCellData()->GetArray("Reversed");
    vtkDataArray* closed = out->GetCellData()->GetArray("Closed");
    ASSERT_TRUE(type && reversed && closed);
    int splines = 0;
    auto it = vtk::TakeSmartPointer(out->GetLines()->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      const vtkIdType cell = it->GetCurrentCellId();
      if (type->GetComponent(cell, 0) != 1)
      {
        continue;
      }
      ++splines;
      EXPECT_EQ(reversed->GetComponent(cell, 0), 1);
      EXPECT_EQ(closed->GetComponent(cell, 0), 1);
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      // Whole closed loop: 12 control points and the closing repeat, walked the other way
      // from the first anchor: A0, h11, h10, A3, h8, h7, A2, ..., h1, A0.
      ASSERT_EQ(n, 13);
      for (vtkIdType i = 0; i < n; ++i)
      {
        const Point2& expected = c[static_cast<std::size_t>((12 - i) % 12)];
        EXPECT_NEAR(out->GetPoint(ids[i])[0], expected[0], 1e-12) << "point " << i;
        EXPECT_NEAR(out->GetPoint(ids[i])[1], expected[1], 1e-12) << "point " << i;
      }
    }
    EXPECT_EQ(splines, 1);
    // Tracing port 2 again gives the region's boundary, point for point.
    vtkPolyData* boundary = f->GetBoundaryOutput();
    auto again = Retrace(mesh, out, 4);
    std::vector<Point2> a, b;
    for (vtkIdType p = 0; p < boundary->GetNumberOfPoints(); ++p)
    {
      a.push_back({ boundary->GetPoint(p)[0], boundary->GetPoint(p)[1] });
    }
    for (vtkIdType p = 0; p < again->GetNumberOfPoints(); ++p)
    {
      b.push_back({ again->GetPoint(p)[0], again->GetPoint(p)[1] });
    }
    EXPECT_TRUE(SameSets(a, b, 1e-9));
    EXPECT_NEAR(PolylineLength(again), PolylineLength(boundary), 1e-9);
  }
}

TEST(BoundaryControlCurves, SameOnOneAndSeveralThreads)
{
  // The Bezier cuts of the control-point outputs run segment by segment on every thread (and
  // the curves are traced so): the outputs must not depend on the number of threads.
  auto sphere = testutils::ToPolyData(boolsurf::MakeIcosphere(4));
  auto at = [](double theta, double phi) -> std::array<double, 3> {
    return { std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta) };
  };
  std::vector<ControlPolygon> drawing;
  for (int s = 0; s < 3; ++s)
  {
    ControlPolygon spline;
    spline.Type = 1;
    spline.ShapeId = s;
    for (int k = 0; k < 6; ++k)
    {
      spline.Points.push_back(at(0.6 + 0.25 * (k % 2) + 0.1 * s, 2 * 3.14159265358979 * k / 6 + s));
    }
    drawing.push_back(spline);
  }
  auto curves = testutils::ToCurves(drawing);
  vtkSmartPointer<vtkPolyData> outputs[2][2];
  for (int run = 0; run < 2; ++run)
  {
    vtkNew<vtkBoolSurf> f;
    f->SetInputData(0, sphere);
    f->SetInputData(1, curves);
    f->SetOperationToExpression();
    f->SetExpression("S0 | S1 | S2");
    f->SetNumberOfThreads(run == 0 ? 1 : 2);
    ASSERT_EQ(testutils::ErrorsOf(f), "");
    for (int port = 0; port < 2; ++port)
    {
      outputs[run][port] = vtkSmartPointer<vtkPolyData>::New();
      outputs[run][port]->DeepCopy(
        port == 0 ? f->GetBoundaryControlCurvesOutput() : f->GetOutput());
    }
  }
  for (int port = 0; port < 2; ++port)
  {
    vtkPolyData* a = outputs[0][port];
    vtkPolyData* b = outputs[1][port];
    ASSERT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints()) << "port " << port;
    ASSERT_EQ(a->GetNumberOfCells(), b->GetNumberOfCells()) << "port " << port;
    ASSERT_GT(a->GetNumberOfPoints(), 20);
    for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
    {
      double x[3], y[3];
      a->GetPoint(i, x);
      b->GetPoint(i, y);
      ASSERT_EQ(x[0], y[0]) << "port " << port << " point " << i;
      ASSERT_EQ(x[1], y[1]);
      ASSERT_EQ(x[2], y[2]);
    }
  }
}

// The result as vector curves on pieces (Core/Distributed/PieceVectorOutput.h), from records
// as the pieces send them: boundary loops whose segments name their curve and stations give the
// one-rank sub-curves (a change of curve starts a sub-curve, a closed curve all around is whole,
// a reversed walk lists its points backwards), clipped segments given twice and out of order
// give each piece once, the messages read back what was packed, and a cubic Bezier is refused
// by name.
#include "Distributed/PieceVectorOutput.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace boolsurf;

namespace
{

/// A geodesic polygon with `n` control points on triangles 10, 11, ..., traced through its
/// control points only (parameter k at traced point k).
CurveSource Polygon(int n, bool closed, int curveId)
{
  CurveSource s;
  s.Type = CurveType::GeodesicPolygon;
  s.Closed = closed;
  s.CurveId = curveId;
  s.ShapeId = curveId;
  for (int k = 0; k < n; ++k)
  {
    s.Points.push_back({ 10 + k, 0.25, 0.25 });
    s.Parameter.push_back(k);
  }
  return s;
}

/// The positions of every control point: (curve, point, 0).
ControlPointPositions Positions(const std::vector<CurveSource>& sources)
{
  ControlPointPositions positions(sources.size());
  for (std::size_t c = 0; c < sources.size(); ++c)
  {
    for (std::size_t k = 0; k < sources[c].Points.size(); ++k)
    {
      positions[c].push_back({ static_cast<double>(c), static_cast<double>(k), 0.0 });
    }
  }
  return positions;
}

/// A boundary point between control points (on triangle 100 + id), leaving along `curve`.
BoundaryPointRecord Point(int id, int curve, bool reversed, double from, double to)
{
  BoundaryPointRecord p;
  p.Key = { 2, id, 0, 0 };
  p.Surface = { 100 + id, 0.5, 0.25 };
  p.SurfacePosition = { 9.0, static_cast<double>(id), 9.0 };
  p.Next = { curve, reversed, from, to };
  return p;
}

} // namespace

TEST(PieceVectorOutput, ClosedCurveAllAroundIsWhole)
{
  const std::vector<CurveSource> sources = { Polygon(4, true, 7) };
  BoundaryRun loop;
  loop.Closed = true;
  // Started at its lowest point, as the chaining starts loops; the last segment passes the
  // curve's start (station 4 is station 0 of the next turn).
  loop.Points = { Point(1, 0, false, 1.5, 2.5),
    Point(2, 0, false, 2.5, 3.5),
    Point(3, 0, false, 3.5, 4.0),
    Point(4, 0, false, 0.0, 0.5),
    Point(0, 0, false, 0.5, 1.5) };
  std::vector<ControlSubCurve> out;
  std::string error;
  ASSERT_TRUE(PieceBoundaryControlCurves({ loop }, sources, Positions(sources), out, error))
    << error;
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(out[0].Whole);
  EXPECT_EQ(out[0].T0, 0.0);
  EXPECT_EQ(out[0].T1, 4.0);
  ASSERT_EQ(out[0].Points.size(), 4u);
  for (int k = 0; k < 4; ++k)
  {
    EXPECT_EQ(out[0].Points[k].Triangle, 10 + k);
    EXPECT_EQ(out[0].Positions[k].y, k);
  }
  EXPECT_EQ(out[0].SourceCurveId, 7);
}

TEST(PieceVectorOutput, WholeCurveWalkedBackwardsStartsAtItsSecondPatchEnd)
{
  const std::vector<CurveSource> sources = { Polygon(4, true, 0) };
  BoundaryRun loop;
  loop.Closed = true;
  // Walked against the curve; other curves meet it at stations 1.5 and 3.5 (patch ends). One
  // rank's loop starts with the patch from 1.5 to 3.5, walked from 3.5 down.
  loop.Points = { Point(0, 0, true, 3.5, 2.5),
    Point(1, 0, true, 2.5, 1.5),
    Point(2, 0, true, 1.5, 0.5),
    Point(3, 0, true, 0.5, 0.0),
    Point(4, 0, true, 4.0, 3.5) };
  loop.Points[0].PatchEnd = loop.Points[2].PatchEnd = true;
  std::vector<ControlSubCurve> out;
  std::string error;
  ASSERT_TRUE(PieceBoundaryControlCurves({ loop }, sources, Positions(sources), out, error))
    << error;
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(out[0].Whole);
  EXPECT_TRUE(out[0].Reversed);
  EXPECT_EQ(out[0].T0, -0.5);
  EXPECT_EQ(out[0].T1, 3.5);
  const std::vector<int> triangles = { 100, 13, 12, 11, 10 };
  ASSERT_EQ(out[0].Points.size(), triangles.size());
  for (std::size_t k = 0; k < triangles.size(); ++k)
  {
    EXPECT_EQ(out[0].Points[k].Triangle, triangles[k]);
  }
}

TEST(PieceVectorOutput, SubCurvesStartWhereTheLoopChangesCurve)
{
  const std::vector<CurveSource> sources = { Polygon(4, true, 0), Polygon(4, true, 1) };
  BoundaryRun loop;
  loop.Closed = true;
  // Curve 0 forward from station 0.5 to 2.5 (through controls 1 and 2), then curve 1 walked
  // backwards from station 3.5 to 1.5 (through controls 3 and 2), back to the start; the loop
  // starts inside curve 0's stretch.
  loop.Points = { Point(1, 0, false, 1.5, 2.5),
    Point(2, 1, true, 3.5, 2.0),
    Point(3, 1, true, 2.0, 1.5),
    Point(0, 0, false, 0.5, 1.5) };
  std::vector<ControlSubCurve> out;
  std::string error;
  ASSERT_TRUE(PieceBoundaryControlCurves({ loop }, sources, Positions(sources), out, error))
    << error;
  ASSERT_EQ(out.size(), 2u);
  // Curve 1 first (the first change of curve), walked from station 3.5 down to 1.5.
  EXPECT_EQ(out[0].Curve, 1);
  EXPECT_TRUE(out[0].Reversed);
  EXPECT_EQ(out[0].T0, 1.5);
  EXPECT_EQ(out[0].T1, 3.5);
  ASSERT_EQ(out[0].Points.size(), 4u);
  EXPECT_EQ(out[0].Points[0].Triangle, 102); // the point at station 3.5
  EXPECT_EQ(out[0].Points[1].Triangle, 13);
  EXPECT_EQ(out[0].Points[2].Triangle, 12);
  EXPECT_EQ(out[0].Points[3].Triangle, 100); // the point at station 1.5
  EXPECT_EQ(out[0].Positions[0].y, 2.0);
  EXPECT_EQ(out[0].Positions[1].y, 3.0);
  // Then curve 0 forward, 0.5 to 2.5.
  EXPECT_EQ(out[1].Curve, 0);
  EXPECT_FALSE(out[1].Reversed);
  EXPECT_EQ(out[1].T0, 0.5);
  EXPECT_EQ(out[1].T1, 2.5);
  ASSERT_EQ(out[1].Points.size(), 4u);
  EXPECT_EQ(out[1].Points[0].Triangle, 100);
  EXPECT_EQ(out[1].Points[1].Triangle, 11);
  EXPECT_EQ(out[1].Points[2].Triangle, 12);
  EXPECT_EQ(out[1].Points[3].Triangle, 102);
  for (const ControlSubCurve& sub : out)
  {
    EXPECT_EQ(sub.Group, 0);
    EXPECT_FALSE(sub.Whole);
  }
}

TEST(PieceVectorOutput, ClippedSegmentsJoinOncePerPiece)
{
  const std::vector<CurveSource> sources = { Polygon(4, false, 3) };
  const auto segment = [](int a, int b, double from, double to)
  {
    ClippedSegment s;
    s.Curve = 0;
    s.From = from;
    s.To = to;
    s.A = Point(a, -1, false, 0, 0);
    s.B = Point(b, -1, false, 0, 0);
    return s;
  };
  // Two pieces: 0.5 to 2.5 (its middle segment given by two ranks), and 2.8 to the end.
  std::vector<ClippedSegment> segments = { segment(6, 7, 2.8, 3.0),
    segment(2, 3, 1.0, 2.0),
    segment(1, 2, 0.5, 1.0),
    segment(3, 4, 2.0, 2.5),
    segment(2, 3, 1.0, 2.0) };
  segments[4].B.Key = segments[1].B.Key; // the same ends, as the other rank names them
  std::vector<ControlSubCurve> out;
  std::string error;
  ASSERT_TRUE(PieceClippedControlCurves(segments, sources, Positions(sources), out, error))
    << error;
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].Group, 0);
  EXPECT_EQ(out[0].T0, 0.5);
  EXPECT_EQ(out[0].T1, 2.5);
  ASSERT_EQ(out[0].Points.size(), 4u);
  EXPECT_EQ(out[0].Points[0].Triangle, 101);
  EXPECT_EQ(out[0].Points[1].Triangle, 11);
  EXPECT_EQ(out[0].Points[2].Triangle, 12);
  EXPECT_EQ(out[0].Points[3].Triangle, 104);
  EXPECT_EQ(out[1].Group, 1);
  ASSERT_EQ(out[1].Points.size(), 2u);
  EXPECT_EQ(out[1].Points[0].Triangle, 106);
  EXPECT_EQ(out[1].Points[1].Triangle, 13); // the curve's last control point, its own
  EXPECT_EQ(out[1].Positions[1].y, 3.0);
}

TEST(PieceVectorOutput, BezierIsRefusedByName)
{
  std::vector<CurveSource> sources = { Polygon(4, true, 0) };
  sources[0].Type = CurveType::CubicBezier;
  BoundaryRun loop;
  loop.Closed = true;
  loop.Points = { Point(0, 0, false, 0.0, 1.0), Point(1, 0, false, 1.0, 4.0) };
  std::vector<ControlSubCurve> out;
  std::string error;
  EXPECT_FALSE(PieceBoundaryControlCurves({ loop }, sources, Positions(sources), out, error));
  EXPECT_NE(error.find("curve 0 is a cubic Bezier"), std::string::npos) << error;
}

TEST(PieceVectorOutput, MessagesReadBackWhatWasPacked)
{
  std::vector<ClippedSegment> segments(1);
  segments[0].Curve = 2;
  segments[0].From = 0.25;
  segments[0].To = 0.75;
  segments[0].A = Point(1, 2, true, 0.5, 0.125);
  segments[0].B = Point(2, -1, false, 0, 0);
  std::vector<long long> words;
  PackClippedSegments(segments, words);
  std::size_t at = 0;
  std::vector<ClippedSegment> back;
  std::string error;
  ASSERT_TRUE(UnpackClippedSegments(words, at, back, error)) << error;
  EXPECT_EQ(at, words.size());
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(back[0].Curve, 2);
  EXPECT_EQ(back[0].To, 0.75);
  EXPECT_EQ(back[0].A.Key, segments[0].A.Key);
  EXPECT_EQ(back[0].A.Next.Curve, 2);
  EXPECT_TRUE(back[0].A.Next.Reversed);
  EXPECT_EQ(back[0].A.Next.To, 0.125);
  EXPECT_EQ(back[0].A.SurfacePosition.y, 1.0);
  // A short message is an error, not a read past its end.
  words.pop_back();
  at = 0;
  back.clear();
  EXPECT_FALSE(UnpackClippedSegments(words, at, back, error));
  std::vector<long long> positions = { 1, 0, 5, 0, 0, 0 };
  ControlPointPositions known(1, std::vector<Vec3>(2));
  at = 0;
  EXPECT_FALSE(UnpackControlPositions(positions, at, known, error)); // point 5 of 2
}

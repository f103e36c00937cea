// Boundary-Sampled Curves: the min cut and the search for sample-connectedness on hand-made
// cell graphs (exact cell sets), then on real arrangements: two overlapping squares on a flat
// mesh (exact areas) and torus meridians (inconsistent curves; areas by symmetry).
#include "../Arrangement/ArrangementTestUtils.h"
#include "Selection/BoundarySamples.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace boolsurf;
using namespace boolsurf::testing;

namespace
{

// Paper Fig. 6 as a cell graph: a red curve (counter-clockwise) and a green one (clockwise)
// overlapping. Cells: 0 outside, 1 red only, 2 green only, 3 both. Both curves meet at points
// 10 and 11; arcs: red outside green (length 3), red inside green (1), green outside red (3),
// green inside red (1). A clockwise curve has its inside on the right.
enum Cells
{
  Outside = 0,
  RedOnly = 1,
  GreenOnly = 2,
  Both = 3
};
enum Patches
{
  RedOuter = 0,
  RedInner = 1,
  GreenOuter = 2,
  GreenInner = 3
};

BscInput FigureSix()
{
  BscInput in;
  in.NumberOfCells = 4;
  in.Patches = {
    { RedOnly, Outside, 0, 10, 11, 3.0 },   // left = inside red
    { Both, GreenOnly, 0, 11, 10, 1.0 },    //
    { Outside, GreenOnly, 1, 10, 11, 3.0 }, // right = inside green
    { RedOnly, Both, 1, 11, 10, 1.0 },      //
  };
  return in;
}

std::vector<char> Cells(std::initializer_list<int> selected)
{
  std::vector<char> s(4, 0);
  for (int c : selected)
    s[c] = 1;
  return s;
}

BscResult SelectOrDie(const BscInput& in)
{
  BscResult r;
  std::string error;
  EXPECT_TRUE(SelectBoundarySampledCells(in, r, error)) << error;
  return r;
}

double SelectedArea(const TriangleMesh& mesh,
  const Arrangement& arr,
  const std::vector<char>& selected)
{
  const std::vector<double> areas = CellAreas(mesh, arr);
  double a = 0;
  for (int c = 0; c < arr.NumberOfCells; ++c)
    a += selected[c] ? areas[c] : 0.0;
  return a;
}

} // namespace

TEST(BoundarySampledCurves, FigureSixSampleSetsGiveTheirRegions)
{
  BscInput in = FigureSix();
  // Outer arcs sampled towards their curves' insides: the union.
  in.Samples = { { RedOuter, true }, { GreenOuter, false } };
  BscResult r = SelectOrDie(in);
  EXPECT_EQ(r.Selected, Cells({ RedOnly, GreenOnly, Both }));
  EXPECT_EQ(r.SampleOnBoundary, (std::vector<char>{ 1, 1 }));
  EXPECT_DOUBLE_EQ(r.BoundaryLength, 6.0);
  // Inner arcs sampled towards the lens: the intersection.
  in.Samples = { { RedInner, true }, { GreenInner, false } };
  EXPECT_EQ(SelectOrDie(in).Selected, Cells({ Both }));
  // Red's outer arc into red, green's inner arc out of green: red minus green.
  in.Samples = { { RedOuter, true }, { GreenInner, true } };
  EXPECT_EQ(SelectOrDie(in).Selected, Cells({ RedOnly }));
  // One sample on red's inner arc: the cheapest cut is the lens (length 2), but its green arc
  // holds no sample; forbidding it leaves the whole red disk (length 4), sample-connected.
  in.Samples = { { RedInner, true } };
  r = SelectOrDie(in);
  EXPECT_EQ(r.Selected, Cells({ RedOnly, Both }));
  EXPECT_EQ(r.ForbiddenPatches, (std::vector<int>{ GreenInner }));
  EXPECT_DOUBLE_EQ(r.BoundaryLength, 4.0);
  EXPECT_GE(r.Cuts, 2);
  EXPECT_FALSE(r.Greedy);
}

TEST(BoundarySampledCurves, ConflictsAndNonSeparatingPatchesDropSamples)
{
  BscInput in = FigureSix();
  // Both sides of one patch asked for: neither can be kept; the other sample still is.
  in.Samples = { { RedOuter, true }, { RedOuter, false }, { GreenOuter, false } };
  BscResult r = SelectOrDie(in);
  EXPECT_EQ(r.SampleOnBoundary, (std::vector<char>{ 0, 0, 1 }));
  EXPECT_EQ(r.Selected, Cells({ GreenOnly, Both }));
  // A patch with the same cell on both sides (a lone non-contractible curve) is ignored.
  in.Patches.push_back({ Outside, Outside, 2, 20, 20, 5.0 });
  in.Samples = { { 4, true } };
  r = SelectOrDie(in);
  EXPECT_EQ(r.Selected, Cells({}));
  EXPECT_EQ(r.SampleOnBoundary, (std::vector<char>{ 0 }));
  // No samples: nothing selected.
  in.Samples.clear();
  EXPECT_EQ(SelectOrDie(in).Selected, Cells({}));
  // A sample naming a patch that does not exist is a named error.
  in.Samples = { { 9, true } };
  std::string error;
  EXPECT_FALSE(SelectBoundarySampledCells(in, r, error));
  EXPECT_NE(error.find("sample 0 names patch 9"), std::string::npos) << error;
}

TEST(BoundarySampledCurves, GreedyEndIsSampleConnectedAndDeterministic)
{
  BscInput in = FigureSix();
  in.Samples = { { RedInner, true } };
  in.MaxSearchStates = 1; // the first cut is not sample-connected: the greedy end takes over
  const BscResult a = SelectOrDie(in), b = SelectOrDie(in);
  EXPECT_TRUE(a.Greedy);
  EXPECT_EQ(a.Selected, Cells({ RedOnly, Both }));
  EXPECT_EQ(a.Selected, b.Selected);
  EXPECT_EQ(a.ForbiddenPatches, b.ForbiddenPatches);
  // An abort asked for between cuts stops the search with a message.
  in.MaxSearchStates = 64;
  in.Abort = [] { return true; };
  BscResult r;
  std::string error;
  EXPECT_FALSE(SelectBoundarySampledCells(in, r, error));
  EXPECT_EQ(error, "aborted");
}

TEST(BoundarySampledCurves, OverlappingSquaresOnAFlatMesh)
{
  const TriangleMesh mesh = MeshOf(MakeFlatSquare(20, 1.0, 0.3, 5));
  FlatPolygonTracer tracer(mesh);
  // Red [0.2, 0.6]^2 counter-clockwise, green [0.4, 0.8]^2 clockwise.
  const std::vector<Vec2> red{ { 0.2, 0.2 }, { 0.6, 0.2 }, { 0.6, 0.6 }, { 0.2, 0.6 } };
  const std::vector<Vec2> green{ { 0.4, 0.4 }, { 0.4, 0.8 }, { 0.8, 0.8 }, { 0.8, 0.4 } };
  const Arrangement arr = ArrangeOrDie(
    mesh, { TraceOrDie(tracer, red, true, 0, 0), TraceOrDie(tracer, green, true, 1, 1) });
  ASSERT_EQ(arr.NumberOfCells, 4);
  const SampleQuery redOuterIn{ { 0.2, 0.4, 0 }, { 1, 0, 0 } };
  const SampleQuery redInnerIn{ { 0.6, 0.5, 0 }, { -1, 0, 0 } };
  const SampleQuery greenOuterIn{ { 0.8, 0.6, 0 }, { -1, 0, 0 } };
  const SampleQuery greenInnerIn{ { 0.4, 0.5, 0 }, { 1, 0, 0 } };
  const SampleQuery greenInnerOut{ { 0.4, 0.5, 0 }, { -1, 0, 0 } };
  struct Case
  {
    std::vector<SampleQuery> Samples;
    double Area;
  };
  const Case cases[] = {
    { { redOuterIn, greenOuterIn }, 0.28 },  // union
    { { redInnerIn, greenInnerIn }, 0.04 },  // intersection
    { { redOuterIn, greenInnerOut }, 0.12 }, // red minus green
    { { redInnerIn }, 0.16 },                // the lens is not sample-connected: red
  };
  for (const Case& c : cases)
  {
    std::vector<PatchSnap> snaps;
    BscResult r;
    std::string error;
    ASSERT_TRUE(SelectBySamples(mesh, arr, c.Samples, 1e-6, 64, snaps, r, error)) << error;
    EXPECT_NEAR(SelectedArea(mesh, arr, r.Selected), c.Area, 1e-12);
    for (char kept : r.SampleOnBoundary)
      EXPECT_EQ(kept, 1);
    for (const PatchSnap& s : snaps)
      EXPECT_LT(s.Distance, 1e-12);
  }
}

TEST(BoundarySampledCurves, BadSamplesAreNamed)
{
  const TriangleMesh mesh = MeshOf(MakeFlatSquare(8, 1.0, 0.0, 1));
  FlatPolygonTracer tracer(mesh);
  const std::vector<Vec2> square{ { 0.25, 0.25 }, { 0.75, 0.25 }, { 0.75, 0.75 }, { 0.25, 0.75 } };
  const Arrangement arr = ArrangeOrDie(mesh, { TraceOrDie(tracer, square) });
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const SampleQuery good{ { 0.25, 0.5, 0 }, { 1, 0, 0 } };
  struct Case
  {
    SampleQuery Bad;
    const char* Message;
  };
  const Case cases[] = {
    { { { 0.5, 0.5, 0 }, { 1, 0, 0 } }, "sample 1 at (0.5" }, // far from every patch
    { { { 0.25, 0.5, 0 }, { 0, 0, 0 } }, "sample 1: its Direction has zero length" },
    { { { 0.25, 0.5, 0 }, { nan, 0, 0 } }, "sample 1: its Direction is not a finite" },
    { { { nan, 0.5, 0 }, { 1, 0, 0 } }, "sample 1: its position is not a finite" },
    { { { 0.25, 0.5, 0 }, { 0, 1, 0 } }, "sample 1: its Direction runs along patch 0" },
  };
  for (const Case& c : cases)
  {
    std::vector<PatchSnap> snaps;
    BscResult r;
    std::string error;
    EXPECT_FALSE(SelectBySamples(mesh, arr, { good, c.Bad }, 0.01, 64, snaps, r, error));
    EXPECT_NE(error.find(c.Message), std::string::npos) << error;
  }
}

TEST(BoundarySampledCurves, TorusMeridiansBoundABand)
{
  const TriangleMesh mesh = MeshOf(MakeTorus(2.0, 0.7, 48, 24));
  // The plane through the axis at a small angle (no mesh vertex on it) cuts two meridians; the
  // torus is symmetric under the half turn that swaps the two bands, so each is half the area.
  const Vec3 normal{ std::cos(0.1), std::sin(0.1), 0 };
  std::vector<TracedCurve> meridians = PlaneSectionCurves(mesh, normal, 0.0, 0);
  ASSERT_EQ(meridians.size(), 2u);
  meridians[1].ShapeId = 1; // each meridian alone is an inconsistent shape
  const Arrangement arr = ArrangeOrDie(mesh, meridians);
  ASSERT_EQ(arr.NumberOfCells, 2);
  double total = 0;
  for (double a : CellAreas(mesh, arr))
    total += a;
  for (double side : { 1.0, -1.0 })
  {
    std::vector<SampleQuery> samples;
    for (int c = 0; c < 2; ++c)
      samples.push_back({ arr.GetPosition(mesh, arr.CurvePoints[c][0]), side * normal });
    std::vector<PatchSnap> snaps;
    BscResult r;
    std::string error;
    ASSERT_TRUE(SelectBySamples(mesh, arr, samples, 1e-3, 64, snaps, r, error)) << error;
    EXPECT_NEAR(SelectedArea(mesh, arr, r.Selected), 0.5 * total, 1e-9 * total);
    EXPECT_EQ(r.SampleOnBoundary, (std::vector<char>{ 1, 1 }));
    // The selected band is on the side the samples point to.
    const int inside = r.Selected[0] ? 0 : 1;
    const auto& t = arr.GetTriangle(mesh, arr.CellFirstTriangle[inside]);
    const Vec3 x =
      arr.GetPosition(mesh, t[0]) + arr.GetPosition(mesh, t[1]) + arr.GetPosition(mesh, t[2]);
    EXPECT_GT(side * Dot(x, normal), 0.0);
  }
  // One meridian separates nothing: its sample is dropped and nothing is selected.
  const Arrangement single = ArrangeOrDie(mesh, { meridians[0] });
  ASSERT_EQ(single.NumberOfCells, 1);
  std::vector<PatchSnap> snaps;
  BscResult r;
  std::string error;
  ASSERT_TRUE(SelectBySamples(mesh,
    single,
    { { single.GetPosition(mesh, single.CurvePoints[0][0]), normal } },
    1e-3,
    64,
    snaps,
    r,
    error))
    << error;
  EXPECT_EQ(r.Selected, std::vector<char>{ 0 });
  EXPECT_EQ(r.SampleOnBoundary, std::vector<char>{ 0 });
}

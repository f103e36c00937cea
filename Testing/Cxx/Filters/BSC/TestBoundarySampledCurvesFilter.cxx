// Boundary Sampled Curves through VTK: the stage filter on flat meshes against Clipper (paper
// Fig. 6 and random polygons, samples placed on the arrangement's patches), the one-step
// filter's Selection = BSC on torus meridians (inconsistent), and named errors.
#include "ClipperOracle.h"
#include "FilterTestUtils.h"
#include "vtkBoolSurf.h"
#include "vtkBoolSurfArrangement.h"
#include "vtkBoolSurfBSC.h"
#include "vtkBoolSurfLabeling.h"
#include "vtkBoolSurfSamples.h"
#include "vtkBoolSurfTraceCurves.h"

#include <vtkCommand.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

using testutils::ControlPolygon;

using testutils::MessageCatcher;

namespace
{
constexpr double Pi = 3.14159265358979323846;

struct Sample
{
  double X[3];
  double Direction[3];
};

vtkSmartPointer<vtkPolyData> ToSamples(const std::vector<Sample>& samples)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> direction;
  direction->SetName("Direction");
  direction->SetNumberOfComponents(3);
  for (const Sample& s : samples)
  {
    points->InsertNextPoint(s.X);
    direction->InsertNextTuple(s.Direction);
  }
  pd->SetPoints(points);
  pd->GetPointData()->AddArray(direction);
  return pd;
}

// One patch of the arrangement's second output: a point in its middle, its left normal (the
// direction to its left cell on a +z mesh) and its shape.
struct PatchSite
{
  double X[2];
  double Left[2];
  int Shape;
  double Length;
};

std::vector<PatchSite> PatchSites(vtkPolyData* patches)
{
  std::vector<PatchSite> sites;
  vtkDataArray* shape = patches->GetCellData()->GetArray("ShapeId");
  vtkDataArray* length = patches->GetCellData()->GetArray("Length");
  for (vtkIdType c = 0; c < patches->GetNumberOfCells(); ++c)
  {
    vtkIdType n;
    const vtkIdType* ids;
    patches->GetCellPoints(c, n, ids);
    // The middle segment of the polyline: away from the patch's ends (intersection points).
    const vtkIdType k = (n - 2) / 2;
    double a[3], b[3];
    patches->GetPoint(ids[k], a);
    patches->GetPoint(ids[k + 1], b);
    const double tx = b[0] - a[0], ty = b[1] - a[1], len = std::hypot(tx, ty);
    sites.push_back({ { 0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]) },
      { -ty / len, tx / len },
      static_cast<int>(shape->GetComponent(c, 0)),
      length->GetComponent(c, 0) });
  }
  return sites;
}

Sample At(const PatchSite& s, double towardsLeft)
{
  return { { s.X[0], s.X[1], 0 }, { towardsLeft * s.Left[0], towardsLeft * s.Left[1], 0 } };
}

// Trace + arrange two polygons on a flat mesh; BSC reads the arrangement's first output.
struct FlatScene
{
  vtkNew<vtkBoolSurfTraceCurves> Trace;
  vtkNew<vtkBoolSurfArrangement> Arrangement;
  vtkNew<vtkBoolSurfBSC> Bsc;
  vtkNew<MessageCatcher> Messages;

  FlatScene(vtkPolyData* mesh, const std::vector<ControlPolygon>& polygons)
  {
    this->Trace->SetInputData(0, mesh);
    this->Trace->SetInputData(1, testutils::ToCurves(polygons));
    this->Arrangement->SetInputData(0, mesh);
    this->Arrangement->SetInputConnection(1, this->Trace->GetOutputPort());
    this->Arrangement->Update();
    this->Bsc->SetInputConnection(0, this->Arrangement->GetOutputPort(0));
    this->Bsc->AddObserver(vtkCommand::ErrorEvent, this->Messages);
  }

  std::vector<PatchSite> Sites() { return PatchSites(this->Arrangement->GetOutput(1)); }

  double Run(const std::vector<Sample>& samples)
  {
    this->Messages->Errors.clear();
    this->Bsc->SetInputData(1, ToSamples(samples));
    this->Bsc->Update();
    return testutils::Area(this->Bsc->GetOutput());
  }

  // The same samples from the BSC Samples source (properties), as ParaView users give them.
  double RunFromSource(const std::vector<Sample>& samples)
  {
    this->Messages->Errors.clear();
    this->Source->SetNumberOfPoints(static_cast<int>(samples.size()));
    this->Source->SetNumberOfDirections(static_cast<int>(samples.size()));
    for (size_t i = 0; i < samples.size(); ++i)
    {
      const Sample& s = samples[i];
      this->Source->SetPoint(static_cast<int>(i), s.X[0], s.X[1], s.X[2]);
      this->Source->SetDirection(
        static_cast<int>(i), s.Direction[0], s.Direction[1], s.Direction[2]);
    }
    this->Bsc->SetInputConnection(1, this->Source->GetOutputPort());
    this->Bsc->Update();
    return testutils::Area(this->Bsc->GetOutput());
  }
  vtkNew<vtkBoolSurfSamples> Source;

  std::vector<int> Field(const char* name)
  {
    std::vector<int> values;
    vtkDataArray* a = this->Bsc->GetOutput()->GetFieldData()->GetArray(name);
    for (vtkIdType i = 0; a && i < a->GetNumberOfTuples(); ++i)
    {
      values.push_back(static_cast<int>(a->GetComponent(i, 0)));
    }
    return values;
  }
};

ControlPolygon Polygon(std::vector<std::array<double, 2>> xy, int shape)
{
  ControlPolygon p;
  p.ShapeId = shape;
  for (const auto& q : xy)
  {
    p.Points.push_back({ q[0], q[1], 0.0 });
  }
  return p;
}

// A random simple polygon, counter-clockwise: star-shaped around a center (sorted angles),
// vertices on a 1/4096 grid so Clipper's input is exact.
ControlPolygon RandomStar(std::mt19937& rng, int shape)
{
  std::uniform_real_distribution<double> center(0.35, 0.65), radius(0.12, 0.3), unit(0, 1);
  std::uniform_int_distribution<int> count(4, 8);
  const double cx = center(rng), cy = center(rng);
  const int n = count(rng);
  std::vector<std::array<double, 2>> xy;
  for (int i = 0; i < n; ++i)
  {
    const double angle = 2 * Pi * (i + 0.2 + 0.6 * unit(rng)) / n, r = radius(rng);
    xy.push_back({ std::round((cx + r * std::cos(angle)) * 4096) / 4096,
      std::round((cy + r * std::sin(angle)) * 4096) / 4096 });
  }
  return Polygon(xy, shape);
}

} // namespace

// Paper Fig. 6: a red (counter-clockwise) and a green (clockwise) curve overlapping; three
// sample sets give three regions.
TEST(BoundarySampledCurvesFilter, FigureSixThreeSampleSets)
{
  auto mesh = testutils::ToPolyData(boolsurf::MakeFlatSquare(40, 1.0, 0.3, 6));
  const ControlPolygon red =
    Polygon({ { 0.2, 0.25 }, { 0.6, 0.2 }, { 0.65, 0.55 }, { 0.4, 0.7 }, { 0.15, 0.5 } }, 0);
  const ControlPolygon green = Polygon( // clockwise
    { { 0.4, 0.35 }, { 0.45, 0.8 }, { 0.85, 0.75 }, { 0.8, 0.3 } },
    1);
  FlatScene scene(mesh, { red, green });
  std::vector<Sample> redOuter, redInner, greenOuter, greenInnerOut;
  for (const PatchSite& s : scene.Sites())
  {
    const bool red0 = s.Shape == 0;
    const bool inOther = testutils::InsidePolygon(red0 ? green : red, s.X[0], s.X[1]);
    // Red's inside is on its left; green (clockwise) has its inside on the right.
    if (red0)
    {
      (inOther ? redInner : redOuter).push_back(At(s, 1));
    }
    else
    {
      (inOther ? greenInnerOut : greenOuter).push_back(At(s, inOther ? 1 : -1));
    }
  }
  ASSERT_FALSE(redOuter.empty() || redInner.empty() || greenOuter.empty() || greenInnerOut.empty());

  // 1. Outer arcs towards their curves' insides: the union.
  std::vector<Sample> samples = redOuter;
  samples.insert(samples.end(), greenOuter.begin(), greenOuter.end());
  const double unionArea = scene.Run(samples);
  EXPECT_NEAR(unionArea, ClipperResultArea(red, green, ClipperLib::ctUnion), 1e-9);
  EXPECT_EQ(scene.Messages->Errors, "");
  EXPECT_EQ(scene.RunFromSource(samples), unionArea); // the BSC Samples source: same answer
  EXPECT_EQ(scene.Source->GetOutput()->GetNumberOfVerts(), vtkIdType(samples.size()));
  EXPECT_EQ(scene.Messages->Errors, "");
  EXPECT_TRUE(scene.Field("DroppedSamples").empty());
  // The labeled arrangement is accepted as well, with the same answer; the labels table travels
  // with the region.
  vtkNew<vtkBoolSurfLabeling> labeling;
  labeling->SetInputConnection(scene.Arrangement->GetOutputPort(0));
  scene.Bsc->SetInputConnection(0, labeling->GetOutputPort());
  EXPECT_NEAR(scene.Run(samples), ClipperResultArea(red, green, ClipperLib::ctUnion), 1e-9);
  EXPECT_NE(scene.Bsc->GetOutput()->GetFieldData()->GetArray("CellLabels"), nullptr);
  scene.Bsc->SetInputConnection(0, scene.Arrangement->GetOutputPort(0));
  // 2. Red's outer arcs into red, green's arcs inside red out of green: red minus green.
  samples = redOuter;
  samples.insert(samples.end(), greenInnerOut.begin(), greenInnerOut.end());
  EXPECT_NEAR(scene.Run(samples), ClipperResultArea(red, green, ClipperLib::ctDifference), 1e-9);
  // 3. One sample on red inside green: the cheapest cut is the lens, whose green arcs hold no
  // sample; the sample-connected answer is the whole red disk. Every region triangle is in
  // red, and the area is red's (the hand-computed cell set: the cells inside red).
  const double area = scene.Run({ redInner.front() });
  const double redArea = std::abs(ClipperLib::Area(testutils::ToClipper(red))) /
    (testutils::ClipperScale * testutils::ClipperScale);
  EXPECT_NEAR(area, redArea, 1e-9);
  vtkPolyData* region = scene.Bsc->GetOutput();
  for (vtkIdType t = 0; t < region->GetNumberOfCells(); ++t)
  {
    double c[3] = { 0, 0, 0 }, x[3];
    vtkIdType n;
    const vtkIdType* ids;
    region->GetCellPoints(t, n, ids);
    for (vtkIdType k = 0; k < n; ++k)
    {
      region->GetPoint(ids[k], x);
      c[0] += x[0] / n;
      c[1] += x[1] / n;
    }
    ASSERT_TRUE(testutils::InsidePolygon(red, c[0], c[1])) << "region triangle " << t;
  }
  EXPECT_EQ(scene.Field("SampleOnBoundary"), std::vector<int>{ 1 });
  EXPECT_GE(scene.Field("BSCCuts").at(0), 2);
  // The boundary output: closed loops, as long as red's perimeter.
  EXPECT_GT(scene.Bsc->GetBoundaryOutput()->GetNumberOfCells(), 0);
}

// Samples on every patch of A's curve, towards A's inside, select A; adding samples on B's
// arcs inside A pointing out of B (and keeping A's only outside B) gives A - B.
TEST(BoundarySampledCurvesFilter, RandomPolygonsMatchClipper)
{
  auto mesh = testutils::ToPolyData(boolsurf::MakeFlatSquare(40, 1.0, 0.3, 9));
  std::mt19937 rng(77);
  int nonEmptyDifferences = 0, oneArcTrials = 0, shorterB = 0;
  for (int trial = 0; trial < 12; ++trial)
  {
    const ControlPolygon a = RandomStar(rng, 0), b = RandomStar(rng, 1);
    FlatScene scene(mesh, { a, b });
    std::vector<Sample> allOfA, difference, bInsideA;
    int aPatchesInB = 0;
    double aLengthInB = 0, bLengthInA = 0;
    for (const PatchSite& s : scene.Sites())
    {
      const bool inOther = testutils::InsidePolygon(s.Shape == 0 ? b : a, s.X[0], s.X[1]);
      if (s.Shape == 0)
      {
        allOfA.push_back(At(s, 1));
        if (!inOther)
        {
          difference.push_back(At(s, 1));
        }
        aPatchesInB += inOther ? 1 : 0;
        aLengthInB += inOther ? s.Length : 0;
      }
      else if (inOther)
      {
        difference.push_back(At(s, -1)); // B is counter-clockwise: its outside is on the right
        bInsideA.push_back(At(s, -1));
        bLengthInA += s.Length;
      }
    }
    const double areaA = std::abs(ClipperLib::Area(testutils::ToClipper(a))) /
      (testutils::ClipperScale * testutils::ClipperScale);
    EXPECT_NEAR(scene.Run(allOfA), areaA, 1e-9) << "trial " << trial;
    EXPECT_EQ(scene.Messages->Errors, "") << "trial " << trial;
    const double expected = ClipperResultArea(a, b, ClipperLib::ctDifference);
    EXPECT_NEAR(scene.Run(difference), expected, 1e-9) << "trial " << trial;
    EXPECT_TRUE(scene.Field("DroppedSamples").empty()) << "trial " << trial;
    nonEmptyDifferences += (expected > 1e-3 && expected < areaA - 1e-3) ? 1 : 0;
    // Every patch of A sampled, plus one sample on B's single arc inside A pointing out of B:
    // A keeps A's samples and drops B's; A - B keeps B's and drops A's single arc inside B.
    // One sample dropped either way, so the shorter boundary wins: A - B exactly when B's arc
    // inside A is shorter than A's arc inside B.
    if (aPatchesInB == 1 && bInsideA.size() == 1)
    {
      std::vector<Sample> samples = allOfA;
      samples.push_back(bInsideA.front());
      const double area = scene.Run(samples);
      EXPECT_NEAR(area, bLengthInA < aLengthInB ? expected : areaA, 1e-9) << "trial " << trial;
      EXPECT_EQ(scene.Field("DroppedSamples").size(), 1u) << "trial " << trial;
      ++oneArcTrials;
      shorterB += bLengthInA < aLengthInB ? 1 : 0;
    }
  }
  EXPECT_GE(nonEmptyDifferences, 3); // B really cuts A in several trials
  EXPECT_GE(oneArcTrials, 2);
  EXPECT_GE(shorterB, 1); // A - B was the answer at least once
}

TEST(BoundarySampledCurvesFilter, BadSamplesAreNamedErrors)
{
  auto mesh = testutils::ToPolyData(boolsurf::MakeFlatSquare(16, 1.0, 0.0, 1));
  FlatScene scene(
    mesh, { Polygon({ { 0.25, 0.25 }, { 0.75, 0.25 }, { 0.75, 0.75 }, { 0.25, 0.75 } }, 0) });
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Sample good{ { 0.25, 0.5, 0 }, { 1, 0, 0 } };
  EXPECT_NEAR(scene.Run({ good }), 0.25, 1e-12);
  struct Case
  {
    Sample Bad;
    const char* Message;
  };
  const Case cases[] = {
    { { { 0.5, 0.5, 0 }, { 1, 0, 0 } }, "sample 1 at (0.5" },
    { { { 0.25, 0.5, 0 }, { 0, 0, 0 } }, "sample 1: its Direction has zero length" },
    { { { 0.25, 0.5, 0 }, { nan, 1, 0 } }, "sample 1: its Direction is not a finite" },
    { { { 0.25, nan, 0 }, { 1, 0, 0 } }, "sample 1: its position is not a finite" },
  };
  for (const Case& c : cases)
  {
    EXPECT_EQ(scene.Run({ good, c.Bad }), 0.0);
    EXPECT_EQ(scene.Bsc->GetOutput()->GetNumberOfPoints(), 0);
    EXPECT_NE(scene.Messages->Errors.find(c.Message), std::string::npos) << scene.Messages->Errors;
  }
  // Samples without a Direction array.
  auto noDirection = ToSamples({ good });
  noDirection->GetPointData()->RemoveArray("Direction");
  scene.Messages->Errors.clear();
  scene.Bsc->SetInputData(1, noDirection);
  scene.Bsc->Update();
  EXPECT_NE(scene.Messages->Errors.find("lack point data 'Direction'"), std::string::npos);
}

// A torus meridian (circle around the tube at angle u) as 8 control points on the mesh's
// vertex ring.
ControlPolygon Meridian(double R, double r, int nu, int column, int shape)
{
  ControlPolygon c;
  c.ShapeId = shape;
  const double u = 2 * Pi * column / nu;
  for (int k = 0; k < 8; ++k)
  {
    const double v = 2 * Pi * k / 8;
    c.Points.push_back({ (R + r * std::cos(v)) * std::cos(u),
      (R + r * std::cos(v)) * std::sin(u),
      r * std::sin(v) });
  }
  return c;
}

TEST(BoundarySampledCurvesFilter, OneStepTorusMeridians)
{
  const double R = 2, r = 0.7;
  const int nu = 48, nv = 24;
  auto torus = testutils::ToPolyData(boolsurf::MakeTorus(R, r, nu, nv));
  const double total = testutils::Area(torus);
  vtkNew<vtkBoolSurf> f;
  vtkNew<MessageCatcher> messages;
  f->AddObserver(vtkCommand::ErrorEvent, messages);
  f->SetInputData(0, torus);
  // Two meridians at u = 0 and u = pi, separate shapes: each alone is inconsistent.
  f->SetInputData(
    1, testutils::ToCurves({ Meridian(R, r, nu, 0, 0), Meridian(R, r, nu, nu / 2, 1) }));
  f->SetSelectionToBSC();
  // The area argument below needs the two meridians to be images of each other under the half
  // turn. Exact shortest legs between ring vertices leave the ring on the saddle-shaped inner
  // side, where mirror-image paths tie and either may be taken; locally shortest legs stay
  // symmetric.
  f->SetGeodesicMethodToLocallyShortest();
  // Samples on the outer equator of each meridian, pointing to y > 0: the band u in (0, pi),
  // half of the torus (the half turn around z maps the mesh onto itself and swaps the bands).
  f->SetInputData(
    2, ToSamples({ { { R + r, 0, 0 }, { 0, 1, 0 } }, { { -R - r, 0, 0 }, { 0, 1, 0 } } }));
  f->Update();
  EXPECT_EQ(messages->Errors, "");
  EXPECT_NEAR(testutils::Area(f->GetOutput()), 0.5 * total, 1e-9 * total);
  // (Geodesics between the control points may leave the vertex ring by a little on the
  // inner, saddle-shaped side of the torus: the band's edges are within 0.01 of y = 0.)
  vtkPolyData* out = f->GetOutput();
  for (vtkIdType t = 0; t < out->GetNumberOfCells(); ++t)
  {
    double bounds[6];
    out->GetCellBounds(t, bounds);
    ASSERT_GE(bounds[2], -0.01) << "triangle " << t << " is not in the band y > 0";
  }
  EXPECT_EQ(out->GetFieldData()->GetArray("DroppedSamples")->GetNumberOfTuples(), 0);
  EXPECT_GT(f->GetBoundaryOutput()->GetNumberOfCells(), 0);

  // Exact surface points (TriangleId/Barycentric) are used when given: point the samples the
  // other way, with coordinates far off but exact surface points on the meridians' vertices.
  // (Vertex (i, j) of the torus is point i * nv + j: column 0 and nu/2, ring 0.)
  auto exact = ToSamples({ { { 9, 9, 9 }, { 0, -1, 0 } }, { { 9, 9, 9 }, { 0, -1, 0 } } });
  vtkNew<vtkIdTypeArray> tid;
  tid->SetName("TriangleId");
  vtkNew<vtkDoubleArray> uv;
  uv->SetName("Barycentric");
  uv->SetNumberOfComponents(2);
  for (int column : { 0, nu / 2 })
  {
    // The first triangle with the vertex (column, 0) as a corner, and that corner's weights.
    const vtkIdType vertex = static_cast<vtkIdType>(column) * nv;
    for (vtkIdType t = 0; t < torus->GetNumberOfCells(); ++t)
    {
      vtkIdType n;
      const vtkIdType* ids;
      torus->GetCellPoints(t, n, ids);
      const int k = static_cast<int>(std::find(ids, ids + 3, vertex) - ids);
      if (k < 3)
      {
        tid->InsertNextValue(t);
        uv->InsertNextTuple2(k == 1 ? 1 : 0, k == 2 ? 1 : 0);
        break;
      }
    }
  }
  exact->GetPointData()->AddArray(tid);
  exact->GetPointData()->AddArray(uv);
  f->SetInputData(2, exact);
  f->Update();
  EXPECT_EQ(messages->Errors, "");
  EXPECT_NEAR(testutils::Area(f->GetOutput()), 0.5 * total, 1e-9 * total);
  out = f->GetOutput();
  for (vtkIdType t = 0; t < out->GetNumberOfCells(); ++t)
  {
    double bounds[6];
    out->GetCellBounds(t, bounds);
    ASSERT_LE(bounds[3], 0.01) << "triangle " << t << " is not in the band y < 0";
  }

  // A single meridian separates nothing: the sample is dropped, the region is empty, no error.
  f->SetInputData(1, testutils::ToCurves({ Meridian(R, r, nu, 0, 0) }));
  f->SetInputData(2, ToSamples({ { { R + r, 0, 0 }, { 0, 1, 0 } } }));
  f->Update();
  EXPECT_EQ(messages->Errors, "");
  EXPECT_EQ(f->GetOutput()->GetNumberOfCells(), 0);
  auto* dropped = f->GetOutput()->GetFieldData()->GetArray("DroppedSamples");
  ASSERT_NE(dropped, nullptr);
  ASSERT_EQ(dropped->GetNumberOfTuples(), 1);
  EXPECT_EQ(dropped->GetComponent(0, 0), 0);

  // BSC without a samples input: an empty region, no crash.
  f->RemoveAllInputConnections(2);
  f->Update();
  EXPECT_EQ(messages->Errors, "");
  EXPECT_EQ(f->GetOutput()->GetNumberOfCells(), 0);
}

// The BSC Samples source: one vertex and one Direction per sample; a Directions count that is
// not the Points count is an error naming both, with an empty output.
TEST(BoundarySampledCurvesFilter, SamplesSourceChecksItsProperties)
{
  vtkNew<vtkBoolSurfSamples> source;
  source->SetPoint(0, 0.1, 0.2, 0.0);
  source->SetPoint(1, 0.3, 0.4, 0.0);
  source->SetDirection(0, 1.0, 0.0, 0.0);
  source->SetDirection(1, 0.0, -2.0, 0.0);
  source->Update();
  vtkPolyData* out = source->GetOutput();
  ASSERT_EQ(out->GetNumberOfPoints(), 2);
  EXPECT_EQ(out->GetNumberOfVerts(), 2);
  vtkDataArray* direction = out->GetPointData()->GetArray("Direction");
  ASSERT_NE(direction, nullptr);
  EXPECT_EQ(direction->GetComponent(1, 1), -2.0);
  EXPECT_EQ(out->GetPoint(1)[0], 0.3);

  source->SetNumberOfDirections(1);
  EXPECT_NE(
    testutils::ErrorsOf(source).find("Each of the 2 sample Points needs a Direction; got 1"),
    std::string::npos)
    << testutils::ErrorsOf(source);
  EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), 0);
}

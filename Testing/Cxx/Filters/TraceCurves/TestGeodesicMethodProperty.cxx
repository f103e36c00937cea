// The GeodesicMethod property of the filters that trace geodesics (Trace Surface Curves, the
// one-step BoolSurf, Surface Curves' traced port, Resolve Inconsistent Shapes) and the
// deprecated ExactGeodesics switch that maps onto it. On an open 48-sided prism (developable,
// so the shortest path between two points is the straight line of the unrolled prism), legs
// between near-opposite points are exactly that long with Exact and Bounded (the exact search
// stays small on a mesh this size); with Locally shortest some come out longer (the path around
// the wrong side), none shorter. The method reaches every stage: the one-step filter and the
// stage chain give the same outputs for each method, the control points of results included,
// and those outputs differ between methods.
#include "FilterTestUtils.h"
#include "Support/UnrolledPrism.h"
#include "vtkBoolSurf.h"
#include "vtkBoolSurfArrangement.h"
#include "vtkBoolSurfBoolean.h"
#include "vtkBoolSurfLabeling.h"
#include "vtkBoolSurfResolve.h"
#include "vtkBoolSurfSurfaceCurves.h"
#include "vtkBoolSurfTraceCurves.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <sstream>
#include <utility>

namespace
{

using Point = std::array<double, 3>;

constexpr int Bounded = vtkBoolSurfAlgorithm::GEODESIC_BOUNDED;
constexpr int Exact = vtkBoolSurfAlgorithm::GEODESIC_EXACT;
constexpr int LocallyShortest = vtkBoolSurfAlgorithm::GEODESIC_LOCALLY_SHORTEST;

/// The open prism of the tests and 200 legs between near-opposite points of it, with the
/// length of each leg on the unrolled prism.
struct PrismLegs
{
  static constexpr int Around = 48, Along = 16;
  static constexpr double Radius = 1, Height = 3;
  vtkSmartPointer<vtkPolyData> Prism;
  std::vector<testutils::ControlPolygon> Legs;
  std::vector<double> Unrolled;

  PrismLegs()
  {
    const double pi = std::acos(-1.0);
    this->Prism = testutils::ToPolyData(boolsurf::MakeOpenCylinder(Radius, Height, Around, Along));
    const boolsurf::testing::UnrolledPrism unrolledPrism{ Around, Radius };
    // A point on facet j at fraction f between its corners, at height z.
    auto onFacet = [&](int j, double f, double z)
    {
      const double a0 = 2 * pi * j / Around, a1 = 2 * pi * (j + 1) / Around;
      return Point{ Radius * ((1 - f) * std::cos(a0) + f * std::cos(a1)),
        Radius * ((1 - f) * std::sin(a0) + f * std::sin(a1)),
        z };
    };
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> unit(0.05, 0.95);
    for (int i = 0; i < 200; ++i)
    {
      const int j0 = static_cast<int>(rng() % Around);
      const int j1 = (j0 + 23 + static_cast<int>(rng() % 3)) % Around;
      testutils::ControlPolygon c;
      c.Closed = false;
      c.Points = { onFacet(j0, unit(rng), Height * unit(rng)),
        onFacet(j1, unit(rng), Height * unit(rng)) };
      auto vec = [](const Point& p) { return boolsurf::Vec3{ p[0], p[1], p[2] }; };
      this->Unrolled.push_back(unrolledPrism.ShortestLength(vec(c.Points[0]), vec(c.Points[1])));
      this->Legs.push_back(c);
    }
  }
};

/// Lengths of the traced curves (cell data Length) of one update of `trace`.
std::vector<double> TracedLengths(vtkBoolSurfTraceCurves* trace)
{
  const std::string errors = testutils::ErrorsOf(trace);
  EXPECT_TRUE(errors.empty()) << errors;
  std::vector<double> lengths;
  vtkDataArray* length = trace->GetOutput()->GetCellData()->GetArray("Length");
  for (vtkIdType i = 0; length && i < length->GetNumberOfTuples(); ++i)
  {
    lengths.push_back(length->GetTuple1(i));
  }
  return lengths;
}

/// Empty when `a` and `b` have the same points, cells and point and cell arrays, bit for bit;
/// else what differs first.
std::string Difference(vtkPolyData* a, vtkPolyData* b)
{
  std::ostringstream why;
  if (a->GetNumberOfPoints() != b->GetNumberOfPoints() ||
    a->GetNumberOfCells() != b->GetNumberOfCells())
  {
    why << a->GetNumberOfPoints() << " points, " << a->GetNumberOfCells() << " cells vs "
        << b->GetNumberOfPoints() << ", " << b->GetNumberOfCells();
    return why.str();
  }
  for (vtkIdType p = 0; p < a->GetNumberOfPoints(); ++p)
  {
    double x[3], y[3];
    a->GetPoint(p, x);
    b->GetPoint(p, y);
    if (x[0] != y[0] || x[1] != y[1] || x[2] != y[2])
    {
      why << "point " << p;
      return why.str();
    }
  }
  vtkIdType na, nb;
  const vtkIdType *ia, *ib;
  for (vtkIdType c = 0; c < a->GetNumberOfCells(); ++c)
  {
    a->GetCellPoints(c, na, ia);
    b->GetCellPoints(c, nb, ib);
    if (na != nb || !std::equal(ia, ia + na, ib))
    {
      why << "cell " << c;
      return why.str();
    }
  }
  using Attributes = std::pair<vtkDataSetAttributes*, vtkDataSetAttributes*>;
  for (const auto& [x, y] : { Attributes{ a->GetPointData(), b->GetPointData() },
         Attributes{ a->GetCellData(), b->GetCellData() } })
  {
    if (x->GetNumberOfArrays() != y->GetNumberOfArrays())
    {
      return "array count";
    }
    for (int i = 0; i < x->GetNumberOfArrays(); ++i)
    {
      vtkDataArray* u = x->GetArray(i);
      vtkDataArray* v = u ? y->GetArray(u->GetName()) : nullptr;
      if (!u || !v || u->GetNumberOfValues() != v->GetNumberOfValues())
      {
        return std::string("array ") + (u ? u->GetName() : "?");
      }
      for (vtkIdType k = 0; k < u->GetNumberOfValues(); ++k)
      {
        if (u->GetVariantValue(k) != v->GetVariantValue(k))
        {
          why << "array " << u->GetName() << ", value " << k;
          return why.str();
        }
      }
    }
  }
  return "";
}

/// The property's API on one filter class: default, named setters, clamping.
template <class Filter>
void ExpectMethodApi(const char* name)
{
  vtkNew<Filter> f;
  EXPECT_EQ(f->GetGeodesicMethod(), Bounded) << name;
  f->SetGeodesicMethodToExact();
  EXPECT_EQ(f->GetGeodesicMethod(), Exact) << name;
  f->SetGeodesicMethodToLocallyShortest();
  EXPECT_EQ(f->GetGeodesicMethod(), LocallyShortest) << name;
  f->SetGeodesicMethodToBounded();
  EXPECT_EQ(f->GetGeodesicMethod(), Bounded) << name;
  f->SetGeodesicMethod(7);
  EXPECT_EQ(f->GetGeodesicMethod(), LocallyShortest) << name;
  f->SetGeodesicMethod(-1);
  EXPECT_EQ(f->GetGeodesicMethod(), Bounded) << name;
  // A change re-executes the filter.
  const vtkMTimeType before = f->GetMTime();
  f->SetGeodesicMethod(Exact);
  EXPECT_GT(f->GetMTime(), before) << name;
}

/// The deprecated switch: on is Exact, off is Locally shortest; it reads on for Exact only.
template <class Filter>
void ExpectDeprecatedSwitch(const char* name)
{
  vtkNew<Filter> f;
  EXPECT_EQ(f->GetExactGeodesics(), 0) << name << ": the default is Bounded, not Exact";
  f->SetExactGeodesics(1);
  EXPECT_EQ(f->GetGeodesicMethod(), Exact) << name;
  EXPECT_EQ(f->GetExactGeodesics(), 1) << name;
  f->SetExactGeodesics(0);
  EXPECT_EQ(f->GetGeodesicMethod(), LocallyShortest) << name;
  EXPECT_EQ(f->GetExactGeodesics(), 0) << name;
  f->ExactGeodesicsOn();
  EXPECT_EQ(f->GetGeodesicMethod(), Exact) << name;
  f->ExactGeodesicsOff();
  EXPECT_EQ(f->GetGeodesicMethod(), LocallyShortest) << name;
  f->SetExactGeodesics(5); // any true value
  EXPECT_EQ(f->GetGeodesicMethod(), Exact) << name;
  f->SetGeodesicMethodToBounded();
  EXPECT_EQ(f->GetExactGeodesics(), 0) << name;
}

} // namespace

TEST(GeodesicMethodProperty, DefaultSettersAndClamping)
{
  ExpectMethodApi<vtkBoolSurfTraceCurves>("Trace Surface Curves");
  ExpectMethodApi<vtkBoolSurf>("BoolSurf");
  ExpectMethodApi<vtkBoolSurfSurfaceCurves>("Surface Curves");
  ExpectMethodApi<vtkBoolSurfResolve>("Resolve Inconsistent Shapes");
}

TEST(GeodesicMethodProperty, DeprecatedExactGeodesicsMapsOntoTheMethod)
{
  ExpectDeprecatedSwitch<vtkBoolSurfTraceCurves>("Trace Surface Curves");
  ExpectDeprecatedSwitch<vtkBoolSurf>("BoolSurf");
}

// Each method on the same filter, switched back and forth (the tracer's memory of legs must not
// hand one method's legs to another), and the deprecated switch giving the same legs as the
// method it maps to.
TEST(GeodesicMethodProperty, PrismNearOppositePointsAreJoinedByTheUnrolledLine)
{
  const PrismLegs prism;
  vtkSmartPointer<vtkPolyData> curves = testutils::ToCurves(prism.Legs);
  vtkNew<vtkBoolSurfTraceCurves> trace;
  trace->SetInputData(0, prism.Prism);
  trace->SetInputData(1, curves);
  const std::vector<double> byDefault = TracedLengths(trace);
  trace->SetGeodesicMethodToExact();
  const std::vector<double> exact = TracedLengths(trace);
  trace->SetGeodesicMethodToLocallyShortest();
  const std::vector<double> local = TracedLengths(trace);
  trace->SetGeodesicMethodToBounded();
  const std::vector<double> bounded = TracedLengths(trace);
  trace->SetExactGeodesics(1);
  const std::vector<double> switchedOn = TracedLengths(trace);
  trace->SetExactGeodesics(0);
  const std::vector<double> switchedOff = TracedLengths(trace);
  const size_t n = prism.Unrolled.size();
  ASSERT_EQ(exact.size(), n);
  ASSERT_EQ(local.size(), n);
  ASSERT_EQ(bounded.size(), n);
  int longer = 0;
  for (size_t i = 0; i < n; ++i)
  {
    const double unrolled = prism.Unrolled[i];
    EXPECT_NEAR(exact[i], unrolled, 1e-9 * unrolled) << "leg " << i;
    // Bounded is exact while the exact search stays small, as it does on 1,536 triangles.
    EXPECT_NEAR(bounded[i], unrolled, 1e-9 * unrolled) << "leg " << i;
    EXPECT_GE(local[i], unrolled * (1 - 1e-9)) << "leg " << i;
    longer += local[i] > unrolled * (1 + 1e-6) ? 1 : 0;
  }
  // The method reaches the tracer: without an exact search some legs go the long way round.
  EXPECT_GT(longer, 0);
  EXPECT_EQ(byDefault, bounded);
  EXPECT_EQ(switchedOn, exact);
  EXPECT_EQ(switchedOff, local);
}

// Surface Curves' Traced Curves port is Trace Surface Curves' output with the same method.
TEST(GeodesicMethodProperty, SurfaceCurvesTracedPortFollowsTheMethod)
{
  const PrismLegs prism;
  // The legs' ends as exact surface points (as the curve editor stores them): the control
  // points Trace Surface Curves projected.
  vtkNew<vtkBoolSurfTraceCurves> projection;
  projection->SetInputData(0, prism.Prism);
  projection->SetInputData(1, testutils::ToCurves(prism.Legs));
  ASSERT_EQ(testutils::ErrorsOf(projection), "");
  vtkFieldData* controls = projection->GetOutput()->GetFieldData();
  vtkDataArray* controlTriangle = controls->GetArray("ControlTriangleId");
  vtkDataArray* controlBarycentric = controls->GetArray("ControlBarycentric");
  const int legs = static_cast<int>(prism.Legs.size());
  ASSERT_TRUE(controlTriangle && controlBarycentric);
  ASSERT_EQ(controlTriangle->GetNumberOfTuples(), 2 * legs);
  vtkNew<vtkBoolSurfSurfaceCurves> drawing;
  drawing->SetInputData(0, prism.Prism);
  drawing->SetNumberOfPoints(2 * legs);
  drawing->SetNumberOfTriangleIds(2 * legs);
  drawing->SetNumberOfBarycentrics(2 * legs);
  drawing->SetNumberOfCurveSizes(legs);
  drawing->SetNumberOfClosedCurves(legs);
  for (int i = 0; i < 2 * legs; ++i)
  {
    drawing->SetPoint(i, 0, 0, 0);
    drawing->SetTriangleId(i, static_cast<vtkIdType>(controlTriangle->GetTuple1(i)));
    drawing->SetBarycentric(
      i, controlBarycentric->GetComponent(i, 0), controlBarycentric->GetComponent(i, 1));
  }
  for (int i = 0; i < legs; ++i)
  {
    drawing->SetCurveSize(i, 2);
    drawing->SetClosedCurve(i, 0);
  }
  vtkNew<vtkBoolSurfTraceCurves> trace;
  trace->SetInputData(0, prism.Prism);
  trace->SetInputConnection(1, drawing->GetOutputPort(0));
  std::vector<vtkSmartPointer<vtkPolyData>> shown;
  for (int method : { Bounded, Exact, LocallyShortest })
  {
    drawing->SetGeodesicMethod(method);
    trace->SetGeodesicMethod(method);
    EXPECT_EQ(testutils::ErrorsOf(drawing), "");
    EXPECT_EQ(testutils::ErrorsOf(trace), "");
    vtkPolyData* traced = drawing->GetOutput(1);
    ASSERT_EQ(traced->GetNumberOfCells(), legs);
    EXPECT_EQ(Difference(traced, trace->GetOutput()), "") << "method " << method;
    shown.emplace_back(vtkSmartPointer<vtkPolyData>::New());
    shown.back()->DeepCopy(traced);
  }
  EXPECT_NE(Difference(shown[1], shown[2]), "") << "Exact and Locally shortest drew the same";
}

// The one-step filter and the stage chain (Trace Surface Curves -> Surface Arrangement -> Label
// Arrangement Cells -> Surface Boolean) give the same four outputs for each method: the
// method travels with the traced curves to the Boolean, which traces the control points of
// its results (ports 2 and 3) the same way. The outputs change with the method.
TEST(GeodesicMethodProperty, OneStepAndStageChainAgreeForEachMethod)
{
  const PrismLegs prism;
  // A leg that the locally shortest method takes the long way round.
  int leg = -1;
  {
    vtkNew<vtkBoolSurfTraceCurves> trace;
    trace->SetInputData(0, prism.Prism);
    trace->SetInputData(1, testutils::ToCurves(prism.Legs));
    trace->SetGeodesicMethodToLocallyShortest();
    const std::vector<double> local = TracedLengths(trace);
    ASSERT_EQ(local.size(), prism.Unrolled.size());
    for (size_t i = 0; i < local.size() && leg < 0; ++i)
    {
      if (local[i] > prism.Unrolled[i] * (1 + 1e-3))
      {
        leg = static_cast<int>(i);
      }
    }
    ASSERT_GE(leg, 0);
  }
  const Point a = prism.Legs[leg].Points[0], b = prism.Legs[leg].Points[1];
  auto lifted = [](Point p, double dz)
  {
    p[2] += p[2] < PrismLegs::Height / 2 ? dz : -dz;
    return p;
  };
  // Shape 0: a quadrilateral with that leg as a side. Shape 1: a closed cubic Bezier with that
  // leg between its handles, crossing shape 0 (so the boundary's Bezier pieces are split there
  // by geodesic de Casteljau insertion).
  testutils::ControlPolygon quad{ { a, b, lifted(b, 0.8), lifted(a, 0.8) }, 0 };
  testutils::ControlPolygon bezier{
    { lifted(a, 0.4), a, b, lifted(b, 0.4), lifted(b, 1.2), lifted(a, 1.2) }, 1
  };
  bezier.Type = 1;
  vtkSmartPointer<vtkPolyData> curves = testutils::ToCurves({ quad, bezier });

  std::vector<std::array<vtkSmartPointer<vtkPolyData>, 4>> outputs;
  for (int method : { Bounded, Exact, LocallyShortest })
  {
    vtkNew<vtkBoolSurf> one;
    one->SetInputData(0, prism.Prism);
    one->SetInputData(1, curves);
    one->SetGeodesicMethod(method);
    one->SetShapeA(-1); // the union of both shapes
    one->SetShapeB(-1);
    ASSERT_EQ(testutils::ErrorsOf(one), "") << "method " << method;

    vtkNew<vtkBoolSurfTraceCurves> trace;
    vtkNew<vtkBoolSurfArrangement> arrange;
    vtkNew<vtkBoolSurfLabeling> label;
    vtkNew<vtkBoolSurfBoolean> boolean;
    trace->SetInputData(0, prism.Prism);
    trace->SetInputData(1, curves);
    trace->SetGeodesicMethod(method);
    arrange->SetInputData(0, prism.Prism);
    arrange->SetInputConnection(1, trace->GetOutputPort());
    label->SetInputConnection(arrange->GetOutputPort(0));
    boolean->SetInputConnection(label->GetOutputPort(0));
    boolean->SetShapeA(-1);
    boolean->SetShapeB(-1);
    ASSERT_EQ(testutils::ErrorsOf(boolean), "") << "method " << method;

    std::array<vtkSmartPointer<vtkPolyData>, 4> kept;
    for (int port = 0; port < 4; ++port)
    {
      EXPECT_EQ(Difference(one->GetOutput(port), boolean->GetOutput(port)), "")
        << "method " << method << ", port " << port;
      kept[port] = vtkSmartPointer<vtkPolyData>::New();
      kept[port]->DeepCopy(one->GetOutput(port));
    }
    EXPECT_GT(kept[0]->GetNumberOfCells(), 0) << "method " << method;
    EXPECT_GT(kept[2]->GetNumberOfCells(), 0) << "method " << method;
    outputs.push_back(kept);
  }
  // Bounded and Exact agree on a mesh this small; Locally shortest changes the region and the
  // control points of its boundary.
  for (int port = 0; port < 4; ++port)
  {
    EXPECT_EQ(Difference(outputs[0][port], outputs[1][port]), "") << "port " << port;
  }
  EXPECT_NE(Difference(outputs[1][0], outputs[2][0]), "");
  EXPECT_NE(Difference(outputs[1][2], outputs[2][2]), "");
}

// Resolve Inconsistent Shapes traces the curves to find their classes with its method: a
// meridian of a torus is duplicated reversed whatever the method.
TEST(GeodesicMethodProperty, ResolveRunsWithEachMethod)
{
  const double R = 2, r = 0.7;
  auto torus = testutils::ToPolyData(boolsurf::MakeTorus(R, r, 48, 24));
  testutils::ControlPolygon meridian;
  for (int k = 0; k < 12; ++k)
  {
    const double v = 2 * std::acos(-1.0) * k / 12.0;
    meridian.Points.push_back({ R + r * std::cos(v), 0, r * std::sin(v) });
  }
  for (int method : { Bounded, Exact, LocallyShortest })
  {
    vtkNew<vtkBoolSurfResolve> resolve;
    resolve->SetInputData(0, torus);
    resolve->SetInputData(1, testutils::ToCurves({ meridian }));
    resolve->SetGeodesicMethod(method);
    ASSERT_EQ(testutils::ErrorsOf(resolve), "") << "method " << method;
    vtkDataArray* action = resolve->GetOutput()->GetCellData()->GetArray("Resolution");
    ASSERT_NE(action, nullptr);
    ASSERT_EQ(action->GetNumberOfTuples(), 2) << "method " << method;
    EXPECT_EQ(action->GetTuple1(0) + action->GetTuple1(1), 2) << "kept (0) + duplicated (2)";
  }
}

// Bounded: the per-surface site graph of far legs is reported in the output's field data,
// built once per surface: moving the curves keeps it, a new surface gets a new one.
TEST(GeodesicMethodProperty, SiteGraphIsBuiltOncePerSurface)
{
  auto graphOf = [](vtkBoolSurfTraceCurves* trace) -> std::array<double, 4>
  {
    vtkDataArray* field = trace->GetOutput()->GetFieldData()->GetArray("GeodesicSiteGraph");
    if (!field || field->GetNumberOfComponents() != 4)
    {
      return { -1, -1, -1, -1 };
    }
    return { field->GetComponent(0, 0),
      field->GetComponent(0, 1),
      field->GetComponent(0, 2),
      field->GetComponent(0, 3) };
  };
  // A torus too large for the exact search's budget between opposite points (0.4 apart
  // through the hole, 2.7 around the tube) and a second one of another resolution.
  vtkSmartPointer<vtkPolyData> torus =
    testutils::ToPolyData(boolsurf::MakeTorus(1.0, 0.35, 400, 160));
  vtkSmartPointer<vtkPolyData> other =
    testutils::ToPolyData(boolsurf::MakeTorus(1.0, 0.35, 360, 150));
  auto farLeg = [](double z)
  {
    testutils::ControlPolygon leg;
    leg.Points = { Point{ 1.35, 0.0, z }, Point{ -1.35, 0.0, z } };
    leg.Closed = false;
    return leg;
  };
  vtkNew<vtkBoolSurfTraceCurves> trace;
  trace->SetInputData(0, torus);
  trace->SetInputData(1, testutils::ToCurves({ farLeg(0.0) }));
  trace->Update();
  ASSERT_EQ(testutils::ErrorsOf(trace), "");
  const std::array<double, 4> first = graphOf(trace);
  ASSERT_GT(first[0], 100) << "no site graph reported after a far leg";
  EXPECT_GT(first[2], 0.0);
  // Only the curves change: the same graph.
  trace->SetInputData(1, testutils::ToCurves({ farLeg(0.1), farLeg(-0.1) }));
  trace->Update();
  ASSERT_EQ(testutils::ErrorsOf(trace), "");
  EXPECT_EQ(graphOf(trace)[3], first[3]) << "the graph was rebuilt for new curves";
  // Another surface: another graph.
  trace->SetInputData(0, other);
  trace->Update();
  ASSERT_EQ(testutils::ErrorsOf(trace), "");
  const std::array<double, 4> second = graphOf(trace);
  EXPECT_GT(second[0], 100);
  EXPECT_NE(second[3], first[3]) << "the new surface kept the old surface's graph";
  EXPECT_NE(second[0], first[0]);
}

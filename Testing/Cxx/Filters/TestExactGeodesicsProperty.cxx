// The ExactGeodesics property of Trace Surface Curves: on an open 48-sided prism (developable,
// so the shortest path between two points is the straight line of the unrolled prism), legs
// between near-opposite points are exactly that long when it is on; off, some come out
// longer (the locally shortest path around the wrong side), none shorter.
#include "FilterTestUtils.h"
#include "Support/UnrolledPrism.h"
#include "vtkBoolSurfTraceCurves.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

namespace
{

/// Lengths of the traced legs (one open two-point curve per pair).
std::vector<double> TracedLengths(vtkPolyData* surface, vtkPolyData* curves, bool exact)
{
  vtkNew<vtkBoolSurfTraceCurves> trace;
  trace->SetInputData(0, surface);
  trace->SetInputData(1, curves);
  trace->SetExactGeodesics(exact);
  const std::string errors = testutils::ErrorsOf(trace);
  EXPECT_TRUE(errors.empty()) << errors;
  std::vector<double> lengths;
  vtkDataArray* length = trace->GetOutput()->GetCellData()->GetArray("Length");
  for (vtkIdType i = 0; length && i < length->GetNumberOfTuples(); ++i)
    lengths.push_back(length->GetTuple1(i));
  return lengths;
}

} // namespace

TEST(ExactGeodesicsProperty, PrismNearOppositePointsAreJoinedByTheUnrolledLine)
{
  const int around = 48, along = 16;
  const double radius = 1, height = 3, pi = std::acos(-1.0);
  vtkSmartPointer<vtkPolyData> prism =
    testutils::ToPolyData(boolsurf::MakeOpenCylinder(radius, height, around, along));
  const boolsurf::testing::UnrolledPrism unrolledPrism{ around, radius };
  // A point on facet j at fraction f between its corners, at height z.
  auto onFacet = [&](int j, double f, double z)
  {
    const double a0 = 2 * pi * j / around, a1 = 2 * pi * (j + 1) / around;
    return std::array<double, 3>{ radius * ((1 - f) * std::cos(a0) + f * std::cos(a1)),
      radius * ((1 - f) * std::sin(a0) + f * std::sin(a1)),
      z };
  };
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0.05, 0.95);
  std::vector<testutils::ControlPolygon> legs;
  std::vector<double> unrolled;
  for (int i = 0; i < 200; ++i)
  {
    const int j0 = static_cast<int>(rng() % around);
    const int j1 = (j0 + 23 + static_cast<int>(rng() % 3)) % around;
    testutils::ControlPolygon c;
    c.Closed = false;
    c.Points = { onFacet(j0, unit(rng), height * unit(rng)),
      onFacet(j1, unit(rng), height * unit(rng)) };
    auto vec = [](const std::array<double, 3>& p) { return boolsurf::Vec3{ p[0], p[1], p[2] }; };
    unrolled.push_back(unrolledPrism.ShortestLength(vec(c.Points[0]), vec(c.Points[1])));
    legs.push_back(c);
  }
  vtkSmartPointer<vtkPolyData> curves = testutils::ToCurves(legs);
  const std::vector<double> exact = TracedLengths(prism, curves, true);
  const std::vector<double> local = TracedLengths(prism, curves, false);
  ASSERT_EQ(exact.size(), unrolled.size());
  ASSERT_EQ(local.size(), unrolled.size());
  int longer = 0;
  for (size_t i = 0; i < unrolled.size(); ++i)
  {
    EXPECT_NEAR(exact[i], unrolled[i], 1e-9 * unrolled[i]) << "leg " << i;
    EXPECT_GE(local[i], unrolled[i] * (1 - 1e-9)) << "leg " << i;
    longer += local[i] > unrolled[i] * (1 + 1e-6) ? 1 : 0;
  }
  // The property reaches the tracer: without exact search some legs go the long way round.
  EXPECT_GT(longer, 0);
}

// The one-step filter's and the stage filters' outputs carry their arrays' ranges
// (vtkBoolSurfArrayRanges), so that ParaView's data information reads them without a pass per
// component: every range an array answers must be, bit for bit, the one VTK computes on a copy
// of the array holding none, after the first update and after edits (a stage output keeps
// arrays from one update to the next; a kept array's ranges must still be its values').
#include "FilterTestUtils.h"

#include "vtkBoolSurf.h"
#include "vtkBoolSurfArrangement.h"
#include "vtkBoolSurfArrayRanges.h" // private header of the module
#include "vtkBoolSurfBoolean.h"
#include "vtkBoolSurfLabeling.h"
#include "vtkBoolSurfTraceCurves.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkInformation.h>
#include <vtkIntArray.h>
#include <vtkLongLongArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <string>

namespace
{

/// A closed polygon of `n` points on the unit sphere around the direction `center`.
testutils::ControlPolygon SphereCircle(const std::array<double, 3>& center,
  double radius,
  int n,
  int shape)
{
  testutils::ControlPolygon c;
  c.ShapeId = shape;
  // A tangent direction: the center crossed with the x axis (no center here lies on it).
  std::array<double, 3> u{ 0, center[2], -center[1] };
  const double lu = std::sqrt(u[1] * u[1] + u[2] * u[2]);
  u = { 0, u[1] / lu, u[2] / lu };
  const std::array<double, 3> v{ center[1] * u[2] - center[2] * u[1],
    center[2] * u[0] - center[0] * u[2],
    center[0] * u[1] - center[1] * u[0] };
  for (int k = 0; k < n; ++k)
  {
    const double a = 2 * vtkMath::Pi() * k / n;
    std::array<double, 3> p;
    for (int i = 0; i < 3; ++i)
    {
      p[i] = center[i] + radius * (std::cos(a) * u[i] + std::sin(a) * v[i]);
    }
    const double l = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    c.Points.push_back({ p[0] / l, p[1] / l, p[2] / l });
  }
  return c;
}

bool SameBits(const double a[2], const double b[2])
{
  return std::memcmp(a, b, 2 * sizeof(double)) == 0;
}

/// Every range `array` answers (each component and -1, with and without non-finite values)
/// against those VTK computes on a copy.
void ExpectRangesAsComputed(vtkDataArray* array, const std::string& what)
{
  vtkSmartPointer<vtkDataArray> copy = vtk::TakeSmartPointer(array->NewInstance());
  copy->DeepCopy(array);
  copy->Modified(); // drops whatever ranges the copy took along
  for (int c = -1; c < array->GetNumberOfComponents(); ++c)
  {
    double held[2], computed[2];
    array->GetRange(held, c);
    copy->GetRange(computed, c);
    EXPECT_TRUE(SameBits(held, computed)) << what << " component " << c << ": " << held[0] << " "
                                          << held[1] << " vs " << computed[0] << " " << computed[1];
    array->GetFiniteRange(held, c);
    copy->GetFiniteRange(computed, c);
    EXPECT_TRUE(SameBits(held, computed)) << what << " finite, component " << c;
  }
}

void ExpectAttributeRanges(vtkFieldData* data, const std::string& what)
{
  for (int a = 0; a < data->GetNumberOfArrays(); ++a)
  {
    if (vtkDataArray* array = data->GetArray(a))
    {
      ExpectRangesAsComputed(array, what + " " + array->GetName());
    }
  }
}

void ExpectOutputRanges(vtkAlgorithm* filter, const std::string& name)
{
  for (int port = 0; port < filter->GetNumberOfOutputPorts(); ++port)
  {
    vtkPolyData* output = vtkPolyData::SafeDownCast(filter->GetOutputDataObject(port));
    ASSERT_NE(output, nullptr);
    const std::string what = name + " port " + std::to_string(port);
    if (output->GetPoints())
    {
      ExpectRangesAsComputed(output->GetPoints()->GetData(), what + " points");
    }
    ExpectAttributeRanges(output->GetPointData(), what + " point data");
    ExpectAttributeRanges(output->GetCellData(), what + " cell data");
    ExpectAttributeRanges(output->GetFieldData(), what + " field data");
  }
}

/// Three circles on the sphere, the third centred on `third`.
vtkSmartPointer<vtkPolyData> ThreeCircles(const std::array<double, 3>& third)
{
  testutils::ControlPolygon outside = SphereCircle({ 0, 0, 1 }, 0.5, 16, 0);
  std::reverse(outside.Points.begin(), outside.Points.end());
  return testutils::ToCurves(
    { outside, SphereCircle({ 0.3, 0, 0.95 }, 0.5, 16, 1), SphereCircle(third, 0.4, 12, 2) });
}

} // namespace

TEST(OutputRanges, StageFiltersCarryTheRangesVTKComputesAfterEdits)
{
  auto surface = testutils::ToPolyData(boolsurf::MakeIcosphere(5));
  vtkNew<vtkBoolSurfTraceCurves> trace;
  vtkNew<vtkBoolSurfArrangement> arrange;
  vtkNew<vtkBoolSurfLabeling> label;
  vtkNew<vtkBoolSurfBoolean> boolean;
  trace->SetInputData(0, surface);
  arrange->SetInputData(0, surface);
  arrange->SetInputConnection(1, trace->GetOutputPort());
  label->SetInputConnection(arrange->GetOutputPort(0));
  label->SetPerTriangleLabels(true);
  boolean->SetInputConnection(label->GetOutputPort(0));
  boolean->SetShapeA(-1);
  boolean->SetShapeB(-1);
  // The first update, then the third circle moved twice: the stage outputs keep what the
  // edit left unchanged.
  for (const std::array<double, 3>& third : { std::array<double, 3>{ 0, 0.3, 0.95 },
         std::array<double, 3>{ 0.1, 0.35, 0.93 },
         std::array<double, 3>{ -0.5, 0.2, 0.84 } })
  {
    trace->SetInputData(1, ThreeCircles(third));
    boolean->Update();
    ASSERT_EQ(testutils::ErrorsOf(boolean), "");
    ASSERT_GT(boolean->GetOutput(0)->GetNumberOfCells(), 1000);
    // The filters stored them, not VTK on first use.
    vtkDataArray* cells = arrange->GetOutput(0)->GetCellData()->GetArray("ArrangementCell");
    ASSERT_NE(cells, nullptr);
    ASSERT_TRUE(cells->HasInformation());
    EXPECT_TRUE(cells->GetInformation()->Has(vtkAbstractArray::PER_COMPONENT()));
    ExpectOutputRanges(trace, "Trace Surface Curves");
    ExpectOutputRanges(arrange, "Surface Arrangement");
    ExpectOutputRanges(label, "Label Arrangement Cells");
    ExpectOutputRanges(boolean, "Surface Boolean");
  }
}

TEST(OutputRanges, EveryPortCarriesTheRangesVTKComputes)
{
  // Enough triangles that the region's arrays span several of the ranges' blocks.
  auto surface = testutils::ToPolyData(boolsurf::MakeIcosphere(6));
  // Shape 0 runs clockwise: its inside is the sphere's larger part.
  testutils::ControlPolygon outside = SphereCircle({ 0, 0, 1 }, 0.5, 16, 0);
  std::reverse(outside.Points.begin(), outside.Points.end());
  auto curves = testutils::ToCurves({ outside,
    SphereCircle({ 0.3, 0, 0.95 }, 0.5, 16, 1),
    SphereCircle({ 0, 0.3, 0.95 }, 0.4, 12, 2) });
  vtkNew<vtkBoolSurf> filter;
  filter->SetInputData(0, surface);
  filter->SetInputData(1, curves);
  filter->SetShapeA(-1);
  filter->SetShapeB(-1);
  filter->SetOperation(0);
  filter->SetNumberOfThreads(2);
  filter->Update();
  vtkPolyData* region = filter->GetOutput(0);
  ASSERT_GT(region->GetNumberOfCells(), 40000);
  // The filter stored them (a region's big arrays), not VTK on first use.
  vtkDataArray* cells = region->GetCellData()->GetArray("ArrangementCell");
  ASSERT_NE(cells, nullptr);
  ASSERT_TRUE(cells->HasInformation());
  EXPECT_TRUE(cells->GetInformation()->Has(vtkAbstractArray::PER_COMPONENT()));
  EXPECT_TRUE(region->GetPoints()->GetData()->GetInformation()->Has(vtkDataArray::L2_NORM_RANGE()));
  for (int port = 0; port < 4; ++port)
  {
    vtkPolyData* output = filter->GetOutput(port);
    const std::string what = "port " + std::to_string(port);
    if (output->GetPoints())
    {
      ExpectRangesAsComputed(output->GetPoints()->GetData(), what + " points");
    }
    ExpectAttributeRanges(output->GetPointData(), what + " point data");
    ExpectAttributeRanges(output->GetCellData(), what + " cell data");
    ExpectAttributeRanges(output->GetFieldData(), what + " field data");
  }
}

// The scan itself on arrays no filter writes: one to four components (the scan keeps one, two
// and three components' accumulators in registers, more in vectors), each value type the
// outputs use, several blocks of tuples, ties between 0 and -0 (the first of equal values is
// the range's), values of both signs.
TEST(OutputRanges, ScannedRangesAreVTKsForEveryComponentCount)
{
  std::mt19937 random(60);
  std::uniform_int_distribution<int> value(-40, 40);
  const vtkIdType tuples = 70000; // three blocks of the scan
  const auto fill = [&](vtkDataArray* array, int components, bool zeros)
  {
    array->SetNumberOfComponents(components);
    array->SetNumberOfTuples(tuples);
    for (vtkIdType i = 0; i < tuples * components; ++i)
    {
      const int v = value(random);
      array->SetVariantValue(i, zeros && v % 3 == 0 ? (v % 2 ? -0.0 : 0.0) : v * 0.37);
    }
  };
  for (int components = 1; components <= 4; ++components)
  {
    const std::vector<vtkSmartPointer<vtkDataArray>> arrays{ vtkSmartPointer<vtkDoubleArray>::New(),
      vtkSmartPointer<vtkFloatArray>::New(),
      vtkSmartPointer<vtkIntArray>::New(),
      vtkSmartPointer<vtkLongLongArray>::New(),
      vtkSmartPointer<vtkUnsignedCharArray>::New() };
    for (const vtkSmartPointer<vtkDataArray>& array : arrays)
    {
      fill(
        array, components, array->GetDataType() == VTK_DOUBLE || array->GetDataType() == VTK_FLOAT);
      boolsurf::CacheArrayRanges(array, 2);
      ExpectRangesAsComputed(array,
        std::string(array->GetClassName()) + " of " + std::to_string(components) + " components");
    }
  }
}

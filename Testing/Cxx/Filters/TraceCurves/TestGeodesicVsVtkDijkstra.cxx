// Traced geodesics are never longer than VTK's own shortest edge path
// (vtkDijkstraGraphGeodesicPath) between the same mesh vertices, on surfaces of genus 0 and 1.
#include "FilterTestUtils.h"
#include "vtkBoolSurfTraceCurves.h"

#include <vtkDijkstraGraphGeodesicPath.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkPointData.h>

#include <gtest/gtest.h>

#include <random>

namespace
{
double PolylineLength(vtkPolyData* pd)
{
  double length = 0;
  for (vtkIdType i = 0; i + 1 < pd->GetNumberOfPoints(); ++i)
  {
    double a[3], b[3];
    pd->GetPoint(i, a);
    pd->GetPoint(i + 1, b);
    length += std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
  }
  return length;
}

void CompareWithDijkstra(const boolsurf::MeshData& data, int pairs, std::uint32_t seed)
{
  auto mesh = testutils::ToPolyData(data);
  mesh->BuildLinks();
  vtkNew<vtkDijkstraGraphGeodesicPath> dijkstra;
  dijkstra->SetInputData(mesh);
  dijkstra->StopWhenEndReachedOn();
  std::mt19937 rng(seed);
  std::uniform_int_distribution<vtkIdType> vertex(0, mesh->GetNumberOfPoints() - 1);
  // Each curve is given exactly: a triangle of the vertex and the weights putting it there.
  auto surfacePoint = [&](vtkIdType v, vtkIdType& triangle, double uv[2])
  {
    vtkNew<vtkIdList> cells;
    mesh->GetPointCells(v, cells);
    triangle = cells->GetId(0);
    const vtkIdType* ids;
    vtkIdType n;
    mesh->GetCellPoints(triangle, n, ids);
    uv[0] = ids[1] == v ? 1.0 : 0.0;
    uv[1] = ids[2] == v ? 1.0 : 0.0;
  };
  int longer = 0;
  for (int i = 0; i < pairs; ++i)
  {
    const vtkIdType a = vertex(rng), b = vertex(rng);
    if (a == b)
    {
      continue;
    }
    dijkstra->SetStartVertex(a);
    dijkstra->SetEndVertex(b);
    dijkstra->Update();
    const double edgePath = PolylineLength(dijkstra->GetOutput());

    testutils::ControlPolygon c{ { { 0, 0, 0 }, { 0, 0, 1 } }, 0, false };
    auto curves = testutils::ToCurves({ c });
    vtkNew<vtkIdTypeArray> tri;
    tri->SetName("TriangleId");
    vtkNew<vtkDoubleArray> bary;
    bary->SetName("Barycentric");
    bary->SetNumberOfComponents(2);
    for (vtkIdType v : { a, b })
    {
      vtkIdType t;
      double uv[2];
      surfacePoint(v, t, uv);
      tri->InsertNextValue(t);
      bary->InsertNextTuple(uv);
    }
    curves->GetPointData()->AddArray(tri);
    curves->GetPointData()->AddArray(bary);
    vtkNew<vtkBoolSurfTraceCurves> trace;
    trace->SetInputData(0, mesh);
    trace->SetInputData(1, curves);
    trace->Update();
    const double geodesic = PolylineLength(trace->GetOutput());
    ASSERT_GT(geodesic, 0.0);
    EXPECT_LE(geodesic, edgePath * (1 + 1e-12)) << "vertices " << a << " and " << b;
    longer += geodesic > edgePath * (1 + 1e-12);
  }
  EXPECT_EQ(longer, 0);
}
} // namespace

TEST(GeodesicVsVtkDijkstra, SphereNeverLonger)
{
  CompareWithDijkstra(boolsurf::MakeIcosphere(3), 40, 1);
}

TEST(GeodesicVsVtkDijkstra, TorusNeverLonger)
{
  CompareWithDijkstra(boolsurf::MakeTorus(2.0, 0.7, 40, 20), 60, 2);
}

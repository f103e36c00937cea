// A rank's owned triangles as a parallel reader or RedistributeDataSet gives them, for the MPI
// test programs (Testing/Cxx/Mpi): their own points, cell and point global ids, no ghosts.
#ifndef boolsurf_OwnedTriangles_h
#define boolsurf_OwnedTriangles_h

#include "Mesh/TriangleMesh.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <vector>

namespace boolsurf
{
namespace testing
{

inline vtkSmartPointer<vtkPolyData> OwnedTriangles(const TriangleMesh& mesh,
  const std::vector<int>& owner,
  int rank)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkIdTypeArray> pointIds, cellIds;
  pointIds->SetName("GlobalIds");
  cellIds->SetName("GlobalIds");
  vtkNew<vtkCellArray> polys;
  std::vector<vtkIdType> localOf(mesh.GetNumberOfVertices(), -1);
  for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    if (owner[t] != rank)
    {
      continue;
    }
    vtkIdType corners[3];
    for (int k = 0; k < 3; ++k)
    {
      const int v = mesh.GetTriangle(t)[k];
      if (localOf[v] < 0)
      {
        const Vec3 x = mesh.GetPosition(v);
        localOf[v] = points->InsertNextPoint(x.x, x.y, x.z);
        pointIds->InsertNextValue(v);
      }
      corners[k] = localOf[v];
    }
    polys->InsertNextCell(3, corners);
    cellIds->InsertNextValue(t);
  }
  pd->SetPoints(points);
  pd->SetPolys(polys);
  pd->GetPointData()->SetGlobalIds(pointIds);
  pd->GetCellData()->SetGlobalIds(cellIds);
  return pd;
}

} // namespace testing
} // namespace boolsurf

#endif

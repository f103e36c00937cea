#include "vtkBoolSurfSurfaceAdapter.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTriangleFilter.h>

namespace boolsurf
{
namespace
{

// Number of polygons with other than three points.
vtkIdType CountNonTriangles(vtkCellArray* polys)
{
  vtkIdType count = 0;
  auto it = vtk::TakeSmartPointer(polys->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    count += n != 3 ? 1 : 0;
  }
  return count;
}

} // namespace

//------------------------------------------------------------------------------
void ConvertSurface(vtkPolyData* input, vtkSurfaceInput& out, const SurfaceCheckOptions& options)
{
  out = vtkSurfaceInput();
  out.Triangles = vtkSmartPointer<vtkPolyData>::New();
  if (input)
  {
    const vtkIdType verts = input->GetNumberOfVerts();
    const vtkIdType lines = input->GetNumberOfLines();
    const vtkIdType strips = input->GetNumberOfStrips();
    const vtkIdType nonTriangles = CountNonTriangles(input->GetPolys());
    if (verts + lines > 0)
    {
      out.Warnings.push_back("ignored " + std::to_string(verts) + " vertex cell(s) and " +
        std::to_string(lines) + " line cell(s) of the surface input: only polygons are used");
    }
    if (nonTriangles + strips > 0)
    {
      out.Warnings.push_back("triangulated " + std::to_string(nonTriangles) +
        " non-triangle polygon(s) and " + std::to_string(strips) +
        " triangle strip(s); output cell ids refer to the triangles");
    }
    if (verts + lines + strips + nonTriangles == 0)
    {
      out.Triangles->ShallowCopy(input);
    }
    else
    {
      vtkNew<vtkTriangleFilter> triangulate;
      triangulate->PassVertsOff();
      triangulate->PassLinesOff();
      triangulate->SetInputData(input);
      triangulate->Update();
      out.Triangles->ShallowCopy(triangulate->GetOutput());
    }
  }

  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;
  if (vtkPoints* points = out.Triangles->GetPoints())
  {
    positions.resize(points->GetNumberOfPoints());
    double p[3];
    for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
    {
      points->GetPoint(i, p);
      positions[i] = { p[0], p[1], p[2] };
    }
  }
  vtkCellArray* polys = out.Triangles->GetPolys();
  triangles.reserve(polys->GetNumberOfCells());
  auto it = vtk::TakeSmartPointer(polys->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    // vtkTriangleFilter drops polygons it cannot triangulate, so every cell here has 3 ids.
    triangles.push_back(
      { static_cast<int>(ids[0]), static_cast<int>(ids[1]), static_cast<int>(ids[2]) });
  }
  auto mesh = std::make_shared<TriangleMesh>(std::move(positions), std::move(triangles));
  auto topology = std::make_shared<MeshTopology>(MeshTopology::Compute(*mesh));
  out.Check = CheckSurface(*mesh, *topology, options);
  out.Mesh = mesh;
  out.Topology = topology;
}

} // namespace boolsurf

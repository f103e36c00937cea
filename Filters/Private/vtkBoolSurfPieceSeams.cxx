#include "vtkBoolSurfPieceSeams.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <vector>

namespace boolsurf
{

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> WithoutGhostCells(vtkPolyData* input)
{
  vtkUnsignedCharArray* ghosts = input ? input->GetCellGhostArray() : nullptr;
  if (!ghosts)
  {
    return nullptr;
  }
  bool any = false;
  for (vtkIdType c = 0; c < ghosts->GetNumberOfValues() && !any; ++c)
  {
    any = ghosts->GetValue(c) != 0;
  }
  if (!any)
  {
    return nullptr;
  }
  auto owned = vtkSmartPointer<vtkPolyData>::New();
  owned->ShallowCopy(input);
  owned->RemoveGhostCells();
  return owned;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> WeldPieceSeams(vtkPolyData* triangles, const TriangleMesh& mesh)
{
  // Only points on edges with one triangle (or more than two) can be a piece's copy of a
  // point another piece shares: the comparison costs a pass over the half-edges and a map of
  // the boundary's points, nothing on a closed surface.
  const int nv = mesh.GetNumberOfVertices();
  std::vector<char> border(nv, 0);
  for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    for (int k = 0; mesh.IsUsable(t) && k < 3; ++k)
    {
      if (mesh.GetNeighbor(t, k) < 0)
      {
        border[mesh.GetTriangle(t)[k]] = 1;
        border[mesh.GetTriangle(t)[(k + 1) % 3]] = 1;
      }
    }
  }
  std::map<std::array<double, 3>, int> first;
  std::vector<int> into(nv);
  std::iota(into.begin(), into.end(), 0);
  bool welded = false;
  for (int v = 0; v < nv; ++v)
  {
    if (border[v])
    {
      const Vec3& p = mesh.GetPosition(v);
      const auto found = first.emplace(std::array<double, 3>{ p[0], p[1], p[2] }, v);
      into[v] = found.first->second;
      welded = welded || into[v] != v;
    }
  }
  if (!welded)
  {
    return nullptr;
  }

  // The kept points, in their order, with their point data; then the triangles on them.
  auto out = vtkSmartPointer<vtkPolyData>::New();
  std::vector<vtkIdType> newId(nv, -1);
  vtkNew<vtkPoints> points;
  points->SetDataType(triangles->GetPoints()->GetDataType());
  vtkPointData* pointData = out->GetPointData();
  pointData->CopyAllocate(triangles->GetPointData(), nv);
  for (int v = 0; v < nv; ++v)
  {
    if (into[v] == v)
    {
      newId[v] = points->InsertNextPoint(triangles->GetPoint(v));
      pointData->CopyData(triangles->GetPointData(), v, newId[v]);
    }
  }
  out->SetPoints(points);

  // Global cell ids, when the pieces carry them, give the undistributed surface's order.
  const int nt = mesh.GetNumberOfTriangles();
  std::vector<vtkIdType> order(nt);
  std::iota(order.begin(), order.end(), 0);
  vtkDataArray* globalIds = triangles->GetCellData()->GetGlobalIds();
  if (globalIds && globalIds->GetNumberOfTuples() == nt)
  {
    std::stable_sort(order.begin(),
      order.end(),
      [globalIds](vtkIdType a, vtkIdType b)
      { return globalIds->GetTuple1(a) < globalIds->GetTuple1(b); });
  }
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(nt, 3 * nt);
  vtkCellData* cellData = out->GetCellData();
  cellData->CopyAllocate(triangles->GetCellData(), nt);
  for (vtkIdType t : order)
  {
    const Triangle& tri = mesh.GetTriangle(static_cast<int>(t));
    vtkIdType ids[3];
    for (int k = 0; k < 3; ++k)
    {
      // Unusable triangles keep their (out-of-range or repeated) ids: the check names them.
      const int v = tri[k];
      ids[k] = v >= 0 && v < nv ? newId[into[v]] : v;
    }
    const vtkIdType to = polys->InsertNextCell(3, ids);
    cellData->CopyData(triangles->GetCellData(), t, to);
  }
  out->SetPolys(polys);
  out->GetFieldData()->ShallowCopy(triangles->GetFieldData());
  return out;
}

} // namespace boolsurf

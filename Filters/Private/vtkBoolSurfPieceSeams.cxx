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
namespace
{
/// The piece of each point when the mesh is appended pieces (see WeldPieceSeams), all 0
/// otherwise.
std::vector<int> PointPieces(const TriangleMesh& mesh);
}

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
namespace
{
std::vector<int> PointPieces(const TriangleMesh& mesh)
{
  // Appended pieces are runs of cells on runs of points of their own: a cut after cell c
  // where every point of the cells up to c comes before every point of the cells after it.
  const int nt = mesh.GetNumberOfTriangles();
  const int nv = mesh.GetNumberOfVertices();
  std::vector<int> largestUpTo(nt, -1);
  int largest = -1;
  for (int t = 0; t < nt; ++t)
  {
    for (int k = 0; mesh.IsUsable(t) && k < 3; ++k)
    {
      largest = std::max(largest, mesh.GetTriangle(t)[k]);
    }
    largestUpTo[t] = largest;
  }
  std::vector<int> firstPoints; // the first point of each piece after the first
  int smallest = nv;
  for (int t = nt - 1; t > 0; --t)
  {
    for (int k = 0; mesh.IsUsable(t) && k < 3; ++k)
    {
      smallest = std::min(smallest, mesh.GetTriangle(t)[k]);
    }
    if (largestUpTo[t - 1] < smallest && smallest < nv &&
      (firstPoints.empty() || firstPoints.back() != smallest))
    {
      firstPoints.push_back(smallest);
    }
  }
  std::sort(firstPoints.begin(), firstPoints.end());
  std::vector<int> piece(nv, 0);
  for (int v = 0, p = 0; v < nv; ++v)
  {
    while (p < static_cast<int>(firstPoints.size()) && firstPoints[p] <= v)
    {
      ++p;
    }
    piece[v] = p;
  }
  return piece;
}
} // namespace

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> WeldPieceSeams(vtkPolyData* triangles, const TriangleMesh& mesh)
{
  // Only points on edges with one triangle (or more than two) can be a piece's copy of a
  // point another piece shares: the comparison costs a pass over the half-edges and a map of
  // the boundary's points, nothing on a closed surface.
  const int nv = mesh.GetNumberOfVertices();
  std::vector<char> border(nv, 0);
  bool anyBorder = false;
  for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    for (int k = 0; mesh.IsUsable(t) && k < 3; ++k)
    {
      if (mesh.GetNeighbor(t, k) < 0)
      {
        border[mesh.GetTriangle(t)[k]] = 1;
        border[mesh.GetTriangle(t)[(k + 1) % 3]] = 1;
        anyBorder = true;
      }
    }
  }
  if (!anyBorder)
  {
    return nullptr;
  }
  // Points are welded across pieces only: a mesh of one piece cut along a seam (its points
  // doubled there, as for texture coordinates) keeps its seam.
  const std::vector<int> piece = PointPieces(mesh);
  if (piece.empty() || piece.back() == 0)
  {
    return nullptr;
  }
  std::map<std::array<double, 3>, int> first;
  std::vector<int> into(nv);
  std::iota(into.begin(), into.end(), 0);
  bool welded = false;
  for (int v = 0; v < nv; ++v)
  {
    const Vec3& p = mesh.GetPosition(v);
    if (border[v] && IsFinite(p)) // NaN does not order: such points are never welded
    {
      const auto found = first.emplace(std::array<double, 3>{ p[0], p[1], p[2] }, v);
      if (piece[found.first->second] != piece[v])
      {
        into[v] = found.first->second;
        welded = true;
      }
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
  // Every array follows, global and pedigree ids too (VTK copies those only when told).
  pointData->CopyAllOn();
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
  cellData->CopyAllOn();
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

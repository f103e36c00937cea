#include "vtkBoolSurfCurvesMessage.h"

#include "vtkBoolSurfArrayNames.h"
#include "vtkBoolSurfStageHandoff.h"
#include "vtkBoolSurfSurfaceAdapter.h"

#include "Distributed/PieceWire.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkTypeInt64Array.h>

namespace boolsurf
{
namespace
{
/// The ids of `ids` as ints (n of them); false when there are fewer.
bool ReadIds(vtkDataArray* ids, vtkIdType n, std::vector<int>& out)
{
  if (!ids || ids->GetNumberOfTuples() < n)
  {
    return false;
  }
  out.resize(static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    out[i] = static_cast<int>(ids->GetTuple1(i));
  }
  return true;
}

/// True when `ids` holds each of 0 .. size - 1 once.
bool IsPermutation(const std::vector<int>& ids)
{
  std::vector<char> seen(ids.size(), 0);
  for (int id : ids)
  {
    if (id < 0 || id >= static_cast<int>(ids.size()) || seen[id])
    {
      return false;
    }
    seen[id] = 1;
  }
  return true;
}
} // namespace

//------------------------------------------------------------------------------
bool PackPieceCurvesMessage(const vtkSurfaceInput& surface,
  const std::vector<TracedCurve>& curves,
  std::vector<long long>& out,
  std::string& note)
{
  out.clear();
  vtkPolyData* triangles = surface.Triangles;
  const TriangleMesh& mesh = *surface.Mesh;
  std::vector<int> vertexIds, triangleIds;
  // The mesh's vertices are the triangles' points, its triangles their cells.
  if (!triangles || triangles->GetNumberOfPoints() != mesh.GetNumberOfVertices() ||
    triangles->GetNumberOfCells() != mesh.GetNumberOfTriangles() ||
    !ReadIds(triangles->GetPointData()->GetGlobalIds(), mesh.GetNumberOfVertices(), vertexIds) ||
    !ReadIds(triangles->GetCellData()->GetGlobalIds(), mesh.GetNumberOfTriangles(), triangleIds))
  {
    note = "the surface carries no point and cell GlobalIds: the traced curves cannot be named "
           "on the pieces of a split surface";
    return false;
  }
  if (!IsPermutation(vertexIds) || !IsPermutation(triangleIds))
  {
    note = std::string("the surface's ") + (IsPermutation(vertexIds) ? "cell" : "point") +
      " GlobalIds are not one per " + (IsPermutation(vertexIds) ? "triangle" : "point") +
      ", 0 to n - 1, so they are not the undistributed surface's order: on pieces, Surface "
      "Arrangement breaks ties by them and may refine triangles where curves meet mesh vertices "
      "differently from one rank (Generate Global Ids on the undistributed surface avoids it)";
  }
  PackTracedCurves(curves, mesh, vertexIds, triangleIds, out);
  return true;
}

//------------------------------------------------------------------------------
void AddPieceCurvesField(const std::vector<long long>& message, vtkFieldData* fields)
{
  vtkNew<vtkTypeInt64Array> array;
  array->SetName(names::PieceCurvesMessage);
  array->SetNumberOfTuples(static_cast<vtkIdType>(message.size()));
  for (std::size_t i = 0; i < message.size(); ++i)
  {
    array->SetValue(static_cast<vtkIdType>(i), message[i]);
  }
  fields->AddArray(array);
}

//------------------------------------------------------------------------------
bool ReadPieceCurvesMessage(vtkPolyData* curves, std::vector<long long>& out)
{
  if (!curves)
  {
    return false;
  }
  auto traced =
    FindStageResult<TracedCurvesResult>(curves->GetPointData()->GetArray(names::TriangleId));
  if (traced && !traced->PieceMessage.empty())
  {
    out = traced->PieceMessage;
    return true;
  }
  vtkTypeInt64Array* array = vtkTypeInt64Array::SafeDownCast(
    curves->GetFieldData()->GetAbstractArray(names::PieceCurvesMessage));
  if (!array)
  {
    return false;
  }
  out.assign(array->GetPointer(0), array->GetPointer(0) + array->GetNumberOfTuples());
  return true;
}
}

#include "vtkBoolSurfTracedCurves.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

namespace boolsurf
{

//------------------------------------------------------------------------------
bool ReadTracedCurves(vtkPolyData* curves,
  const TriangleMesh& mesh,
  std::vector<TracedCurve>& out,
  std::vector<std::string>& problems)
{
  out.clear();
  if (!curves)
  {
    problems.push_back("no curves input");
    return false;
  }
  vtkDataArray* triangleIds = curves->GetPointData()->GetArray("TriangleId");
  vtkDataArray* barycentric = curves->GetPointData()->GetArray("Barycentric");
  if (!triangleIds || !barycentric || barycentric->GetNumberOfComponents() != 2)
  {
    problems.push_back("the curves input lacks point data TriangleId (1 component) and "
                       "Barycentric (2 components): connect the output of Trace Surface Curves");
    return false;
  }
  vtkDataArray* shapeIds = curves->GetCellData()->GetArray("ShapeId");
  vtkDataArray* curveIds = curves->GetCellData()->GetArray("CurveId");
  vtkDataArray* closedFlags = curves->GetCellData()->GetArray("Closed");
  const size_t before = problems.size();

  auto readCells = [&](vtkCellArray* cells, vtkIdType firstCellId, bool polygon)
  {
    auto it = vtk::TakeSmartPointer(cells->NewIterator());
    vtkIdType cellId = firstCellId;
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++cellId)
    {
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      TracedCurve curve;
      curve.CurveId =
        curveIds ? static_cast<int>(curveIds->GetComponent(cellId, 0)) : static_cast<int>(cellId);
      curve.ShapeId =
        shapeIds ? static_cast<int>(shapeIds->GetComponent(cellId, 0)) : static_cast<int>(cellId);
      const bool repeats = n >= 2 && ids[0] == ids[n - 1];
      curve.Closed = closedFlags ? closedFlags->GetComponent(cellId, 0) != 0 : (polygon || repeats);
      if (repeats)
      {
        --n; // the closing point is implied by Closed
      }
      if (curve.ShapeId < 0)
      {
        problems.push_back("curve " + std::to_string(curve.CurveId) + ": negative ShapeId " +
          std::to_string(curve.ShapeId));
        continue;
      }
      bool ok = true;
      for (vtkIdType i = 0; i < n; ++i)
      {
        SurfacePoint sp;
        sp.Triangle = static_cast<int>(triangleIds->GetComponent(ids[i], 0));
        sp.U = barycentric->GetComponent(ids[i], 0);
        sp.V = barycentric->GetComponent(ids[i], 1);
        std::string why;
        if (!CheckSurfacePoint(mesh, sp, why))
        {
          problems.push_back("curve " + std::to_string(curve.CurveId) + ", point " +
            std::to_string(ids[i]) + ": " + why);
          ok = false;
          break;
        }
        curve.Points.push_back(Canonicalize(mesh, sp));
      }
      if (ok)
      {
        out.push_back(std::move(curve));
      }
    }
  };
  const vtkIdType firstLine = curves->GetNumberOfVerts();
  readCells(curves->GetLines(), firstLine, false);
  readCells(curves->GetPolys(), firstLine + curves->GetNumberOfLines(), true);
  return problems.size() == before;
}

} // namespace boolsurf

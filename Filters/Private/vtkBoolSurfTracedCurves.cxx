#include "vtkBoolSurfTracedCurves.h"

#include "vtkBoolSurfArrayNames.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

namespace boolsurf
{

//------------------------------------------------------------------------------
void ForEachCurveCell(vtkPolyData* curves,
  const std::function<void(vtkIdType cellId, vtkIdType n, const vtkIdType* ids, bool polygon)>&
    visit)
{
  // vtkPolyData numbers cells vertices first, then lines, polygons, strips.
  vtkIdType cellId = curves->GetNumberOfVerts();
  for (const bool polygon : { false, true })
  {
    vtkCellArray* cells = polygon ? curves->GetPolys() : curves->GetLines();
    auto it = vtk::TakeSmartPointer(cells->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++cellId)
    {
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      visit(cellId, n, ids, polygon);
    }
  }
}

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
  if (curves->GetNumberOfPoints() == 0 && curves->GetNumberOfCells() == 0)
  {
    // What a failed BoolSurf filter leaves: say so rather than ask for a rewiring.
    std::string why = "the curves input is empty: the filter before it (Trace Surface Curves) "
                      "reported an error or has no curves";
    auto* errors = vtkStringArray::SafeDownCast(
      curves->GetFieldData()->GetAbstractArray(boolsurf::names::TraceErrors));
    for (vtkIdType i = 0; errors && i < errors->GetNumberOfValues(); ++i)
    {
      why += (i == 0 ? ":\n    " : "\n    ") + errors->GetValue(i);
    }
    problems.push_back(why);
    return false;
  }
  vtkDataArray* triangleIds = curves->GetPointData()->GetArray(boolsurf::names::TriangleId);
  vtkDataArray* barycentric = curves->GetPointData()->GetArray(boolsurf::names::Barycentric);
  if (!triangleIds || !barycentric || barycentric->GetNumberOfComponents() != 2)
  {
    problems.push_back("the curves input lacks point data TriangleId (1 component) and "
                       "Barycentric (2 components): connect the output of Trace Surface Curves");
    return false;
  }
  vtkDataArray* shapeIds = curves->GetCellData()->GetArray(boolsurf::names::ShapeId);
  vtkDataArray* curveIds = curves->GetCellData()->GetArray(boolsurf::names::CurveId);
  vtkDataArray* closedFlags = curves->GetCellData()->GetArray(boolsurf::names::Closed);
  const size_t before = problems.size();

  ForEachCurveCell(curves,
    [&](vtkIdType cellId, vtkIdType n, const vtkIdType* ids, bool polygon)
    {
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
        return;
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
        curve.Points.push_back(LocateSurfacePoint(mesh, sp));
      }
      if (ok)
      {
        out.push_back(std::move(curve));
      }
    });
  return problems.size() == before;
}

} // namespace boolsurf

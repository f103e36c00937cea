#include "vtkBoolSurfBSCStage.h"

#include "vtkBoolSurfArrayNames.h"

#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <cmath>

namespace boolsurf
{

//------------------------------------------------------------------------------
bool ReadSampleQueries(vtkPolyData* samples,
  const TriangleMesh* mesh,
  std::vector<SampleQuery>& queries,
  std::string& error)
{
  queries.clear();
  if (!samples || samples->GetNumberOfPoints() == 0)
  {
    return true; // no samples: an empty selection
  }
  vtkDataArray* direction = samples->GetPointData()->GetArray(boolsurf::names::Direction);
  if (!direction || direction->GetNumberOfComponents() != 3)
  {
    error = "the samples lack point data 'Direction' (3 components: the side each sample "
            "wants inside)";
    return false;
  }
  vtkDataArray* tid = samples->GetPointData()->GetArray(boolsurf::names::TriangleId);
  vtkDataArray* uv = samples->GetPointData()->GetArray(boolsurf::names::Barycentric);
  const bool exact = mesh && tid && uv && uv->GetNumberOfComponents() == 2;
  queries.resize(samples->GetNumberOfPoints());
  for (vtkIdType k = 0; k < samples->GetNumberOfPoints(); ++k)
  {
    double x[3], d[3];
    samples->GetPoint(k, x);
    direction->GetTuple(k, d);
    queries[k].Position = { x[0], x[1], x[2] };
    queries[k].Direction = { d[0], d[1], d[2] };
    if (exact)
    {
      const double t = tid->GetComponent(k, 0);
      const double u = uv->GetComponent(k, 0), v = uv->GetComponent(k, 1);
      if (!(t >= 0 && t < mesh->GetNumberOfTriangles()) || !std::isfinite(u) || !std::isfinite(v) ||
        !mesh->IsUsable(static_cast<int>(t)))
      {
        error = "sample " + std::to_string(k) + ": TriangleId " + std::to_string(t) +
          " / Barycentric is not a point of the surface";
        return false;
      }
      queries[k].Position = mesh->Evaluate(static_cast<int>(t), u, v);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void AddSampleFields(const std::vector<PatchSnap>& snaps,
  const BscResult& result,
  vtkPolyData* output)
{
  vtkFieldData* fd = output->GetFieldData();
  vtkNew<vtkIntArray> patch, onBoundary, dropped, cuts;
  vtkNew<vtkDoubleArray> distance, length;
  patch->SetName(boolsurf::names::SamplePatch);
  onBoundary->SetName(boolsurf::names::SampleOnBoundary);
  dropped->SetName(boolsurf::names::DroppedSamples);
  distance->SetName(boolsurf::names::SampleDistance);
  length->SetName(boolsurf::names::BoundaryLength);
  cuts->SetName(boolsurf::names::BSCCuts);
  for (std::size_t k = 0; k < snaps.size(); ++k)
  {
    patch->InsertNextValue(snaps[k].Patch);
    distance->InsertNextValue(snaps[k].Distance);
    const bool kept = k < result.SampleOnBoundary.size() && result.SampleOnBoundary[k];
    onBoundary->InsertNextValue(kept ? 1 : 0);
    if (!kept)
    {
      dropped->InsertNextValue(static_cast<int>(k));
    }
  }
  length->InsertNextValue(result.BoundaryLength);
  cuts->InsertNextValue(result.Cuts);
  vtkNew<vtkStringArray> selection;
  selection->SetName(boolsurf::names::Selection);
  selection->InsertNextValue("BSC");
  for (vtkAbstractArray* a : std::initializer_list<vtkAbstractArray*>{
         patch, distance, onBoundary, dropped, length, cuts, selection })
  {
    fd->AddArray(a);
  }
}

} // namespace boolsurf

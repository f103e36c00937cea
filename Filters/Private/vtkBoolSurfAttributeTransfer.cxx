#include "vtkBoolSurfAttributeTransfer.h"

#include "vtkBoolSurfArrayNames.h"

#include <vtkCellData.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <cstring>

namespace boolsurf
{
namespace
{
// Arrays BoolSurf computes itself: an input carrying them (e.g. the output of an earlier run)
// must not shadow the new values. The labeling's per-triangle arrays (Labels, ShapeLabel) are
// among them: a region's labels are the field data CellLabels, whether the labeled surface came
// handed over (its Core result has no such arrays) or from a file (its cell data has them).
bool IsBoolSurfArray(const char* name)
{
  static const char* const names[] = { boolsurf::names::TriangleId,
    boolsurf::names::Barycentric,
    boolsurf::names::ArrangementCell,
    boolsurf::names::SourceTriangle,
    boolsurf::names::Region,
    boolsurf::names::WindingNumber,
    boolsurf::names::Labels,
    boolsurf::names::ShapeLabel,
    boolsurf::names::ComponentId,
    boolsurf::names::BoundaryLoopId,
    "vtkOriginalCellIds",
    "vtkOriginalPointIds",
    boolsurf::names::Normals };
  if (!name)
  {
    return false;
  }
  for (const char* n : names)
  {
    if (std::strcmp(n, name) == 0)
    {
      return true;
    }
  }
  return false;
}
} // namespace

//------------------------------------------------------------------------------
void TransferSurfaceAttributes(vtkPolyData* source,
  const TriangleMesh& mesh,
  vtkIdType numberOfPoints,
  const std::function<SurfacePoint(vtkIdType)>& pointSurface,
  const std::vector<int>& sourceTriangle,
  vtkPolyData* target)
{
  // Work on shallow copies so the input's copy flags stay untouched; drop the arrays BoolSurf
  // computes itself, and normals (interpolated normals are wrong on refined triangles).
  vtkNew<vtkPointData> inPD;
  inPD->ShallowCopy(source->GetPointData());
  vtkNew<vtkCellData> inCD;
  inCD->ShallowCopy(source->GetCellData());
  for (vtkDataSetAttributes* attributes :
    std::initializer_list<vtkDataSetAttributes*>{ inPD, inCD })
  {
    for (int i = attributes->GetNumberOfArrays() - 1; i >= 0; --i)
    {
      if (IsBoolSurfArray(attributes->GetArrayName(i)))
      {
        attributes->RemoveArray(i);
      }
    }
  }
  inPD->CopyNormalsOff();
  if (inPD->GetNumberOfArrays() == 0 && inCD->GetNumberOfArrays() == 0)
  {
    return; // nothing to carry: skip a per-point and per-triangle loop over the whole mesh
  }
  vtkPointData* outPD = target->GetPointData();
  vtkCellData* outCD = target->GetCellData();
  const vtkIdType np = numberOfPoints;
  const vtkIdType nc = static_cast<vtkIdType>(sourceTriangle.size());
  outPD->InterpolateAllocate(inPD, np);
  outCD->CopyAllocate(inCD, nc);
  vtkNew<vtkIdList> ids;
  ids->SetNumberOfIds(3);
  double weights[3];
  for (vtkIdType p = 0; p < np; ++p)
  {
    const SurfacePoint sp = pointSurface(p);
    const Triangle& tri = mesh.GetTriangle(sp.Triangle);
    for (int k = 0; k < 3; ++k)
    {
      ids->SetId(k, tri[k]);
    }
    weights[0] = 1.0 - sp.U - sp.V;
    weights[1] = sp.U;
    weights[2] = sp.V;
    outPD->InterpolatePoint(inPD, p, ids, weights);
  }
  for (vtkIdType c = 0; c < nc; ++c)
  {
    outCD->CopyData(inCD, sourceTriangle[c], c);
  }
}

} // namespace boolsurf

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
// Shallow copies of the source's point and cell data without the arrays BoolSurf computes
// itself and without normals (interpolated normals are wrong on refined triangles), so the
// input's copy flags stay untouched. False when nothing is left to carry.
bool CarriedArrays(vtkPolyData* source, vtkPointData* inPD, vtkCellData* inCD)
{
  inPD->ShallowCopy(source->GetPointData());
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
  return inPD->GetNumberOfArrays() > 0 || inCD->GetNumberOfArrays() > 0;
}

// Points [first, last) of outPD, interpolated at their surface points.
void InterpolatePoints(vtkPointData* inPD,
  vtkPointData* outPD,
  const TriangleMesh& mesh,
  vtkIdType first,
  vtkIdType last,
  const std::function<SurfacePoint(vtkIdType)>& pointSurface)
{
  vtkNew<vtkIdList> ids;
  ids->SetNumberOfIds(3);
  double weights[3];
  for (vtkIdType p = first; p < last; ++p)
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
}

// Cells [first, last) of outCD, copied from their source triangles.
void CopyCells(vtkCellData* inCD,
  vtkCellData* outCD,
  vtkIdType first,
  vtkIdType last,
  const std::vector<int>& sourceTriangle)
{
  for (vtkIdType c = first; c < last; ++c)
  {
    outCD->CopyData(inCD, sourceTriangle[c], c);
  }
}

// The arrays of `from` added to `to`, with the attributes they are in `from`.
void AddArraysOf(vtkDataSetAttributes* from, vtkDataSetAttributes* to)
{
  for (int i = 0; i < from->GetNumberOfArrays(); ++i)
  {
    to->AddArray(from->GetAbstractArray(i));
  }
  for (int t = 0; t < vtkDataSetAttributes::NUM_ATTRIBUTES; ++t)
  {
    if (vtkAbstractArray* a = from->GetAbstractAttribute(t))
    {
      to->SetActiveAttribute(a->GetName(), t);
    }
  }
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
  vtkNew<vtkPointData> inPD;
  vtkNew<vtkCellData> inCD;
  if (!CarriedArrays(source, inPD, inCD))
  {
    return; // nothing to carry: skip a per-point and per-triangle loop over the whole mesh
  }
  vtkPointData* outPD = target->GetPointData();
  vtkCellData* outCD = target->GetCellData();
  const vtkIdType np = numberOfPoints;
  const vtkIdType nc = static_cast<vtkIdType>(sourceTriangle.size());
  outPD->InterpolateAllocate(inPD, np);
  outCD->CopyAllocate(inCD, nc);
  InterpolatePoints(inPD, outPD, mesh, 0, np, pointSurface);
  CopyCells(inCD, outCD, 0, nc, sourceTriangle);
}

//------------------------------------------------------------------------------
void UpdateSurfaceAttributes(vtkPolyData* source,
  const TriangleMesh& mesh,
  vtkIdType numberOfPoints,
  vtkIdType meshVertices,
  vtkIdType meshTriangles,
  const std::function<SurfacePoint(vtkIdType)>& pointSurface,
  const std::vector<int>& sourceTriangle,
  CarriedAttributes& kept,
  vtkPolyData* target)
{
  vtkNew<vtkPointData> inPD;
  vtkNew<vtkCellData> inCD;
  if (!CarriedArrays(source, inPD, inCD))
  {
    kept = CarriedAttributes();
    return;
  }
  const vtkIdType np = numberOfPoints;
  const vtkIdType nc = static_cast<vtkIdType>(sourceTriangle.size());
  std::vector<vtkAbstractArray*> inputs;
  std::vector<vtkMTimeType> times;
  for (vtkDataSetAttributes* in : std::initializer_list<vtkDataSetAttributes*>{ inPD, inCD })
  {
    for (int i = 0; i < in->GetNumberOfArrays(); ++i)
    {
      inputs.push_back(in->GetAbstractArray(i));
      times.push_back(inputs.back()->GetMTime());
    }
  }
  // The kept values hold for the first vertices and triangles when they were carried from the
  // same arrays, unchanged since, on the same mesh. Past them the writes below set each array's
  // end, so at least one point and one triangle must be past them.
  bool inPlace = kept.MeshSerial != 0 && kept.MeshSerial == mesh.GetSerial() && kept.Points &&
    kept.Cells && kept.Inputs.size() == inputs.size() && meshVertices < np && meshTriangles < nc &&
    meshTriangles > 0;
  for (std::size_t k = 0; inPlace && k < inputs.size(); ++k)
  {
    inPlace = kept.Inputs[k].GetPointer() == inputs[k] && kept.InputTimes[k] == times[k];
  }
  // Copy on write: arrays an output handed out still holds keep their values.
  const auto owned = [](vtkDataSetAttributes* attributes, vtkIdType rows)
  {
    for (int i = 0; i < attributes->GetNumberOfArrays(); ++i)
    {
      vtkAbstractArray* a = attributes->GetAbstractArray(i);
      if (a->GetReferenceCount() != 1 || a->GetNumberOfTuples() < rows)
      {
        return false;
      }
    }
    return true;
  };
  inPlace = inPlace && owned(kept.Points, meshVertices) && owned(kept.Cells, meshTriangles);
  kept.MeshSerial = 0; // until consistent again
  if (!inPlace)
  {
    kept.Points = vtkSmartPointer<vtkPointData>::New();
    kept.Cells = vtkSmartPointer<vtkCellData>::New();
    kept.Points->InterpolateAllocate(inPD, np);
    kept.Cells->CopyAllocate(inCD, nc);
    InterpolatePoints(inPD, kept.Points, mesh, 0, np, pointSurface);
    CopyCells(inCD, kept.Cells, 0, nc, sourceTriangle);
  }
  else
  {
    // Reset keeps the values and moves each array's end back; writing the points and cells
    // past the mesh's moves it to their number again (growing the memory only when needed).
    for (vtkDataSetAttributes* attributes :
      std::initializer_list<vtkDataSetAttributes*>{ kept.Points, kept.Cells })
    {
      for (int i = 0; i < attributes->GetNumberOfArrays(); ++i)
      {
        attributes->GetAbstractArray(i)->Reset();
      }
    }
    InterpolatePoints(inPD, kept.Points, mesh, meshVertices, np, pointSurface);
    CopyCells(inCD, kept.Cells, meshTriangles, nc, sourceTriangle);
    for (vtkDataSetAttributes* attributes :
      std::initializer_list<vtkDataSetAttributes*>{ kept.Points, kept.Cells })
    {
      for (int i = 0; i < attributes->GetNumberOfArrays(); ++i)
      {
        attributes->GetAbstractArray(i)->Modified(); // cached ranges are stale
      }
    }
  }
  if (meshTriangles > 0)
  {
    kept.Inputs.assign(inputs.begin(), inputs.end());
    kept.InputTimes = times;
    kept.MeshSerial = mesh.GetSerial();
  }
  AddArraysOf(kept.Points, target->GetPointData());
  AddArraysOf(kept.Cells, target->GetCellData());
}

} // namespace boolsurf

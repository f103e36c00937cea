#include "vtkBoolSurfBSCStage.h"

#include "vtkBoolSurfArrayNames.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

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
double SnapDistance(vtkPolyData* surface, double relativeTolerance)
{
  return relativeTolerance * surface->GetLength();
}

//------------------------------------------------------------------------------
bool SelectSampledCells(vtkPolyData* refined,
  const ArrangementFields& fields,
  const std::vector<SampleQuery>& queries,
  double tolerance,
  int maxSearchStates,
  std::vector<PatchSnap>& snaps,
  BscResult& result,
  std::string& error,
  const std::function<bool()>& abort)
{
  // The patch points only, in a compact array: the cost is the curves', not the surface's.
  const int np = static_cast<int>(fields.Patches.size());
  std::vector<Vec3> positions;
  std::vector<int> globalOf; // compact index -> refined point id
  std::vector<std::vector<int>> local(np);
  std::vector<const std::vector<int>*> points(np);
  const vtkIdType numberOfPoints = refined->GetNumberOfPoints();
  BscInput input;
  input.NumberOfCells = fields.NumberOfCells;
  input.MaxSearchStates = maxSearchStates;
  input.Abort = abort;
  input.Patches.resize(np);
  std::map<std::pair<int, int>, int> curveIndex; // (shape, curve id) -> dense curve
  for (int i = 0; i < np; ++i)
  {
    const BoundaryPatch& p = fields.Patches[i];
    BscPatch& b = input.Patches[i];
    for (int id : p.Points)
    {
      if (id < 0 || id >= numberOfPoints)
      {
        error = "patch " + std::to_string(i) + " names point " + std::to_string(id) +
          " of a surface of " + std::to_string(numberOfPoints) + " points";
        return false;
      }
      double x[3];
      refined->GetPoint(id, x);
      local[i].push_back(static_cast<int>(positions.size()));
      positions.push_back({ x[0], x[1], x[2] });
      globalOf.push_back(id);
      if (local[i].size() > 1)
      {
        b.Length += Distance(positions[positions.size() - 2], positions.back());
      }
    }
    points[i] = &local[i];
    // Open curves clip, they bound nothing (as BscPatchesOf says for a Core arrangement).
    const bool closed = i >= static_cast<int>(fields.PatchClosed.size()) || fields.PatchClosed[i];
    b.LeftCell = closed ? p.LeftCell : -1;
    b.RightCell = closed ? p.RightCell : -1;
    const int shape = i < static_cast<int>(fields.PatchShape.size()) ? fields.PatchShape[i] : 0;
    const int curve = i < static_cast<int>(fields.PatchCurve.size()) ? fields.PatchCurve[i] : i;
    b.Curve = curveIndex.emplace(std::make_pair(shape, curve), static_cast<int>(curveIndex.size()))
                .first->second;
    if (!p.Points.empty())
    {
      b.FirstPoint = p.Points.front();
      b.LastPoint = p.Points.back();
    }
  }
  // The surface normal at a patch point is its source triangle's, as for a Core arrangement:
  // point data TriangleId names the source triangle, cell data SourceTriangle its first refined
  // triangle.
  vtkDataArray* pointTriangle = refined->GetPointData()->GetArray(boolsurf::names::TriangleId);
  vtkDataArray* source = refined->GetCellData()->GetArray(boolsurf::names::SourceTriangle);
  if (!pointTriangle || !source || source->GetNumberOfTuples() != refined->GetNumberOfCells() ||
    refined->GetNumberOfCells() != refined->GetNumberOfPolys())
  {
    error = "the input lacks point data 'TriangleId' or cell data 'SourceTriangle' on every "
            "triangle (the surface normals at the samples are read from them): connect the "
            "first output of Surface Arrangement";
    return false;
  }
  std::vector<vtkIdType> firstRefined; // source triangle -> its first refined triangle
  auto normalOf = [&](int compact)
  {
    if (firstRefined.empty())
    {
      vtkIdType largest = -1;
      for (vtkIdType c = 0; c < source->GetNumberOfTuples(); ++c)
      {
        largest = std::max(largest, static_cast<vtkIdType>(source->GetComponent(c, 0)));
      }
      firstRefined.assign(largest + 1, -1);
      for (vtkIdType c = source->GetNumberOfTuples() - 1; c >= 0; --c)
      {
        const auto t = static_cast<vtkIdType>(source->GetComponent(c, 0));
        if (t >= 0)
        {
          firstRefined[t] = c;
        }
      }
    }
    const auto t = static_cast<vtkIdType>(pointTriangle->GetComponent(globalOf[compact], 0));
    if (t < 0 || t >= static_cast<vtkIdType>(firstRefined.size()) || firstRefined[t] < 0)
    {
      return Vec3();
    }
    vtkIdType n;
    const vtkIdType* ids;
    refined->GetCellPoints(firstRefined[t], n, ids);
    Vec3 corner[3];
    for (int k = 0; k < 3; ++k)
    {
      double x[3];
      refined->GetPoint(ids[k], x);
      corner[k] = { x[0], x[1], x[2] };
    }
    return UnitTriangleNormal(corner[0], corner[1], corner[2]);
  };
  return SelectBySamples([&](int p) { return positions[p]; },
    points,
    normalOf,
    queries,
    tolerance,
    input,
    snaps,
    result,
    error);
}

//------------------------------------------------------------------------------
void AddSampleFields(const std::vector<PatchSnap>& snaps,
  const BscResult& result,
  vtkPolyData* output)
{
  vtkFieldData* fd = output->GetFieldData();
  vtkNew<vtkIntArray> patch, onBoundary, dropped, cuts;
  vtkNew<vtkDoubleArray> distance, length;
  patch->SetName("SamplePatch");
  onBoundary->SetName("SampleOnBoundary");
  dropped->SetName("DroppedSamples");
  distance->SetName("SampleDistance");
  length->SetName("BoundaryLength");
  cuts->SetName("BSCCuts");
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
  selection->SetName("Selection");
  selection->InsertNextValue("BSC");
  for (vtkAbstractArray* a : std::initializer_list<vtkAbstractArray*>{
         patch, distance, onBoundary, dropped, length, cuts, selection })
  {
    fd->AddArray(a);
  }
}

} // namespace boolsurf

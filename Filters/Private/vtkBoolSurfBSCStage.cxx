#include "vtkBoolSurfBSCStage.h"

#include "vtkBoolSurfArrayNames.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

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
    b.LeftCell = p.LeftCell;
    b.RightCell = p.RightCell;
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
  const PatchSnapper snapper(positions, points);
  if (!SnapSamples(snapper, queries, tolerance, snaps, error))
  {
    return false;
  }
  // Normals at the snapped segments' ends: one pass over the triangles' corners.
  std::vector<char> wanted(numberOfPoints, 0);
  std::map<int, Vec3> normals;
  for (const PatchSnap& s : snaps)
  {
    for (int k : { s.Segment, s.Segment + 1 })
    {
      wanted[fields.Patches[s.Patch].Points[k]] = 1;
      normals[fields.Patches[s.Patch].Points[k]] = Vec3();
    }
  }
  if (!snaps.empty())
  {
    vtkCellArray* polys = refined->GetPolys();
    vtkIdType n;
    const vtkIdType* ids;
    for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
    {
      if (n != 3 || (!wanted[ids[0]] && !wanted[ids[1]] && !wanted[ids[2]]))
      {
        continue;
      }
      double a[3], b[3], c[3];
      refined->GetPoint(ids[0], a);
      refined->GetPoint(ids[1], b);
      refined->GetPoint(ids[2], c);
      const Vec3 pa{ a[0], a[1], a[2] }, pb{ b[0], b[1], b[2] }, pc{ c[0], c[1], c[2] };
      const Vec3 normal = Cross(pb - pa, pc - pa);
      for (int k = 0; k < 3; ++k)
      {
        if (wanted[ids[k]])
        {
          Vec3& m = normals[static_cast<int>(ids[k])];
          m = m + normal;
        }
      }
    }
  }
  // OrientSamples reads compact point indices: map them back to refined point ids.
  auto normalOf = [&](int compact) { return normals[globalOf[compact]]; };
  if (!OrientSamples(positions, points, queries, snaps, normalOf, input.Samples, error))
  {
    return false;
  }
  return SelectBoundarySampledCells(input, result, error);
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

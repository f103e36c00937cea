#include "vtkBoolSurfArrangementRebuild.h"

#include "vtkBoolSurfArrayNames.h"

#include "Arrangement/Arrangement.h"
#include "Arrangement/RefinedSurfaceArrays.h"
#include "Labeling/ArrangementLabelingInput.h"
#include "Labeling/CellLabeling.h"
#include "vtkBoolSurfStageHandoff.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTypeInt64Array.h>

#include <array>

namespace boolsurf
{
namespace
{

template <class T>
std::vector<T> ReadTuples(vtkFieldData* fd, const char* name, int comps)
{
  std::vector<T> v;
  vtkDataArray* a = fd->GetArray(name);
  if (!a || a->GetNumberOfComponents() != comps)
  {
    return v;
  }
  v.resize(static_cast<std::size_t>(a->GetNumberOfTuples()) * comps);
  auto* wide = vtkArrayDownCast<vtkTypeInt64Array>(a);
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    for (int k = 0; k < comps; ++k)
    {
      v[i * comps + k] = wide ? static_cast<T>(wide->GetTypedComponent(i, k))
                              : static_cast<T>(a->GetComponent(i, k));
    }
  }
  return v;
}

// Offsets 0 = o[0] <= o[1] <= ... <= o[n] = size, as counted items.
bool ValidOffsets(const std::vector<int>& offsets, std::size_t items, std::size_t count)
{
  if (offsets.size() != count + 1 || offsets.front() != 0 ||
    offsets.back() != static_cast<int>(items))
  {
    return false;
  }
  for (std::size_t i = 0; i < count; ++i)
  {
    if (offsets[i] > offsets[i + 1])
    {
      return false;
    }
  }
  return true;
}

// The mesh the arrangement was computed on: the refined surface's first points, the mesh
// triangles it keeps whole and the recorded corners of the others, with the point and cell
// arrays the refined surface carries (the input surface's own, as Surface Arrangement passed
// them on: exact at the mesh's vertices and copied from the source triangles).
bool RebuildMesh(vtkPolyData* refined,
  int vertices,
  int triangles,
  const std::vector<int>& recorded,
  vtkDataArray* sourceTriangle,
  vtkPolyData* mesh,
  std::string& error)
{
  if (vertices < 0 || vertices > refined->GetNumberOfPoints() || triangles < 0)
  {
    error = "field data ArrangedMeshSize does not fit the refined surface's points";
    return false;
  }
  std::vector<std::array<vtkIdType, 3>> corners(triangles, { -1, -1, -1 });
  std::vector<vtkIdType> firstPiece(triangles, -1);
  for (std::size_t i = 0; i + 3 < recorded.size(); i += 4)
  {
    if (recorded[i] < 0 || recorded[i] >= triangles)
    {
      error = "field data ArrangedMeshCorners names a triangle out of range";
      return false;
    }
    corners[recorded[i]] = { recorded[i + 1], recorded[i + 2], recorded[i + 3] };
  }
  const vtkIdType nr = refined->GetNumberOfCells();
  vtkCellArray* polys = refined->GetPolys();
  if (!polys || refined->GetNumberOfPolys() != nr || sourceTriangle->GetNumberOfTuples() != nr)
  {
    error = "the refined surface must hold only triangles, each with its SourceTriangle";
    return false;
  }
  vtkNew<vtkIdList> pts;
  for (vtkIdType r = 0; r < nr; ++r)
  {
    const auto s = static_cast<vtkIdType>(sourceTriangle->GetComponent(r, 0));
    if (s < 0 || s >= triangles)
    {
      continue;
    }
    if (firstPiece[s] < 0)
    {
      firstPiece[s] = r;
    }
    if (corners[s][0] < 0)
    {
      polys->GetCellAtId(r, pts);
      if (pts->GetNumberOfIds() != 3)
      {
        error = "the refined surface must hold only triangles";
        return false;
      }
      corners[s] = { pts->GetId(0), pts->GetId(1), pts->GetId(2) };
    }
  }
  vtkNew<vtkCellArray> meshPolys;
  for (const auto& c : corners)
  {
    if (c[0] < 0 || c[0] >= vertices || c[1] >= vertices || c[2] >= vertices)
    {
      error = "the refined surface does not give every mesh triangle's corners";
      return false;
    }
    meshPolys->InsertNextCell(3, c.data());
  }
  vtkNew<vtkPoints> points;
  points->SetDataType(refined->GetPoints()->GetDataType());
  points->SetNumberOfPoints(vertices);
  for (vtkIdType p = 0; p < vertices; ++p)
  {
    points->SetPoint(p, refined->GetPoint(p));
  }
  mesh->SetPoints(points);
  mesh->SetPolys(meshPolys);
  vtkNew<vtkIdList> firstPoints, firstPieces;
  firstPoints->SetNumberOfIds(vertices);
  for (vtkIdType p = 0; p < vertices; ++p)
  {
    firstPoints->SetId(p, p);
  }
  firstPieces->SetNumberOfIds(triangles);
  for (vtkIdType t = 0; t < triangles; ++t)
  {
    // An unusable triangle has no piece: its arrays come from triangle 0's (never read).
    firstPieces->SetId(t, firstPiece[t] < 0 ? 0 : firstPiece[t]);
  }
  mesh->GetPointData()->CopyAllocate(refined->GetPointData(), vertices);
  mesh->GetPointData()->CopyData(refined->GetPointData(), firstPoints, firstPoints);
  if (nr > 0)
  {
    vtkNew<vtkIdList> destination;
    destination->SetNumberOfIds(triangles);
    for (vtkIdType t = 0; t < triangles; ++t)
    {
      destination->SetId(t, t);
    }
    mesh->GetCellData()->CopyAllocate(refined->GetCellData(), triangles);
    mesh->GetCellData()->CopyData(refined->GetCellData(), firstPieces, destination);
  }
  return true;
}

bool ReadCurves(vtkFieldData* fd, std::vector<TracedCurve>& curves, std::string& error)
{
  const auto offsets = ReadTuples<int>(fd, names::ArrangedCurveOffsets, 1);
  const auto info = ReadTuples<int>(fd, names::ArrangedCurveInfo, 3);
  const auto ids = ReadTuples<int>(fd, names::ArrangedCurvePointIds, 2);
  const auto weights = ReadTuples<double>(fd, names::ArrangedCurvePointWeights, 3);
  const std::size_t nc = info.size() / 3;
  if (nc == 0 && offsets.empty() && ids.empty())
  {
    curves.clear();
    return true;
  }
  if (!ValidOffsets(offsets, ids.size() / 2, nc) || weights.size() / 3 != ids.size() / 2)
  {
    error = "field data ArrangedCurveOffsets, ArrangedCurveInfo, ArrangedCurvePointIds and "
            "ArrangedCurvePointWeights disagree in size";
    return false;
  }
  curves.assign(nc, TracedCurve());
  for (std::size_t c = 0; c < nc; ++c)
  {
    TracedCurve& curve = curves[c];
    curve.ShapeId = info[3 * c];
    curve.CurveId = info[3 * c + 1];
    curve.Closed = info[3 * c + 2] != 0;
    for (int i = offsets[c]; i < offsets[c + 1]; ++i)
    {
      CanonicalPoint p;
      p.Location = static_cast<PointLocation>(ids[2 * i]);
      p.Id = ids[2 * i + 1];
      p.U = weights[3 * i];
      p.V = weights[3 * i + 1];
      p.T = weights[3 * i + 2];
      curve.Points.push_back(p);
    }
  }
  return true;
}

bool ReadSources(vtkFieldData* fd, std::vector<CurveSource>& sources, std::string& error)
{
  const auto info = ReadTuples<long long>(fd, names::ArrangedSourceInfo, 5);
  const auto controlOffsets = ReadTuples<int>(fd, names::ArrangedSourceControlOffsets, 1);
  const auto controls = ReadTuples<double>(fd, names::ArrangedSourceControls, 3);
  const auto parameterOffsets = ReadTuples<int>(fd, names::ArrangedSourceParameterOffsets, 1);
  const auto parameters = ReadTuples<double>(fd, names::ArrangedSourceParameters, 1);
  const std::size_t ns = info.size() / 5;
  sources.clear();
  if (ns == 0)
  {
    return true; // the curves came without control points
  }
  if (!ValidOffsets(controlOffsets, controls.size() / 3, ns) ||
    !ValidOffsets(parameterOffsets, parameters.size(), ns))
  {
    error = "field data ArrangedSourceInfo, ArrangedSourceControlOffsets, "
            "ArrangedSourceControls, ArrangedSourceParameterOffsets and "
            "ArrangedSourceParameters disagree in size";
    return false;
  }
  sources.resize(ns);
  for (std::size_t c = 0; c < ns; ++c)
  {
    CurveSource& s = sources[c];
    s.Type = static_cast<CurveType>(info[5 * c]);
    s.Closed = info[5 * c + 1] != 0;
    s.ShapeId = static_cast<int>(info[5 * c + 2]);
    s.CurveId = static_cast<int>(info[5 * c + 3]);
    s.InputCurveId = info[5 * c + 4];
    for (int i = controlOffsets[c]; i < controlOffsets[c + 1]; ++i)
    {
      s.Points.push_back(SurfacePoint{
        static_cast<int>(controls[3 * i]), controls[3 * i + 1], controls[3 * i + 2] });
    }
    s.Parameter.assign(
      parameters.begin() + parameterOffsets[c], parameters.begin() + parameterOffsets[c + 1]);
  }
  return true;
}

// The refined triangles and cells of `arr` against those of `refined`, in the order Surface
// Arrangement writes them (holes left out).
bool SameRefinedSurface(vtkPolyData* refined,
  const TriangleMesh& mesh,
  const Arrangement& arr,
  vtkDataArray* cellOf,
  std::string& error)
{
  const RefinedSurfaceArrays whole = RefinedSurfaceArrays::Of(mesh, arr);
  vtkCellArray* polys = refined->GetPolys();
  const vtkIdType nr = refined->GetNumberOfCells();
  vtkNew<vtkIdList> pts;
  vtkIdType written = 0;
  bool same = arr.GetNumberOfPoints() == refined->GetNumberOfPoints();
  for (std::size_t r = 0; same && r < whole.Triangles.size(); ++r)
  {
    if (whole.SourceTriangle[r] < 0)
    {
      continue; // a hole: not written
    }
    if (written >= nr)
    {
      same = false;
      break;
    }
    polys->GetCellAtId(written, pts);
    const Triangle& t = whole.Triangles[r];
    same = pts->GetNumberOfIds() == 3 && pts->GetId(0) == t[0] && pts->GetId(1) == t[1] &&
      pts->GetId(2) == t[2] &&
      static_cast<int>(cellOf->GetComponent(written, 0)) == arr.CellOfTriangle(static_cast<int>(r));
    ++written;
  }
  if (!same || written != nr)
  {
    error = "the curves arranged again do not give the input's refined triangles and "
            "ArrangementCell (the input was edited since Surface Arrangement wrote it): run "
            "Surface Arrangement again";
    return false;
  }
  return true;
}

} // namespace

//------------------------------------------------------------------------------
bool RebuildArrangement(vtkPolyData* refined,
  int threads,
  ArrangementResult& out,
  std::string& error)
{
  vtkFieldData* fd = refined ? refined->GetFieldData() : nullptr;
  if (!refined ||
    (refined->GetNumberOfPoints() == 0 && refined->GetNumberOfCells() == 0 &&
      !fd->GetArray(names::NumberOfCells)))
  {
    // What a failed BoolSurf filter leaves: say so rather than ask for a rewiring.
    error = "the input is empty: the filter before it (Surface Arrangement, or a stage above "
            "it) reported an error; see its message";
    return false;
  }
  vtkDataArray* cellOf = refined->GetCellData()->GetArray(names::ArrangementCell);
  vtkDataArray* sourceTriangle = refined->GetCellData()->GetArray(names::SourceTriangle);
  if (!cellOf || !fd->GetArray(names::NumberOfCells))
  {
    error = "the input lacks cell data 'ArrangementCell' or field data 'NumberOfCells': "
            "connect the first output of Surface Arrangement (or of Label Arrangement Cells)";
    return false;
  }
  std::string missing;
  for (const char* name : { names::ArrangedMeshSize, names::ArrangedTraceMethod })
  {
    if (!fd->GetArray(name))
    {
      missing += std::string(missing.empty() ? "" : ", ") + "'" + name + "'";
    }
  }
  if (!sourceTriangle)
  {
    missing += std::string(missing.empty() ? "" : ", ") + "cell data 'SourceTriangle'";
  }
  if (!missing.empty())
  {
    error = "the input carries no Core arrangement and lacks field data " + missing +
      " to compute it again (written by an older Surface Arrangement): run Surface "
      "Arrangement again on the surface and curves";
    return false;
  }
  const auto size = ReadTuples<int>(fd, names::ArrangedMeshSize, 2);
  const auto method = ReadTuples<int>(fd, names::ArrangedTraceMethod, 1);
  if (size.size() != 2 || method.size() != 1)
  {
    error = "field data ArrangedMeshSize must hold 2 components, ArrangedTraceMethod 1";
    return false;
  }
  vtkNew<vtkPolyData> mesh;
  if (!RebuildMesh(refined,
        size[0],
        size[1],
        ReadTuples<int>(fd, names::ArrangedMeshCorners, 4),
        sourceTriangle,
        mesh,
        error))
  {
    return false;
  }
  ConvertSurface(mesh, out.Surface);
  if (!out.Surface.Mesh || !out.Surface.Topology || out.Surface.Check.HasErrors() ||
    out.Surface.Mesh->GetNumberOfTriangles() != size[1])
  {
    error = "the mesh of the refined surface could not be rebuilt";
    return false;
  }
  if (!ReadCurves(fd, out.Curves, error) || !ReadSources(fd, out.Sources, error))
  {
    return false;
  }
  out.Method = static_cast<GeodesicMethod>(method[0]);
  ArrangementOptions options;
  options.Threads = threads;
  if (!ComputeArrangement(*out.Surface.Mesh, out.Curves, options, out.Arrangement, error))
  {
    error = "Arrangement failed: " + error;
    return false;
  }
  return SameRefinedSurface(refined, *out.Surface.Mesh, out.Arrangement, cellOf, error);
}

//------------------------------------------------------------------------------
std::shared_ptr<const ArrangementResult> RebuiltArrangement::Get(vtkPolyData* refined,
  std::string& error)
{
  std::vector<vtkObject*> objects;
  if (refined)
  {
    objects = { refined->GetPoints() ? refined->GetPoints()->GetData() : nullptr,
      refined->GetPolys(),
      refined->GetCellData()->GetArray(names::ArrangementCell),
      refined->GetFieldData() };
  }
  std::vector<vtkMTimeType> times;
  bool same = this->Result && objects.size() == this->Objects.size();
  for (std::size_t i = 0; i < objects.size(); ++i)
  {
    times.push_back(objects[i] ? objects[i]->GetMTime() : 0);
    same = same && objects[i] == this->Objects[i].GetPointer() && times[i] == this->Times[i];
  }
  if (same)
  {
    return this->Result;
  }
  this->Result = nullptr;
  auto rebuilt = std::make_shared<ArrangementResult>();
  if (!RebuildArrangement(refined, 0, *rebuilt, error))
  {
    return nullptr;
  }
  this->Result = rebuilt;
  this->Objects.assign(objects.begin(), objects.end());
  this->Times = times;
  return this->Result;
}

//------------------------------------------------------------------------------
bool ReadLabelTable(vtkPolyData* input,
  const ArrangementResult& arranged,
  LabelingResult& labels,
  std::string& error)
{
  vtkFieldData* fd = input->GetFieldData();
  vtkDataArray* cellLabels = fd->GetArray(names::CellLabels);
  vtkDataArray* consistent = fd->GetArray(names::ShapeConsistent);
  const std::vector<int> shapeIds = DistinctShapeIds(arranged.Curves);
  const int ns = static_cast<int>(shapeIds.size());
  const int cells = arranged.Arrangement.NumberOfCells;
  if (!cellLabels || !consistent || cellLabels->GetNumberOfComponents() != ns ||
    cellLabels->GetNumberOfTuples() != cells || consistent->GetNumberOfTuples() != ns)
  {
    error = "field data CellLabels or ShapeConsistent does not match the arrangement's " +
      std::to_string(cells) + " cells and " + std::to_string(ns) + " shapes";
    return false;
  }
  labels = LabelingResult();
  labels.NumberOfShapes = ns;
  labels.ShapeIds = shapeIds;
  labels.Labels.resize(static_cast<std::size_t>(cells) * ns);
  for (vtkIdType c = 0; c < cells; ++c)
  {
    for (int s = 0; s < ns; ++s)
    {
      labels.Labels[c * ns + s] = static_cast<int>(cellLabels->GetComponent(c, s));
    }
  }
  for (int s = 0; s < ns; ++s)
  {
    labels.ShapeConsistent.push_back(consistent->GetComponent(s, 0) != 0);
  }
  return true;
}

} // namespace boolsurf

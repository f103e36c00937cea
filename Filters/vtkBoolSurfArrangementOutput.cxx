#include "vtkBoolSurfArrangementOutput.h"

#include "vtkBoolSurfAttributeTransfer.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <map>
#include <tuple>

namespace boolsurf
{
namespace
{

vtkSmartPointer<vtkIntArray> IntArray(const char* name,
  const std::vector<int>& values,
  int comps = 1)
{
  auto a = vtkSmartPointer<vtkIntArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(comps);
  a->SetNumberOfTuples(static_cast<vtkIdType>(values.size()) / comps);
  std::copy(values.begin(), values.end(), a->GetPointer(0));
  return a;
}

// VTK 9.2's XML writer cannot store an empty numeric array (the file becomes unreadable), so
// empty arrays are left out; readers treat a missing array as empty.
void AddField(vtkFieldData* fd, vtkAbstractArray* a)
{
  if (a->GetNumberOfTuples() > 0)
  {
    fd->AddArray(a);
  }
}

// Patches lying on the same refined sub-edges (overlapping curves) get one location id: they
// are crossed together. Overlapping patches have the same point sequence, maybe reversed.
std::vector<int> PatchLocations(const std::vector<ArrangementPatch>& patches)
{
  std::map<std::tuple<int, int, int, int>, int> ids;
  std::vector<int> location(patches.size(), -1);
  for (size_t p = 0; p < patches.size(); ++p)
  {
    const std::vector<int>& pts = patches[p].Points;
    if (pts.size() < 2)
    {
      // Degenerate patch: a place of its own.
      location[p] =
        ids
          .emplace(std::make_tuple(-1 - static_cast<int>(p), 0, 0, 0), static_cast<int>(ids.size()))
          .first->second;
      continue;
    }
    const int a = pts.front(), b = pts.back();
    const int c = pts[1], d = pts[pts.size() - 2];
    auto key = std::make_tuple(std::min(a, b), std::max(a, b), a <= b ? c : d, a <= b ? d : c);
    if (a == b) // a closed patch: its two directions give (c, d) and (d, c)
    {
      key = std::make_tuple(a, b, std::min(c, d), std::max(c, d));
    }
    location[p] = ids.emplace(key, static_cast<int>(ids.size())).first->second;
  }
  return location;
}

// Per surface component, a cell at its longest boundary loop (-1 for closed components): the
// zero cell of the labeling (paper §3.4: plugged holes are outside every shape).
std::vector<int> ZeroCellCandidates(const vtkSurfaceInput& surface, const Arrangement& arr)
{
  const TriangleMesh& mesh = *surface.Mesh;
  const MeshTopology& topo = *surface.Topology;
  std::vector<int> result(topo.GetNumberOfComponents(), -1);
  std::vector<int> longest(topo.GetNumberOfComponents(), -1);
  for (int l = 0; l < static_cast<int>(topo.BoundaryLoops.size()); ++l)
  {
    const int c = topo.BoundaryLoops[l].Component;
    if (longest[c] < 0 || topo.BoundaryLoops[l].Length > topo.BoundaryLoops[longest[c]].Length)
    {
      longest[c] = l;
    }
  }
  // Refined triangles are grouped by source triangle in increasing order.
  auto firstRefined = [&](int t)
  {
    auto it = std::lower_bound(arr.SourceTriangle.begin(), arr.SourceTriangle.end(), t);
    return it != arr.SourceTriangle.end() && *it == t
      ? static_cast<int>(it - arr.SourceTriangle.begin())
      : -1;
  };
  for (int c = 0; c < topo.GetNumberOfComponents(); ++c)
  {
    if (longest[c] < 0)
    {
      continue;
    }
    const BoundaryLoop& loop = topo.BoundaryLoops[longest[c]];
    for (size_t i = 0; i < loop.HalfEdges.size() && result[c] < 0; ++i)
    {
      const int h = loop.HalfEdges[i];
      const int t = h / 3;
      const int a = mesh.GetTriangle(t)[h % 3], b = mesh.GetTriangle(t)[(h % 3 + 1) % 3];
      const int e = mesh.GetEdgeId(t, h % 3);
      // The refined triangle of t holding the boundary sub-edge that starts at vertex a
      // (mesh vertices keep their ids in the refined surface; the next point is b or a
      // point on edge e).
      for (int r = firstRefined(t); r >= 0 && r < static_cast<int>(arr.Triangles.size()) &&
           arr.SourceTriangle[r] == t && result[c] < 0;
           ++r)
      {
        const auto& tri = arr.Triangles[r];
        for (int k = 0; k < 3; ++k)
        {
          const int next = tri[(k + 1) % 3];
          const CanonicalPoint& q = arr.PointOnMesh[next];
          const bool onEdge = next == b || (q.Location == PointLocation::Edge && q.Id == e);
          if (tri[k] == a && onEdge)
          {
            result[c] = arr.TriangleCell[r];
          }
        }
      }
    }
  }
  return result;
}

std::vector<int> ReadInts(vtkFieldData* fd, const char* name, int comps = 1)
{
  std::vector<int> v;
  vtkDataArray* a = fd->GetArray(name);
  if (!a)
  {
    return v;
  }
  v.resize(static_cast<size_t>(a->GetNumberOfTuples()) * comps);
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    for (int k = 0; k < comps; ++k)
    {
      v[i * comps + k] = static_cast<int>(a->GetComponent(i, k));
    }
  }
  return v;
}

} // namespace

//------------------------------------------------------------------------------
bool ArrangeCurves(const vtkSurfaceInput& surface,
  const std::vector<TracedCurve>& curves,
  int threads,
  vtkPolyData* refined,
  vtkPolyData* patches,
  std::string& error)
{
  ArrangementOptions options;
  options.Threads = threads;
  Arrangement arrangement;
  if (!ComputeArrangement(*surface.Mesh, curves, options, arrangement, error))
  {
    error = "Arrangement failed: " + error;
    return false;
  }
  WriteArrangementSurface(surface, curves, arrangement, refined);
  if (patches)
  {
    WriteArrangementPatches(arrangement, refined, patches);
  }
  return true;
}

//------------------------------------------------------------------------------
void WriteArrangementSurface(const vtkSurfaceInput& surface,
  const std::vector<TracedCurve>& curves,
  const Arrangement& arr,
  vtkPolyData* output)
{
  output->Initialize();
  // Bulk copies into the arrays VTK stores (Vec3 is three packed doubles; a triangle list is a
  // connectivity array with offsets 0, 3, 6, ...): per-element insertion costs tens of
  // milliseconds on a million triangles.
  static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 must be three packed doubles");
  const vtkIdType np = static_cast<vtkIdType>(arr.Positions.size());
  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(np);
  std::copy_n(
    reinterpret_cast<const double*>(arr.Positions.data()), 3 * np, coordinates->GetPointer(0));
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  output->SetPoints(points);

  const vtkIdType nt = static_cast<vtkIdType>(arr.Triangles.size());
  vtkNew<vtkIdTypeArray> cellOffsets, connectivity;
  cellOffsets->SetNumberOfTuples(nt + 1);
  connectivity->SetNumberOfTuples(3 * nt);
  vtkIdType* offset = cellOffsets->GetPointer(0);
  vtkIdType* conn = connectivity->GetPointer(0);
  for (vtkIdType t = 0; t < nt; ++t)
  {
    offset[t] = 3 * t;
    conn[3 * t] = arr.Triangles[t][0];
    conn[3 * t + 1] = arr.Triangles[t][1];
    conn[3 * t + 2] = arr.Triangles[t][2];
  }
  offset[nt] = 3 * nt;
  vtkNew<vtkCellArray> polys;
  polys->SetData(cellOffsets, connectivity);
  output->SetPolys(polys);

  TransferSurfaceAttributes(
    surface.Triangles, *surface.Mesh, arr.PointSurface, arr.SourceTriangle, output);

  output->GetCellData()->AddArray(IntArray("ArrangementCell", arr.TriangleCell));
  vtkNew<vtkIdTypeArray> source;
  source->SetName("SourceTriangle");
  source->SetNumberOfTuples(nt);
  std::copy(arr.SourceTriangle.begin(), arr.SourceTriangle.end(), source->GetPointer(0));
  output->GetCellData()->AddArray(source);

  vtkNew<vtkIdTypeArray> triangleId;
  triangleId->SetName("TriangleId");
  triangleId->SetNumberOfTuples(np);
  vtkNew<vtkDoubleArray> barycentric;
  barycentric->SetName("Barycentric");
  barycentric->SetNumberOfComponents(2);
  barycentric->SetNumberOfTuples(np);
  vtkIdType* tid = triangleId->GetPointer(0);
  double* uv = barycentric->GetPointer(0);
  for (vtkIdType i = 0; i < np; ++i)
  {
    tid[i] = arr.PointSurface[i].Triangle;
    uv[2 * i] = arr.PointSurface[i].U;
    uv[2 * i + 1] = arr.PointSurface[i].V;
  }
  output->GetPointData()->AddArray(triangleId);
  output->GetPointData()->AddArray(barycentric);

  // --- field data: cell graph, patches, components
  vtkFieldData* fd = output->GetFieldData();
  int numberOfShapes = 0;
  for (const TracedCurve& c : curves)
  {
    numberOfShapes = std::max(numberOfShapes, c.ShapeId + 1);
  }
  fd->AddArray(IntArray("NumberOfCells", { arr.NumberOfCells }));
  fd->AddArray(IntArray("NumberOfShapes", { numberOfShapes }));

  const std::vector<int> location = PatchLocations(arr.Patches);
  std::vector<int> arcs, arcShape, arcPatch, arcLocation;
  for (const CellGraphArc& a : arr.CellGraph)
  {
    arcs.push_back(a.RightCell);
    arcs.push_back(a.LeftCell);
    arcShape.push_back(a.Shape);
    arcPatch.push_back(a.Patch);
    arcLocation.push_back(a.Patch >= 0 ? location[a.Patch] : -1);
  }
  AddField(fd, IntArray("CellGraphArcs", arcs, 2));
  AddField(fd, IntArray("CellGraphShape", arcShape));
  AddField(fd, IntArray("CellGraphPatch", arcPatch));
  AddField(fd, IntArray("CellGraphLocation", arcLocation));

  std::vector<int> cellComponent(arr.NumberOfCells, 0);
  for (size_t r = 0; r < arr.TriangleCell.size(); ++r)
  {
    cellComponent[arr.TriangleCell[r]] = surface.Topology->TriangleComponent[arr.SourceTriangle[r]];
  }
  AddField(fd, IntArray("CellComponent", cellComponent));
  AddField(fd, IntArray("ZeroCellCandidates", ZeroCellCandidates(surface, arr)));

  std::vector<int> offsets{ 0 }, pointIds, left, right, shape, curve;
  for (const ArrangementPatch& p : arr.Patches)
  {
    pointIds.insert(pointIds.end(), p.Points.begin(), p.Points.end());
    offsets.push_back(static_cast<int>(pointIds.size()));
    left.push_back(p.LeftCell);
    right.push_back(p.RightCell);
    shape.push_back(p.ShapeId);
    curve.push_back(p.CurveId);
  }
  AddField(fd, IntArray("PatchOffsets", offsets));
  AddField(fd, IntArray("PatchPoints", pointIds));
  AddField(fd, IntArray("PatchLeftCell", left));
  AddField(fd, IntArray("PatchRightCell", right));
  AddField(fd, IntArray("PatchShape", shape));
  AddField(fd, IntArray("PatchCurve", curve));

  vtkNew<vtkDoubleArray> times;
  times->SetName("StageTimes");
  times->SetNumberOfComponents(6);
  const char* names[] = {
    "Hash", "Intersections", "Refinement", "FloodFill", "CellGraph", "Total"
  };
  for (int k = 0; k < 6; ++k)
  {
    times->SetComponentName(k, names[k]);
  }
  const ArrangementStageTimes& t = arr.Times;
  times->InsertNextTypedTuple(std::array<double, 6>{
    t.Hash, t.Intersections, t.Refinement, t.FloodFill, t.CellGraph, t.Total }
                                .data());
  fd->AddArray(times);
}

//------------------------------------------------------------------------------
void WriteArrangementPatches(const Arrangement& arr,
  vtkPolyData* refinedSurface,
  vtkPolyData* patches)
{
  patches->Initialize();
  patches->SetPoints(refinedSurface->GetPoints());
  patches->GetPointData()->PassData(refinedSurface->GetPointData());
  vtkNew<vtkCellArray> lines;
  std::vector<int> patchId, shape, curve, left, right;
  vtkNew<vtkDoubleArray> length;
  length->SetName("Length");
  for (size_t p = 0; p < arr.Patches.size(); ++p)
  {
    const ArrangementPatch& patch = arr.Patches[p];
    lines->InsertNextCell(static_cast<vtkIdType>(patch.Points.size()));
    for (int id : patch.Points)
    {
      lines->InsertCellPoint(id);
    }
    patchId.push_back(static_cast<int>(p));
    shape.push_back(patch.ShapeId);
    curve.push_back(patch.CurveId);
    left.push_back(patch.LeftCell);
    right.push_back(patch.RightCell);
    length->InsertNextValue(patch.Length);
  }
  patches->SetLines(lines);
  vtkCellData* cd = patches->GetCellData();
  cd->AddArray(IntArray("PatchId", patchId));
  cd->AddArray(IntArray("ShapeId", shape));
  cd->AddArray(IntArray("CurveId", curve));
  cd->AddArray(IntArray("LeftCell", left));
  cd->AddArray(IntArray("RightCell", right));
  cd->AddArray(length);
}

//------------------------------------------------------------------------------
bool ReadArrangementFields(vtkPolyData* input, ArrangementFields& out, std::string& error)
{
  out = ArrangementFields();
  if (!input)
  {
    error = "no input";
    return false;
  }
  vtkFieldData* fd = input->GetFieldData();
  for (const char* required : { "NumberOfCells", "NumberOfShapes" })
  {
    if (!fd->GetArray(required))
    {
      error = std::string("the input lacks field data '") + required +
        "': connect the first output of Surface Arrangement (or of Label Arrangement Cells)";
      return false;
    }
  }
  if (!input->GetCellData()->GetArray("ArrangementCell"))
  {
    error = "the input lacks cell data 'ArrangementCell': connect the first output of "
            "Surface Arrangement";
    return false;
  }
  out.NumberOfCells = ReadInts(fd, "NumberOfCells")[0];
  out.NumberOfShapes = ReadInts(fd, "NumberOfShapes")[0];
  const std::vector<int> arcs = ReadInts(fd, "CellGraphArcs", 2);
  const std::vector<int> shape = ReadInts(fd, "CellGraphShape");
  const std::vector<int> location = ReadInts(fd, "CellGraphLocation");
  if (shape.size() * 2 != arcs.size() || location.size() != shape.size())
  {
    error = "the cell graph arrays CellGraphArcs/CellGraphShape/CellGraphLocation disagree in size";
    return false;
  }
  for (size_t i = 0; i < shape.size(); ++i)
  {
    out.Arcs.push_back({ arcs[2 * i], arcs[2 * i + 1], shape[i], location[i] });
  }
  out.CellComponent = ReadInts(fd, "CellComponent");
  out.ZeroCellCandidates = ReadInts(fd, "ZeroCellCandidates");
  const std::vector<int> offsets = ReadInts(fd, "PatchOffsets");
  const std::vector<int> points = ReadInts(fd, "PatchPoints");
  const std::vector<int> left = ReadInts(fd, "PatchLeftCell");
  const std::vector<int> right = ReadInts(fd, "PatchRightCell");
  out.PatchShape = ReadInts(fd, "PatchShape");
  out.PatchCurve = ReadInts(fd, "PatchCurve");
  for (size_t p = 0; p + 1 < offsets.size() && p < left.size() && p < right.size(); ++p)
  {
    BoundaryPatch patch;
    patch.Points.assign(points.begin() + offsets[p], points.begin() + offsets[p + 1]);
    patch.LeftCell = left[p];
    patch.RightCell = right[p];
    out.Patches.push_back(std::move(patch));
  }
  return true;
}

} // namespace boolsurf

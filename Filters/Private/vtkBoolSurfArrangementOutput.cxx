#include "vtkBoolSurfArrangementOutput.h"

#include "vtkBoolSurfArrayNames.h"

#include "Arrangement/EditBuffers.h"
#include "Labeling/ArrangementLabelingInput.h"
#include "Mesh/ParallelRange.h"
#include "vtkBoolSurfArrangementRebuildWriter.h"
#include "vtkBoolSurfArrayView.h"
#include "vtkBoolSurfAttributeTransfer.h"
#include "vtkBoolSurfOutputReuse.h"
#include "vtkBoolSurfStageHandoff.h"
#include "vtkBoolSurfTraceStage.h"

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
#include <vtkTypeInt32Array.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <type_traits>

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

// Arrays of fewer tuples are filled on the calling thread (waking others costs more than the
// copy); larger ones in blocks of ArrayBlock tuples.
constexpr vtkIdType ParallelArrayTuples = 1 << 15;
constexpr int ArrayBlock = 1 << 14;

// A triangle list as VTK cell arrays, sized by the caller: offsets 0, 3, 6, ... and the
// corners.
void FillTriangleArrays(const int* corners,
  vtkIdType count,
  vtkIdTypeArray* offsets,
  vtkIdTypeArray* connectivity,
  int threads)
{
  vtkIdType* offset = offsets->GetPointer(0);
  vtkIdType* connected = connectivity->GetPointer(0);
  offset[count] = 3 * count;
  // Blocks of triangles, each written by one thread (the first touch of fresh pages too).
  ParallelBlocks(
    threads,
    count >= ParallelArrayTuples,
    static_cast<int>(count),
    [&](int first, int last)
    {
      for (vtkIdType t = first; t < last; ++t)
      {
        offset[t] = 3 * t;
      }
      std::copy(corners + 3 * static_cast<vtkIdType>(first),
        corners + 3 * static_cast<vtkIdType>(last),
        connected + 3 * static_cast<vtkIdType>(first));
    },
    ArrayBlock);
}

// Surface points as TriangleId/Barycentric values, in arrays sized by the caller.
void FillSurfacePointArrays(const std::vector<SurfacePoint>& points,
  vtkIdTypeArray* triangleId,
  vtkDoubleArray* barycentric,
  int threads)
{
  vtkIdType* tid = triangleId->GetPointer(0);
  double* uv = barycentric->GetPointer(0);
  const vtkIdType np = static_cast<vtkIdType>(points.size());
  ParallelBlocks(
    threads,
    np >= ParallelArrayTuples,
    static_cast<int>(np),
    [&](int first, int last)
    {
      for (vtkIdType i = first; i < last; ++i)
      {
        tid[i] = points[i].Triangle;
        uv[2 * i] = points[i].U;
        uv[2 * i + 1] = points[i].V;
      }
    },
    ArrayBlock);
}

} // namespace

//------------------------------------------------------------------------------
void SetTriangles(const int* corners, vtkIdType count, vtkPolyData* output, int threads)
{
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfTuples(count + 1);
  connectivity->SetNumberOfTuples(3 * count);
  FillTriangleArrays(corners, count, offsets, connectivity, threads);
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  output->SetPolys(polys);
}

//------------------------------------------------------------------------------
void AddSurfacePointArrays(const std::vector<SurfacePoint>& points,
  vtkPointData* pointData,
  int threads)
{
  const vtkIdType np = static_cast<vtkIdType>(points.size());
  vtkNew<vtkIdTypeArray> triangleId;
  triangleId->SetName(boolsurf::names::TriangleId);
  triangleId->SetNumberOfTuples(np);
  vtkNew<vtkDoubleArray> barycentric;
  barycentric->SetName(boolsurf::names::Barycentric);
  barycentric->SetNumberOfComponents(2);
  barycentric->SetNumberOfTuples(np);
  FillSurfacePointArrays(points, triangleId, barycentric, threads);
  pointData->AddArray(triangleId);
  pointData->AddArray(barycentric);
}

//------------------------------------------------------------------------------
bool ArrangeCurves(const vtkSurfaceInput& surface,
  const std::vector<TracedCurve>& curves,
  const ArrangementOptions& options,
  Arrangement& arrangement,
  const ArrangementMemory& memory,
  vtkPolyData* refined,
  vtkPolyData* patches,
  std::string& error)
{
  if (!ComputeArrangement(*surface.Mesh, curves, options, arrangement, error))
  {
    error = "Arrangement failed: " + error;
    return false;
  }
  WriteArrangementSurface(surface, curves, arrangement, memory, refined, options.Threads);
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
  const ArrangementMemory& memory,
  vtkPolyData* output,
  int threads)
{
  EmptyPolyData(output);
  static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 must be three packed doubles");
  static_assert(sizeof(std::array<int, 3>) == 3 * sizeof(int), "triangles must be packed ints");
  const vtkIdType np = arr.GetNumberOfPoints();
  // Points, triangles and the per-triangle arrays are written into the result's buffers, kept
  // from edit to edit (RefinedSurfaceArrays: an edit rewrites what curves cross), and read in
  // place by VTK: on a million triangles a fresh copy is ~50 MB written per edit. VTK takes a
  // triangle list as a connectivity array (the corners, as the arrangement stores them) and offsets
  // 0, 3, 6, ..., which the result keeps and extends, with room for later edits, only when it
  // grows. Cells are kept per tile by the arrangement: they are written out per triangle here.
  std::vector<int>& triangleCells = *memory.TriangleCells;
  UpdateTriangleCells(arr, triangleCells, *memory.WrittenCells, threads);
  RefinedSurfaceArrays& whole = *memory.Surface;
  whole.Update(*surface.Mesh, arr, threads);
  const std::array<int, 3>* corners = whole.Triangles.data();
  const int* sourceTriangle = whole.SourceTriangle.data();
  vtkIdType nt = static_cast<vtkIdType>(whole.Triangles.size());
  // Unusable mesh triangles leave holes in the refined triangles (their entries name no point):
  // such meshes get compacted copies instead.
  std::vector<std::array<int, 3>> compactCorners;
  std::vector<int> compactSource;
  if (arr.NumberOfHoles > 0)
  {
    std::vector<int> compactCells;
    for (vtkIdType r = 0; r < nt; ++r)
    {
      if (whole.SourceTriangle[r] >= 0)
      {
        compactCorners.push_back(whole.Triangles[r]);
        compactSource.push_back(whole.SourceTriangle[r]);
        compactCells.push_back(triangleCells[r]);
      }
    }
    triangleCells = std::move(compactCells);
    *memory.WrittenCells = WrittenTriangleCells(); // compacted: written whole next time
    corners = compactCorners.data();
    sourceTriangle = compactSource.data();
    nt = static_cast<vtkIdType>(compactCorners.size());
  }
  const bool compacted = arr.NumberOfHoles > 0;
  std::vector<int>& cellStarts = *memory.CellOffsets;
  const std::size_t known = cellStarts.size();
  if (known < static_cast<std::size_t>(nt) + 1)
  {
    cellStarts.resize(EditCapacity(nt + 1));
    for (std::size_t t = known; t < cellStarts.size(); ++t)
    {
      cellStarts[t] = static_cast<int>(3 * t);
    }
  }
  auto coordinates = MakeArrayView<vtkDoubleArray>(&whole.Positions.data()->x, np, 3, memory.Owner);
  auto cellOffsets = MakeArrayView<vtkTypeInt32Array>(cellStarts.data(), nt + 1, 1, memory.Owner);
  vtkSmartPointer<vtkTypeInt32Array> connectivity;
  vtkSmartPointer<vtkIntArray> source;
  if (compacted)
  {
    connectivity = vtkSmartPointer<vtkTypeInt32Array>::New();
    connectivity->SetNumberOfValues(3 * nt);
    std::copy_n(reinterpret_cast<const int*>(corners), 3 * nt, connectivity->GetPointer(0));
    source = vtkSmartPointer<vtkIntArray>::New();
    source->SetNumberOfValues(nt);
    std::copy_n(sourceTriangle, nt, source->GetPointer(0));
  }
  else
  {
    connectivity = MakeArrayView<vtkTypeInt32Array>(
      reinterpret_cast<const int*>(corners), 3 * nt, 1, memory.Owner);
    source = MakeArrayView<vtkIntArray>(sourceTriangle, nt, 1, memory.Owner);
  }
  auto cellOf = MakeArrayView<vtkIntArray>(triangleCells.data(), nt, 1, memory.Owner);
  cellOf->SetName(boolsurf::names::ArrangementCell);
  source->SetName(boolsurf::names::SourceTriangle);

  // The per-point surface points: copies (one struct per point in the arrangement) into the
  // result's buffers, read in place too.
  std::vector<vtkIdType>& pointTriangle = *memory.PointTriangle;
  std::vector<double>& pointBarycentric = *memory.PointBarycentric;
  const vtkIdType nv = surface.Mesh->GetNumberOfVertices();
  const std::uint64_t serial = surface.Mesh->GetSerial();
  const bool verticesKept = serial != 0 && *memory.PointArraysMeshSerial == serial &&
    static_cast<vtkIdType>(pointTriangle.size()) >= nv;
  *memory.PointArraysMeshSerial = 0; // until the vertices' part is written
  ResizeForEdits(pointTriangle, np);
  ResizeForEdits(pointBarycentric, 2 * np);
  const vtkIdType firstWritten = verticesKept ? std::min(nv, np) : 0;
  const auto fill = [&](vtkIdType first, vtkIdType last)
  {
    for (vtkIdType i = first; i < last; ++i)
    {
      const SurfacePoint p = arr.GetPointSurface(*surface.Mesh, static_cast<int>(i));
      pointTriangle[i] = p.Triangle;
      pointBarycentric[2 * i] = p.U;
      pointBarycentric[2 * i + 1] = p.V;
    }
  };
  constexpr vtkIdType Grain = 1 << 15;
  if (np - firstWritten <= Grain)
  {
    fill(firstWritten, np); // a few points: not worth waking other threads
  }
  else
  {
    tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
    arena.execute(
      [&]
      {
        tbb::parallel_for(tbb::blocked_range<vtkIdType>(firstWritten, np, Grain),
          [&](const tbb::blocked_range<vtkIdType>& range) { fill(range.begin(), range.end()); });
      });
  }
  *memory.PointArraysMeshSerial = serial;
  auto triangleId = MakeArrayView<vtkIdTypeArray>(pointTriangle.data(), np, 1, memory.Owner);
  auto barycentric = MakeArrayView<vtkDoubleArray>(pointBarycentric.data(), np, 2, memory.Owner);
  triangleId->SetName(boolsurf::names::TriangleId);
  barycentric->SetName(boolsurf::names::Barycentric);
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  output->SetPoints(points);
  vtkNew<vtkCellArray> polys;
  polys->SetData(cellOffsets, connectivity);
  output->SetPolys(polys);

  const auto pointSurface = [&](vtkIdType p) // the surface points just written, not derived again
  {
    return SurfacePoint{
      static_cast<int>(pointTriangle[p]), pointBarycentric[2 * p], pointBarycentric[2 * p + 1]
    };
  };
  const std::vector<int>& sources = compacted ? compactSource : whole.SourceTriangle;
  if (memory.Attributes)
  {
    // Points are numbered the mesh's vertices first, and triangles the mesh's first unless
    // holes were compacted away.
    UpdateSurfaceAttributes(surface.Triangles,
      *surface.Mesh,
      np,
      arr.NumberOfMeshVertices,
      compacted ? 0 : arr.NumberOfMeshTriangles,
      pointSurface,
      sources,
      *memory.Attributes,
      output);
  }
  else
  {
    TransferSurfaceAttributes(surface.Triangles, *surface.Mesh, np, pointSurface, sources, output);
  }
  output->GetCellData()->AddArray(cellOf);
  output->GetCellData()->AddArray(source);
  output->GetPointData()->AddArray(triangleId);
  output->GetPointData()->AddArray(barycentric);

  // --- field data: cell graph, patches, components
  vtkFieldData* fd = output->GetFieldData();
  // Shapes are numbered densely (index i is ShapeIds[i]); arrays keep the users' ids.
  const std::vector<int> shapeIds = DistinctShapeIds(curves);
  fd->AddArray(IntArray(boolsurf::names::NumberOfCells, { arr.NumberOfCells }));
  fd->AddArray(IntArray(boolsurf::names::NumberOfShapes, { static_cast<int>(shapeIds.size()) }));
  AddField(fd, IntArray(boolsurf::names::ShapeIds, shapeIds));

  const std::vector<PatchPlace> places = PatchPlaces(arr.Patches);
  // The boundary loops' plugs are nodes NumberOfCells + loop of the cell graph: their arcs
  // follow the arcs between cells, and the links to the cells along free stretches of the
  // boundary are an array of their own.
  const BoundaryPlugs plugs = FindBoundaryPlugs(*surface.Mesh, *surface.Topology, arr);
  std::vector<int> arcs, arcShape, arcPatch, arcLocation, arcDirection;
  for (const std::vector<CellGraphArc>* list : { &arr.CellGraph, &plugs.Arcs })
  {
    for (const CellGraphArc& a : *list)
    {
      arcs.push_back(a.RightCell);
      arcs.push_back(a.LeftCell);
      arcShape.push_back(a.Shape);
      arcPatch.push_back(a.Patch);
      const PatchPlace place = a.Patch >= 0 ? places[a.Patch] : PatchPlace{};
      arcLocation.push_back(place.Location);
      arcDirection.push_back(place.Direction);
    }
  }
  AddField(fd, IntArray(boolsurf::names::CellGraphArcs, arcs, 2));
  AddField(fd, IntArray(boolsurf::names::CellGraphShape, arcShape));
  AddField(fd, IntArray(boolsurf::names::CellGraphPatch, arcPatch));
  AddField(fd, IntArray(boolsurf::names::CellGraphLocation, arcLocation));
  AddField(fd, IntArray(boolsurf::names::CellGraphDirection, arcDirection));

  std::vector<int> components = CellComponents(*surface.Mesh, *surface.Topology, arr);
  components.insert(components.end(), plugs.PlugComponent.begin(), plugs.PlugComponent.end());
  AddField(fd, IntArray(boolsurf::names::CellComponent, components));
  AddField(fd, IntArray(boolsurf::names::ZeroCellCandidates, plugs.ZeroNodes));
  fd->AddArray(IntArray(boolsurf::names::NumberOfBoundaryPlugs, { plugs.NumberOfPlugs }));
  std::vector<int> links;
  for (const auto& link : plugs.Links)
  {
    links.push_back(link.first);
    links.push_back(link.second);
  }
  AddField(fd, IntArray(boolsurf::names::BoundaryPlugLinks, links, 2));

  std::vector<int> offsets{ 0 }, pointIds, left, right, shape, curve, closed;
  for (const ArrangementPatch& p : arr.Patches)
  {
    pointIds.insert(pointIds.end(), p.Points.begin(), p.Points.end());
    offsets.push_back(static_cast<int>(pointIds.size()));
    left.push_back(p.LeftCell);
    right.push_back(p.RightCell);
    shape.push_back(p.ShapeId);
    curve.push_back(p.CurveId);
    closed.push_back(p.Closed ? 1 : 0);
  }
  AddField(fd, IntArray(boolsurf::names::PatchOffsets, offsets));
  AddField(fd, IntArray(boolsurf::names::PatchPoints, pointIds));
  AddField(fd, IntArray(boolsurf::names::PatchLeftCell, left));
  AddField(fd, IntArray(boolsurf::names::PatchRightCell, right));
  AddField(fd, IntArray(boolsurf::names::PatchShape, shape));
  AddField(fd, IntArray(boolsurf::names::PatchCurve, curve));
  AddField(fd, IntArray(boolsurf::names::PatchClosed, closed));

  vtkNew<vtkDoubleArray> times;
  times->SetName(boolsurf::names::StageTimes);
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
  EmptyPolyData(patches);
  patches->SetPoints(refinedSurface->GetPoints());
  patches->GetPointData()->PassData(refinedSurface->GetPointData());
  const vtkIdType np = static_cast<vtkIdType>(arr.Patches.size());
  vtkIdType corners = 0;
  for (const ArrangementPatch& patch : arr.Patches)
  {
    corners += static_cast<vtkIdType>(patch.Points.size());
  }
  auto offsets = NewSizedArray<vtkIdTypeArray>(nullptr, 1, np + 1);
  auto connectivity = NewSizedArray<vtkIdTypeArray>(nullptr, 1, corners);
  std::vector<int> patchId(np), shape(np), curve(np), left(np), right(np);
  auto length = NewSizedArray<vtkDoubleArray>(boolsurf::names::Length, 1, np);
  vtkIdType corner = 0;
  for (vtkIdType p = 0; p < np; ++p)
  {
    const ArrangementPatch& patch = arr.Patches[p];
    offsets->SetValue(p, corner);
    for (int id : patch.Points)
    {
      connectivity->SetValue(corner++, id);
    }
    patchId[p] = static_cast<int>(p);
    shape[p] = patch.ShapeId;
    curve[p] = patch.CurveId;
    left[p] = patch.LeftCell;
    right[p] = patch.RightCell;
    length->SetValue(p, patch.Length);
  }
  offsets->SetValue(np, corner);
  vtkNew<vtkCellArray> lines;
  lines->SetData(offsets, connectivity);
  patches->SetLines(lines);
  vtkCellData* cd = patches->GetCellData();
  cd->AddArray(IntArray(boolsurf::names::PatchId, patchId));
  cd->AddArray(IntArray(boolsurf::names::ShapeId, shape));
  cd->AddArray(IntArray(boolsurf::names::CurveId, curve));
  cd->AddArray(IntArray(boolsurf::names::LeftCell, left));
  cd->AddArray(IntArray(boolsurf::names::RightCell, right));
  cd->AddArray(length);
}

//------------------------------------------------------------------------------
std::vector<int> ReadTriangleCells(vtkDataArray* arrangementCell)
{
  const vtkIdType n = arrangementCell->GetNumberOfTuples();
  std::vector<int> cells(n);
  if (auto* ints = vtkArrayDownCast<vtkIntArray>(arrangementCell))
  {
    std::copy_n(ints->GetPointer(0), n, cells.data());
  }
  else
  {
    for (vtkIdType t = 0; t < n; ++t)
    {
      cells[t] = static_cast<int>(arrangementCell->GetComponent(t, 0));
    }
  }
  return cells;
}

bool ArrangeResult(const std::shared_ptr<ArrangementResult>& result,
  const std::vector<CurveSource>& sources,
  const ArrangementOptions& options,
  vtkPolyData* refined,
  vtkPolyData* patches,
  std::string& error)
{
  const ArrangementMemory memory{ result,
    &result->CellOffsets,
    &result->PointTriangle,
    &result->PointBarycentric,
    &result->PointArraysMeshSerial,
    &result->TriangleCells,
    &result->WrittenCells,
    &result->Whole,
    &result->Attributes };
  if (ArrangeCurves(result->Surface,
        result->Curves,
        options,
        result->Arrangement,
        memory,
        refined,
        patches,
        error))
  {
    // What a copy without this result (a file) needs to compute it again.
    WriteRebuildFields(*result->Surface.Mesh,
      result->Arrangement,
      result->Curves,
      sources,
      result->Method,
      refined->GetFieldData());
    return true;
  }
  const Arrangement& failed = result->Arrangement;
  if (failed.FailedCurve >= 0)
  {
    error += "\n  (at " +
      DescribeCurvePoint(result->Curves, sources, failed.FailedCurve, failed.FailedPoint) + ")";
  }
  return false;
}

} // namespace boolsurf

#include "vtkBoolSurfRegionOutput.h"

#include "vtkBoolSurfArrayNames.h"

#include "vtkBoolSurfArrangementOutput.h"
#include "vtkBoolSurfAttributeTransfer.h"

#include "Mesh/ParallelRange.h"

#include <vtkDataArray.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>

namespace boolsurf
{
namespace
{

/// Cell data Region (1 everywhere) as the active scalars: ParaView colors a new display by the
/// active scalars, and the plugin maps Region to one color distinct from the surface, so a
/// result reads as one region; its cells are one click away (ArrangementCell).
void MarkRegion(vtkPolyData* region)
{
  vtkNew<vtkUnsignedCharArray> mark;
  mark->SetName(boolsurf::names::Region);
  mark->SetNumberOfTuples(region->GetNumberOfCells());
  mark->FillValue(1);
  region->GetCellData()->AddArray(mark);
  region->GetCellData()->SetActiveScalars(boolsurf::names::Region);
}

} // namespace

//------------------------------------------------------------------------------
void WriteRegion(const vtkSurfaceInput& surface,
  const Arrangement& arr,
  const RegionMesh& mesh,
  vtkPolyData* region,
  int threads)
{
  const vtkIdType np = static_cast<vtkIdType>(mesh.Points.size());
  const vtkIdType nt = static_cast<vtkIdType>(mesh.Triangles.size());
  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(np);
  double* xyz = coordinates->GetPointer(0);
  std::vector<SurfacePoint> pointSurface(np);
  vtkNew<vtkIntArray> cell;
  cell->SetName(boolsurf::names::ArrangementCell);
  cell->SetNumberOfTuples(nt);
  vtkNew<vtkIntArray> source; // int, as on the refined surface (mesh triangle ids are ints)
  source->SetName(boolsurf::names::SourceTriangle);
  source->SetNumberOfTuples(nt);
  std::vector<int> sourceTriangle(nt);
  const TriangleCellLookup cellOf = arr.GetCellLookup();
  int* cellValue = cell->GetPointer(0);
  int* sourceValue = source->GetPointer(0);
  // Points, then triangles, as ranges of one index: each range reads the arrangement's entries
  // of its own points or triangles and writes its own slots.
  const auto write = [&](int first, int last)
  {
    for (vtkIdType i = first; i < std::min<vtkIdType>(last, np); ++i)
    {
      const int p = mesh.Points[i];
      const Vec3 x = arr.GetPosition(*surface.Mesh, p);
      xyz[3 * i] = x.x;
      xyz[3 * i + 1] = x.y;
      xyz[3 * i + 2] = x.z;
      pointSurface[i] = arr.GetPointSurface(*surface.Mesh, p);
    }
    for (vtkIdType t = std::max<vtkIdType>(first, np) - np; t < last - np; ++t)
    {
      const int r = mesh.Triangles[t];
      sourceTriangle[t] = arr.GetSourceTriangle(*surface.Mesh, r);
      cellValue[t] = cellOf(r);
      sourceValue[t] = sourceTriangle[t];
    }
  };
  ParallelBlocks(threads,
    nt >= static_cast<vtkIdType>(RegionExtractor::ParallelTriangles),
    static_cast<int>(np + nt),
    write,
    4096);
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  region->SetPoints(points);
  SetTriangles(
    mesh.Connectivity.data(), static_cast<vtkIdType>(mesh.Triangles.size()), region, threads);

  // The surface's own arrays first (they skip BoolSurf's names), then ours.
  TransferSurfaceAttributes(
    surface.Triangles,
    *surface.Mesh,
    np,
    [&](vtkIdType i) { return pointSurface[i]; },
    sourceTriangle,
    region);
  region->GetCellData()->AddArray(cell);
  region->GetCellData()->AddArray(source);
  AddSurfacePointArrays(pointSurface, region->GetPointData(), threads);
  MarkRegion(region);
}

} // namespace boolsurf

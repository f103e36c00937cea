// Writing a selected region and its boundary (a private header of the module), from a
// labeled refined surface in VTK form (the stage filters) or straight from the Core
// arrangement (the one-step filter, which never builds the whole refined surface in VTK).
// Either way the cost is the size of the region, plus at most one pass over the triangles'
// cell ids.
#ifndef vtkBoolSurfRegionOutput_h
#define vtkBoolSurfRegionOutput_h

#include "Arrangement/Arrangement.h"
#include "Selection/RegionBoundary.h"
#include "Selection/RegionExtraction.h"
#include "vtkBoolSurfArrangementOutput.h"
#include "vtkBoolSurfArrayNames.h"
#include "vtkBoolSurfSurfaceAdapter.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <vector>

namespace boolsurf
{

/// The region `mesh` (refined triangles and points of `arrangement`) as polydata: cell data
/// ArrangementCell, SourceTriangle and the surface's own cell arrays; point data
/// TriangleId/Barycentric and the surface's own point arrays (interpolated). A large region is
/// written on at most `threads` threads (0: all).
void WriteRegion(const vtkSurfaceInput& surface,
  const Arrangement& arrangement,
  const RegionMesh& mesh,
  vtkPolyData* region,
  int threads = 0);

/// Boundary polylines (closed loops repeat their first point id), cell data `Closed`, and point
/// data TriangleId/Barycentric when `withSurfacePoints`. positionOf(p, double[3]) and
/// surfacePointOf(p) -> SurfacePoint read refined point p.
template <class PositionOf, class SurfacePointOf>
void WriteBoundary(const std::vector<BoundaryPolyline>& lines,
  PositionOf positionOf,
  SurfacePointOf surfacePointOf,
  bool withSurfacePoints,
  vtkPolyData* boundary)
{
  vtkIdType total = 0, cellSize = 0;
  for (const BoundaryPolyline& line : lines)
  {
    total += static_cast<vtkIdType>(line.Points.size());
    cellSize += static_cast<vtkIdType>(line.Points.size()) + (line.Closed ? 1 : 0);
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(total);
  double* xyz = vtkDoubleArray::SafeDownCast(points->GetData())->GetPointer(0);
  std::vector<SurfacePoint> surfacePoints(withSurfacePoints ? total : 0);
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfTuples(static_cast<vtkIdType>(lines.size()) + 1);
  connectivity->SetNumberOfTuples(cellSize);
  vtkNew<vtkIntArray> closed;
  closed->SetName(boolsurf::names::Closed);
  closed->SetNumberOfTuples(static_cast<vtkIdType>(lines.size()));
  vtkIdType next = 0, slot = 0;
  for (size_t l = 0; l < lines.size(); ++l)
  {
    const BoundaryPolyline& line = lines[l];
    offsets->SetValue(static_cast<vtkIdType>(l), slot);
    const vtkIdType first = next;
    for (int p : line.Points)
    {
      positionOf(p, xyz + 3 * next);
      if (withSurfacePoints)
      {
        surfacePoints[next] = surfacePointOf(p);
      }
      connectivity->SetValue(slot++, next++);
    }
    if (line.Closed)
    {
      connectivity->SetValue(slot++, first);
    }
    closed->SetValue(static_cast<vtkIdType>(l), line.Closed ? 1 : 0);
  }
  offsets->SetValue(static_cast<vtkIdType>(lines.size()), slot);
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  boundary->SetPoints(points);
  boundary->SetLines(cells);
  if (withSurfacePoints)
  {
    AddSurfacePointArrays(surfacePoints, boundary->GetPointData(), 1); // small: one thread
  }
  boundary->GetCellData()->AddArray(closed);
}

} // namespace boolsurf

#endif

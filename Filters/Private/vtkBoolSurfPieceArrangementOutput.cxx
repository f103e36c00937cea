#include "vtkBoolSurfPieceArrangementOutput.h"

#include "vtkBoolSurfArrayNames.h"
#include "vtkBoolSurfPieceArrangement.h"

#include "Distributed/MergedLabeling.h"

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
#include <vtkTypeInt64Array.h>

#include <algorithm>
#include <string>
#include <vector>

namespace boolsurf
{

void WritePieceTriangles(const PieceMesh& piece,
  const vtkBoolSurfPieceArrangement& run,
  const std::vector<int>& triangles,
  const std::vector<int>& sources,
  const std::vector<int>& cells,
  vtkPolyData* output)
{
  output->Initialize();
  const Arrangement& arr = run.GetArrangement();
  const TriangleMesh& mesh = piece.Mesh;
  const vtkIdType n = static_cast<vtkIdType>(triangles.size());
  // Output point of each refined point, made on first use (a piece uses few of the refined
  // points of its ring), and the connectivity, in one pass; then the points in that order.
  // Arrays are sized once and written through their pointers (an edit of a large piece
  // writes millions of values: InsertNext* per value cost more than the arrangement's edit).
  std::vector<vtkIdType> outputPoint(static_cast<std::size_t>(arr.GetNumberOfPoints()), -1);
  std::vector<int> refinedPoint; // per output point
  vtkNew<vtkTypeInt64Array> offsets, connectivity;
  offsets->SetNumberOfValues(n + 1);
  connectivity->SetNumberOfValues(3 * n);
  vtkTypeInt64* offset = offsets->GetPointer(0);
  vtkTypeInt64* corner = connectivity->GetPointer(0);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const Triangle corners = arr.GetTriangle(mesh, triangles[static_cast<std::size_t>(i)]);
    offset[i] = 3 * i;
    for (int k = 0; k < 3; ++k)
    {
      vtkIdType& id = outputPoint[corners[k]];
      if (id < 0)
      {
        id = static_cast<vtkIdType>(refinedPoint.size());
        refinedPoint.push_back(corners[k]);
      }
      corner[3 * i + k] = id;
    }
  }
  offset[n] = 3 * n;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  const vtkIdType m = static_cast<vtkIdType>(refinedPoint.size());
  points->SetNumberOfPoints(m);
  vtkNew<vtkIdTypeArray> triangleId;
  vtkNew<vtkDoubleArray> barycentric;
  triangleId->SetName(names::TriangleId);
  barycentric->SetName(names::Barycentric);
  barycentric->SetNumberOfComponents(2);
  triangleId->SetNumberOfValues(m);
  barycentric->SetNumberOfTuples(m);
  double* position = vtkDoubleArray::SafeDownCast(points->GetData())->GetPointer(0);
  vtkIdType* named = triangleId->GetPointer(0);
  double* uv = barycentric->GetPointer(0);
  for (vtkIdType q = 0; q < m; ++q)
  {
    const int p = refinedPoint[static_cast<std::size_t>(q)];
    const Vec3 x = arr.GetPosition(mesh, p);
    position[3 * q] = x.x;
    position[3 * q + 1] = x.y;
    position[3 * q + 2] = x.z;
    // On global triangle ids; a mesh vertex names one of its triangles in the piece.
    const SurfacePoint s = arr.GetPointSurface(mesh, p);
    named[q] = piece.GlobalTriangle[s.Triangle];
    uv[2 * q] = s.U;
    uv[2 * q + 1] = s.V;
  }
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  vtkNew<vtkIntArray> cellOf, source;
  cellOf->SetName(names::ArrangementCell);
  source->SetName(names::SourceTriangle);
  cellOf->SetNumberOfValues(n);
  source->SetNumberOfValues(n);
  std::copy(cells.begin(), cells.end(), cellOf->GetPointer(0));
  std::copy(sources.begin(), sources.end(), source->GetPointer(0));
  output->SetPoints(points);
  output->SetPolys(polys);
  output->GetCellData()->AddArray(cellOf);
  output->GetCellData()->AddArray(source);
  output->GetPointData()->AddArray(triangleId);
  output->GetPointData()->AddArray(barycentric);
}

void WritePieceArrangement(const PieceMesh& piece,
  const vtkBoolSurfPieceArrangement& run,
  vtkPolyData* output)
{
  const Arrangement& arr = run.GetArrangement();
  std::vector<int> triangles, sources, cells;
  triangles.reserve(static_cast<std::size_t>(piece.NumberOfOwnedTriangles));
  sources.reserve(triangles.capacity());
  cells.reserve(triangles.capacity());
  // Local triangles are in ascending global order (PieceMesh), so the owned ones come out in
  // the one-rank output's order of source triangles.
  for (int t = 0; t < piece.Mesh.GetNumberOfTriangles(); ++t)
  {
    if (!piece.Owned[t])
    {
      continue;
    }
    ForEachRefinedTriangle(piece.Mesh,
      arr,
      t,
      [&](int r)
      {
        triangles.push_back(r);
        sources.push_back(piece.GlobalTriangle[t]);
        cells.push_back(run.GetGlobalCell(arr.CellOfTriangle(r)));
      });
  }
  WritePieceTriangles(piece, run, triangles, sources, cells, output);
  vtkNew<vtkIntArray> count;
  count->SetName(names::NumberOfCells);
  count->InsertNextValue(run.GetMerged().NumberOfCells);
  output->GetFieldData()->AddArray(count);
  WriteMergedPlugFields(run.GetMerged(), output->GetFieldData());
}

void WriteMergedPlugFields(const MergedArrangement& merged, vtkFieldData* fd)
{
  // As the one-rank port 0 writes them: an empty list is left out, the count never.
  const auto add = [fd](const char* name, const std::vector<int>& values, int components)
  {
    if (values.empty() && std::string(name) != names::NumberOfBoundaryPlugs)
    {
      return;
    }
    vtkNew<vtkIntArray> array;
    array->SetName(name);
    array->SetNumberOfComponents(components);
    array->SetNumberOfTuples(static_cast<vtkIdType>(values.size() / components));
    std::copy(values.begin(), values.end(), array->GetPointer(0));
    fd->AddArray(array);
  };
  add(names::CellComponent, merged.NodeComponent, 1);
  add(names::ZeroCellCandidates, merged.ZeroNodes, 1);
  add(names::NumberOfBoundaryPlugs, { merged.NumberOfPlugs }, 1);
  std::vector<int> links;
  for (const auto& link : MergedPlugLinks(merged))
  {
    links.push_back(link.first);
    links.push_back(link.second);
  }
  add(names::BoundaryPlugLinks, links, 2);
}

} // namespace boolsurf

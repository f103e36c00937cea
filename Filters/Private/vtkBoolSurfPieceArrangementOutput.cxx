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
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkIntArray> cellOf, source;
  cellOf->SetName(names::ArrangementCell);
  source->SetName(names::SourceTriangle);
  vtkNew<vtkIdTypeArray> triangleId;
  vtkNew<vtkDoubleArray> barycentric;
  triangleId->SetName(names::TriangleId);
  barycentric->SetName(names::Barycentric);
  barycentric->SetNumberOfComponents(2);
  // Output point of each refined point, made on first use (a piece uses few of the refined
  // points of its ring).
  std::vector<vtkIdType> outputPoint(static_cast<std::size_t>(arr.GetNumberOfPoints()), -1);
  for (std::size_t i = 0; i < triangles.size(); ++i)
  {
    const Triangle corners = arr.GetTriangle(mesh, triangles[i]);
    vtkIdType ids[3];
    for (int k = 0; k < 3; ++k)
    {
      vtkIdType& id = outputPoint[corners[k]];
      if (id < 0)
      {
        const Vec3 x = arr.GetPosition(mesh, corners[k]);
        id = points->InsertNextPoint(x.x, x.y, x.z);
        // On global triangle ids; a mesh vertex names one of its triangles in the piece.
        const SurfacePoint p = arr.GetPointSurface(mesh, corners[k]);
        triangleId->InsertNextValue(piece.GlobalTriangle[p.Triangle]);
        barycentric->InsertNextTuple2(p.U, p.V);
      }
      ids[k] = id;
    }
    polys->InsertNextCell(3, ids);
    cellOf->InsertNextValue(cells[i]);
    source->InsertNextValue(sources[i]);
  }
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

#include "vtkBoolSurfSurfaceAdapter.h"

#include "vtkBoolSurfPieceSeams.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTriangleFilter.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <limits>
#include <utility>

namespace boolsurf
{
namespace
{

// Calls visit(cells, cellId, n, ids) for every polygon, then every strip, of `input`, with
// its polydata cell id (polygons come after vertices and lines, strips after polygons).
template <class Visit>
void ForEachPolygonOrStrip(vtkPolyData* input, const Visit& visit)
{
  vtkIdType cellId = input->GetNumberOfVerts() + input->GetNumberOfLines();
  for (vtkCellArray* cells : { input->GetPolys(), input->GetStrips() })
  {
    auto it = vtk::TakeSmartPointer(cells->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++cellId)
    {
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      visit(cells, cellId, n, ids);
    }
  }
}

// Index of the first id outside [0, points), or -1.
vtkIdType FirstInvalidId(vtkIdType n, const vtkIdType* ids, vtkIdType points)
{
  for (vtkIdType k = 0; k < n; ++k)
  {
    if (ids[k] < 0 || ids[k] >= points)
    {
      return k;
    }
  }
  return -1;
}

// Polygon and strip cells naming a point id outside [0, points): (cell id, first bad id). They
// are checked before anything reads them (vtkTriangleFilter would crash on them or drop the
// cell silently, and a conversion to int would wrap ids of 2^32 and more).
std::vector<std::pair<vtkIdType, vtkIdType>> CellsWithInvalidIds(vtkPolyData* input)
{
  std::vector<std::pair<vtkIdType, vtkIdType>> bad;
  const vtkIdType np = input->GetNumberOfPoints();
  ForEachPolygonOrStrip(input,
    [&](vtkCellArray*, vtkIdType cellId, vtkIdType n, const vtkIdType* ids)
    {
      const vtkIdType k = FirstInvalidId(n, ids, np);
      if (k >= 0)
      {
        bad.emplace_back(cellId, ids[k]);
      }
    });
  return bad;
}

// A copy of `input`'s points and polygons/strips without the cells naming invalid point ids.
vtkSmartPointer<vtkPolyData> WithoutInvalidCells(vtkPolyData* input)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->SetPoints(input->GetPoints());
  copy->GetPointData()->ShallowCopy(input->GetPointData());
  vtkNew<vtkCellArray> polys, strips;
  const vtkIdType np = input->GetNumberOfPoints();
  ForEachPolygonOrStrip(input,
    [&](vtkCellArray* cells, vtkIdType, vtkIdType n, const vtkIdType* ids)
    {
      if (FirstInvalidId(n, ids, np) < 0)
      {
        (cells == input->GetPolys() ? polys.GetPointer() : strips.GetPointer())
          ->InsertNextCell(n, ids);
      }
    });
  copy->SetPolys(polys);
  copy->SetStrips(strips);
  return copy;
}

// Number of polygons with other than three points.
vtkIdType CountNonTriangles(vtkCellArray* polys)
{
  vtkIdType count = 0;
  auto it = vtk::TakeSmartPointer(polys->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    count += n != 3 ? 1 : 0;
  }
  return count;
}

// ConvertSurface without the pieces' seams: the input as it is.
void ConvertOnce(vtkPolyData* input, vtkSurfaceInput& out, const SurfaceCheckOptions& options)
{
  out = vtkSurfaceInput();
  out.Triangles = vtkSmartPointer<vtkPolyData>::New();
  SurfaceProblem invalidIds;
  vtkSmartPointer<vtkPolyData> filtered; // the input without its invalid cells, when it has some
  if (input && input->GetNumberOfPoints() > std::numeric_limits<int>::max())
  {
    invalidIds.Kind = "TooManyPoints";
    invalidIds.Message = "the surface has " + std::to_string(input->GetNumberOfPoints()) +
      " points; at most " + std::to_string(std::numeric_limits<int>::max()) + " are supported";
    input = nullptr;
  }
  if (input)
  {
    const std::vector<std::pair<vtkIdType, vtkIdType>> bad = CellsWithInvalidIds(input);
    if (!bad.empty())
    {
      invalidIds.Kind = "InvalidVertexIndex";
      invalidIds.Message = std::to_string(bad.size()) + " polygon(s) use point ids outside [0, " +
        std::to_string(input->GetNumberOfPoints()) + "), cell id (point id)";
      for (size_t i = 0; i < bad.size(); ++i)
      {
        if (i == 10)
        {
          invalidIds.Message += " ... and " + std::to_string(bad.size() - 10) + " more";
          break;
        }
        invalidIds.Message += std::string(i ? ", " : ": ") + std::to_string(bad[i].first) + " (" +
          std::to_string(bad[i].second) + ")";
      }
      for (const auto& cell : bad)
      {
        invalidIds.Ids.push_back(cell.first);
      }
      // The rest of the surface is still converted, so Check Surface can describe it.
      filtered = WithoutInvalidCells(input);
      input = filtered;
    }
  }
  if (input)
  {
    const vtkIdType verts = input->GetNumberOfVerts();
    const vtkIdType lines = input->GetNumberOfLines();
    const vtkIdType strips = input->GetNumberOfStrips();
    const vtkIdType nonTriangles = CountNonTriangles(input->GetPolys());
    if (verts + lines > 0)
    {
      out.Warnings.push_back("ignored " + std::to_string(verts) + " vertex cell(s) and " +
        std::to_string(lines) + " line cell(s) of the surface input: only polygons are used");
    }
    if (nonTriangles + strips > 0)
    {
      out.Warnings.push_back("triangulated " + std::to_string(nonTriangles) +
        " non-triangle polygon(s) and " + std::to_string(strips) +
        " triangle strip(s); output cell ids refer to the triangles");
    }
    if (verts + lines + strips + nonTriangles == 0)
    {
      out.Triangles->ShallowCopy(input);
    }
    else
    {
      vtkNew<vtkTriangleFilter> triangulate;
      triangulate->PassVertsOff();
      triangulate->PassLinesOff();
      triangulate->SetInputData(input);
      triangulate->Update();
      out.Triangles->ShallowCopy(triangulate->GetOutput());
    }
  }

  // Copied in parallel blocks (a mesh of millions of triangles is opened once, and this copy
  // is part of what the user waits for): reading tuples into a local buffer is thread-safe.
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;
  if (vtkPoints* points = out.Triangles->GetPoints())
  {
    vtkDataArray* coordinates = points->GetData();
    positions.resize(points->GetNumberOfPoints());
    tbb::parallel_for(tbb::blocked_range<vtkIdType>(0, points->GetNumberOfPoints(), 1 << 14),
      [&](const tbb::blocked_range<vtkIdType>& range)
      {
        double p[3];
        for (vtkIdType i = range.begin(); i != range.end(); ++i)
        {
          coordinates->GetTuple(i, p);
          positions[i] = { p[0], p[1], p[2] };
        }
      });
  }
  // vtkTriangleFilter drops polygons it cannot triangulate, so every cell here has 3 ids:
  // cell i is connectivity entries 3i .. 3i + 2.
  vtkCellArray* polys = out.Triangles->GetPolys();
  vtkDataArray* connectivity = polys->GetConnectivityArray();
  triangles.resize(polys->GetNumberOfCells());
  if (connectivity->GetNumberOfValues() != 3 * polys->GetNumberOfCells())
  {
    // Not expected after the checks above; cells are then read one by one, their first three
    // ids each.
    vtkIdType i = 0;
    auto it = vtk::TakeSmartPointer(polys->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++i)
    {
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      for (int k = 0; k < 3; ++k)
      {
        triangles[i][k] = k < n ? static_cast<int>(ids[k]) : -1;
      }
    }
  }
  else
  {
    tbb::parallel_for(tbb::blocked_range<vtkIdType>(0, polys->GetNumberOfCells(), 1 << 14),
      [&](const tbb::blocked_range<vtkIdType>& range)
      {
        for (vtkIdType i = range.begin(); i != range.end(); ++i)
        {
          for (int k = 0; k < 3; ++k)
          {
            triangles[i][k] = static_cast<int>(connectivity->GetComponent(3 * i + k, 0));
          }
        }
      });
  }
  auto mesh = std::make_shared<TriangleMesh>(std::move(positions), std::move(triangles));
  auto topology = std::make_shared<MeshTopology>(MeshTopology::Compute(*mesh));
  MeshTopology::Share(*mesh, topology); // the site graph, if a far leg builds one, reads it
  out.Check = CheckSurface(*mesh, *topology, options);
  if (!invalidIds.Kind.empty())
  {
    out.Check.Problems.insert(out.Check.Problems.begin(), invalidIds);
  }
  out.Mesh = mesh;
  out.Topology = topology;
}
} // namespace

//------------------------------------------------------------------------------
void ConvertSurface(vtkPolyData* input, vtkSurfaceInput& out, const SurfaceCheckOptions& options)
{
  // The appended pieces of a partitioned file (vtkBoolSurfPieceSeams.h): their ghost cells
  // dropped, then their shared points welded and the triangles converted again.
  vtkSmartPointer<vtkPolyData> owned = WithoutGhostCells(input);
  ConvertOnce(owned ? owned.GetPointer() : input, out, options);
  if (!out.Mesh || out.Mesh->GetNumberOfTriangles() == 0)
  {
    return;
  }
  if (vtkSmartPointer<vtkPolyData> welded = WeldPieceSeams(out.Triangles, *out.Mesh))
  {
    // The first conversion's notes and id problems are the input's; the welded triangles have
    // none of their own.
    std::vector<std::string> warnings = std::move(out.Warnings);
    std::vector<SurfaceProblem> inputProblems;
    for (const SurfaceProblem& p : out.Check.Problems)
    {
      if (p.Kind == "InvalidVertexIndex" || p.Kind == "TooManyPoints")
      {
        inputProblems.push_back(p);
      }
    }
    ConvertOnce(welded, out, options);
    out.Warnings = std::move(warnings);
    out.Check.Problems.insert(
      out.Check.Problems.begin(), inputProblems.begin(), inputProblems.end());
  }
}

} // namespace boolsurf

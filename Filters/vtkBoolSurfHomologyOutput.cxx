#include "vtkBoolSurfHomologyOutput.h"

#include "Homology/HomologyBasis.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>

namespace boolsurf
{
namespace
{

void NameGeneratorComponents(vtkDataArray* a, int generators)
{
  a->SetNumberOfComponents(generators);
  for (int g = 0; g < generators; ++g)
  {
    a->SetComponentName(g, ("G" + std::to_string(g)).c_str());
  }
}

vtkSmartPointer<vtkIntArray> Ints(const char* name, const std::vector<int>& values)
{
  auto a = vtkSmartPointer<vtkIntArray>::New();
  a->SetName(name);
  a->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  std::copy(values.begin(), values.end(), a->GetPointer(0));
  return a;
}

std::vector<int> ReadInts(vtkFieldData* fd, const char* name)
{
  std::vector<int> out;
  vtkDataArray* a = fd ? fd->GetArray(name) : nullptr;
  if (!a)
  {
    return out;
  }
  const vtkIdType n = a->GetNumberOfTuples() * a->GetNumberOfComponents();
  out.resize(static_cast<size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    out[i] = static_cast<int>(a->GetComponent(
      i / a->GetNumberOfComponents(), static_cast<int>(i % a->GetNumberOfComponents())));
  }
  return out;
}

std::string Signed(int x)
{
  return (x > 0 ? "+" : "") + std::to_string(x);
}

} // namespace

//------------------------------------------------------------------------------
bool AddHomologyFields(const TriangleMesh& mesh,
  const HomologyBasis& basis,
  const std::vector<TracedCurve>& curves,
  vtkFieldData* fd,
  std::string& error)
{
  const int ng = basis.GetNumberOfGenerators();
  fd->AddArray(Ints("NumberOfHomologyGenerators", { ng }));
  if (ng == 0)
  {
    return true; // genus 0: no generators, every class is zero (no empty arrays written)
  }
  std::vector<int> ids, shapes, classes;
  std::vector<int> h;
  for (const TracedCurve& c : curves)
  {
    if (!basis.ClassOf(c, h, error))
    {
      return false;
    }
    ids.push_back(c.CurveId);
    shapes.push_back(c.ShapeId);
    classes.insert(classes.end(), h.begin(), h.end());
  }
  if (!curves.empty())
  {
    vtkNew<vtkIntArray> table;
    table->SetName("CurveHomology");
    NameGeneratorComponents(table, ng);
    table->SetNumberOfTuples(static_cast<vtkIdType>(curves.size()));
    std::copy(classes.begin(), classes.end(), table->GetPointer(0));
    fd->AddArray(table);
    fd->AddArray(Ints("CurveHomologyCurveId", ids));
    fd->AddArray(Ints("CurveHomologyShapeId", shapes));
  }
  std::vector<int> offsets{ 0 }, triangles;
  vtkNew<vtkDoubleArray> positions, barycentric;
  positions->SetName("HomologyGeneratorPoints");
  positions->SetNumberOfComponents(3);
  barycentric->SetName("HomologyGeneratorBarycentric");
  barycentric->SetNumberOfComponents(2);
  for (const HomologyGenerator& g : basis.GetGenerators())
  {
    for (const CanonicalPoint& p : g.Points)
    {
      const Vec3 x = PositionOf(mesh, p);
      positions->InsertNextTuple3(x.x, x.y, x.z);
      const SurfacePoint s = ToSurfacePoint(mesh, p);
      triangles.push_back(s.Triangle);
      barycentric->InsertNextTuple2(s.U, s.V);
    }
    offsets.push_back(static_cast<int>(triangles.size()));
  }
  fd->AddArray(Ints("HomologyGeneratorOffsets", offsets));
  fd->AddArray(Ints("HomologyGeneratorTriangleId", triangles));
  fd->AddArray(positions);
  fd->AddArray(barycentric);
  return true;
}

//------------------------------------------------------------------------------
bool ComputeCurveClasses(const HomologyBasis& basis,
  const std::vector<TracedCurve>& curves,
  HomologyFields& out,
  std::string& error)
{
  out = HomologyFields();
  out.Present = true;
  out.NumberOfGenerators = basis.GetNumberOfGenerators();
  std::vector<int> h;
  for (const TracedCurve& c : curves)
  {
    if (!basis.ClassOf(c, h, error))
    {
      return false;
    }
    out.CurveIds.push_back(c.CurveId);
    out.CurveShapeIds.push_back(c.ShapeId);
    out.CurveClasses.push_back(h);
  }
  return true;
}

//------------------------------------------------------------------------------
HomologyFields ReadHomologyFields(vtkFieldData* fd)
{
  HomologyFields h;
  const std::vector<int> count = ReadInts(fd, "NumberOfHomologyGenerators");
  if (count.size() != 1)
  {
    return h;
  }
  h.Present = true;
  h.NumberOfGenerators = std::max(0, count[0]);
  const int ng = h.NumberOfGenerators;
  if (ng == 0)
  {
    return h;
  }
  h.CurveIds = ReadInts(fd, "CurveHomologyCurveId");
  h.CurveShapeIds = ReadInts(fd, "CurveHomologyShapeId");
  const std::vector<int> table = ReadInts(fd, "CurveHomology");
  const size_t rows = h.CurveIds.size();
  if (h.CurveShapeIds.size() != rows || table.size() != rows * ng)
  {
    h.CurveIds.clear();
    h.CurveShapeIds.clear();
  }
  else
  {
    for (size_t r = 0; r < rows; ++r)
    {
      h.CurveClasses.emplace_back(table.begin() + r * ng, table.begin() + (r + 1) * ng);
    }
  }
  h.GeneratorOffsets = ReadInts(fd, "HomologyGeneratorOffsets");
  const std::vector<int> triangles = ReadInts(fd, "HomologyGeneratorTriangleId");
  vtkDataArray* positions = fd->GetArray("HomologyGeneratorPoints");
  vtkDataArray* barycentric = fd->GetArray("HomologyGeneratorBarycentric");
  const vtkIdType np = static_cast<vtkIdType>(triangles.size());
  if (static_cast<int>(h.GeneratorOffsets.size()) != ng + 1 || h.GeneratorOffsets.back() != np ||
    !positions || !barycentric || positions->GetNumberOfTuples() != np ||
    barycentric->GetNumberOfTuples() != np || positions->GetNumberOfComponents() != 3 ||
    barycentric->GetNumberOfComponents() != 2)
  {
    h.GeneratorOffsets.clear();
    return h;
  }
  for (vtkIdType i = 0; i < np; ++i)
  {
    double x[3];
    positions->GetTuple(i, x);
    h.GeneratorPositions.insert(h.GeneratorPositions.end(), x, x + 3);
    h.GeneratorPoints.push_back(
      { triangles[i], barycentric->GetComponent(i, 0), barycentric->GetComponent(i, 1) });
  }
  return h;
}

//------------------------------------------------------------------------------
std::vector<std::vector<int>> ShapeExcess(const HomologyFields& h, const std::vector<int>& shapeIds)
{
  std::vector<std::vector<int>> excess(shapeIds.size(), std::vector<int>(h.NumberOfGenerators, 0));
  for (size_t r = 0; r < h.CurveClasses.size(); ++r)
  {
    const auto it = std::lower_bound(shapeIds.begin(), shapeIds.end(), h.CurveShapeIds[r]);
    if (it != shapeIds.end() && *it == h.CurveShapeIds[r])
    {
      std::vector<int>& sum = excess[it - shapeIds.begin()];
      for (int g = 0; g < h.NumberOfGenerators; ++g)
      {
        sum[g] += h.CurveClasses[r][g];
      }
    }
  }
  return excess;
}

//------------------------------------------------------------------------------
void AddHomologyExcess(const std::vector<std::vector<int>>& excess,
  const std::vector<int>& shapeIds,
  vtkFieldData* fd)
{
  if (excess.empty() || excess[0].empty())
  {
    return;
  }
  const int ng = static_cast<int>(excess[0].size());
  vtkNew<vtkIntArray> table;
  table->SetName("HomologyExcess");
  NameGeneratorComponents(table, ng);
  table->SetNumberOfTuples(static_cast<vtkIdType>(excess.size()));
  for (size_t s = 0; s < excess.size(); ++s)
  {
    std::copy(
      excess[s].begin(), excess[s].end(), table->GetPointer(static_cast<vtkIdType>(s) * ng));
  }
  (void)shapeIds; // rows follow ShapeIds, written by the labeling next to this table
  fd->AddArray(table);
}

//------------------------------------------------------------------------------
std::string DescribeClass(const std::vector<int>& homology)
{
  std::string text;
  for (size_t g = 0; g < homology.size(); ++g)
  {
    if (homology[g] != 0)
    {
      text += (text.empty() ? "" : ", ") + Signed(homology[g]) + " x G" + std::to_string(g);
    }
  }
  return text.empty() ? "no generator" : text;
}

//------------------------------------------------------------------------------
std::string ExplainInconsistency(const LabelingResult& labels, const HomologyFields& h)
{
  std::string text;
  for (int s = 0; s < labels.NumberOfShapes; ++s)
  {
    if (labels.ShapeConsistent[s])
    {
      continue;
    }
    const int shapeId = labels.ShapeIdOf(s);
    std::string curves;
    std::vector<int> excess(h.NumberOfGenerators, 0);
    std::vector<int> offending;
    for (size_t r = 0; r < h.CurveClasses.size(); ++r)
    {
      if (h.CurveShapeIds[r] != shapeId)
      {
        continue;
      }
      const std::vector<int>& c = h.CurveClasses[r];
      for (int g = 0; g < h.NumberOfGenerators; ++g)
      {
        excess[g] += c[g];
      }
      if (std::any_of(c.begin(), c.end(), [](int x) { return x != 0; }))
      {
        offending.push_back(h.CurveIds[r]);
        curves += (curves.empty() ? "" : "; ") + std::string("curve ") +
          std::to_string(h.CurveIds[r]) + " winds " + DescribeClass(c);
      }
    }
    text += (text.empty() ? "" : "\n") + std::string("Shape S") + std::to_string(shapeId) + ": ";
    if (offending.empty())
    {
      text += "no curve winds around a handle of the surface (an open curve, or curves meeting "
              "within rounding, keep the labels from agreeing).";
      continue;
    }
    std::string ids;
    for (int id : offending)
    {
      ids += (ids.empty() ? "" : ", ") + std::to_string(id);
    }
    text += curves + ". Generators in excess: " + DescribeClass(excess) +
      " (drawn by the second output of Label Arrangement Cells). Its curves do not bound a "
      "region. Fixes (Resolve Inconsistent Shapes, Strategy): AddGenerators adds a reversed "
      "copy of each generator in excess so the shape closes across the handles; "
      "DuplicateReversed turns each offending curve (" +
      ids +
      ") into a thin solid strip with a reversed copy beside it; RemoveCurves drops (or flips) "
      "curves whose windings add up to the excess.";
  }
  return text;
}

//------------------------------------------------------------------------------
void WriteGeneratorPolylines(const HomologyFields& h, vtkPolyData* out)
{
  out->Initialize();
  const int ng = static_cast<int>(h.GeneratorOffsets.size()) - 1;
  if (ng <= 0)
  {
    return;
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkIntArray> triangleId, generatorId;
  vtkNew<vtkDoubleArray> barycentric;
  triangleId->SetName("TriangleId");
  barycentric->SetName("Barycentric");
  barycentric->SetNumberOfComponents(2);
  generatorId->SetName("GeneratorId");
  vtkNew<vtkCellArray> lines;
  const vtkIdType np = static_cast<vtkIdType>(h.GeneratorPoints.size());
  for (vtkIdType i = 0; i < np; ++i)
  {
    points->InsertNextPoint(&h.GeneratorPositions[3 * i]);
    triangleId->InsertNextValue(h.GeneratorPoints[i].Triangle);
    barycentric->InsertNextTuple2(h.GeneratorPoints[i].U, h.GeneratorPoints[i].V);
  }
  for (int g = 0; g < ng; ++g)
  {
    const int first = h.GeneratorOffsets[g], last = h.GeneratorOffsets[g + 1];
    lines->InsertNextCell(last - first + 1);
    for (int i = first; i < last; ++i)
    {
      lines->InsertCellPoint(i);
    }
    lines->InsertCellPoint(first); // closed loop
    generatorId->InsertNextValue(g);
  }
  out->SetPoints(points);
  out->SetLines(lines);
  out->GetPointData()->AddArray(triangleId);
  out->GetPointData()->AddArray(barycentric);
  out->GetCellData()->AddArray(generatorId);
}

} // namespace boolsurf

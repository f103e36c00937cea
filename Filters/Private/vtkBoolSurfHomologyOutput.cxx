#include "vtkBoolSurfHomologyOutput.h"

#include "vtkBoolSurfArrayNames.h"
#include "vtkBoolSurfOutputReuse.h"

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

// Closed loops of edge points as field data <prefix>Offsets, <prefix>Points (xyz),
// <prefix>TriangleId, <prefix>Barycentric, <prefix>Id.
void WriteLoops(const TriangleMesh& mesh,
  const std::string& prefix,
  const std::vector<std::vector<CanonicalPoint>>& loops,
  const std::vector<int>& ids,
  vtkFieldData* fd)
{
  std::vector<int> offsets{ 0 }, triangles;
  vtkNew<vtkDoubleArray> positions, barycentric;
  positions->SetName((prefix + boolsurf::names::LoopPoints).c_str());
  positions->SetNumberOfComponents(3);
  barycentric->SetName((prefix + boolsurf::names::Barycentric).c_str());
  barycentric->SetNumberOfComponents(2);
  for (const std::vector<CanonicalPoint>& loop : loops)
  {
    for (const CanonicalPoint& p : loop)
    {
      const Vec3 x = PositionOf(mesh, p);
      positions->InsertNextTuple3(x.x, x.y, x.z);
      const SurfacePoint sp = ToSurfacePoint(mesh, p);
      triangles.push_back(sp.Triangle);
      barycentric->InsertNextTuple2(sp.U, sp.V);
    }
    offsets.push_back(static_cast<int>(triangles.size()));
  }
  fd->AddArray(Ints((prefix + boolsurf::names::LoopOffsets).c_str(), offsets));
  fd->AddArray(Ints((prefix + boolsurf::names::TriangleId).c_str(), triangles));
  fd->AddArray(Ints((prefix + boolsurf::names::LoopId).c_str(), ids));
  fd->AddArray(positions);
  fd->AddArray(barycentric);
}

// Reads what WriteLoops wrote; false when absent or inconsistent.
bool ReadLoops(vtkFieldData* fd, const std::string& prefix, HomologyLoops& out)
{
  out = HomologyLoops();
  out.Offsets = ReadInts(fd, (prefix + boolsurf::names::LoopOffsets).c_str());
  out.Ids = ReadInts(fd, (prefix + boolsurf::names::LoopId).c_str());
  const std::vector<int> triangles = ReadInts(fd, (prefix + boolsurf::names::TriangleId).c_str());
  vtkDataArray* positions = fd->GetArray((prefix + boolsurf::names::LoopPoints).c_str());
  vtkDataArray* barycentric = fd->GetArray((prefix + boolsurf::names::Barycentric).c_str());
  const vtkIdType np = static_cast<vtkIdType>(triangles.size());
  if (out.Offsets.empty() || out.Ids.size() + 1 != out.Offsets.size() || out.Offsets.back() != np ||
    !positions || !barycentric || positions->GetNumberOfTuples() != np ||
    barycentric->GetNumberOfTuples() != np || positions->GetNumberOfComponents() != 3 ||
    barycentric->GetNumberOfComponents() != 2)
  {
    out = HomologyLoops();
    return false;
  }
  for (vtkIdType i = 0; i < np; ++i)
  {
    double x[3];
    positions->GetTuple(i, x);
    out.Positions.insert(out.Positions.end(), x, x + 3);
    out.Points.push_back(
      { triangles[i], barycentric->GetComponent(i, 0), barycentric->GetComponent(i, 1) });
  }
  return true;
}

} // namespace

//------------------------------------------------------------------------------
bool AddHomologyFields(const TriangleMesh& mesh,
  const HomologyBasis& basis,
  const std::vector<TracedCurve>& curves,
  const std::vector<TracedCurve>* shortened,
  vtkFieldData* fd,
  std::string& error,
  vtkFieldData* generatorCache)
{
  const int ng = basis.GetNumberOfGenerators();
  fd->AddArray(Ints(boolsurf::names::NumberOfHomologyGenerators, { ng }));
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
    table->SetName(boolsurf::names::CurveHomology);
    NameGeneratorComponents(table, ng);
    table->SetNumberOfTuples(static_cast<vtkIdType>(curves.size()));
    std::copy(classes.begin(), classes.end(), table->GetPointer(0));
    fd->AddArray(table);
    fd->AddArray(Ints(boolsurf::names::CurveHomologyCurveId, ids));
    fd->AddArray(Ints(boolsurf::names::CurveHomologyShapeId, shapes));
  }
  if (generatorCache && generatorCache->GetNumberOfArrays() > 0)
  {
    for (int a = 0; a < generatorCache->GetNumberOfArrays(); ++a)
    {
      fd->AddArray(generatorCache->GetAbstractArray(a));
    }
    return true;
  }
  vtkFieldData* generators = generatorCache ? generatorCache : fd;
  std::vector<std::vector<CanonicalPoint>> loops;
  std::vector<int> loopIds;
  for (int g = 0; g < ng; ++g)
  {
    loops.push_back(basis.GetGenerator(g).Points);
    loopIds.push_back(g);
  }
  WriteLoops(mesh, boolsurf::names::HomologyGenerator, loops, loopIds, generators);
  if (shortened)
  {
    loops.clear();
    loopIds.clear();
    for (size_t g = 0; g < shortened->size(); ++g)
    {
      if (!(*shortened)[g].Points.empty())
      {
        loops.push_back((*shortened)[g].Points);
        loopIds.push_back(static_cast<int>(g));
      }
    }
    if (!loops.empty())
    {
      WriteLoops(mesh, boolsurf::names::HomologyShortGenerator, loops, loopIds, generators);
    }
  }
  if (generatorCache)
  {
    for (int a = 0; a < generatorCache->GetNumberOfArrays(); ++a)
    {
      fd->AddArray(generatorCache->GetAbstractArray(a));
    }
  }
  return true;
}

//------------------------------------------------------------------------------
HomologyFields ReadHomologyFields(vtkFieldData* fd, bool withLoops)
{
  HomologyFields h;
  const std::vector<int> count = ReadInts(fd, boolsurf::names::NumberOfHomologyGenerators);
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
  h.CurveIds = ReadInts(fd, boolsurf::names::CurveHomologyCurveId);
  h.CurveShapeIds = ReadInts(fd, boolsurf::names::CurveHomologyShapeId);
  const std::vector<int> table = ReadInts(fd, boolsurf::names::CurveHomology);
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
  if (withLoops)
  {
    ReadLoops(fd, boolsurf::names::HomologyGenerator, h.Generators);
    ReadLoops(fd, boolsurf::names::HomologyShortGenerator, h.ShortGenerators);
  }
  return h;
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
  table->SetName(boolsurf::names::HomologyExcess);
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
void WriteGeneratorPolylines(const HomologyFields& h, vtkPolyData* out)
{
  EmptyPolyData(out);
  if (h.Generators.Ids.empty())
  {
    return;
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkIntArray> triangleId, generatorId, shortened;
  vtkNew<vtkDoubleArray> barycentric;
  triangleId->SetName(boolsurf::names::TriangleId);
  barycentric->SetName(boolsurf::names::Barycentric);
  barycentric->SetNumberOfComponents(2);
  generatorId->SetName(boolsurf::names::GeneratorId);
  shortened->SetName(boolsurf::names::Shortened);
  vtkNew<vtkCellArray> lines;
  for (const HomologyLoops* loops : { &h.Generators, &h.ShortGenerators })
  {
    const vtkIdType base = points->GetNumberOfPoints();
    for (size_t i = 0; i < loops->Points.size(); ++i)
    {
      points->InsertNextPoint(&loops->Positions[3 * i]);
      triangleId->InsertNextValue(loops->Points[i].Triangle);
      barycentric->InsertNextTuple2(loops->Points[i].U, loops->Points[i].V);
    }
    for (size_t g = 0; g < loops->Ids.size(); ++g)
    {
      const int first = loops->Offsets[g], last = loops->Offsets[g + 1];
      lines->InsertNextCell(last - first + 1);
      for (int i = first; i < last; ++i)
      {
        lines->InsertCellPoint(base + i);
      }
      lines->InsertCellPoint(base + first); // closed loop
      generatorId->InsertNextValue(loops->Ids[g]);
      shortened->InsertNextValue(loops == &h.ShortGenerators ? 1 : 0);
    }
  }
  out->SetPoints(points);
  out->SetLines(lines);
  out->GetPointData()->AddArray(triangleId);
  out->GetPointData()->AddArray(barycentric);
  out->GetCellData()->AddArray(generatorId);
  out->GetCellData()->AddArray(shortened);
}

} // namespace boolsurf

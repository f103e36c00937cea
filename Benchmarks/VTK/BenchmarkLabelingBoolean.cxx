// Labeling and Boolean selection times on the reference scenes whose meshes are present
// (the scenes' curves are traced and arranged once, outside the timed loop).
// Run: BoolSurfVTKBenchmarks --benchmark_filter=Labeling
#include "../SharedScenes.h"
#include "vtkBoolSurfArrangement.h"
#include "vtkBoolSurfBoolean.h"
#include "vtkBoolSurfLabeling.h"
#include "vtkBoolSurfTraceCurves.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPLYReader.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <map>
#include <memory>

namespace
{

struct PreparedScene
{
  vtkSmartPointer<vtkPolyData> Arranged; // refined surface (port 0 of the arrangement)
  std::string Expression;                // union of the consistent shapes
  std::string Error;
  int Cells = 0;
};

// Control polygons from the scene's face/uv points, shapes and closedness.
vtkSmartPointer<vtkPolyData> SceneCurves(const nlohmann::json& scene, vtkPolyData* mesh)
{
  auto curves = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkIdTypeArray> tri;
  tri->SetName("TriangleId");
  vtkNew<vtkDoubleArray> bary;
  bary->SetName("Barycentric");
  bary->SetNumberOfComponents(2);
  for (const auto& p : scene["points"])
  {
    const vtkIdType f = p["face"].get<vtkIdType>();
    const double u = p["uv"][0].get<double>(), v = p["uv"][1].get<double>();
    const vtkIdType* ids;
    vtkIdType n;
    mesh->GetCellPoints(f, n, ids);
    double a[3], b[3], c[3], x[3];
    mesh->GetPoint(ids[0], a);
    mesh->GetPoint(ids[1], b);
    mesh->GetPoint(ids[2], c);
    for (int k = 0; k < 3; ++k)
    {
      x[k] = (1 - u - v) * a[k] + u * b[k] + v * c[k];
    }
    points->InsertNextPoint(x);
    tri->InsertNextValue(f);
    bary->InsertNextTuple2(u, v);
  }
  const auto& polygons = scene["polygons"];
  std::vector<int> shapeOf(polygons.size());
  for (size_t i = 0; i < polygons.size(); ++i)
  {
    shapeOf[i] = static_cast<int>(i);
  }
  if (scene.contains("shapes"))
  {
    for (size_t s = 0; s < scene["shapes"].size(); ++s)
    {
      for (const auto& poly : scene["shapes"][s])
      {
        shapeOf[poly.get<size_t>()] = static_cast<int>(s);
      }
    }
  }
  vtkNew<vtkCellArray> lines, polys;
  vtkNew<vtkIntArray> lineShapes, polyShapes;
  for (size_t i = 0; i < polygons.size(); ++i)
  {
    if (polygons[i].size() < 2)
    {
      continue;
    }
    const bool closed = !scene.contains("are_closed") || scene["are_closed"][i].get<bool>();
    vtkCellArray* cells = closed ? polys.GetPointer() : lines.GetPointer();
    cells->InsertNextCell(static_cast<vtkIdType>(polygons[i].size()));
    for (const auto& id : polygons[i])
    {
      cells->InsertCellPoint(id.get<vtkIdType>());
    }
    (closed ? polyShapes : lineShapes)->InsertNextValue(shapeOf[i]);
  }
  vtkNew<vtkIntArray> shapes;
  shapes->SetName("ShapeId");
  for (vtkIdType i = 0; i < lineShapes->GetNumberOfTuples(); ++i)
  {
    shapes->InsertNextValue(lineShapes->GetValue(i));
  }
  for (vtkIdType i = 0; i < polyShapes->GetNumberOfTuples(); ++i)
  {
    shapes->InsertNextValue(polyShapes->GetValue(i));
  }
  curves->SetPoints(points);
  curves->SetLines(lines);
  curves->SetPolys(polys);
  curves->GetPointData()->AddArray(tri);
  curves->GetPointData()->AddArray(bary);
  curves->GetCellData()->AddArray(shapes);
  return curves;
}

const PreparedScene& Prepare(const benchutil::SceneFile& file)
{
  static std::map<std::string, std::unique_ptr<PreparedScene>> cache;
  auto& slot = cache[file.Scene];
  if (slot)
  {
    return *slot;
  }
  slot = std::make_unique<PreparedScene>();
  const std::string data = BOOLSURF_SHARED_DATA_DIR;
  std::ifstream in(data + "/boolsurf-scenes/" + file.Scene);
  const nlohmann::json scene = nlohmann::json::parse(in, nullptr, false);
  if (scene.is_discarded() || !scene.contains("points"))
  {
    slot->Error = "cannot read scene " + file.Scene;
    return *slot;
  }
  vtkNew<vtkPLYReader> reader;
  reader->SetFileName((data + "/meshes/" + file.Mesh).c_str());
  reader->Update();
  vtkPolyData* mesh = reader->GetOutput();
  vtkNew<vtkBoolSurfTraceCurves> trace;
  trace->SetInputData(0, mesh);
  trace->SetInputData(1, SceneCurves(scene, mesh));
  vtkNew<vtkBoolSurfArrangement> arrangement;
  arrangement->SetInputData(0, mesh);
  arrangement->SetInputConnection(1, trace->GetOutputPort());
  vtkNew<vtkBoolSurfLabeling> labeling;
  labeling->SetInputConnection(arrangement->GetOutputPort(0));
  labeling->Update();
  slot->Arranged = vtkSmartPointer<vtkPolyData>::New();
  slot->Arranged->ShallowCopy(arrangement->GetOutput(0));
  vtkDataArray* consistent = labeling->GetOutput()->GetFieldData()->GetArray("ShapeConsistent");
  if (!consistent || !slot->Arranged->GetFieldData()->GetArray("NumberOfCells"))
  {
    slot->Error = "the pipeline failed on " + file.Scene;
    return *slot;
  }
  slot->Cells =
    static_cast<int>(slot->Arranged->GetFieldData()->GetArray("NumberOfCells")->GetComponent(0, 0));
  for (vtkIdType s = 0; s < consistent->GetNumberOfTuples(); ++s)
  {
    if (consistent->GetComponent(s, 0) != 0)
    {
      slot->Expression += (slot->Expression.empty() ? "S" : " | S") + std::to_string(s);
    }
  }
  return *slot;
}

void BM_Labeling(benchmark::State& state, benchutil::SceneFile file)
{
  const PreparedScene& scene = Prepare(file);
  if (!scene.Error.empty())
  {
    state.SkipWithError(scene.Error.c_str());
    return;
  }
  vtkNew<vtkBoolSurfLabeling> labeling;
  labeling->SetInputData(scene.Arranged);
  for (auto _ : state)
  {
    labeling->Modified();
    labeling->Update();
  }
  state.counters["cells"] = scene.Cells;
  state.counters["triangles"] = static_cast<double>(scene.Arranged->GetNumberOfCells());
}

void BM_Boolean(benchmark::State& state, benchutil::SceneFile file)
{
  const PreparedScene& scene = Prepare(file);
  if (!scene.Error.empty() || scene.Expression.empty())
  {
    state.SkipWithError(scene.Error.empty() ? "no consistent shape" : scene.Error.c_str());
    return;
  }
  vtkNew<vtkBoolSurfLabeling> labeling;
  labeling->SetInputData(scene.Arranged);
  labeling->Update();
  vtkNew<vtkBoolSurfBoolean> boolean;
  boolean->SetInputConnection(labeling->GetOutputPort());
  boolean->SetOperationToExpression();
  boolean->SetExpression(scene.Expression.c_str());
  for (auto _ : state)
  {
    boolean->Modified();
    boolean->Update();
  }
  state.counters["cells"] = scene.Cells;
}

// Registered at start-up: one benchmark per available scene.
const bool registered = []
{
  for (const benchutil::SceneFile& file : benchutil::AvailableScenes(BOOLSURF_SHARED_DATA_DIR))
  {
    benchmark::RegisterBenchmark(("BM_Labeling/" + file.Scene).c_str(), BM_Labeling, file)
      ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("BM_Boolean/" + file.Scene).c_str(), BM_Boolean, file)
      ->Unit(benchmark::kMillisecond);
  }
  return true;
}();

} // namespace

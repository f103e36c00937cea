// Labeling and Boolean selection times on the reference scenes whose meshes are present
// (the scenes' curves are traced and arranged once, outside the timed loop).
// Run: BoolSurfVTKBenchmarks --benchmark_filter=Labeling
#include "../SharedScenes.h"
#include "vtkBoolSurfArrangement.h"
#include "vtkBoolSurfBoolean.h"
#include "vtkBoolSurfLabeling.h"
#include "vtkBoolSurfSceneReader.h"
#include "vtkBoolSurfTraceCurves.h"

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>

#include <benchmark/benchmark.h>

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
  vtkNew<vtkBoolSurfSceneReader> reader;
  reader->SetFileName((data + "/boolsurf-scenes/" + file.Scene).c_str());
  reader->SetMeshFileName((data + "/meshes/" + file.Mesh).c_str());
  reader->Update();
  vtkPolyData* mesh = reader->GetOutput(0);
  if (mesh->GetNumberOfCells() == 0 || reader->GetCurvesOutput()->GetNumberOfCells() == 0)
  {
    slot->Error = "cannot read scene " + file.Scene;
    return *slot;
  }
  vtkNew<vtkBoolSurfTraceCurves> trace;
  trace->SetInputData(0, mesh);
  trace->SetInputConnection(1, reader->GetOutputPort(1));
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

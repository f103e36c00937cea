// The reference scenes whose meshes are present, through the VTK filters: labeling and Boolean
// selection on an arrangement made once outside the timed loop (BM_Labeling, BM_Boolean), and
// whole edits of the one-step filter with per-stage times (BM_OneStepScene/<scene>/<threads>).
// Run: BoolSurfVTKBenchmarks --benchmark_filter='Labeling|Boolean|OneStepScene'
#include "../SharedScenes.h"
#include "vtkBoolSurf.h"
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
  vtkSmartPointer<vtkPolyData> Arranged;     // refined surface (port 0 of the arrangement)
  std::string Expression;                    // union of the consistent shapes
  vtkSmartPointer<vtkPolyData> Mesh, Curves; // the scene's inputs
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
  // ShapeConsistent is per shape index, in the order of ShapeIds.
  vtkDataArray* ids = labeling->GetOutput()->GetFieldData()->GetArray("ShapeIds");
  for (vtkIdType s = 0; ids && s < consistent->GetNumberOfTuples(); ++s)
  {
    if (consistent->GetComponent(s, 0) != 0)
    {
      slot->Expression += (slot->Expression.empty() ? "S" : " | S") +
        std::to_string(static_cast<int>(ids->GetComponent(s, 0)));
    }
  }
  slot->Mesh = vtkSmartPointer<vtkPolyData>::New();
  slot->Mesh->DeepCopy(mesh);
  slot->Curves = vtkSmartPointer<vtkPolyData>::New();
  slot->Curves->DeepCopy(reader->GetCurvesOutput());
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

// What an edit of a reference scene costs through the one-step filter: the curves are marked
// modified every iteration, so tracing, arrangement, labeling and the Boolean all rerun on the
// cached surface (arrange + label is what the authors' tool times for its scenes).
void BM_OneStepScene(benchmark::State& state, benchutil::SceneFile file)
{
  const PreparedScene& scene = Prepare(file);
  if (!scene.Error.empty() || scene.Expression.empty())
  {
    state.SkipWithError(scene.Error.empty() ? "no consistent shape" : scene.Error.c_str());
    return;
  }
  vtkNew<vtkBoolSurf> one;
  one->SetInputData(0, scene.Mesh);
  one->SetInputData(1, scene.Curves);
  one->SetOperationToExpression();
  one->SetExpression(scene.Expression.c_str());
  one->SetNumberOfThreads(static_cast<int>(state.range(0)));
  one->Update(); // surface conversion, tiles, first trace: not part of an edit
  std::map<std::string, double> sums;
  for (auto _ : state)
  {
    scene.Curves->Modified();
    one->Update();
    if (vtkDataArray* t = one->GetOutput()->GetFieldData()->GetArray("StageTimes"))
    {
      for (int k = 0; k < t->GetNumberOfComponents(); ++k)
      {
        sums[t->GetComponentName(k)] += t->GetComponent(0, k);
      }
    }
  }
  const double n = static_cast<double>(state.iterations());
  for (const auto& [name, sum] : sums)
  {
    state.counters[name + "_ms"] = sum / n;
  }
  // Arrangement plus labeling: the stages the authors' command-line tool reports together.
  state.counters["ArrangeLabel_ms"] = (sums["Hash"] + sums["Intersections"] + sums["Refinement"] +
                                        sums["FloodFill"] + sums["CellGraph"] + sums["Labeling"]) /
    n;
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
    benchmark::RegisterBenchmark(("BM_OneStepScene/" + file.Scene).c_str(), BM_OneStepScene, file)
      ->Arg(1)
      ->Arg(2)
      ->Unit(benchmark::kMillisecond);
  }
  return true;
}();

} // namespace

// The reference scenes whose meshes are present, through the VTK filters: labeling and Boolean
// selection on an arrangement made once outside the timed loop (BM_Labeling, BM_Boolean), and
// whole edits of the one-step filter with per-stage times (BM_OneStepScene/<scene>/<threads>).
// BM_BSC/<scene>: Boundary Sampled Curves on the same arrangement, one sample per patch of the
// first curve of every shape, pointing to the patch's left (a shape's inside): against
// BM_Boolean, what choosing the region by samples costs instead of by labels.
// Run: BoolSurfVTKBenchmarks --benchmark_filter='Labeling|Boolean|OneStepScene|BSC'
#include "../SharedScenes.h"
#include "FilterUpdateTimer.h"
#include "vtkBoolSurf.h"
#include "vtkBoolSurfArrangement.h"
#include "vtkBoolSurfBSC.h"
#include "vtkBoolSurfBoolean.h"
#include "vtkBoolSurfLabeling.h"
#include "vtkBoolSurfSceneReader.h"
#include "vtkBoolSurfTraceCurves.h"

#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <map>
#include <memory>
#include <vector>

namespace
{

struct PreparedScene
{
  vtkSmartPointer<vtkPolyData> Arranged;     // refined surface (port 0 of the arrangement)
  std::string Expression;                    // union of the consistent shapes
  vtkSmartPointer<vtkPolyData> Mesh, Curves; // the scene's inputs
  std::string Error;
  int Cells = 0;
  vtkSmartPointer<vtkPolyData> Samples; // BSC samples (built on first use)
};

/// One sample per patch of the first curve of every shape: the middle of the patch's middle
/// segment, pointing to its left (normal x tangent, normal of a refined triangle on the
/// segment).
vtkSmartPointer<vtkPolyData> PatchSamples(vtkPolyData* arranged)
{
  auto samples = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> direction;
  direction->SetName("Direction");
  direction->SetNumberOfComponents(3);
  vtkFieldData* fd = arranged->GetFieldData();
  vtkDataArray* offsets = fd->GetArray("PatchOffsets");
  vtkDataArray* ids = fd->GetArray("PatchPoints");
  vtkDataArray* shape = fd->GetArray("PatchShape");
  vtkDataArray* curve = fd->GetArray("PatchCurve");
  if (!offsets || !ids || !shape || !curve)
  {
    return samples;
  }
  arranged->BuildLinks();
  std::map<int, int> firstCurve; // shape -> its first curve id
  vtkNew<vtkIdList> cells;
  for (vtkIdType p = 0; p + 1 < offsets->GetNumberOfTuples(); ++p)
  {
    const int s = static_cast<int>(shape->GetComponent(p, 0));
    const int c = static_cast<int>(curve->GetComponent(p, 0));
    if (firstCurve.emplace(s, c).first->second != c)
    {
      continue;
    }
    const vtkIdType begin = static_cast<vtkIdType>(offsets->GetComponent(p, 0));
    const vtkIdType end = static_cast<vtkIdType>(offsets->GetComponent(p + 1, 0));
    if (end - begin < 2)
    {
      continue;
    }
    const vtkIdType k = begin + (end - begin - 2) / 2;
    const vtkIdType a = static_cast<vtkIdType>(ids->GetComponent(k, 0));
    const vtkIdType b = static_cast<vtkIdType>(ids->GetComponent(k + 1, 0));
    arranged->GetPointCells(a, cells);
    double normal[3] = { 0, 0, 0 };
    for (vtkIdType i = 0; i < cells->GetNumberOfIds(); ++i)
    {
      vtkIdType n;
      const vtkIdType* corners;
      arranged->GetCellPoints(cells->GetId(i), n, corners);
      if (n == 3 && (corners[0] == b || corners[1] == b || corners[2] == b))
      {
        double x0[3], x1[3], x2[3], e1[3], e2[3];
        arranged->GetPoint(corners[0], x0);
        arranged->GetPoint(corners[1], x1);
        arranged->GetPoint(corners[2], x2);
        vtkMath::Subtract(x1, x0, e1);
        vtkMath::Subtract(x2, x0, e2);
        vtkMath::Cross(e1, e2, normal);
        break;
      }
    }
    double xa[3], xb[3], tangent[3], left[3], mid[3];
    arranged->GetPoint(a, xa);
    arranged->GetPoint(b, xb);
    vtkMath::Subtract(xb, xa, tangent);
    vtkMath::Cross(normal, tangent, left);
    if (vtkMath::Norm(left) == 0)
    {
      continue;
    }
    for (int i = 0; i < 3; ++i)
    {
      mid[i] = 0.5 * (xa[i] + xb[i]);
    }
    points->InsertNextPoint(mid);
    direction->InsertNextTuple(left);
  }
  samples->SetPoints(points);
  samples->GetPointData()->AddArray(direction);
  return samples;
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

void BM_BSC(benchmark::State& state, benchutil::SceneFile file)
{
  const PreparedScene& scene = Prepare(file);
  if (!scene.Error.empty())
  {
    state.SkipWithError(scene.Error.c_str());
    return;
  }
  if (!scene.Samples)
  {
    const_cast<PreparedScene&>(scene).Samples = PatchSamples(scene.Arranged);
  }
  vtkNew<vtkBoolSurfBSC> bsc;
  bsc->SetInputData(0, scene.Arranged);
  bsc->SetInputData(1, scene.Samples);
  bsc->SetSnapTolerance(1e-6);
  for (auto _ : state)
  {
    bsc->Modified();
    bsc->Update();
  }
  vtkFieldData* fd = bsc->GetOutput()->GetFieldData();
  vtkDataArray* dropped = fd->GetArray("DroppedSamples");
  vtkDataArray* cuts = fd->GetArray("BSCCuts");
  if (!dropped || !cuts)
  {
    state.SkipWithError("BSC failed");
    return;
  }
  state.counters["cells"] = scene.Cells;
  state.counters["samples"] = static_cast<double>(scene.Samples->GetNumberOfPoints());
  state.counters["dropped"] = static_cast<double>(dropped->GetNumberOfTuples());
  state.counters["cuts"] = cuts->GetComponent(0, 0);
  state.counters["regionTriangles"] = static_cast<double>(bsc->GetOutput()->GetNumberOfCells());
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

/// The stage filters chained on a scene (Trace Surface Curves -> Surface Arrangement -> Label
/// Arrangement Cells -> Surface Boolean of the scene's expression).
struct SceneChain
{
  vtkNew<vtkBoolSurfTraceCurves> Trace;
  vtkNew<vtkBoolSurfArrangement> Arrange;
  vtkNew<vtkBoolSurfLabeling> Label;
  vtkNew<vtkBoolSurfBoolean> Boolean;

  SceneChain(const PreparedScene& scene, int threads)
  {
    this->Trace->SetInputData(0, scene.Mesh);
    this->Trace->SetInputData(1, scene.Curves);
    this->Arrange->SetInputData(0, scene.Mesh);
    this->Arrange->SetInputConnection(1, this->Trace->GetOutputPort());
    this->Arrange->SetNumberOfThreads(threads);
    this->Label->SetInputConnection(this->Arrange->GetOutputPort(0));
    this->Boolean->SetInputConnection(this->Label->GetOutputPort(0));
    this->Boolean->SetOperationToExpression();
    this->Boolean->SetExpression(scene.Expression.c_str());
  }
};

// The same edits through the stage filters (Trace Surface Curves -> Surface Arrangement ->
// Label Arrangement Cells -> Surface Boolean). The benchmark's time is the whole edit as the
// user waits for it: one update of the last filter, as ParaView and pvpython update a pipeline
// (compare with BM_OneStepScene's time: the one-step filter's update on the same edit).
// Counters split it into the filters' own executions (FilterUpdateTimer): tracing (Trace_ms),
// the arrangement with its refined-surface output plus the labeling (ArrangeLabel_ms) and the
// Boolean (Boolean_ms); the rest of the edit is VTK's executive.
void BM_StageChainScene(benchmark::State& state, benchutil::SceneFile file)
{
  const PreparedScene& scene = Prepare(file);
  if (!scene.Error.empty() || scene.Expression.empty())
  {
    state.SkipWithError(scene.Error.empty() ? "no consistent shape" : scene.Error.c_str());
    return;
  }
  SceneChain chain(scene, static_cast<int>(state.range(0)));
  vtkBoolSurfTraceCurves* trace = chain.Trace;
  vtkBoolSurfArrangement* arrange = chain.Arrange;
  vtkBoolSurfLabeling* label = chain.Label;
  vtkBoolSurfBoolean* boolean = chain.Boolean;
  for (int warm = 0; warm < 3; ++warm) // surface conversions, first trace, both buffers
  {
    scene.Curves->Modified();
    boolean->Update();
  }
  // No per-filter fault counts: their system calls would be charged to the chain's edit.
  benchutil::FilterUpdateTimer stages({ trace, arrange, label, boolean }, false);
  // The Core arrangement inside the arrangement filter, per stage (its StageTimes; the last
  // component is its total).
  std::map<std::string, double> core;
  for (auto _ : state)
  {
    scene.Curves->Modified();
    boolean->Update();
    if (vtkDataArray* t = arrange->GetOutput()->GetFieldData()->GetArray("StageTimes"))
    {
      for (int k = 0; k < t->GetNumberOfComponents(); ++k)
      {
        core[t->GetComponentName(k)] += t->GetComponent(0, k);
      }
    }
  }
  const double n = static_cast<double>(state.iterations());
  for (const auto& [name, sum] : core)
  {
    state.counters[(name == "Total" ? "CoreArrangement" : "Core" + name) + "_ms"] = sum / n;
  }
  state.counters["Trace_ms"] = stages.Milliseconds(0) / n;
  state.counters["ArrangeLabel_ms"] = (stages.Milliseconds(1) + stages.Milliseconds(2)) / n;
  state.counters["Boolean_ms"] = stages.Milliseconds(3) / n;
  state.counters["cells"] = scene.Cells;
}

// The one-step filter and the stage chain on the same edits, updated in turn within each
// iteration (the order alternating), so both see the same state of a shared machine: their
// ratio is measured in pairs instead of across runs minutes apart, where this VM drifts by more
// than the difference being measured. Counters: the medians over iterations of each
// pipeline's edit (OneStep_ms, Chain_ms) and of the per-edit ratio (Ratio).
// Benchmarks/VTK/chain_ratio.py sums them over the scenes.
void BM_PairedSceneEdit(benchmark::State& state, benchutil::SceneFile file)
{
  const PreparedScene& scene = Prepare(file);
  if (!scene.Error.empty() || scene.Expression.empty())
  {
    state.SkipWithError(scene.Error.empty() ? "no consistent shape" : scene.Error.c_str());
    return;
  }
  const int threads = static_cast<int>(state.range(0));
  vtkNew<vtkBoolSurf> one;
  one->SetInputData(0, scene.Mesh);
  one->SetInputData(1, scene.Curves);
  one->SetOperationToExpression();
  one->SetExpression(scene.Expression.c_str());
  one->SetNumberOfThreads(threads);
  SceneChain stages(scene, threads);
  vtkBoolSurfBoolean* chain = stages.Boolean;
  for (int warm = 0; warm < 3; ++warm) // surface conversions, first trace, both buffers
  {
    scene.Curves->Modified();
    one->Update();
    chain->Update();
  }
  using Clock = std::chrono::steady_clock;
  const auto timedUpdate = [](vtkAlgorithm* filter)
  {
    const Clock::time_point start = Clock::now();
    filter->Update();
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  };
  std::vector<double> oneMs, chainMs, ratio;
  bool chainFirst = false;
  for (auto _ : state)
  {
    scene.Curves->Modified();
    double a = 0, b = 0;
    if (chainFirst)
    {
      b = timedUpdate(chain);
      a = timedUpdate(one);
    }
    else
    {
      a = timedUpdate(one);
      b = timedUpdate(chain);
    }
    chainFirst = !chainFirst;
    oneMs.push_back(a);
    chainMs.push_back(b);
    ratio.push_back(b / a);
  }
  if (one->GetOutput()->GetNumberOfCells() != chain->GetOutput()->GetNumberOfCells())
  {
    state.SkipWithError("the chain's region differs from the one-step filter's");
    return;
  }
  const auto median = [](std::vector<double>& v)
  {
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  };
  state.counters["OneStep_ms"] = median(oneMs);
  state.counters["Chain_ms"] = median(chainMs);
  state.counters["Ratio"] = median(ratio);
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
    benchmark::RegisterBenchmark(("BM_BSC/" + file.Scene).c_str(), BM_BSC, file)
      ->Unit(benchmark::kMillisecond);
    for (benchmark::internal::Benchmark* edits :
      { benchmark::RegisterBenchmark(
          ("BM_OneStepScene/" + file.Scene).c_str(), BM_OneStepScene, file),
        benchmark::RegisterBenchmark(
          ("BM_StageChainScene/" + file.Scene).c_str(), BM_StageChainScene, file),
        benchmark::RegisterBenchmark(
          ("BM_PairedSceneEdit/" + file.Scene).c_str(), BM_PairedSceneEdit, file) })
    {
      edits->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);
      // A fixed number of edits, for instruction counts under callgrind (where the timings
      // that choose the number of iterations mean nothing).
      if (const char* iterations = std::getenv("BOOLSURF_BENCHMARK_ITERATIONS"))
      {
        edits->Iterations(std::atoi(iterations));
      }
    }
  }
  return true;
}();

} // namespace

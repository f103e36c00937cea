// The paper's randomized benchmark (BoolSurf §5, Fig. 22) through the VTK filters: on every
// shared mesh of at least 100k triangles, trials that each take two random shared SVG drawings,
// map them around one random center with random rotations and sizes (vtkBoolSurfSVGMapper),
// and combine them with a random Boolean among union, intersection, difference and symmetric
// difference (vtkBoolSurf, the one-step filter), where drawing A is the union of the first
// SVG's shapes and drawing B that of the second's.
//
// What is timed is what a user waits for after choosing new drawings: a fresh Update() of the
// whole pipeline (both mappers, their append, tracing, arrangement, labeling, Boolean, outputs),
// with the surface kept as the same input object, as in ParaView. The first update on each
// mesh, which also builds the surface's structures (adjacency, topology, tiles, geodesic
// state), is reported apart as "cold" and not counted among the trials.
//
// Output: one CSV row per trial (mesh, drawings, operation, placement, times per stage from
// the filter's StageTimes field data, region size, status), and a summary on stdout: trials,
// failures with their messages, min / median / max of the full-update time per mesh and over
// all, the core count, and the CPU time over the wall time of the trials' updates (how busy
// the cores were). Benchmarks/RandomSvg/plot_histogram.py draws the histogram PNG.
//
// Usage: BoolSurfRandomSvgBenchmark [--trials N] [--seed S] [--csv FILE] [--mesh NAME]...
//        [--only-trial K] (replays trial K of each mesh: each mesh has its own generator)
//        [--verbose] (each trial named before it runs, and its update's start and end on the
//        steady clock with its wall and CPU time)
//        [--geodesic-method=bounded|exact|locally-shortest] (the filter's GeodesicMethod;
//        default bounded; --locally-shortest is kept as an alias of
//        --geodesic-method=locally-shortest) [--no-control-curves] (ComputeControlCurves off:
//        no vector output, as the paper's timings) [--threads N] (at most N threads for every
//        stage: the filter's NumberOfThreads and a cap on all of TBB's work, such as mapping the
//        SVGs; default 0, all cores)
// (shared data from BOOLSURF_SHARED_DATA or the build's configured path; a missing collection
// ends the program with a message and exit code 0, nothing measured).
#include "vtkBoolSurf.h"
#include "vtkBoolSurfSVGMapper.h"

#include <vtkAppendPolyData.h>
#include <vtkCallbackCommand.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkPLYReader.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>

#include <nlohmann/json.hpp>

#include <tbb/global_control.h>

#include <sys/resource.h>

// Under valgrind --tool=callgrind --instr-atstart=no, only the trials' updates are measured
// (not the reading of the meshes, nor each mesh's cold update): instruction counts of the
// tail's trials, replayed with --only-trial, on a machine too loaded for wall times.
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#define BOOLSURF_MEASURE_TRIAL(on)                                                                 \
  do                                                                                               \
  {                                                                                                \
    if (on)                                                                                        \
    {                                                                                              \
      CALLGRIND_START_INSTRUMENTATION;                                                             \
    }                                                                                              \
    else                                                                                           \
    {                                                                                              \
      CALLGRIND_STOP_INSTRUMENTATION;                                                              \
    }                                                                                              \
  } while (false)
#else
#define BOOLSURF_MEASURE_TRIAL(on)                                                                 \
  do                                                                                               \
  {                                                                                                \
  } while (false)
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace
{
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double Ms(Clock::time_point from, Clock::time_point to)
{
  return std::chrono::duration<double, std::milli>(to - from).count();
}

/// User and system CPU time of the process (every thread; RUSAGE_THREAD: the calling thread
/// only), in seconds.
double ProcessCpuSeconds(int who = RUSAGE_SELF)
{
  rusage usage{};
  getrusage(who, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
    1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

/// Collects the ErrorEvent texts and counts the WarningEvents of the algorithms it observes
/// (VTK's own printing of both is turned off: the summary reports them).
struct ErrorLog
{
  std::string Text;
  int Warnings = 0;
  vtkNew<vtkCallbackCommand> Catcher;

  ErrorLog()
  {
    this->Catcher->SetClientData(this);
    this->Catcher->SetCallback(
      [](vtkObject*, unsigned long event, void* log, void* message)
      {
        auto* self = static_cast<ErrorLog*>(log);
        if (event == vtkCommand::ErrorEvent)
        {
          self->Text += static_cast<const char*>(message);
        }
        else
        {
          ++self->Warnings;
        }
      });
  }
  void Watch(vtkAlgorithm* algorithm)
  {
    algorithm->AddObserver(vtkCommand::ErrorEvent, this->Catcher);
    algorithm->AddObserver(vtkCommand::WarningEvent, this->Catcher);
  }
};

struct Options
{
  int Trials = 40;
  unsigned Seed = 22;
  std::string Csv = "random_svg_booleans.csv";
  std::vector<std::string> Meshes; // empty: every shared mesh of >= 100k triangles
  int OnlyTrial = -1;              // >= 0: run only this trial (and the cold update)
  bool Verbose = false;            // print each trial before it runs
  int GeodesicMethod = vtkBoolSurf::GEODESIC_BOUNDED; // the filter's GeodesicMethod
  bool ControlCurves = true; // ComputeControlCurves (the vector output, ports 2-3)
  int Threads = 0;           // the filter's NumberOfThreads and TBB's cap (0: all cores)
};

Options ParseOptions(int argc, char** argv)
{
  Options options;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    const bool hasValue = i + 1 < argc;
    if (arg == "--trials" && hasValue)
    {
      options.Trials = std::max(1, std::atoi(argv[++i]));
    }
    else if (arg == "--seed" && hasValue)
    {
      options.Seed = static_cast<unsigned>(std::strtoul(argv[++i], nullptr, 10));
    }
    else if (arg == "--csv" && hasValue)
    {
      options.Csv = argv[++i];
    }
    else if (arg.rfind("--geodesic-method=", 0) == 0 || (arg == "--geodesic-method" && hasValue))
    {
      const std::string method = arg == "--geodesic-method"
        ? argv[++i]
        : arg.substr(std::string("--geodesic-method=").size());
      const std::map<std::string, int> methods{ { "bounded", vtkBoolSurf::GEODESIC_BOUNDED },
        { "exact", vtkBoolSurf::GEODESIC_EXACT },
        { "locally-shortest", vtkBoolSurf::GEODESIC_LOCALLY_SHORTEST } };
      const auto it = methods.find(method);
      if (it == methods.end())
      {
        std::cerr << "unknown geodesic method '" << method
                  << "': use bounded, exact or locally-shortest\n";
        std::exit(2);
      }
      options.GeodesicMethod = it->second;
    }
    else if (arg == "--locally-shortest") // the option's name before --geodesic-method
    {
      options.GeodesicMethod = vtkBoolSurf::GEODESIC_LOCALLY_SHORTEST;
    }
    else if (arg == "--no-control-curves")
    {
      options.ControlCurves = false;
    }
    else if (arg == "--threads" && hasValue)
    {
      options.Threads = std::max(0, std::atoi(argv[++i]));
    }
    else if (arg == "--verbose")
    {
      options.Verbose = true;
    }
    else if (arg == "--only-trial" && hasValue)
    {
      options.OnlyTrial = std::atoi(argv[++i]);
    }
    else if (arg == "--mesh" && hasValue)
    {
      options.Meshes.emplace_back(argv[++i]);
    }
    else
    {
      std::cerr << "usage: " << argv[0]
                << " [--trials N] [--seed S] [--csv FILE] [--mesh NAME.ply]... [--only-trial K] "
                   "[--verbose] [--geodesic-method=bounded|exact|locally-shortest] "
                   "[--no-control-curves] [--threads N]\n";
      std::exit(2);
    }
  }
  return options;
}

fs::path SharedData()
{
  const char* data = std::getenv("BOOLSURF_SHARED_DATA");
  if (data && *data)
  {
    return data;
  }
  return BOOLSURF_SHARED_DATA_DIR;
}

/// The shared meshes of at least 100k triangles, by the collection's manifest, smallest first.
std::vector<std::pair<std::string, long>> LargeMeshes(const fs::path& meshes)
{
  std::ifstream in(meshes / "manifest.json");
  const nlohmann::json manifest = nlohmann::json::parse(in);
  std::vector<std::pair<std::string, long>> large;
  for (const auto& entry : manifest)
  {
    const long triangles = entry.at("triangles").get<long>();
    if (triangles >= 100000)
    {
      large.emplace_back(entry.at("file").get<std::string>(), triangles);
    }
  }
  std::sort(
    large.begin(), large.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
  return large;
}

std::vector<fs::path> SharedSvgs(const fs::path& data)
{
  std::vector<fs::path> svgs;
  for (const auto& entry : fs::recursive_directory_iterator(data / "boolsurf-scenes" / "svgs"))
  {
    if (entry.path().extension() == ".svg")
    {
      svgs.push_back(entry.path());
    }
  }
  std::sort(svgs.begin(), svgs.end());
  return svgs;
}

/// "(S<first> | ... | S<last>)" over the distinct ShapeIds of one drawing's output.
std::string UnionOfShapes(vtkPolyData* drawing)
{
  std::set<int> shapes;
  if (vtkDataArray* ids = drawing->GetCellData()->GetArray("ShapeId"))
  {
    for (vtkIdType c = 0; c < ids->GetNumberOfTuples(); ++c)
    {
      shapes.insert(static_cast<int>(ids->GetComponent(c, 0)));
    }
  }
  std::string text = "(";
  for (int s : shapes)
  {
    text += (text.size() > 1 ? " | S" : "S") + std::to_string(s);
  }
  return text + ")";
}

bool SuggestsEvenOdd(vtkPolyData* drawing)
{
  auto* rule =
    vtkStringArray::SafeDownCast(drawing->GetFieldData()->GetAbstractArray("SuggestedFillRule"));
  return rule && rule->GetNumberOfValues() > 0 && rule->GetValue(0) == "EvenOdd";
}

double Percentile(std::vector<double> values, double q)
{
  if (values.empty())
  {
    return std::nan("");
  }
  std::sort(values.begin(), values.end());
  const double at = q * (values.size() - 1);
  const size_t below = static_cast<size_t>(std::floor(at));
  const size_t above = std::min(below + 1, values.size() - 1);
  return values[below] + (at - below) * (values[above] - values[below]);
}

std::string Summary(const std::vector<double>& times)
{
  std::ostringstream out;
  out << std::fixed << std::setprecision(1) << "min " << Percentile(times, 0) << "  median "
      << Percentile(times, 0.5) << "  p90 " << Percentile(times, 0.9) << "  p99 "
      << Percentile(times, 0.99) << "  max " << Percentile(times, 1) << " ms";
  return out.str();
}

/// The pipeline of one mesh: two SVG mappers on the same surface, appended, into the one-step
/// filter. Built once per mesh so the surface's cached structures live across trials.
struct Pipeline
{
  vtkNew<vtkBoolSurfSVGMapper> DrawingA, DrawingB;
  vtkNew<vtkAppendPolyData> Both;
  vtkNew<vtkBoolSurf> Boolean;
  ErrorLog Errors;

  explicit Pipeline(vtkPolyData* surface)
  {
    for (vtkBoolSurfSVGMapper* drawing : { this->DrawingA.Get(), this->DrawingB.Get() })
    {
      drawing->SetInputData(surface);
      this->Both->AddInputConnection(drawing->GetOutputPort());
      this->Errors.Watch(drawing);
    }
    this->DrawingB->SetShapeIdOffset(100000); // keeps B's shapes apart from A's
    this->Boolean->SetInputData(0, surface);
    this->Boolean->SetInputConnection(1, this->Both->GetOutputPort());
    this->Boolean->SetOperationToExpression();
    this->Errors.Watch(this->Both);
    this->Errors.Watch(this->Boolean);
  }
};

const char* const OperationNames[] = { "union", "intersection", "difference", "xor" };
const char* const OperationSymbols[] = { " | ", " & ", " - ", " ^ " };
} // namespace

int main(int argc, char** argv)
{
  const Options options = ParseOptions(argc, argv);
  const fs::path data = SharedData();
  if (!fs::is_regular_file(data / "meshes" / "manifest.json") ||
    !fs::is_directory(data / "boolsurf-scenes" / "svgs"))
  {
    std::cout << "the shared data (meshes/manifest.json and boolsurf-scenes/svgs) is not at '"
              << data.string() << "': set BOOLSURF_SHARED_DATA; nothing measured\n";
    return 0;
  }
  std::vector<std::pair<std::string, long>> meshes = LargeMeshes(data / "meshes");
  if (!options.Meshes.empty())
  {
    meshes.erase(std::remove_if(meshes.begin(),
                   meshes.end(),
                   [&](const auto& m)
                   {
                     return std::find(options.Meshes.begin(), options.Meshes.end(), m.first) ==
                       options.Meshes.end();
                   }),
      meshes.end());
  }
  const std::vector<fs::path> svgs = SharedSvgs(data);
  const unsigned cores = std::thread::hardware_concurrency();
  // Every TBB loop of the process (the mappers' too, which have no thread setting) on at most
  // that many threads, so a one-thread run is one thread throughout.
  std::unique_ptr<tbb::global_control> threadCap;
  if (options.Threads > 0)
  {
    threadCap = std::make_unique<tbb::global_control>(
      tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(options.Threads));
  }
  // Warnings and errors are counted per trial (observers); the executive's own reports of a
  // failed filter are not printed.
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  std::cout << "Random SVG Booleans (paper Fig. 22): " << meshes.size() << " meshes, "
            << svgs.size() << " SVGs, " << options.Trials << " trials per mesh, seed "
            << options.Seed << ", geodesic method "
            << vtkBoolSurf::GetGeodesicMethodName(options.GeodesicMethod) << ", " << cores
            << " cores, "
            << (options.Threads > 0 ? std::to_string(options.Threads) : std::string("all"))
            << " threads\n";

  // Rows are kept until the end: the stage columns are known from the first successful update.
  struct Row
  {
    std::string Head, Tail;
    std::vector<double> Stages;
  };
  std::vector<Row> rows;
  std::vector<std::string> stageNames;
  int failedTrials = 0, warnedTrials = 0;

  std::vector<double> all;
  double wallMs = 0, cpuMs = 0, mainCpuMs = 0; // the trials' updates: how busy the cores were
  // The same trials without the one-off build of the surface's geodesic site graph: it is
  // built lazily, by the first leg that needs a route, so whichever trial of a mesh routes
  // first pays it once (its time is in the CSV's site_graph_build_ms).
  std::vector<double> allWithoutBuilds;
  std::map<std::string, std::vector<std::string>> failures;
  // The tail by name: each good trial's wall and CPU time, for the slowest ones in the summary
  // (on a loaded machine the CPU time says which trials are long, the wall time does not).
  struct SlowTrial
  {
    double WallMs, CpuMs;
    std::string Name;
  };
  std::vector<SlowTrial> slowest;
  for (const auto& [name, triangles] : meshes)
  {
    vtkNew<vtkPLYReader> reader;
    reader->SetFileName((data / "meshes" / name).string().c_str());
    reader->Update();
    vtkSmartPointer<vtkPolyData> surface = reader->GetOutput();
    double bounds[6];
    surface->GetBounds(bounds);
    const double diagonal = std::sqrt(std::pow(bounds[1] - bounds[0], 2) +
      std::pow(bounds[3] - bounds[2], 2) + std::pow(bounds[5] - bounds[4], 2));
    Pipeline pipeline(surface);
    pipeline.Boolean->SetGeodesicMethod(options.GeodesicMethod);
    pipeline.Boolean->SetComputeControlCurves(options.ControlCurves);
    pipeline.Boolean->SetNumberOfThreads(options.Threads);
    // One generator per mesh, seeded by the seed and the mesh's name, so a run on a subset of
    // the meshes (--mesh) repeats the same trials.
    std::seed_seq seeds{ options.Seed, static_cast<unsigned>(std::hash<std::string>()(name)) };
    std::mt19937 rng(seeds);
    std::uniform_int_distribution<vtkIdType> anyTriangle(0, surface->GetNumberOfCells() - 1);
    std::uniform_int_distribution<size_t> anySvg(0, svgs.size() - 1);
    std::uniform_int_distribution<int> anyOperation(0, 3);
    std::uniform_real_distribution<double> unit(0.0, 1.0);

    std::vector<double> times, mapTimes;
    std::vector<std::vector<double>> stageTimes; // per stage, over this mesh's good trials
    double cold = -1;
    double siteGraphBuild = -1; // BuildNumber of the site graph the last update reported
    for (int trial = -1; trial < options.Trials; ++trial) // trial -1: the cold update
    {
      const fs::path& a = svgs[anySvg(rng)];
      const fs::path& b = svgs[anySvg(rng)];
      const int operation = anyOperation(rng);
      const vtkIdType center = anyTriangle(rng);
      double u = unit(rng), v = unit(rng);
      if (u + v > 1)
      {
        u = 1 - u;
        v = 1 - v;
      }
      // Sizes from 2 % to 15 % of the diagonal; B near A's size so the two overlap.
      const double radiusA = diagonal * (0.02 + 0.13 * unit(rng));
      const double radiusB = radiusA * (0.6 + 0.8 * unit(rng));
      const double rotationA = 360 * unit(rng), rotationB = 360 * unit(rng);
      for (auto [drawing, file, radius, rotation] :
        { std::make_tuple(pipeline.DrawingA.Get(), &a, radiusA, rotationA),
          std::make_tuple(pipeline.DrawingB.Get(), &b, radiusB, rotationB) })
      {
        drawing->SetFileName(file->string().c_str());
        drawing->SetCenterTriangleId(center);
        drawing->SetCenterBarycentric(u, v);
        drawing->SetRadius(radius);
        drawing->SetRotation(rotation);
      }
      if (options.OnlyTrial >= 0 && trial >= 0 && trial != options.OnlyTrial)
      {
        continue; // its random draws are made: the other trials stay the same
      }
      pipeline.Errors.Text.clear();
      pipeline.Errors.Warnings = 0;
      if (options.Verbose)
      {
        std::cout << "  trial " << trial << ": " << a.filename().string() << " "
                  << OperationNames[operation] << " " << b.filename().string() << std::endl;
      }

      // The expression needs each drawing's shape ids, and the fill rule what the SVGs say:
      // both come from the mappers' outputs, so the mappers run first (timed as part of it).
      if (trial >= 0)
      {
        BOOLSURF_MEASURE_TRIAL(true);
      }
      const double cpu0 = ProcessCpuSeconds(), mainCpu0 = ProcessCpuSeconds(RUSAGE_THREAD);
      const auto start = Clock::now();
      pipeline.DrawingA->Update();
      pipeline.DrawingB->Update();
      const auto mapped = Clock::now();
      const bool evenOdd = SuggestsEvenOdd(pipeline.DrawingA->GetOutput()) &&
        SuggestsEvenOdd(pipeline.DrawingB->GetOutput());
      pipeline.Boolean->SetExpression((UnionOfShapes(pipeline.DrawingA->GetOutput()) +
        OperationSymbols[operation] + UnionOfShapes(pipeline.DrawingB->GetOutput()))
                                        .c_str());
      pipeline.Boolean->SetFillRule(evenOdd ? 1 : 0);
      pipeline.Boolean->Update();
      const auto done = Clock::now();
      BOOLSURF_MEASURE_TRIAL(false);
      const double updateMs = Ms(start, done);
      const double updateCpuMs = 1000.0 * (ProcessCpuSeconds() - cpu0);
      const double updateMainCpuMs = 1000.0 * (ProcessCpuSeconds(RUSAGE_THREAD) - mainCpu0);
      if (options.Verbose)
      {
        // The steady clock is CLOCK_MONOTONIC: `perf record -k CLOCK_MONOTONIC` samples of
        // this update are those between these two times (perf report --time FROM,TO).
        const auto seconds = [](Clock::time_point t)
        { return std::chrono::duration<double>(t.time_since_epoch()).count(); };
        std::cout << std::setprecision(6) << std::fixed << "    updated from " << seconds(start)
                  << " to " << seconds(done) << " s (steady clock): " << updateMs << " ms, CPU "
                  << updateCpuMs << " ms" << std::endl;
      }

      vtkPolyData* region = pipeline.Boolean->GetOutput();
      const std::string error = pipeline.Errors.Text;
      // A site graph built during this update (not during an earlier one) was paid here.
      double buildMs = 0;
      if (vtkDataArray* graph = region->GetFieldData()->GetArray("GeodesicSiteGraph"))
      {
        if (graph->GetComponent(0, 3) != siteGraphBuild)
        {
          buildMs = graph->GetComponent(0, 1);
          siteGraphBuild = graph->GetComponent(0, 3);
        }
      }
      if (trial < 0)
      {
        cold = updateMs;
        if (!error.empty())
        {
          failures[name].push_back("cold update: " + error);
        }
        continue;
      }
      vtkDataArray* stages = region->GetFieldData()->GetArray("StageTimes");
      Row row;
      std::ostringstream head;
      head << name << "," << triangles << "," << trial << "," << a.filename().string() << ","
           << b.filename().string() << "," << OperationNames[operation] << ","
           << (evenOdd ? "EvenOdd" : "NonZero") << "," << radiusA << "," << radiusB << ","
           << rotationA << "," << rotationB << "," << center << "," << u << "," << v << ","
           << pipeline.Both->GetOutput()->GetNumberOfCells() << "," << updateMs << ","
           << updateCpuMs << "," << Ms(start, mapped);
      row.Head = head.str();
      if (stages && error.empty())
      {
        for (int k = 0; k < stages->GetNumberOfComponents(); ++k)
        {
          row.Stages.push_back(stages->GetComponent(0, k));
          if (stageNames.size() < static_cast<size_t>(stages->GetNumberOfComponents()))
          {
            const char* stage = stages->GetComponentName(k);
            stageNames.push_back(stage ? stage : "Stage" + std::to_string(k));
          }
        }
      }
      std::string status = error.empty() ? "ok" : error.substr(0, error.find('\n'));
      std::replace(status.begin(), status.end(), ',', ';');
      std::replace(status.begin(), status.end(), '"', '\'');
      row.Tail = std::to_string(buildMs) + "," + std::to_string(region->GetNumberOfCells()) + "," +
        std::to_string(pipeline.Errors.Warnings) + "," + status;
      warnedTrials += pipeline.Errors.Warnings > 0 ? 1 : 0;
      rows.push_back(std::move(row));
      if (!error.empty())
      {
        failures[name].push_back(a.filename().string() + " " + OperationNames[operation] + " " +
          b.filename().string() + ": " + error);
        ++failedTrials;
        continue;
      }
      times.push_back(updateMs);
      all.push_back(updateMs);
      wallMs += updateMs;
      cpuMs += updateCpuMs;
      mainCpuMs += updateMainCpuMs;
      allWithoutBuilds.push_back(updateMs - buildMs);
      slowest.push_back({ updateMs,
        updateCpuMs,
        "--mesh " + name + " --only-trial " + std::to_string(trial) + " (" + a.filename().string() +
          " " + OperationNames[operation] + " " + b.filename().string() +
          (buildMs > 0 ? ", site graph built" : "") + ")" });
      mapTimes.push_back(Ms(start, mapped));
      const std::vector<double>& stagesOfTrial = rows.back().Stages;
      stageTimes.resize(std::max(stageTimes.size(), stagesOfTrial.size()));
      for (size_t k = 0; k < stagesOfTrial.size(); ++k)
      {
        stageTimes[k].push_back(stagesOfTrial[k]);
      }
    }
    std::cout << std::setw(22) << std::left << name << std::right << std::setw(9) << triangles
              << " triangles: " << times.size() << " ok, "
              << (options.OnlyTrial >= 0 ? 1 : options.Trials) - static_cast<int>(times.size())
              << " failed; cold update " << std::fixed << std::setprecision(1) << cold
              << " ms; full update " << Summary(times) << "\n    median per stage (ms): map "
              << std::setprecision(2) << Percentile(mapTimes, 0.5);
    for (size_t k = 0; k < stageTimes.size() && k < stageNames.size(); ++k)
    {
      std::cout << ", " << stageNames[k] << " " << Percentile(stageTimes[k], 0.5);
    }
    std::cout << std::endl;
  }
  std::ofstream csv(options.Csv);
  csv
    << "mesh,triangles,trial,svg_a,svg_b,operation,fill_rule,radius_a,radius_b,rotation_a,"
       "rotation_b,center_triangle,center_u,center_v,control_curves,update_ms,update_cpu_ms,map_ms";
  for (const std::string& stage : stageNames)
  {
    csv << "," << stage << "_ms";
  }
  csv << ",site_graph_build_ms,region_triangles,warnings,status\n";
  for (const Row& row : rows)
  {
    csv << row.Head;
    for (size_t k = 0; k < stageNames.size(); ++k)
    {
      csv << "," << (k < row.Stages.size() ? std::to_string(row.Stages[k]) : std::string());
    }
    csv << "," << row.Tail << "\n";
  }
  std::cout << "all meshes: " << all.size() << " trials ok, " << failedTrials << " failed, "
            << warnedTrials << " with warnings (unknown SVG attributes, points stopped at a "
            << "boundary), " << Summary(all) << " (" << cores << " cores)\n"
            << "without the one-off geodesic site-graph builds: " << Summary(allWithoutBuilds)
            << "\n"
            << "CPU time / wall time of the trials' updates: " << std::setprecision(2)
            << (wallMs > 0 ? cpuMs / wallMs : 0.0) << " (" << std::setprecision(1) << cpuMs / 1000.0
            << " s CPU in " << wallMs / 1000.0
            << " s); share of that CPU time on other threads than the caller's: "
            << std::setprecision(0)
            << (cpuMs > 0 ? std::max(0.0, 100.0 * (cpuMs - mainCpuMs) / cpuMs) : 0.0)
            << " % (on a loaded machine the wall time grows, this share does not)\n";
  std::sort(slowest.begin(),
    slowest.end(),
    [](const SlowTrial& x, const SlowTrial& y) { return x.WallMs > y.WallMs; });
  std::cout << "slowest trials (wall / CPU ms):\n";
  for (size_t k = 0; k < slowest.size() && k < 8; ++k)
  {
    std::cout << "  " << std::setprecision(0) << slowest[k].WallMs << " / " << slowest[k].CpuMs
              << "  " << slowest[k].Name << "\n";
  }
  for (const auto& [name, messages] : failures)
  {
    for (const std::string& message : messages)
    {
      std::cout << "failed on " << name << ": " << message.substr(0, 300) << "\n";
    }
  }
  std::cout << "per-trial rows: " << options.Csv << "\n";
  return 0;
}

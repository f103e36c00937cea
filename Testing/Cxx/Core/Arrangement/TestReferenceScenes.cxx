// The BoolSurf authors' own test scenes (../shared/data/boolsurf-scenes, see its README): every
// scene whose mesh is in ../shared/data/meshes is traced (geodesic polygons through its control
// points) and arranged, and its number of cells and of self-arcs (cell-graph arcs with the same
// cell on both sides: patches of curves that do not separate cells, e.g. non-contractible loops)
// must equal Testing/Data/scene_cells.json exactly.
//
// Set BOOLSURF_UPDATE_SCENE_CELLS=1 to rewrite that file from the current results (then review
// the diff). The test skips when BOOLSURF_SHARED_DATA (set by ctest) is unset or missing.
#include "Arrangement/Arrangement.h"
#include "Geodesic/CurveTracer.h"
#include "Mesh/PlyReader.h"
#include "Mesh/TriangleMesh.h"
#include "Scene/SceneMeshLookup.h"
#include "Support/SourceTree.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

using namespace boolsurf;

namespace
{
/// The message of the last failed trace or path (a test reads it only after a failure).
std::string traceError;
}
namespace fs = std::filesystem;
using json = nlohmann::json;

namespace
{

/// Scenes whose meshes have more triangles than this are skipped (test time); none of the
/// available scenes does today.
constexpr int MaxTriangles = 300000;

/// The scene README's map from `model` (separators normalised, leading "./" removed) to a
/// file in ../meshes. Models not listed are not available.
const std::map<std::string, std::string>& MeshOfModel()
{
  static const std::map<std::string, std::string> map = {
    { "data/complex_meshes/bimba.ply", "bimba.ply" },
    { "data/complex_meshes/cow_notsolowpoly.ply", "spot.ply" },
    { "data/complex_meshes/cow_lowpoly.ply", "cow_lowpoly.ply" },
    { "data/complex_meshes/3Torus_200k.ply", "3torus_200k.ply" },
    { "data/complex_meshes/eight200k-remeshed.ply", "eight_200k.ply" },
    { "data/models/bunny.ply", "bunny_boolsurf.ply" },
    { "data/models/sphere_complete.ply", "sphere_complete.ply" },
    { "data/models/torus.ply", "torus.ply" },
    { "data/models/floor.ply", "floor.ply" },
  };
  return map;
}

struct SceneResult
{
  std::string File, Mesh;
  int Triangles = 0;
  int Curves = 0;
  int TraceFailures = 0;
  int Cells = -1;
  int SelfArcs = 0;
  /// Nodes of the authors' cell-graph dump (tests/examples/*.txt) when it belongs to this scene
  /// (one label per polygon, or per non-empty polygon); some dumps are of other scenes.
  int GraphCells = -1;
  bool GraphStale = false;
  /// Length of the scene's `cell_colors` (one color per cell when the authors saved it), if any.
  int CellColors = -1;
  std::string Error;
  double TraceMs = 0, ArrangeMs = 0;
};

/// Nodes of a Graphviz dump of BoolSurf's cell graph ("<id> [label=\"<id>" then a line with
/// the cell's labels, one per shape), and the number of labels of the first node.
struct GraphDump
{
  int Nodes = -1;
  int Labels = -1;
};

GraphDump ReadGraphDump(const fs::path& path)
{
  GraphDump dump;
  std::ifstream in(path);
  if (!in)
  {
    return dump;
  }
  dump.Nodes = 0;
  std::string line;
  bool labelsNext = false;
  while (std::getline(in, line))
  {
    if (labelsNext)
    {
      std::istringstream labels(line.substr(0, line.find('"')));
      int value, count = 0;
      while (labels >> value)
      {
        ++count;
      }
      dump.Labels = count;
      labelsNext = false;
    }
    const size_t bracket = line.find(" [label=");
    if (bracket != std::string::npos && bracket > 0 &&
      std::all_of(
        line.begin(), line.begin() + bracket, [](char c) { return c >= '0' && c <= '9'; }))
    {
      labelsNext = dump.Nodes++ == 0;
    }
  }
  return dump;
}

struct MeshCache
{
  std::map<std::string, std::unique_ptr<TriangleMesh>> Meshes;

  const TriangleMesh* Get(const fs::path& meshDir, const std::string& name, std::string& error)
  {
    auto it = this->Meshes.find(name);
    if (it != this->Meshes.end())
    {
      return it->second.get();
    }
    MeshData d;
    if (!ReadPly((meshDir / name).string(), d, error))
    {
      return nullptr;
    }
    std::unique_ptr<TriangleMesh>& m = this->Meshes[name];
    m.reset(new TriangleMesh(d.Positions, d.Triangles));
    return m.get();
  }
};

using Clock = std::chrono::steady_clock;

double Ms(Clock::time_point a, Clock::time_point b)
{
  return std::chrono::duration<double, std::milli>(b - a).count();
}

/// Traces the scene's polygons (closed per `are_closed`, shape ids from `shapes`, each polygon
/// its own shape otherwise; empty polygons skipped).
void TraceScene(const json& scene,
  const TriangleMesh& mesh,
  std::vector<TracedCurve>& curves,
  SceneResult& result)
{
  std::vector<SurfacePoint> points;
  for (const json& p : scene.at("points"))
  {
    SurfacePoint s;
    s.Triangle = p.at("face").get<int>();
    s.U = p.at("uv")[0].get<double>();
    s.V = p.at("uv")[1].get<double>();
    points.push_back(s);
  }
  const json& polygons = scene.at("polygons");
  std::vector<int> shapeOf(polygons.size());
  for (size_t i = 0; i < shapeOf.size(); ++i)
  {
    shapeOf[i] = static_cast<int>(i);
  }
  if (scene.contains("shapes"))
  {
    const json& shapes = scene.at("shapes");
    for (size_t s = 0; s < shapes.size(); ++s)
    {
      for (const json& p : shapes[s])
      {
        const int i = p.get<int>();
        if (i >= 0 && i < static_cast<int>(shapeOf.size()))
        {
          shapeOf[i] = static_cast<int>(s);
        }
      }
    }
  }
  CurveTracer tracer(mesh);
  for (size_t i = 0; i < polygons.size(); ++i)
  {
    std::vector<SurfacePoint> control;
    for (const json& k : polygons[i])
    {
      control.push_back(points.at(k.get<size_t>()));
    }
    if (control.size() < 2)
    {
      continue;
    }
    bool closed = true;
    if (scene.contains("are_closed") && i < scene.at("are_closed").size())
    {
      closed = scene.at("are_closed")[i].get<bool>();
    }
    CurveTrace trace;
    const bool traced = tracer.Trace(
      control, CurveType::GeodesicPolygon, closed, trace, traceError, static_cast<int>(i));
    if (!traced)
    {
      ++result.TraceFailures;
      if (result.Error.empty())
      {
        result.Error = "polygon " + std::to_string(i) + ": " + traceError;
      }
      continue;
    }
    trace.Curve.ShapeId = shapeOf[i];
    trace.Curve.CurveId = static_cast<int>(i);
    curves.push_back(trace.Curve);
  }
  result.Curves = static_cast<int>(curves.size());
}

json ToJson(const SceneResult& r)
{
  json j;
  j["file"] = r.File;
  j["mesh"] = r.Mesh;
  j["triangles"] = r.Triangles;
  j["curves"] = r.Curves;
  j["trace_failures"] = r.TraceFailures;
  j["cells"] = r.Cells;
  j["self_arcs"] = r.SelfArcs;
  if (r.GraphCells >= 0)
  {
    j["boolsurf_graph_cells"] = r.GraphCells;
  }
  if (r.CellColors >= 0)
  {
    j["boolsurf_cell_colors"] = r.CellColors;
  }
  if (r.GraphStale)
  {
    j["boolsurf_graph"] = "dump of another scene (label count differs), not compared";
  }
  return j;
}

} // namespace

TEST(ReferenceScenes, CellCountsMatchExpectations)
{
  const char* shared = std::getenv("BOOLSURF_SHARED_DATA");
  if (!shared || !*shared)
  {
    GTEST_SKIP() << "BOOLSURF_SHARED_DATA is not set (ctest sets it to the shared data folder)";
  }
  const fs::path sceneDir = fs::path(shared) / "boolsurf-scenes";
  const fs::path meshDir = fs::path(shared) / "meshes";
  if (!fs::is_directory(sceneDir) || !fs::is_directory(meshDir))
  {
    GTEST_SKIP() << "shared data folder " << shared << " has no boolsurf-scenes/ or meshes/ folder";
  }
  const fs::path expectedPath =
    boolsurf::testing::SourceTree() / "Testing" / "Data" / "scene_cells.json";
  const bool update = std::getenv("BOOLSURF_UPDATE_SCENE_CELLS") != nullptr;

  std::vector<std::string> files;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(sceneDir))
  {
    const std::string rel = fs::relative(e.path(), sceneDir).generic_string();
    if (e.is_regular_file() && e.path().extension() == ".json" && rel.rfind("homotopy/", 0) != 0)
    {
      files.push_back(rel);
    }
  }
  std::sort(files.begin(), files.end());

  MeshCache meshes;
  std::vector<SceneResult> results;
  json skipped = json::array();
  for (const std::string& file : files)
  {
    std::ifstream in(sceneDir / file);
    json scene;
    try
    {
      in >> scene;
    }
    catch (const std::exception& e)
    {
      ADD_FAILURE() << file << ": " << e.what();
      continue;
    }
    if (!scene.contains("model"))
    {
      skipped.push_back({ { "file", file }, { "reason", "screen-space scene (no mesh)" } });
      continue;
    }
    const std::string model = NormalizeModelPath(scene.at("model").get<std::string>());
    auto it = MeshOfModel().find(model);
    if (it == MeshOfModel().end() || !fs::exists(meshDir / it->second))
    {
      skipped.push_back({ { "file", file }, { "reason", "mesh not available: " + model } });
      continue;
    }
    SceneResult r;
    r.File = file;
    r.Mesh = it->second;
    std::string error;
    const TriangleMesh* mesh = meshes.Get(meshDir, r.Mesh, error);
    ASSERT_NE(mesh, nullptr) << r.Mesh << ": " << error;
    r.Triangles = mesh->GetNumberOfTriangles();
    if (r.Triangles > MaxTriangles)
    {
      skipped.push_back({ { "file", file }, { "reason", "mesh over 300k triangles" } });
      continue;
    }
    const Clock::time_point t0 = Clock::now();
    std::vector<TracedCurve> curves;
    TraceScene(scene, *mesh, curves, r);
    const Clock::time_point t1 = Clock::now();
    Arrangement arr;
    ArrangementOptions options;
    if (ComputeArrangement(*mesh, curves, options, arr, error))
    {
      r.Cells = arr.NumberOfCells;
      for (const CellGraphArc& a : arr.CellGraph)
      {
        r.SelfArcs += a.LeftCell == a.RightCell;
      }
    }
    else
    {
      r.Error = error;
    }
    r.TraceMs = Ms(t0, t1);
    r.ArrangeMs = Ms(t1, Clock::now());
    if (scene.contains("cell_colors"))
    {
      r.CellColors = static_cast<int>(scene.at("cell_colors").size());
    }
    const fs::path graph = fs::path(sceneDir / file).replace_extension(".txt");
    if (fs::exists(graph))
    {
      const GraphDump dump = ReadGraphDump(graph);
      int nonEmpty = 0;
      for (const json& p : scene.at("polygons"))
      {
        nonEmpty += !p.empty();
      }
      if (dump.Labels == static_cast<int>(scene.at("polygons").size()) || dump.Labels == nonEmpty)
      {
        r.GraphCells = dump.Nodes;
      }
      else
      {
        r.GraphStale = true;
      }
    }
    std::printf("%-38s %-20s %7d tris %3d curves %4d cells %3d self-arcs (BoolSurf graph: %d) "
                "trace %.0f ms, arrangement %.1f ms%s%s\n",
      r.File.c_str(),
      r.Mesh.c_str(),
      r.Triangles,
      r.Curves,
      r.Cells,
      r.SelfArcs,
      r.GraphCells,
      r.TraceMs,
      r.ArrangeMs,
      r.Error.empty() ? "" : "  ERROR: ",
      r.Error.c_str());
    results.push_back(r);
  }

  if (update)
  {
    json out;
    out["about"] = "Cells per BoolSurf reference scene (../shared/data/boolsurf-scenes) whose mesh "
                   "is in ../shared/data/meshes, checked exactly by TestReferenceScenes.cxx. "
                   "Curves are geodesic polygons through the scene's control points; self_arcs "
                   "counts cell-graph arcs with the same cell on both sides. "
                   "boolsurf_graph_cells is the node count of the authors' cell-graph dump "
                   "(tests/examples/*.txt) where the dump has one label per polygon (some dumps "
                   "are of other scenes); the test also checks cells against it, and against "
                   "boolsurf_cell_colors (the length of the "
                   "scene's cell_colors, one per BoolSurf cell) when that holds more than one "
                   "color. Scenes on meshes over 300k "
                   "triangles would be skipped for test time; none is. "
                   "Regenerate with BOOLSURF_UPDATE_SCENE_CELLS=1.";
    out["scenes"] = json::array();
    for (const SceneResult& r : results)
    {
      out["scenes"].push_back(ToJson(r));
    }
    out["skipped"] = skipped;
    std::ofstream file(expectedPath);
    ASSERT_TRUE(file) << "cannot write " << expectedPath;
    file << out.dump(2) << "\n";
    std::printf("wrote %s\n", expectedPath.string().c_str());
    return;
  }

  std::ifstream in(expectedPath);
  ASSERT_TRUE(in) << "missing expectations file " << expectedPath
                  << " (create it with BOOLSURF_UPDATE_SCENE_CELLS=1)";
  json expected;
  in >> expected;
  std::map<std::string, json> byFile;
  for (const json& e : expected.at("scenes"))
  {
    byFile[e.at("file").get<std::string>()] = e;
  }
  EXPECT_EQ(byFile.size(), results.size()) << "the set of available scenes changed";
  for (const SceneResult& r : results)
  {
    EXPECT_TRUE(r.Error.empty()) << r.File << ": " << r.Error;
    auto it = byFile.find(r.File);
    if (it == byFile.end())
    {
      ADD_FAILURE() << r.File << " has no entry in " << expectedPath;
      continue;
    }
    const json got = ToJson(r);
    for (const char* key : { "mesh", "curves", "trace_failures", "cells", "self_arcs" })
    {
      EXPECT_EQ(got.at(key), it->second.at(key)) << r.File << ": " << key;
    }
    // The authors' own cell graph, where the dump belongs to the scene: an independent check.
    if (r.GraphCells >= 0)
    {
      EXPECT_EQ(r.Cells, r.GraphCells) << r.File << ": cells differ from BoolSurf's cell graph";
    }
    // Likewise the authors' saved cell colors; lists of 0 or 1 colors are placeholders.
    if (r.CellColors > 1)
    {
      EXPECT_EQ(r.Cells, r.CellColors) << r.File << ": cells differ from BoolSurf's cell colors";
    }
  }
}

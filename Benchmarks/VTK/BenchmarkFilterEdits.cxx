// What a user waits for after an edit: fresh Update()s of the one-step filter vtkBoolSurf on a
// large surface (igea_1m, 1.07M triangles), with the surface kept as the same input object so
// its cached conversion (adjacency, topology, geodesic search state) is reused, as in ParaView.
// Each benchmark builds its own filter and updates it once before timing (surface conversion
// and first labeling are not what an edit costs). threads:N sets NumberOfThreads.
//
// - BM_OneStepCurveEdit/threads:N: 10 circles x 12 control points in two clusters of
//   overlapping ones, union of all shapes; each iteration moves the curves (switches between two
//   prepared curve sets: the same circles moved by 5 % of their radius and rotated by half a
//   control-point step; every control point also moved by ~1e-12 so that no curve is
//   recalled from the tracer's memory of earlier iterations) and updates: tracing,
//   arrangement, labeling and Boolean all rerun.
// - BM_OneStepCurveEditSubdivided/threads:N: the same ten circles (the same control point
//   positions, snapped again) on igea_1m subdivided once (vtkLinearSubdivisionFilter: each
//   triangle split into four in its own plane, 4.29M triangles, the same surface), the same
//   edits: what an edit costs as the mesh grows under the same curves.
// - BM_OneStepCurveEdit[Subdivided]LocallyShortest/threads:N: the same edits with
//   GeodesicMethod = Locally shortest (legs straightened in a strip, not searched exactly).
// - BM_OneStepDragOneCurve/threads:N: same scene; each iteration moves one circle (the next
//   one each time) and the other nine stay: a user dragging one curve among many (the tracer
//   recalls the nine).
// - BM_OneStepOperationChange/threads:N: same scene; each iteration only toggles Union and
//   SymmetricDifference (the labeled arrangement is reused, only the Boolean reruns).
// - BM_OneStepPaperScaleXor/threads:N: 112 circles x 32 control points (the scale of the paper's
//   largest scenes) in clusters of 4, symmetric difference of all shapes, curve edits as above.
// - BM_OneStepPaperScaleXorAllPorts/threads:N: the same edits with every output port updated
//   and read as ParaView does (UpdateEveryPort, ReadPortInformation): the default outputs a
//   pvpython user gets. Counters Port0Region_ms ... Port3ClippedCurves_ms (the filter's own
//   time per port), PortInformation_ms (reading the ports), ExecutionsPerEdit (must be 1).
// - BM_OneStepPaperScaleSelection/bsc:B: the paper-scale scene with the labeled arrangement
//   reused, only the selection reruns: the Boolean (B = 0) or BSC with 112 samples (B = 1).
// - BM_OneStepHugeShapeId: two overlapping circles with ShapeIds 0 and 1000000 on a small mesh
//   (bunny_npm), union of all shapes, curve edits: what a sparse, huge ShapeId costs.
//
// Control points are given exactly (point data TriangleId/Barycentric of the closest surface
// point), so no projection tolerance is involved. Circles are placed with a fixed-seed RNG:
// every run measures the same scenes.
//
// Counters: <Stage>_ms per stage when output 0 carries the field data array StageTimes
// (milliseconds, named components, averaged over iterations; absent: no such counters);
// RegionTriangles and RegionCells (arrangement cells) of output 0 and BoundaryPoints (points of
// output 1) after the last update;
// DeepCopyMs (median of 5 vtkPolyData::DeepCopy of the surface in this process: the yardstick
// "as slow as copying the mesh") and EditOverDeepCopy (mean update time over it); PeakRSS_MB
// (ru_maxrss, reset at the start of each benchmark on Linux so it is that benchmark's peak) and
// PeakRSSGrowth_MB (that peak above the RSS the benchmark started from: meshes already loaded);
// TracedVertices (paper-scale scene, from one vtkBoolSurfTraceCurves run outside the timing);
// FirstUpdateMs (the warm-up update of a fresh filter on a surface it has not seen: surface
// conversion, tiles, first tracing and labeling: what a user waits for when a pipeline opens)
// and First<Stage>_ms (its per-stage times; the rest of it prepares the surface).
// Meshes come from BOOLSURF_SHARED_DATA_DIR/meshes; a missing mesh skips the benchmark.
//
// - BM_StageChainCurveEdit/threads:N: BM_OneStepCurveEdit's edits through the four stage
//   filters, one update of the last filter per edit, with each filter's mean execution time:
//   the stage chain's cost against the one-step filter's.
// - BM_StageChainPaperScaleXor/threads:N: BM_OneStepPaperScaleXor's edits through the stage
//   filters (symmetric difference of all shapes).
// - BM_StageChainPaperScaleXorColored, BM_StageChainCurveEditLabeled: the same with Label
//   Arrangement Cells' per-triangle arrays (ShapeLabel of shape 0; and Labels for ten circles,
//   on the surface with a point and a cell scalar of its own).
//
// Run: BoolSurfVTKBenchmarks --benchmark_filter='OneStep|StageChain'
#include "FilterUpdateTimer.h"

#include "vtkBoolSurf.h"
#include "vtkBoolSurfArrangement.h"
#include "vtkBoolSurfBoolean.h"
#include "vtkBoolSurfLabeling.h"
#include "vtkBoolSurfTraceCurves.h"
#include "vtkBoolSurfWindingNumbers.h"

#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkDataSetAttributes.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkGenericCell.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkIntArray.h>
#include <vtkLinearSubdivisionFilter.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPLYReader.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStaticCellLocator.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <benchmark/benchmark.h>

#include <sys/resource.h>
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#else
#define CALLGRIND_START_INSTRUMENTATION
#define CALLGRIND_TOGGLE_COLLECT
#endif

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace
{

using Vec = std::array<double, 3>;

Vec Add(const Vec& a, const Vec& b)
{
  return { a[0] + b[0], a[1] + b[1], a[2] + b[2] };
}
Vec Sub(const Vec& a, const Vec& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}
Vec Scale(const Vec& a, double s)
{
  return { s * a[0], s * a[1], s * a[2] };
}
double Dot(const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec Cross(const Vec& a, const Vec& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
double Norm(const Vec& a)
{
  return std::sqrt(Dot(a, a));
}
Vec Normalized(const Vec& a)
{
  const double n = Norm(a);
  return n > 0 ? Scale(a, 1.0 / n) : a;
}

double PeakRssMB()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0; // ru_maxrss is in KiB on Linux
}

/// Starts a new peak-RSS measurement and returns the resident size it starts from: on Linux,
/// writing 5 to /proc/self/clear_refs resets the high-water mark that ru_maxrss reports to the
/// current RSS, so each benchmark's peak is its own and not that of an earlier, larger one.
/// Elsewhere the peak stays that of the whole process.
double ResetPeakRss()
{
  std::ofstream("/proc/self/clear_refs") << "5";
  return PeakRssMB();
}

double Milliseconds(std::chrono::steady_clock::time_point a,
  std::chrono::steady_clock::time_point b)
{
  return std::chrono::duration<double, std::milli>(b - a).count();
}

/// A surface read once per process, with what the circle placement needs.
struct Surface
{
  vtkSmartPointer<vtkPolyData> Mesh;
  vtkSmartPointer<vtkStaticCellLocator> Locator;
  double Diagonal = 0;
  double DeepCopyMs = 0; // median of 5 DeepCopy runs
  std::string Error;

  Vec Point(vtkIdType id) const
  {
    Vec p;
    this->Mesh->GetPoint(id, p.data());
    return p;
  }
  std::array<vtkIdType, 3> Triangle(vtkIdType t) const
  {
    vtkIdType n;
    const vtkIdType* ids;
    this->Mesh->GetCellPoints(t, n, ids);
    return { ids[0], ids[1], ids[2] };
  }
  /// Area-weighted normal (length = twice the area).
  Vec AreaNormal(vtkIdType t) const
  {
    const auto ids = this->Triangle(t);
    const Vec a = this->Point(ids[0]);
    return Cross(Sub(this->Point(ids[1]), a), Sub(this->Point(ids[2]), a));
  }
};

void PrepareSurface(Surface& s, const std::string& path);

/// The mesh `name` of the shared collection, subdivided `subdivisions` times (each triangle
/// into four in its own plane: the same surface, four times the triangles; point arrays
/// interpolated).
const Surface& LoadSurface(const std::string& name, int subdivisions = 0)
{
  static std::map<std::string, Surface> cache;
  const std::string key = name + "/" + std::to_string(subdivisions);
  auto it = cache.find(key);
  if (it != cache.end())
  {
    return it->second;
  }
  Surface& s = cache[key];
  if (subdivisions > 0)
  {
    const Surface& coarse = LoadSurface(name, subdivisions - 1);
    if (!coarse.Error.empty())
    {
      s.Error = coarse.Error;
      return s;
    }
    vtkNew<vtkLinearSubdivisionFilter> subdivide;
    subdivide->SetInputData(coarse.Mesh);
    subdivide->SetNumberOfSubdivisions(1);
    subdivide->Update();
    s.Mesh = vtkSmartPointer<vtkPolyData>::New();
    s.Mesh->ShallowCopy(subdivide->GetOutput());
    PrepareSurface(s, name + " subdivided " + std::to_string(subdivisions) + " times");
    return s;
  }
  const std::string path = std::string(BOOLSURF_SHARED_DATA_DIR) + "/meshes/" + name;
  if (!vtkPLYReader::CanReadFile(path.c_str()))
  {
    s.Error = "cannot read " + path;
    return s;
  }
  vtkNew<vtkPLYReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  s.Mesh = reader->GetOutput();
  PrepareSurface(s, path);
  return s;
}

void PrepareSurface(Surface& s, const std::string& path)
{
  // Exact control points name triangles by cell id: valid only if every cell is a triangle
  // (the filter then uses the cells as they are, with the same ids).
  if (s.Mesh->GetNumberOfPolys() == 0 || s.Mesh->GetNumberOfCells() != s.Mesh->GetNumberOfPolys())
  {
    s.Error = "no triangles (or other cells than polygons) in " + path;
    return;
  }
  s.Locator = vtkSmartPointer<vtkStaticCellLocator>::New();
  s.Locator->SetDataSet(s.Mesh);
  s.Locator->BuildLocator();
  double b[6];
  s.Mesh->GetBounds(b);
  s.Diagonal = Norm({ b[1] - b[0], b[3] - b[2], b[5] - b[4] });

  std::vector<double> copies;
  for (int k = 0; k < 5; ++k)
  {
    vtkNew<vtkPolyData> copy;
    const auto t0 = std::chrono::steady_clock::now();
    copy->DeepCopy(s.Mesh);
    copies.push_back(Milliseconds(t0, std::chrono::steady_clock::now()));
  }
  std::nth_element(copies.begin(), copies.begin() + 2, copies.end());
  s.DeepCopyMs = copies[2];
}

/// A control point given exactly: triangle and the weights of its 2nd and 3rd vertex.
struct ControlPoint
{
  vtkIdType Triangle = -1;
  double U = 0, V = 0;
  Vec Position{};
};

/// A circle of the tangent plane at Center, (U, V, N) right-handed so that increasing angles
/// run counter-clockwise seen from the normal side: the shape is the enclosed disc.
struct Circle
{
  Vec Center{}, U{}, V{}, N{};
  double Radius = 0;
};

/// The closest surface point of x, with its triangle's unit normal.
ControlPoint Snap(const Surface& s, const Vec& x, vtkGenericCell* cell, Vec& normal)
{
  ControlPoint cp;
  double closest[3], dist2 = 0;
  vtkIdType triangle = -1;
  int subId = 0;
  s.Locator->FindClosestPoint(x.data(), closest, cell, triangle, subId, dist2);
  if (triangle < 0)
  {
    return cp;
  }
  const auto ids = s.Triangle(triangle);
  const Vec a = s.Point(ids[0]);
  const Vec e1 = Sub(s.Point(ids[1]), a), e2 = Sub(s.Point(ids[2]), a);
  const Vec d = Sub({ closest[0], closest[1], closest[2] }, a);
  const double d11 = Dot(e1, e1), d12 = Dot(e1, e2), d22 = Dot(e2, e2);
  const double d1 = Dot(d, e1), d2 = Dot(d, e2);
  const double det = d11 * d22 - d12 * d12;
  if (det <= 0)
  {
    return cp; // degenerate triangle: let the caller reject the point
  }
  // The closest point lies in the triangle: clamp only rounding errors.
  double u = std::max(0.0, (d22 * d1 - d12 * d2) / det);
  double v = std::max(0.0, (d11 * d2 - d12 * d1) / det);
  if (u + v > 1)
  {
    u /= u + v;
    v = 1 - u;
  }
  cp.Triangle = triangle;
  cp.U = u;
  cp.V = v;
  cp.Position = Add(a, Add(Scale(e1, u), Scale(e2, v)));
  normal = Normalized(Cross(e1, e2));
  return cp;
}

/// The tangent frame at the surface point closest to x: the normal averages the face normals
/// within half a radius (one triangle of a 1M mesh is noisy), keeping the side of the closest
/// triangle so the far side of a thin part does not cancel it.
bool MakeCircle(const Surface& s, const Vec& x, double radius, vtkGenericCell* cell, Circle& c)
{
  Vec seedNormal;
  const ControlPoint center = Snap(s, x, cell, seedNormal);
  if (center.Triangle < 0)
  {
    return false;
  }
  const double h = 0.5 * radius;
  const Vec& p = center.Position;
  double box[6] = { p[0] - h, p[0] + h, p[1] - h, p[1] + h, p[2] - h, p[2] + h };
  vtkNew<vtkIdList> cells;
  s.Locator->FindCellsWithinBounds(box, cells);
  Vec sum{};
  for (vtkIdType k = 0; k < cells->GetNumberOfIds(); ++k)
  {
    const Vec n = s.AreaNormal(cells->GetId(k));
    if (Dot(n, seedNormal) > 0)
    {
      sum = Add(sum, n);
    }
  }
  c.N = Norm(sum) > 0 ? Normalized(sum) : seedNormal;
  // Any tangent direction: the axis least aligned with the normal, projected.
  Vec axis{ 0, 0, 0 };
  const int least = std::fabs(c.N[0]) < std::fabs(c.N[1])
    ? (std::fabs(c.N[0]) < std::fabs(c.N[2]) ? 0 : 2)
    : (std::fabs(c.N[1]) < std::fabs(c.N[2]) ? 1 : 2);
  axis[least] = 1;
  c.U = Normalized(Cross(c.N, axis));
  c.V = Cross(c.N, c.U);
  c.Center = p;
  c.Radius = radius;
  return true;
}

/// The control points of one version of a circle: count points from angle phase, the center
/// moved by offset (a fraction of the radius) along U. Fails when the surface is not close to a
/// disc there: a point snaps far from the circle, onto a triangle facing away, or onto its
/// neighbour.
bool CirclePoints(const Surface& s,
  const Circle& c,
  int count,
  double phase,
  double offset,
  vtkGenericCell* cell,
  std::vector<ControlPoint>& points)
{
  points.clear();
  const Vec center = Add(c.Center, Scale(c.U, offset * c.Radius));
  const double chord = 2 * c.Radius * std::sin(vtkMath::Pi() / count);
  for (int i = 0; i < count; ++i)
  {
    const double angle = phase + 2 * vtkMath::Pi() * i / count;
    const Vec x = Add(
      center, Add(Scale(c.U, c.Radius * std::cos(angle)), Scale(c.V, c.Radius * std::sin(angle))));
    Vec normal;
    const ControlPoint cp = Snap(s, x, cell, normal);
    if (cp.Triangle < 0 || Norm(Sub(cp.Position, x)) > 0.25 * c.Radius || Dot(normal, c.N) < 0.3 ||
      (!points.empty() && Norm(Sub(cp.Position, points.back().Position)) < 0.3 * chord))
    {
      return false;
    }
    points.push_back(cp);
  }
  return Norm(Sub(points.front().Position, points.back().Position)) >= 0.3 * chord;
}

/// Two versions of every circle: the prepared "before" and "after" of an edit.
constexpr int Versions = 2;
bool CircleVersions(const Surface& s, const Circle& c, int count, vtkGenericCell* cell)
{
  std::vector<ControlPoint> points;
  for (int k = 0; k < Versions; ++k)
  {
    if (!CirclePoints(s, c, count, k * vtkMath::Pi() / count, 0.05 * k, cell, points))
    {
      return false;
    }
  }
  return true;
}

/// Circles in clusters of clusterSize overlapping ones (each new member 1.1-1.5 radii from a
/// random earlier member, so the curves cross), the clusters' seeds spread over the surface
/// (at least 4 radii from every placed center). Deterministic: fixed seed, fixed order.
std::vector<Circle> PlaceCircles(const Surface& s,
  int number,
  double radius,
  int clusterSize,
  int controlPoints,
  unsigned seed)
{
  std::vector<Circle> circles;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  vtkNew<vtkGenericCell> cell;
  size_t clusterBegin = 0;
  const vtkIdType nPoints = s.Mesh->GetNumberOfPoints();
  for (int attempts = 0; static_cast<int>(circles.size()) < number && attempts < 100000; ++attempts)
  {
    const bool seedCircle = circles.size() % clusterSize == 0;
    Vec x;
    if (seedCircle)
    {
      x = s.Point(static_cast<vtkIdType>(rng() % static_cast<unsigned>(nPoints)));
    }
    else
    {
      const Circle& from =
        circles[clusterBegin + rng() % static_cast<unsigned>(circles.size() - clusterBegin)];
      const double angle = 2 * vtkMath::Pi() * unit(rng);
      const double distance = radius * (1.1 + 0.4 * unit(rng));
      x = Add(from.Center,
        Add(Scale(from.U, distance * std::cos(angle)), Scale(from.V, distance * std::sin(angle))));
    }
    Circle c;
    if (!MakeCircle(s, x, radius, cell, c))
    {
      continue;
    }
    const double minimum = seedCircle ? 4 * radius : 0.9 * radius;
    const bool separated = std::all_of(circles.begin(),
      circles.end(),
      [&](const Circle& o) { return Norm(Sub(o.Center, c.Center)) >= minimum; });
    if (!separated || !CircleVersions(s, c, controlPoints, cell))
    {
      continue;
    }
    if (seedCircle)
    {
      clusterBegin = circles.size();
    }
    circles.push_back(c);
  }
  return circles;
}

/// The control-curve input of vtkBoolSurf: one polygon cell per circle (version `version`),
/// cell data ShapeId and CurveType (0: geodesic polygon), exact point data TriangleId and
/// Barycentric.
vtkSmartPointer<vtkPolyData> CurvesInput(const Surface& s,
  const std::vector<Circle>& circles,
  const std::vector<int>& shapeIds,
  int controlPoints,
  int version)
{
  auto curves = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkIdTypeArray> triangleIds;
  triangleIds->SetName("TriangleId");
  vtkNew<vtkDoubleArray> barycentric;
  barycentric->SetName("Barycentric");
  barycentric->SetNumberOfComponents(2);
  vtkNew<vtkIntArray> shapeId;
  shapeId->SetName("ShapeId");
  vtkNew<vtkIntArray> curveType;
  curveType->SetName("CurveType");
  vtkNew<vtkGenericCell> cell;
  std::vector<ControlPoint> cps;
  for (size_t i = 0; i < circles.size(); ++i)
  {
    // Placement checked every version, so this cannot fail.
    CirclePoints(s,
      circles[i],
      controlPoints,
      version * vtkMath::Pi() / controlPoints,
      0.05 * version,
      cell,
      cps);
    polys->InsertNextCell(static_cast<vtkIdType>(cps.size()));
    for (const ControlPoint& cp : cps)
    {
      polys->InsertCellPoint(points->InsertNextPoint(cp.Position.data()));
      triangleIds->InsertNextValue(cp.Triangle);
      const double uv[2] = { cp.U, cp.V };
      barycentric->InsertNextTuple(uv);
    }
    shapeId->InsertNextValue(shapeIds[i]);
    curveType->InsertNextValue(0);
  }
  curves->SetPoints(points);
  curves->SetPolys(polys);
  curves->GetPointData()->AddArray(triangleIds);
  curves->GetPointData()->AddArray(barycentric);
  curves->GetCellData()->AddArray(shapeId);
  curves->GetCellData()->AddArray(curveType);
  return curves;
}

/// A scene: the surface and the prepared versions of its curves.
struct Scene
{
  const Surface* Mesh = nullptr;
  std::vector<vtkSmartPointer<vtkPolyData>> Curves; // one per version
  int Circles = 0;
  std::vector<Circle> Placed;    // the circles of version 0
  vtkIdType TracedVertices = -1; // computed on demand
  std::string Error;
};

const Scene& GetScene(const std::string& key,
  const std::string& mesh,
  int number,
  double radiusFraction,
  int clusterSize,
  int controlPoints,
  unsigned seed,
  const std::vector<int>& shapeIds = {})
{
  static std::map<std::string, Scene> cache;
  auto it = cache.find(key);
  if (it != cache.end())
  {
    return it->second;
  }
  Scene& scene = cache[key];
  const Surface& s = LoadSurface(mesh);
  if (!s.Error.empty())
  {
    scene.Error = s.Error;
    return scene;
  }
  scene.Mesh = &s;
  const std::vector<Circle> circles =
    PlaceCircles(s, number, radiusFraction * s.Diagonal, clusterSize, controlPoints, seed);
  if (static_cast<int>(circles.size()) < number)
  {
    scene.Error = "placed only " + std::to_string(circles.size()) + " of " +
      std::to_string(number) + " circles on " + mesh;
    return scene;
  }
  std::vector<int> ids = shapeIds;
  for (int i = static_cast<int>(ids.size()); i < number; ++i)
  {
    ids.push_back(i);
  }
  for (int v = 0; v < Versions; ++v)
  {
    scene.Curves.push_back(CurvesInput(s, circles, ids, controlPoints, v));
  }
  scene.Circles = number;
  scene.Placed = circles;
  return scene;
}

// The benchmark scenes (cached: placing 112 circles on 1M triangles is not free).
const Scene& TenCircles()
{
  return GetScene("ten", "igea_1m.ply", 10, 0.03, 5, 12, 7);
}
const Scene& PaperScale()
{
  return GetScene("paper", "igea_1m.ply", 112, 0.027, 4, 32, 11);
}
const Scene& HugeShapeId()
{
  return GetScene("huge", "bunny_npm.ply", 2, 0.1, 2, 12, 3, { 0, 1000000 });
}

/// TenCircles' circles on igea_1m subdivided once: the control points snapped again to the
/// finer mesh, at the same positions (the subdivision keeps the surface).
const Scene& TenCirclesSubdivided()
{
  static Scene scene;
  static bool made = false;
  if (made)
  {
    return scene;
  }
  made = true;
  const Scene& coarse = TenCircles();
  const Surface& s = LoadSurface("igea_1m.ply", 1);
  scene.Error = !coarse.Error.empty() ? coarse.Error : s.Error;
  if (!scene.Error.empty())
  {
    return scene;
  }
  vtkNew<vtkGenericCell> cell;
  std::vector<int> ids;
  for (const Circle& c : coarse.Placed)
  {
    if (!CircleVersions(s, c, 12, cell))
    {
      scene.Error = "a circle of the ten does not snap to the subdivided mesh";
      return scene;
    }
    ids.push_back(static_cast<int>(ids.size()));
  }
  for (int v = 0; v < Versions; ++v)
  {
    scene.Curves.push_back(CurvesInput(s, coarse.Placed, ids, 12, v));
  }
  scene.Mesh = &s;
  scene.Circles = coarse.Circles;
  scene.Placed = coarse.Placed;
  return scene;
}

/// A fresh filter on the scene's surface and first curve version, updated once: the surface
/// conversion and the first labeling are not what an edit costs.
vtkSmartPointer<vtkBoolSurf> WarmFilter(const Scene& scene,
  int operation,
  int threads,
  int geodesicMethod = vtkBoolSurf::GEODESIC_BOUNDED)
{
  auto filter = vtkSmartPointer<vtkBoolSurf>::New();
  filter->SetGeodesicMethod(geodesicMethod);
  filter->SetInputData(0, scene.Mesh->Mesh);
  filter->SetInputData(1, scene.Curves[0]);
  filter->SetOperation(operation);
  filter->SetShapeA(-1);
  filter->SetShapeB(-1);
  filter->SetNumberOfThreads(threads);
  filter->Update();
  return filter;
}

/// Sums the per-stage times of output 0's StageTimes field data (milliseconds, named
/// components) when the filter provides it.
struct StageSums
{
  std::vector<std::string> Names;
  std::vector<double> Sums;
  int Count = 0;

  void Add(vtkPolyData* output)
  {
    vtkDataArray* times = output->GetFieldData()->GetArray("StageTimes");
    if (!times || times->GetNumberOfTuples() < 1)
    {
      return;
    }
    const int n = times->GetNumberOfComponents();
    if (this->Names.empty())
    {
      for (int k = 0; k < n; ++k)
      {
        const char* name = times->GetComponentName(k);
        this->Names.push_back(name ? name : "Stage" + std::to_string(k));
      }
      this->Sums.assign(n, 0.0);
    }
    if (n != static_cast<int>(this->Sums.size()))
    {
      return;
    }
    for (int k = 0; k < n; ++k)
    {
      this->Sums[k] += times->GetComponent(0, k);
    }
    ++this->Count;
  }

  void Report(benchmark::State& state, const std::string& prefix = std::string()) const
  {
    for (size_t k = 0; this->Count > 0 && k < this->Names.size(); ++k)
    {
      state.counters[prefix + this->Names[k] + "_ms"] = this->Sums[k] / this->Count;
    }
  }
};

/// What every benchmark reports about the last update: the region's triangles, how many
/// arrangement cells they make up (more cells than circles: the circles cross), and the
/// benchmark's peak RSS, also above the RSS it started from (the meshes already loaded).
void ReportRegion(benchmark::State& state, vtkBoolSurf* filter, double startRssMB)
{
  vtkPolyData* region = filter->GetOutput(0);
  state.counters["RegionTriangles"] = static_cast<double>(region->GetNumberOfCells());
  // The boundary's points are its crossings with mesh edges (and the curves' crossings): what
  // every stage after tracing reads or writes grows with them, not with the mesh.
  state.counters["BoundaryPoints"] = static_cast<double>(filter->GetOutput(1)->GetNumberOfPoints());
  if (vtkDataArray* cellOf = region->GetCellData()->GetArray("ArrangementCell"))
  {
    std::set<double> cells;
    for (vtkIdType t = 0; t < cellOf->GetNumberOfTuples(); ++t)
    {
      cells.insert(cellOf->GetComponent(t, 0));
    }
    state.counters["RegionCells"] = static_cast<double>(cells.size());
  }
  state.counters["PeakRSS_MB"] = PeakRssMB();
  state.counters["PeakRSSGrowth_MB"] = PeakRssMB() - startRssMB;
}

/// A copy of `curves` whose control points of cells `first` to `last` moved by about 1e-12 of
/// their triangle (barycentric weights shifted by `step` ulps-scale amounts): the same shapes,
/// but control points never traced before, so no curve is recalled from the tracer's memory
/// of earlier iterations, as after a real edit (the two prepared versions alone would be
/// remembered after two iterations).
vtkSmartPointer<vtkPolyData> Moved(vtkPolyData* curves, vtkIdType first, vtkIdType last, int step)
{
  auto moved = vtkSmartPointer<vtkPolyData>::New();
  moved->DeepCopy(curves);
  vtkDataArray* uv = moved->GetPointData()->GetArray("Barycentric");
  const double shift = 1e-12 * (1 + step % 4096);
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = first; c <= last && c < moved->GetNumberOfCells(); ++c)
  {
    moved->GetCellPoints(c, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      double w[2];
      uv->GetTuple(ids->GetId(k), w);
      w[0] += w[0] + w[1] + shift < 1 ? shift : -shift;
      uv->SetTuple(ids->GetId(k), w);
    }
  }
  return moved;
}

/// Counts the filter's executions (RequestData runs between StartEvent and EndEvent): an edit
/// that updates several ports must execute once.
struct ExecutionCounter
{
  vtkNew<vtkCallbackCommand> Callback;
  vtkAlgorithm* Filter;
  unsigned long Tag;
  long Count = 0;

  explicit ExecutionCounter(vtkAlgorithm* filter)
    : Filter(filter)
  {
    this->Callback->SetClientData(&this->Count);
    this->Callback->SetCallback(
      [](vtkObject*, unsigned long, void* count, void*) { ++*static_cast<long*>(count); });
    this->Tag = filter->AddObserver(vtkCommand::StartEvent, this->Callback);
  }
  ~ExecutionCounter() { this->Filter->RemoveObserver(this->Tag); }
};

/// Updates every output port in turn, each asking for piece 0 of 1 without ghost levels, as
/// ParaView's UpdatePipeline does (vtkSISourceProxy: one request per output port): what a
/// pvpython user's edit executes when the filter's default outputs are all shown.
void UpdateEveryPort(vtkAlgorithm* filter)
{
  auto* executive = vtkStreamingDemandDrivenPipeline::SafeDownCast(filter->GetExecutive());
  for (int port = 0; port < filter->GetNumberOfOutputPorts(); ++port)
  {
    if (executive)
    {
      executive->UpdateInformation();
      vtkInformation* request = executive->GetOutputInformation(port);
      request->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
      request->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
      request->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
    }
    filter->Update(port);
  }
}

/// What ParaView reads of every port after an update (vtkPVDataInformation: bounds, and each
/// point and cell array's component ranges): O(output) work outside the filter, timed apart.
void ReadPortInformation(vtkAlgorithm* filter)
{
  for (int port = 0; port < filter->GetNumberOfOutputPorts(); ++port)
  {
    vtkPolyData* output = vtkPolyData::SafeDownCast(filter->GetOutputDataObject(port));
    if (!output)
    {
      continue;
    }
    double bounds[6];
    output->GetBounds(bounds);
    for (vtkDataSetAttributes* data : { static_cast<vtkDataSetAttributes*>(output->GetPointData()),
           static_cast<vtkDataSetAttributes*>(output->GetCellData()) })
    {
      for (int a = 0; a < data->GetNumberOfArrays(); ++a)
      {
        if (vtkDataArray* array = data->GetArray(a))
        {
          for (int c = 0; c < array->GetNumberOfComponents(); ++c)
          {
            double range[2];
            array->GetRange(range, c);
          }
        }
      }
    }
  }
}

/// Each iteration switches the curves to the other prepared version, every control point
/// moved slightly (see Moved: a new input object, the filter retraces, rearranges, relabels),
/// and updates. With `dragOne`, only one circle moves per iteration (the next one each time)
/// and the others stay where they were: a user dragging one curve among many.
void CurveEdits(benchmark::State& state,
  const Scene& scene,
  int operation,
  int threads,
  bool dragOne = false,
  int geodesicMethod = vtkBoolSurf::GEODESIC_BOUNDED,
  bool allPorts = false)
{
  if (!scene.Error.empty())
  {
    state.SkipWithError(scene.Error.c_str());
    return;
  }
  const double startRss = ResetPeakRss();
  const auto warm0 = std::chrono::steady_clock::now();
  vtkSmartPointer<vtkBoolSurf> filter = WarmFilter(scene, operation, threads, geodesicMethod);
  const double firstUpdateMs = Milliseconds(warm0, std::chrono::steady_clock::now());
  if (filter->GetOutput(0)->GetNumberOfCells() == 0)
  {
    state.SkipWithError("the warm-up update produced no region");
    return;
  }
  StageSums firstStages; // the first update's stages; the rest of it prepares the surface
  firstStages.Add(filter->GetOutput(0));
  StageSums stages;
  double updateMs = 0, faults = 0, portsMs = 0;
  size_t version = 0;
  int step = 0;
  vtkSmartPointer<vtkPolyData> input;
  ExecutionCounter executions(filter);
  for (auto _ : state)
  {
    state.PauseTiming();
    ++step;
    if (dragOne)
    {
      const vtkIdType circle = step % scene.Circles;
      input = Moved(scene.Curves[0], circle, circle, step);
    }
    else
    {
      version = (version + 1) % scene.Curves.size();
      input = Moved(scene.Curves[version], 0, scene.Circles - 1, step);
    }
    filter->SetInputData(1, input);
    state.ResumeTiming();
    if (step == 1)
    {
      // Under valgrind --tool=callgrind --instr-atstart=no --collect-atstart=no, the edits'
      // instructions alone are counted (no-ops otherwise).
      CALLGRIND_START_INSTRUMENTATION;
    }
    const double faults0 = benchutil::ProcessMinorFaults();
    const auto t0 = std::chrono::steady_clock::now();
    CALLGRIND_TOGGLE_COLLECT;
    if (allPorts)
    {
      UpdateEveryPort(filter);
    }
    else
    {
      filter->Update();
    }
    CALLGRIND_TOGGLE_COLLECT;
    const auto t1 = std::chrono::steady_clock::now();
    if (allPorts)
    {
      ReadPortInformation(filter);
    }
    const auto t2 = std::chrono::steady_clock::now();
    updateMs += Milliseconds(t0, t2);
    portsMs += Milliseconds(t1, t2);
    faults += benchutil::ProcessMinorFaults() - faults0;
    stages.Add(filter->GetOutput(0));
  }
  if (filter->GetOutput(0)->GetNumberOfCells() == 0)
  {
    state.SkipWithError("an edit produced no region");
    return;
  }
  stages.Report(state);
  ReportRegion(state, filter, startRss);
  state.counters["Circles"] = scene.Circles;
  state.counters["DeepCopyMs"] = scene.Mesh->DeepCopyMs;
  state.counters["EditOverDeepCopy"] =
    updateMs / static_cast<double>(state.iterations()) / scene.Mesh->DeepCopyMs;
  state.counters["MinorFaults"] = faults / static_cast<double>(state.iterations());
  state.counters["ExecutionsPerEdit"] =
    static_cast<double>(executions.Count) / static_cast<double>(state.iterations());
  if (allPorts)
  {
    state.counters["PortInformation_ms"] = portsMs / static_cast<double>(state.iterations());
  }
  state.counters["FirstUpdateMs"] = firstUpdateMs;
  firstStages.Report(state, "First");
}

void BM_OneStepCurveEdit(benchmark::State& state)
{
  CurveEdits(state, TenCircles(), 0, static_cast<int>(state.range(0)));
}

void BM_OneStepCurveEditSubdivided(benchmark::State& state)
{
  CurveEdits(state, TenCirclesSubdivided(), 0, static_cast<int>(state.range(0)));
}

// The same edits with locally shortest legs (cost linear in a leg's length in triangles, not
// in the area its exact search explores): what the mesh's resolution costs an edit apart from
// the exact search.
void BM_OneStepCurveEditLocallyShortest(benchmark::State& state)
{
  CurveEdits(state,
    TenCircles(),
    0,
    static_cast<int>(state.range(0)),
    false,
    vtkBoolSurf::GEODESIC_LOCALLY_SHORTEST);
}

void BM_OneStepCurveEditSubdividedLocallyShortest(benchmark::State& state)
{
  CurveEdits(state,
    TenCirclesSubdivided(),
    0,
    static_cast<int>(state.range(0)),
    false,
    vtkBoolSurf::GEODESIC_LOCALLY_SHORTEST);
}

void BM_OneStepDragOneCurve(benchmark::State& state)
{
  CurveEdits(state, TenCircles(), 0, static_cast<int>(state.range(0)), true);
}

void BM_OneStepOperationChange(benchmark::State& state)
{
  const Scene& scene = TenCircles();
  if (!scene.Error.empty())
  {
    state.SkipWithError(scene.Error.c_str());
    return;
  }
  const double startRss = ResetPeakRss();
  vtkSmartPointer<vtkBoolSurf> filter = WarmFilter(scene, 0, static_cast<int>(state.range(0)));
  StageSums stages;
  int operation = 0;
  for (auto _ : state)
  {
    operation = operation == 0 ? 3 : 0; // Union <-> SymmetricDifference
    filter->SetOperation(operation);
    filter->Update();
    stages.Add(filter->GetOutput(0));
  }
  stages.Report(state);
  ReportRegion(state, filter, startRss);
}

void BM_OneStepPaperScaleXor(benchmark::State& state)
{
  const Scene& scene = PaperScale();
  if (!scene.Error.empty())
  {
    state.SkipWithError(scene.Error.c_str());
    return;
  }
  // The traced curves' vertex count (every mesh-edge crossing), once per process: a separate
  // tracing filter, outside any timing.
  static vtkIdType tracedVertices = -1;
  if (tracedVertices < 0)
  {
    vtkNew<vtkBoolSurfTraceCurves> trace;
    trace->SetInputData(0, scene.Mesh->Mesh);
    trace->SetInputData(1, scene.Curves[0]);
    trace->Update();
    tracedVertices = trace->GetOutput()->GetNumberOfPoints();
  }
  CurveEdits(state, scene, 3, static_cast<int>(state.range(0)));
  state.counters["TracedVertices"] = static_cast<double>(tracedVertices);
}

// The same edits with every output port updated as ParaView does (UpdateEveryPort) and read
// as its data information reads them (PortInformation_ms, inside the update's time): a
// pvpython user's edit with the filter's default outputs.
void BM_OneStepPaperScaleXorAllPorts(benchmark::State& state)
{
  CurveEdits(state,
    PaperScale(),
    3,
    static_cast<int>(state.range(0)),
    false,
    vtkBoolSurf::GEODESIC_BOUNDED,
    true);
}

/// BSC samples on the scene's circles (version 0): control point `index` of each circle,
/// pointing to the circle's center (its inside), as exact surface points.
vtkSmartPointer<vtkPolyData> CircleSamples(const Scene& scene, int controlPoints, int index)
{
  auto samples = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> direction;
  direction->SetName("Direction");
  direction->SetNumberOfComponents(3);
  vtkNew<vtkIdTypeArray> triangleIds;
  triangleIds->SetName("TriangleId");
  vtkNew<vtkDoubleArray> barycentric;
  barycentric->SetName("Barycentric");
  barycentric->SetNumberOfComponents(2);
  vtkNew<vtkGenericCell> cell;
  std::vector<ControlPoint> cps;
  for (const Circle& c : scene.Placed)
  {
    CirclePoints(*scene.Mesh, c, controlPoints, 0, 0, cell, cps);
    const ControlPoint& cp = cps[index];
    points->InsertNextPoint(cp.Position.data());
    direction->InsertNextTuple(Sub(c.Center, cp.Position).data());
    triangleIds->InsertNextValue(cp.Triangle);
    const double uv[2] = { cp.U, cp.V };
    barycentric->InsertNextTuple(uv);
  }
  samples->SetPoints(points);
  samples->GetPointData()->AddArray(direction);
  samples->GetPointData()->AddArray(triangleIds);
  samples->GetPointData()->AddArray(barycentric);
  return samples;
}

// What choosing the region costs at paper scale (112 circles, igea_1m, 2 threads), with the
// labeled arrangement reused: bsc:0 toggles the Boolean between Union and SymmetricDifference,
// bsc:1 switches between two BSC sample sets (one sample per circle, pointing inside, at two
// different control points). Selection_ms and Output_ms are the filter's own stage times.
void BM_OneStepPaperScaleSelection(benchmark::State& state)
{
  const Scene& scene = PaperScale();
  if (!scene.Error.empty())
  {
    state.SkipWithError(scene.Error.c_str());
    return;
  }
  const bool bsc = state.range(0) != 0;
  const double startRss = ResetPeakRss();
  vtkSmartPointer<vtkBoolSurf> filter = WarmFilter(scene, 3, 2);
  const vtkSmartPointer<vtkPolyData> samples[2] = { CircleSamples(scene, 32, 0),
    CircleSamples(scene, 32, 16) };
  filter->SetInputData(2, samples[0]);
  filter->SetSelection(bsc ? 1 : 0);
  filter->Update();
  StageSums stages;
  double updateMs = 0;
  int k = 0;
  for (auto _ : state)
  {
    k = 1 - k;
    if (bsc)
    {
      filter->SetInputData(2, samples[k]);
    }
    else
    {
      filter->SetOperation(k == 1 ? 0 : 3);
    }
    const auto t0 = std::chrono::steady_clock::now();
    filter->Update();
    updateMs += Milliseconds(t0, std::chrono::steady_clock::now());
    stages.Add(filter->GetOutput(0));
  }
  if (filter->GetOutput(0)->GetNumberOfCells() == 0)
  {
    state.SkipWithError("the selection produced no region");
    return;
  }
  stages.Report(state);
  ReportRegion(state, filter, startRss);
  state.counters["Update_ms"] = updateMs / static_cast<double>(state.iterations());
  if (bsc)
  {
    vtkFieldData* fd = filter->GetOutput(0)->GetFieldData();
    state.counters["Samples"] = static_cast<double>(samples[0]->GetNumberOfPoints());
    state.counters["DroppedSamples"] =
      static_cast<double>(fd->GetArray("DroppedSamples")->GetNumberOfTuples());
    state.counters["Cuts"] = fd->GetArray("BSCCuts")->GetComponent(0, 0);
  }
}

/// The same edits as BM_OneStepCurveEdit through the stage filters (Trace Surface Curves ->
/// Surface Arrangement -> Label Arrangement Cells -> Surface Boolean), each updated in turn so
/// that each stage's share is timed: counters Trace_ms, Arrangement_ms, Labeling_ms, Boolean_ms
/// (means), and ChainRegionTriangles, which must equal the one-step RegionTriangles.
/// `colorShape` >= 0 and `perTriangleLabels` ask Label Arrangement Cells for its per-triangle
/// arrays (ShapeLabel of that shape, Labels), as a user coloring the surface does;
/// `surfaceArrays` gives the surface a point scalar and a cell scalar of its own, which Surface
/// Arrangement carries onto the refined surface.
void StageChainEdits(benchmark::State& state,
  const Scene& scene,
  int operation,
  int colorShape = -1,
  bool perTriangleLabels = false,
  bool surfaceArrays = false)
{
  if (!scene.Error.empty())
  {
    state.SkipWithError(scene.Error.c_str());
    return;
  }
  const int threads = static_cast<int>(state.range(0));
  const double startRss = ResetPeakRss();
  vtkNew<vtkBoolSurfTraceCurves> trace;
  vtkNew<vtkBoolSurfArrangement> arrange;
  vtkNew<vtkBoolSurfLabeling> label;
  vtkNew<vtkBoolSurfBoolean> boolean;
  vtkSmartPointer<vtkPolyData> surface = scene.Mesh->Mesh;
  if (surfaceArrays)
  {
    // The same points and triangles (the same converted surface) with a height field per
    // point and an id per triangle.
    surface = vtkSmartPointer<vtkPolyData>::New();
    surface->ShallowCopy(scene.Mesh->Mesh);
    vtkNew<vtkDoubleArray> height;
    height->SetName("Height");
    height->SetNumberOfValues(surface->GetNumberOfPoints());
    for (vtkIdType p = 0; p < surface->GetNumberOfPoints(); ++p)
    {
      height->SetValue(p, surface->GetPoint(p)[2]);
    }
    surface->GetPointData()->AddArray(height);
    vtkNew<vtkIntArray> inputCell;
    inputCell->SetName("InputCell");
    inputCell->SetNumberOfValues(surface->GetNumberOfCells());
    for (vtkIdType c = 0; c < surface->GetNumberOfCells(); ++c)
    {
      inputCell->SetValue(c, static_cast<int>(c));
    }
    surface->GetCellData()->AddArray(inputCell);
  }
  trace->SetInputData(0, surface);
  trace->SetInputData(1, scene.Curves[0]);
  arrange->SetInputData(0, surface);
  arrange->SetInputConnection(1, trace->GetOutputPort());
  arrange->SetNumberOfThreads(threads);
  label->SetInputConnection(arrange->GetOutputPort(0));
  label->SetColorShape(colorShape);
  label->SetPerTriangleLabels(perTriangleLabels);
  boolean->SetInputConnection(label->GetOutputPort(0));
  boolean->SetShapeA(-1);
  boolean->SetShapeB(-1);
  boolean->SetOperation(operation);
  boolean->Update();
  if (boolean->GetOutput(0)->GetNumberOfCells() == 0)
  {
    state.SkipWithError("the warm-up update produced no region");
    return;
  }
  double faults = 0;
  StageSums arrangementStages; // the Core arrangement's own split, inside Arrangement_ms
  double iterationMs = 0;
  size_t version = 0;
  int step = 0;
  // The next curve version, every control point moved slightly (see Moved).
  const auto nextEdit = [&]
  {
    ++step;
    version = (version + 1) % scene.Curves.size();
    trace->SetInputData(1, Moved(scene.Curves[version], 0, scene.Circles - 1, step));
  };
  // Edits before timing, as the one-step filter's warm-up: the arrangement's results and arrays
  // are double-buffered (one set is still held downstream while the next is computed), so each
  // buffer sees every curve version and has grown to it (a vector growing past its capacity
  // mid-measurement costs a 30 ms reallocation once) before the timed edits.
  for (int warm = 0; warm < 6; ++warm)
  {
    nextEdit();
    boolean->Update();
  }
  // One update of the last filter per edit, as ParaView and pvpython update a pipeline; the
  // filters' own executions are timed inside it (the rest is VTK's executive).
  benchutil::FilterUpdateTimer stages({ trace, arrange, label, boolean });
  for (auto _ : state)
  {
    state.PauseTiming();
    nextEdit();
    state.ResumeTiming();
    const double faults0 = benchutil::ProcessMinorFaults();
    const auto iterStart = std::chrono::steady_clock::now();
    boolean->Update();
    iterationMs += Milliseconds(iterStart, std::chrono::steady_clock::now());
    faults += benchutil::ProcessMinorFaults() - faults0;
    arrangementStages.Add(arrange->GetOutput(0));
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["Trace_ms"] = stages.Milliseconds(0) / n;
  state.counters["Arrangement_ms"] = stages.Milliseconds(1) / n;
  state.counters["Labeling_ms"] = stages.Milliseconds(2) / n;
  state.counters["Boolean_ms"] = stages.Milliseconds(3) / n;
  state.counters["Update_ms"] = iterationMs / n;
  state.counters["MinorFaults"] = faults / n;
  state.counters["TraceFaults"] = stages.MinorFaults(0) / n;
  state.counters["ArrangementFaults"] = stages.MinorFaults(1) / n;
  state.counters["LabelingFaults"] = stages.MinorFaults(2) / n;
  state.counters["BooleanFaults"] = stages.MinorFaults(3) / n;
  arrangementStages.Report(state);
  state.counters["ChainRegionTriangles"] =
    static_cast<double>(boolean->GetOutput(0)->GetNumberOfCells());
  state.counters["DeepCopyMs"] = scene.Mesh->DeepCopyMs;
  state.counters["PeakRSSGrowth_MB"] = PeakRssMB() - startRss;
}

void BM_StageChainCurveEdit(benchmark::State& state)
{
  StageChainEdits(state, TenCircles(), 0);
}

// BM_OneStepPaperScaleXor's edits through the stage filters: the one-step filter must never be
// slower on the same edit.
void BM_StageChainPaperScaleXor(benchmark::State& state)
{
  StageChainEdits(state, PaperScale(), 3);
}

// The same edits with the labeled surface colored by shape 0 (ShapeLabel, a label per refined
// triangle): what keeping that array from edit to edit saves (Labeling_ms).
void BM_StageChainPaperScaleXorColored(benchmark::State& state)
{
  StageChainEdits(state, PaperScale(), 3, 0);
}

// BM_StageChainCurveEdit with ShapeLabel of shape 0 and every shape's label per triangle
// (Labels: ten components per refined triangle), on the surface with arrays of its own (a
// point scalar and a cell scalar, carried onto the refined surface).
void BM_StageChainCurveEditLabeled(benchmark::State& state)
{
  StageChainEdits(state, TenCircles(), 0, 0, true, true);
}

// One thread: the scene is two circles, there is nothing to share out. Few iterations: with
// per-shape costs an update takes seconds.
void BM_OneStepHugeShapeId(benchmark::State& state)
{
  CurveEdits(state, HugeShapeId(), 0, 1);
}

// Edits at one and two threads (NumberOfThreads), milliseconds of real time, `edits` each
// (BOOLSURF_BENCHMARK_ITERATIONS sets another number, e.g. for a profiler).
/// The curves of `closed` (one polygon cell per circle) broken: each circle's control points
/// 0..k/2-1 and k/2..k-2 as two open polylines of the circle's shape, so each circle has two
/// gaps of one leg (1/12 of it with 12 control points).
vtkSmartPointer<vtkPolyData> Broken(vtkPolyData* closed)
{
  auto broken = vtkSmartPointer<vtkPolyData>::New();
  broken->SetPoints(closed->GetPoints());
  broken->GetPointData()->ShallowCopy(closed->GetPointData());
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkIntArray> shapeId;
  shapeId->SetName("ShapeId");
  vtkNew<vtkIntArray> curveType;
  curveType->SetName("CurveType");
  vtkDataArray* shapes = closed->GetCellData()->GetArray("ShapeId");
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < closed->GetNumberOfCells(); ++c)
  {
    closed->GetCellPoints(c, ids);
    const vtkIdType k = ids->GetNumberOfIds();
    const vtkIdType pieces[2][2] = { { 0, k / 2 - 1 }, { k / 2, k - 2 } };
    for (const auto& piece : pieces)
    {
      lines->InsertNextCell(piece[1] - piece[0] + 1);
      for (vtkIdType i = piece[0]; i <= piece[1]; ++i)
      {
        lines->InsertCellPoint(ids->GetId(i));
      }
      shapeId->InsertNextValue(static_cast<int>(shapes->GetComponent(c, 0)));
      curveType->InsertNextValue(0);
    }
  }
  broken->SetLines(lines);
  broken->GetCellData()->AddArray(shapeId);
  broken->GetCellData()->AddArray(curveType);
  return broken;
}

/// Winding Numbers (issue 57) on TenCircles broken into open curves, through VTK: a fresh
/// filter's first update (the Laplacian's factorization included), then one circle dragged per
/// update (its control points moved, the other nine kept: their shapes keep their solve).
void BM_WindingNumbersDragOneCurve(benchmark::State& state)
{
  const Scene& scene = TenCircles();
  if (!scene.Error.empty())
  {
    state.SkipWithError(scene.Error.c_str());
    return;
  }
  const double startRss = ResetPeakRss();
  auto filter = vtkSmartPointer<vtkBoolSurfWindingNumbers>::New();
  filter->SetInputData(0, scene.Mesh->Mesh);
  filter->SetInputData(1, Broken(scene.Curves[0]));
  filter->SetNumberOfThreads(static_cast<int>(state.range(0)));
  const auto t0 = std::chrono::steady_clock::now();
  filter->Update();
  const double firstUpdateMs = Milliseconds(t0, std::chrono::steady_clock::now());
  const double firstPeak = PeakRssMB() - startRss;
  if (filter->GetOutput(1)->GetNumberOfCells() == 0)
  {
    state.SkipWithError("the first update produced no region");
    return;
  }
  int step = 0;
  for (auto _ : state)
  {
    state.PauseTiming();
    ++step;
    const vtkIdType circle = step % scene.Circles;
    vtkSmartPointer<vtkPolyData> input = Broken(Moved(scene.Curves[0], circle, circle, step));
    filter->SetInputData(1, input);
    state.ResumeTiming();
    filter->Update();
  }
  if (filter->GetOutput(1)->GetNumberOfCells() == 0)
  {
    state.SkipWithError("an edit produced no region");
    return;
  }
  state.counters["FirstUpdateMs"] = firstUpdateMs;
  state.counters["FirstUpdatePeakRSSGrowth_MB"] = firstPeak;
  // The last update's stages (the filter's WindingTimes field data, milliseconds).
  if (vtkDataArray* times = filter->GetOutput(0)->GetFieldData()->GetArray("WindingTimes"))
  {
    for (int c = 0; c < times->GetNumberOfComponents(); ++c)
    {
      const char* name = times->GetComponentName(c);
      state.counters[std::string("Last") + (name ? name : std::to_string(c)) + "Ms"] =
        times->GetComponent(0, c);
    }
  }
  state.counters["RegionCells"] = static_cast<double>(filter->GetOutput(1)->GetNumberOfCells());
  state.counters["Circles"] = scene.Circles;
}

template <int edits>
void AtOneAndTwoThreads(benchmark::internal::Benchmark* b)
{
  const char* iterations = std::getenv("BOOLSURF_BENCHMARK_ITERATIONS");
  b->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(iterations ? std::atoi(iterations) : edits);
}

BENCHMARK(BM_OneStepCurveEdit)->Apply(AtOneAndTwoThreads<10>);
BENCHMARK(BM_OneStepCurveEditSubdivided)->Apply(AtOneAndTwoThreads<10>);
BENCHMARK(BM_OneStepCurveEditLocallyShortest)->Apply(AtOneAndTwoThreads<10>);
BENCHMARK(BM_OneStepCurveEditSubdividedLocallyShortest)->Apply(AtOneAndTwoThreads<10>);
BENCHMARK(BM_StageChainCurveEdit)->Apply(AtOneAndTwoThreads<10>);
BENCHMARK(BM_OneStepDragOneCurve)->Apply(AtOneAndTwoThreads<10>);
BENCHMARK(BM_OneStepOperationChange)->Apply(AtOneAndTwoThreads<10>);
BENCHMARK(BM_OneStepPaperScaleXor)->Apply(AtOneAndTwoThreads<6>);
BENCHMARK(BM_OneStepPaperScaleXorAllPorts)->Apply(AtOneAndTwoThreads<6>);
BENCHMARK(BM_StageChainPaperScaleXor)->Apply(AtOneAndTwoThreads<6>);
BENCHMARK(BM_StageChainPaperScaleXorColored)->Apply(AtOneAndTwoThreads<6>);
BENCHMARK(BM_StageChainCurveEditLabeled)->Apply(AtOneAndTwoThreads<10>);
BENCHMARK(BM_OneStepPaperScaleSelection)
  ->ArgName("bsc")
  ->Arg(0)
  ->Arg(1)
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime()
  ->Iterations(10);
BENCHMARK(BM_WindingNumbersDragOneCurve)
  ->Arg(2)
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime()
  ->Iterations(6)
  ->Repetitions(3);
BENCHMARK(BM_OneStepHugeShapeId)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(5);

} // namespace

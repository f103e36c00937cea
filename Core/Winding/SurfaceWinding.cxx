#include "Winding/SurfaceWinding.h"

#include "Mesh/MeshTopology.h"
#include "Mesh/ParallelRange.h"
#include "Winding/CotanLaplacian.h"
#include "Winding/HarmonicBasis.h"
#include "Winding/JumpLift.h"
#include "Winding/WindingField.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>

namespace boolsurf
{

SurfaceWinding::SurfaceWinding() = default;
SurfaceWinding::~SurfaceWinding() = default;

double WindingResult::Corner(const RefinedTriangles& arr,
  const TriangleMesh& mesh,
  int s,
  int r,
  int k) const
{
  const int p = arr.GetTriangle(mesh, r)[k];
  const int slot = this->JumpSlot[r];
  return this->Base(s, p) + (slot >= 0 ? this->CornerLift[s][3 * slot + k] : 0.0);
}

double WindingResult::Point(int s, int p) const
{
  const std::vector<std::pair<int, double>>& lifts = this->PointLift[s];
  const auto it = std::lower_bound(lifts.begin(), lifts.end(), std::make_pair(p, -HUGE_VAL));
  return this->Base(s, p) + (it != lifts.end() && it->first == p ? it->second : 0.0);
}

void WindingResult::WritePoints(int s, int numberOfPoints, double* values) const
{
  for (int p = 0; p < numberOfPoints; ++p)
  {
    values[p] = this->Base(s, p);
  }
  for (const auto& entry : this->PointLift[s])
  {
    values[entry.first] += entry.second;
  }
}

double WindingResult::Triangle(const RefinedTriangles& arr,
  const TriangleMesh& mesh,
  int s,
  int r) const
{
  return (this->Corner(arr, mesh, s, r, 0) + this->Corner(arr, mesh, s, r, 1) +
           this->Corner(arr, mesh, s, r, 2)) /
    3.0;
}

namespace
{

double Seconds(std::chrono::steady_clock::time_point from)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - from).count();
}

/// Greedy homology correction of one shape: drops the curves most aligned with the shape's
/// excess class until its norm is below 1/2. Returns the dropped curves' indices.
std::vector<int> DropNonBounding(const std::vector<int>& curves,
  const std::vector<std::vector<double>>& coefficients)
{
  std::vector<int> dropped;
  if (curves.empty() || coefficients[curves[0]].empty())
  {
    return dropped;
  }
  const size_t ng = coefficients[curves[0]].size();
  std::vector<double> excess(ng, 0.0);
  for (int c : curves)
  {
    for (size_t g = 0; g < ng; ++g)
    {
      excess[g] += coefficients[c][g];
    }
  }
  auto norm = [](const std::vector<double>& x)
  {
    double s = 0;
    for (double v : x)
    {
      s += v * v;
    }
    return std::sqrt(s);
  };
  std::vector<char> kept(curves.size(), 1);
  while (norm(excess) >= 0.5)
  {
    int best = -1;
    double bestDot = 0.0;
    for (size_t i = 0; i < curves.size(); ++i)
    {
      if (!kept[i])
      {
        continue;
      }
      double dot = 0;
      for (size_t g = 0; g < ng; ++g)
      {
        dot += coefficients[curves[i]][g] * excess[g];
      }
      if (dot > bestDot + 1e-12)
      {
        bestDot = dot;
        best = static_cast<int>(i);
      }
    }
    if (best < 0)
    {
      break;
    }
    kept[best] = 0;
    dropped.push_back(curves[best]);
    for (size_t g = 0; g < ng; ++g)
    {
      excess[g] -= coefficients[curves[best]][g];
    }
  }
  std::sort(dropped.begin(), dropped.end());
  return dropped;
}

//------------------------------------------------------------------------------
// At least one curve, those of the arrangement, each of at least two valid points.
bool CheckCurves(const TriangleMesh& mesh,
  const Arrangement& arr,
  const std::vector<TracedCurve>& curves,
  std::string& error)
{
  if (curves.empty())
  {
    error = "no curves: winding numbers need at least one curve";
    return false;
  }
  if (arr.CurvePoints.size() != curves.size())
  {
    error = "the arrangement was not computed from these curves";
    return false;
  }
  for (size_t c = 0; c < curves.size(); ++c)
  {
    const TracedCurve& curve = curves[c];
    if (curve.Points.size() < 2)
    {
      error = "curve " + std::to_string(curve.CurveId) + " of shape " +
        std::to_string(curve.ShapeId) + " has " + std::to_string(curve.Points.size()) +
        " point(s): a curve needs at least two";
      return false;
    }
    for (size_t i = 0; i < curve.Points.size(); ++i)
    {
      std::string problem;
      if (!CheckCanonicalPoint(mesh, curve.Points[i], problem))
      {
        error = "point " + std::to_string(i) + " of curve " + std::to_string(curve.CurveId) +
          " of shape " + std::to_string(curve.ShapeId) + ": " + problem;
        return false;
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
// The shapes (those of the options, else every curve's, sorted) and the curves of each; a
// shape requested twice or without a curve is refused.
bool GroupCurvesByShape(const std::vector<TracedCurve>& curves,
  const WindingOptions& options,
  std::vector<int>& shapes,
  std::vector<std::vector<int>>& shapeCurves,
  std::string& error)
{
  shapes = options.Shapes;
  if (shapes.empty())
  {
    for (const TracedCurve& curve : curves)
    {
      shapes.push_back(curve.ShapeId);
    }
    std::sort(shapes.begin(), shapes.end());
    shapes.erase(std::unique(shapes.begin(), shapes.end()), shapes.end());
  }
  std::map<int, int> shapeIndex;
  for (size_t s = 0; s < shapes.size(); ++s)
  {
    if (!shapeIndex.emplace(shapes[s], static_cast<int>(s)).second)
    {
      error = "shape " + std::to_string(shapes[s]) + " is requested twice";
      return false;
    }
  }
  const int ns = static_cast<int>(shapes.size());
  shapeCurves.assign(ns, std::vector<int>());
  for (size_t c = 0; c < curves.size(); ++c)
  {
    const auto it = shapeIndex.find(curves[c].ShapeId);
    if (it != shapeIndex.end())
    {
      shapeCurves[it->second].push_back(static_cast<int>(c));
    }
  }
  for (int s = 0; s < ns; ++s)
  {
    if (shapeCurves[s].empty())
    {
      error = "shape " + std::to_string(shapes[s]) + " has no curve";
      return false;
    }
  }

  return true;
}

//------------------------------------------------------------------------------
// The system of a surface: its factorized Laplacian, topology, genus and the boundary loop of
// each block of vertices. Null (with `error`) when the factorization fails.
std::shared_ptr<WindingSystem> BuildWindingSystem(const TriangleMesh& mesh, std::string& error)
{
  auto system = std::make_shared<WindingSystem>();
  if (!system->Laplacian.Factorize(mesh, error))
  {
    return nullptr;
  }
  system->Topology = MeshTopology::Compute(mesh);
  for (const ComponentTopology& component : system->Topology.Components)
  {
    system->Genus += std::max(0, component.Genus);
  }
  const std::vector<int>& blocks = system->Laplacian.GetVertexBlocks();
  system->BlockLoop.assign(system->Laplacian.GetNumberOfBlocks(), -1);
  for (size_t l = 0; l < system->Topology.BoundaryLoops.size(); ++l)
  {
    const BoundaryLoop& loop = system->Topology.BoundaryLoops[l];
    const int b = loop.Vertices.empty() ? -1 : blocks[loop.Vertices[0]];
    if (b >= 0 &&
      (system->BlockLoop[b] < 0 ||
        loop.Length > system->Topology.BoundaryLoops[system->BlockLoop[b]].Length))
    {
      system->BlockLoop[b] = static_cast<int>(l);
    }
  }
  system->MeshSerial = mesh.GetSerial();
  return system;
}

//------------------------------------------------------------------------------
// Homology correction: each curve's harmonic coefficients, then the greedy drop per shape
// (shapes reused from the last call are skipped: kept only when nothing was dropped).
bool DropCurvesAroundHandles(const TriangleMesh& mesh,
  const Arrangement& arr,
  const std::vector<TracedCurve>& curves,
  const std::vector<std::vector<int>>& shapeCurves,
  const std::vector<char>& reused,
  WindingSystem& system,
  std::vector<std::vector<double>>& coefficients,
  std::vector<char>& dropped,
  std::string& error)
{
  const int ns = static_cast<int>(shapeCurves.size());
  if (!system.HarmonicReady)
  {
    if (!system.Harmonic.Compute(mesh, system.Laplacian, error))
    {
      return false;
    }
    system.HarmonicReady = true;
  }
  for (int s = 0; s < ns; ++s)
  {
    if (reused[s])
    {
      continue; // kept only when nothing was dropped
    }
    for (int c : shapeCurves[s])
    {
      CurveEdgeList edges;
      AppendCurveEdges(arr, c, curves[c].Closed, edges);
      JumpLift lift;
      ComputeJumpLift(mesh, arr, edges, lift);
      coefficients[c] = system.Harmonic.Coefficients(mesh, lift);
    }
    for (int c : DropNonBounding(shapeCurves[s], coefficients))
    {
      dropped[c] = 1;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
// Keep u of the shapes where nothing was dropped for the next edit.
void KeepSolvedShapes(const Arrangement& arr,
  const std::vector<TracedCurve>& curves,
  const WindingOptions& options,
  const std::vector<int>& shapes,
  const std::vector<std::vector<int>>& shapeCurves,
  const std::vector<std::vector<Traversal>>& shapeEdges,
  const std::vector<char>& reused,
  const std::vector<char>& dropped,
  const std::vector<std::shared_ptr<const std::vector<double>>>& columns,
  const WindingResult& out,
  WindingSystem& system)
{
  const int ns = static_cast<int>(shapes.size());
  for (int s = 0; s < ns; ++s)
  {
    size_t all = 0;
    bool anyDropped = false;
    for (int c : shapeCurves[s])
    {
      anyDropped = anyDropped || dropped[c];
      all += arr.CurvePoints[c].size() - (curves[c].Closed ? 0 : 1);
    }
    if (!reused[s])
    {
      if (!anyDropped && all == shapeEdges[s].size() && options.RemoveNonBounding)
      {
        WindingSystem::SolvedShape& kept = system.Solved[shapes[s]];
        kept.Curves.clear();
        for (int c : shapeCurves[s])
        {
          kept.Curves.push_back(curves[c]);
        }
        kept.Smooth = columns[s];
        kept.Shift = out.BlockShift[s];
      }
      else
      {
        system.Solved.erase(shapes[s]);
      }
    }
  }
}

//------------------------------------------------------------------------------
// Cell means (area-weighted over each arrangement cell's refined triangles), over fixed
// blocks of triangles summed in order, so the result does not depend on the threads.
void ComputeCellMeans(const TriangleMesh& mesh,
  const Arrangement& arr,
  int threads,
  int ns,
  WindingResult& out)
{
  const int nr = arr.GetNumberOfTriangles();
  const int nc = arr.NumberOfCells;
  constexpr int blockSize = 1 << 16;
  const int nblocks = (nr + blockSize - 1) / blockSize;
  std::vector<std::vector<double>> partial(nblocks);
  ParallelBlocks(
    threads,
    nr > blockSize,
    nblocks,
    [&](int first, int last)
    {
      for (int block = first; block < last; ++block)
      {
        std::vector<double>& sums = partial[block];
        sums.assign(static_cast<size_t>(nc) * (ns + 1), 0.0); // area, then each shape
        const int end = std::min(nr, (block + 1) * blockSize);
        for (int r = block * blockSize; r < end; ++r)
        {
          const int cell = arr.CellOfTriangle(r);
          if (cell < 0)
          {
            continue;
          }
          const Triangle tri = arr.GetTriangle(mesh, r);
          const double area = 0.5 *
            Length(Cross(arr.GetPosition(mesh, tri[1]) - arr.GetPosition(mesh, tri[0]),
              arr.GetPosition(mesh, tri[2]) - arr.GetPosition(mesh, tri[0])));
          double* row = sums.data() + static_cast<size_t>(cell) * (ns + 1);
          row[0] += area;
          const int slot = out.JumpSlot[r];
          for (int s = 0; s < ns; ++s)
          {
            double sum = out.Base(s, tri[0]) + out.Base(s, tri[1]) + out.Base(s, tri[2]);
            if (slot >= 0)
            {
              sum += out.CornerLift[s][3 * slot] + out.CornerLift[s][3 * slot + 1] +
                out.CornerLift[s][3 * slot + 2];
            }
            row[1 + s] += area * sum / 3.0;
          }
        }
      }
    },
    1);
  std::vector<double> total(static_cast<size_t>(nc) * (ns + 1), 0.0);
  for (const std::vector<double>& sums : partial)
  {
    for (size_t i = 0; i < sums.size(); ++i)
    {
      total[i] += sums[i];
    }
  }
  out.CellMean.assign(ns, std::vector<double>(nc, 0.0));
  for (int cell = 0; cell < nc; ++cell)
  {
    const double* row = total.data() + static_cast<size_t>(cell) * (ns + 1);
    for (int s = 0; s < ns; ++s)
    {
      out.CellMean[s][cell] = row[0] > 0 ? row[1 + s] / row[0] : 0.0;
    }
  }
}

//------------------------------------------------------------------------------
// Residual per curve: the share of its length that does not bound, at the final field
// (degreesOf(s): shape s's bounding degrees per kept edge).
template <class DegreesOf>
void ReportCurves(const TriangleMesh& mesh,
  const Arrangement& arr,
  const std::vector<TracedCurve>& curves,
  const std::vector<std::vector<int>>& shapeCurves,
  const std::vector<std::vector<Traversal>>& shapeEdges,
  const std::vector<std::vector<double>>& coefficients,
  const std::vector<char>& dropped,
  const DegreesOf& degreesOf,
  WindingResult& out)
{
  const int ns = static_cast<int>(shapeCurves.size());
  for (int s = 0; s < ns; ++s)
  {
    const std::vector<double>& degree = degreesOf(s);
    std::map<std::pair<int, int>, double> keptDegree;
    for (size_t e = 0; e < shapeEdges[s].size(); ++e)
    {
      keptDegree[{ shapeEdges[s][e].Curve, shapeEdges[s][e].Index }] = std::max(0.0, degree[e]);
    }
    for (int c : shapeCurves[s])
    {
      WindingCurveReport report;
      report.Curve = c;
      report.ShapeId = curves[c].ShapeId;
      report.CurveId = curves[c].CurveId;
      report.Homology = coefficients[c];
      std::vector<Traversal> all;
      AppendTraversals(arr, c, curves[c].Closed, all);
      double total = 0, bound = 0;
      bool anyKept = false;
      for (const Traversal& e : all)
      {
        const double length = Distance(arr.GetPosition(mesh, e.From), arr.GetPosition(mesh, e.To));
        total += length;
        const auto it = keptDegree.find({ c, e.Index });
        if (it != keptDegree.end())
        {
          anyKept = true;
          bound += length * it->second;
        }
      }
      report.Bounds = anyKept;
      report.AroundHandle = dropped[c] != 0;
      report.Residual = total > 0 ? std::min(1.0, std::max(0.0, 1.0 - bound / total)) : 0.0;
      out.Curves.push_back(report);
    }
  }
}

//------------------------------------------------------------------------------
// Per shape, whether its curves are those of the last call on this surface, so that it keeps
// its solved u (`nv` values).
std::vector<char> FindReusedShapes(const std::vector<TracedCurve>& curves,
  const WindingOptions& options,
  const std::vector<int>& shapes,
  const std::vector<std::vector<int>>& shapeCurves,
  int nv,
  WindingSystem& system)
{
  const int ns = static_cast<int>(shapes.size());
  auto sameCurves = [&](const std::vector<TracedCurve>& kept, const std::vector<int>& now)
  {
    if (kept.size() != now.size())
    {
      return false;
    }
    for (size_t i = 0; i < now.size(); ++i)
    {
      const TracedCurve& a = kept[i];
      const TracedCurve& b = curves[now[i]];
      if (a.Closed != b.Closed || a.CurveId != b.CurveId || !(a.Points == b.Points))
      {
        return false;
      }
    }
    return true;
  };
  std::vector<char> reused(ns, 0);
  for (int s = 0; s < ns; ++s)
  {
    const auto it = system.Solved.find(shapes[s]);
    reused[s] = it != system.Solved.end() && options.RemoveNonBounding && it->second.Smooth &&
      static_cast<int>(it->second.Smooth->size()) == nv &&
      sameCurves(it->second.Curves, shapeCurves[s]);
  }

  return reused;
}

//------------------------------------------------------------------------------
// First whole curves that bound nothing on the whole (spurs, isolated arcs): a spur disturbs
// the levels around the curves next to it, so they are judged again without it. Then the
// stretches that still bound nothing (overshooting tails, doubled stretches). The field is
// solved again (solveField) after each round that dropped edges; returns how many it dropped.
template <class DegreesOf, class SolveField>
int DropEdgesThatBoundNothing(const TriangleMesh& mesh,
  const Arrangement& arr,
  const std::vector<char>& reused,
  std::vector<std::vector<Traversal>>& shapeEdges,
  std::vector<char>& changed,
  std::vector<char>& degreesKnown,
  const DegreesOf& degreesOf,
  const SolveField& solveField)
{
  const int ns = static_cast<int>(shapeEdges.size());
  int droppedEdges = 0;
  for (int round = 0; round < 2; ++round)
  {
    bool any = false;
    for (int s = 0; s < ns; ++s)
    {
      if (reused[s])
      {
        continue;
      }
      const std::vector<double>& degree = degreesOf(s);
      const std::vector<char> drop = round == 0
        ? CurvesThatBoundNothing(mesh, arr, shapeEdges[s], degree)
        : StretchesThatBoundNothing(mesh, arr, shapeEdges[s], degree);
      std::vector<Traversal> kept;
      for (size_t e = 0; e < shapeEdges[s].size(); ++e)
      {
        if (!drop[e])
        {
          kept.push_back(shapeEdges[s][e]);
        }
      }
      if (kept.size() != shapeEdges[s].size())
      {
        any = true;
        changed[s] = 1;
        degreesKnown[s] = 0;
      }
      droppedEdges += static_cast<int>(shapeEdges[s].size() - kept.size());
      shapeEdges[s].swap(kept);
    }
    if (any)
    {
      solveField();
    }
  }
  return droppedEdges;
}

} // namespace

bool SurfaceWinding::Compute(const TriangleMesh& mesh,
  const Arrangement& arr,
  const std::vector<TracedCurve>& curves,
  const WindingOptions& options,
  WindingResult& out,
  std::string& error)
{
  const auto start = std::chrono::steady_clock::now();
  out = WindingResult();
  if (!CheckCurves(mesh, arr, curves, error))
  {
    return false;
  }
  std::vector<int> shapes;
  std::vector<std::vector<int>> shapeCurves;
  if (!GroupCurvesByShape(curves, options, shapes, shapeCurves, error))
  {
    return false;
  }
  const int ns = static_cast<int>(shapes.size());

  // The system of this surface: kept from the last call on the same mesh.
  auto phase = std::chrono::steady_clock::now();
  if (!this->System || this->System->MeshSerial != mesh.GetSerial())
  {
    auto system = BuildWindingSystem(mesh, error);
    if (!system)
    {
      return false;
    }
    this->System = system;
  }
  WindingSystem& system = *this->System;
  out.Times.Factorization = Seconds(phase);

  // Shapes whose curves are those of the last call keep their solved u.
  const int nv = mesh.GetNumberOfVertices();
  const std::vector<char> reused =
    FindReusedShapes(curves, options, shapes, shapeCurves, nv, system);

  // Homology correction: each curve's harmonic coefficients, then the greedy drop per shape.
  phase = std::chrono::steady_clock::now();
  std::vector<char> dropped(curves.size(), 0);
  std::vector<std::vector<double>> coefficients(curves.size());
  if (system.Genus > 0 && options.RemoveNonBounding &&
    !DropCurvesAroundHandles(
      mesh, arr, curves, shapeCurves, reused, system, coefficients, dropped, error))
  {
    return false;
  }
  out.Times.Homology = Seconds(phase);

  // Lift, solve and field per shape; then the curve edges that bound nothing at the level
  // they sit on (spurs, overshoots) are dropped and the field computed again.
  std::vector<std::vector<Traversal>> shapeEdges(ns);
  for (int s = 0; s < ns; ++s)
  {
    for (int c : shapeCurves[s])
    {
      if (!dropped[c])
      {
        AppendTraversals(arr, c, curves[c].Closed, shapeEdges[s]);
      }
    }
  }
  std::vector<JumpLift> lifts(ns);
  double liftTime = 0, solveTime = 0, fieldTime = 0;
  std::vector<std::shared_ptr<const std::vector<double>>> columns(ns);
  // Shapes whose curve edges changed since their last lift and solve: all at first (refined ids
  // change with any edit), then those a round of drops touched.
  std::vector<char> changed(ns, 1);
  auto solveField = [&]()
  {
    // Lifts for the changed shapes; loads and back-substitutions for those not reused, all at
    // once.
    auto t0 = std::chrono::steady_clock::now();
    std::vector<int> solving;
    for (int s = 0; s < ns; ++s)
    {
      if (!changed[s])
      {
        continue;
      }
      CurveEdgeList edges;
      for (const Traversal& e : shapeEdges[s])
      {
        edges.emplace_back(e.From, e.To);
      }
      ComputeJumpLift(mesh, arr, edges, lifts[s]);
      if (!reused[s])
      {
        solving.push_back(s);
      }
    }
    std::vector<double> loads(static_cast<size_t>(nv) * solving.size(), 0.0);
    for (size_t i = 0; i < solving.size(); ++i)
    {
      AddLiftLoad(mesh, lifts[solving[i]], loads.data() + i * nv);
    }
    for (double& b : loads)
    {
      b = -b;
    }
    liftTime += Seconds(t0);
    t0 = std::chrono::steady_clock::now();
    system.Laplacian.Solve(loads, static_cast<int>(solving.size()));
    out.Times.BackSubstitutions += static_cast<int>(solving.size());
    for (size_t i = 0; i < solving.size(); ++i)
    {
      columns[solving[i]] = std::make_shared<const std::vector<double>>(
        loads.begin() + i * nv, loads.begin() + (i + 1) * nv);
    }
    for (int s = 0; s < ns; ++s)
    {
      if (reused[s])
      {
        columns[s] = system.Solved[shapes[s]].Smooth;
      }
    }
    solveTime += Seconds(t0);
    t0 = std::chrono::steady_clock::now();
    std::vector<const std::vector<double>*> knownShift(ns, nullptr);
    for (int s = 0; s < ns; ++s)
    {
      if (reused[s])
      {
        knownShift[s] = &system.Solved[shapes[s]].Shift;
      }
    }
    BuildField(mesh, arr, system, shapes, shapeEdges, lifts, columns, knownShift, out);
    fieldTime += Seconds(t0);
    std::fill(changed.begin(), changed.end(), 0);
  };
  solveField();
  // Each shape's bounding degrees at the current field, kept until its edges change.
  std::vector<std::vector<double>> degrees(ns);
  std::vector<char> degreesKnown(ns, 0);
  auto degreesOf = [&](int s) -> const std::vector<double>&
  {
    if (!degreesKnown[s])
    {
      degrees[s] = BoundingDegrees(mesh, arr, out, s, shapeEdges[s], lifts[s]);
      degreesKnown[s] = 1;
    }
    return degrees[s];
  };
  if (options.RemoveNonBounding)
  {
    out.Times.DroppedEdges = DropEdgesThatBoundNothing(
      mesh, arr, reused, shapeEdges, changed, degreesKnown, degreesOf, solveField);
  }
  KeepSolvedShapes(
    arr, curves, options, shapes, shapeCurves, shapeEdges, reused, dropped, columns, out, system);
  out.Times.Lift = liftTime;
  out.Times.Solve = solveTime;
  phase = std::chrono::steady_clock::now();
  ComputeCellMeans(mesh, arr, options.Threads, ns, out);

  ReportCurves(mesh, arr, curves, shapeCurves, shapeEdges, coefficients, dropped, degreesOf, out);
  std::sort(out.Curves.begin(),
    out.Curves.end(),
    [](const WindingCurveReport& a, const WindingCurveReport& b) { return a.Curve < b.Curve; });
  out.Times.Outputs = fieldTime + Seconds(phase);
  out.Times.Total = Seconds(start);
  return true;
}

} // namespace boolsurf

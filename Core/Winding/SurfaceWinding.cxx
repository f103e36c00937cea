#include "Winding/SurfaceWinding.h"

#include "Mesh/MeshTopology.h"
#include "Winding/CotanLaplacian.h"
#include "Winding/HarmonicBasis.h"
#include "Winding/JumpLift.h"
#include "Winding/WindingField.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <unordered_map>
#include <unordered_set>

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
  return this->PointBase[s][p] + (slot >= 0 ? this->CornerLift[s][3 * slot + k] : 0.0);
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
  // Shapes.
  std::vector<int> shapes = options.Shapes;
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
  std::vector<std::vector<int>> shapeCurves(ns);
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

  // The system of this surface: kept from the last call on the same mesh.
  auto phase = std::chrono::steady_clock::now();
  if (!this->System || this->System->MeshSerial != mesh.GetSerial())
  {
    auto system = std::make_shared<WindingSystem>();
    if (!system->Laplacian.Factorize(mesh, error))
    {
      return false;
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
    this->System = system;
  }
  WindingSystem& system = *this->System;
  out.Times.Factorization = Seconds(phase);

  // Homology correction: each curve's harmonic coefficients, then the greedy drop per shape.
  phase = std::chrono::steady_clock::now();
  std::vector<char> dropped(curves.size(), 0);
  std::vector<std::vector<double>> coefficients(curves.size());
  if (system.Genus > 0 && options.RemoveNonBounding)
  {
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
  }
  out.Times.Homology = Seconds(phase);

  // Lift, solve and field per shape; then the curve edges that bound nothing at the level
  // they sit on (spurs, overshoots) are dropped and the field computed again once.
  const int nv = mesh.GetNumberOfVertices();
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
  auto solveField = [&]()
  {
    auto t0 = std::chrono::steady_clock::now();
    std::vector<double> columns(static_cast<size_t>(nv) * ns, 0.0);
    for (int s = 0; s < ns; ++s)
    {
      CurveEdgeList edges;
      for (const Traversal& e : shapeEdges[s])
      {
        edges.emplace_back(e.From, e.To);
      }
      ComputeJumpLift(mesh, arr, edges, lifts[s]);
      AddLiftLoad(mesh, lifts[s], columns.data() + static_cast<size_t>(s) * nv);
    }
    for (double& b : columns)
    {
      b = -b;
    }
    liftTime += Seconds(t0);
    t0 = std::chrono::steady_clock::now();
    system.Laplacian.Solve(columns, ns);
    solveTime += Seconds(t0);
    t0 = std::chrono::steady_clock::now();
    BuildField(mesh, arr, system, shapes, shapeEdges, lifts, columns, out);
    fieldTime += Seconds(t0);
  };
  solveField();
  if (options.RemoveNonBounding)
  {
    // First whole curves that bound nothing on the whole (spurs, isolated arcs): a spur
    // disturbs the levels around the curves next to it, so they are judged again without it.
    // Then the edges that still bound nothing (overshooting tails, doubled stretches).
    for (int round = 0; round < 2; ++round)
    {
      bool any = false;
      for (int s = 0; s < ns; ++s)
      {
        const std::vector<double> degree =
          BoundingDegrees(mesh, arr, out, s, shapeEdges[s], lifts[s]);
        std::map<int, std::pair<double, double>> curveDegree; // curve -> (sum, length)
        if (round == 0)
        {
          for (size_t e = 0; e < shapeEdges[s].size(); ++e)
          {
            const Traversal& t = shapeEdges[s][e];
            const double length =
              Distance(arr.GetPosition(mesh, t.From), arr.GetPosition(mesh, t.To));
            curveDegree[t.Curve].first += length * degree[e];
            curveDegree[t.Curve].second += length;
          }
        }
        std::vector<Traversal> kept;
        for (size_t e = 0; e < shapeEdges[s].size(); ++e)
        {
          const auto& cd = curveDegree[shapeEdges[s][e].Curve];
          const bool keep = round == 0 ? cd.first >= 0.5 * cd.second : degree[e] >= 0.5;
          if (keep)
          {
            kept.push_back(shapeEdges[s][e]);
          }
        }
        any = any || kept.size() != shapeEdges[s].size();
        shapeEdges[s].swap(kept);
      }
      if (any)
      {
        solveField();
      }
    }
  }
  out.Times.Lift = liftTime;
  out.Times.Solve = solveTime;
  phase = std::chrono::steady_clock::now();
  const int nr = arr.GetNumberOfTriangles();
  // Cell means (area-weighted over each arrangement cell's refined triangles).
  out.CellMean.assign(ns, std::vector<double>(arr.NumberOfCells, 0.0));
  {
    std::vector<double> cellArea(arr.NumberOfCells, 0.0);
    for (int r = 0; r < nr; ++r)
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
      cellArea[cell] += area;
      const int slot = out.JumpSlot[r];
      for (int s = 0; s < ns; ++s)
      {
        double sum = 0;
        for (int k = 0; k < 3; ++k)
        {
          sum += out.PointBase[s][tri[k]] + (slot >= 0 ? out.CornerLift[s][3 * slot + k] : 0.0);
        }
        out.CellMean[s][cell] += area * sum / 3.0;
      }
    }
    for (int s = 0; s < ns; ++s)
    {
      for (int cell = 0; cell < arr.NumberOfCells; ++cell)
      {
        out.CellMean[s][cell] = cellArea[cell] > 0 ? out.CellMean[s][cell] / cellArea[cell] : 0.0;
      }
    }
  }

  // Residual per curve: the share of its length that does not bound, at the final field.
  for (int s = 0; s < ns; ++s)
  {
    const std::vector<double> degree = BoundingDegrees(mesh, arr, out, s, shapeEdges[s], lifts[s]);
    std::map<int, std::pair<double, double>> perCurve; // curve -> (bounding, total length)
    std::map<std::pair<int, int>, double> keptDegree;
    for (size_t e = 0; e < shapeEdges[s].size(); ++e)
    {
      keptDegree[{ shapeEdges[s][e].Curve, shapeEdges[s][e].Index }] = degree[e];
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
      report.Residual = total > 0 ? std::min(1.0, std::max(0.0, 1.0 - bound / total)) : 0.0;
      out.Curves.push_back(report);
    }
  }
  std::sort(out.Curves.begin(),
    out.Curves.end(),
    [](const WindingCurveReport& a, const WindingCurveReport& b) { return a.Curve < b.Curve; });
  out.Times.Outputs = fieldTime + Seconds(phase);
  out.Times.Total = Seconds(start);
  return true;
}

} // namespace boolsurf

#include "Winding/WindingField.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <unordered_set>

namespace boolsurf
{

void AppendTraversals(const Arrangement& arr, int c, bool closed, std::vector<Traversal>& out)
{
  const std::vector<int>& points = arr.CurvePoints[c];
  const int n = static_cast<int>(points.size());
  for (int i = 0; i + 1 < n; ++i)
  {
    out.push_back({ points[i], points[i + 1], c, i });
  }
  if (closed && n > 1)
  {
    out.push_back({ points[n - 1], points[0], c, n - 1 });
  }
}

namespace
{

constexpr double Pi = 3.14159265358979323846;

/// u of a solved column at refined point p (linear on the mesh).
double SmoothAt(const TriangleMesh& mesh, const Arrangement& arr, const double* u, int p)
{
  if (p < arr.NumberOfMeshVertices)
  {
    return u[p];
  }
  const CanonicalPoint c = arr.GetPointOnMesh(p);
  if (c.Location == PointLocation::Edge)
  {
    const std::array<int, 2> ends = mesh.GetEdgeVertices(c.Id);
    return (1.0 - c.T) * u[ends[0]] + c.T * u[ends[1]];
  }
  if (c.Location == PointLocation::Vertex)
  {
    return u[c.Id];
  }
  const Triangle& tri = mesh.GetTriangle(c.Id);
  return (1.0 - c.U - c.V) * u[tri[0]] + c.U * u[tri[1]] + c.V * u[tri[2]];
}

} // namespace

void BuildField(const TriangleMesh& mesh,
  const Arrangement& arr,
  const WindingSystem& system,
  const std::vector<int>& shapes,
  const std::vector<std::vector<Traversal>>& shapeEdges,
  const std::vector<JumpLift>& lifts,
  const std::vector<double>& columns,
  WindingResult& out)
{
  const int ns = static_cast<int>(shapes.size());
  const int nv = mesh.GetNumberOfVertices();
  const int nr = arr.GetNumberOfTriangles();
  const int npts = arr.GetNumberOfPoints();
  out.ShapeIds = shapes;
  out.JumpTriangles.clear();
  for (int s = 0; s < ns; ++s)
  {
    out.JumpTriangles.insert(
      out.JumpTriangles.end(), lifts[s].Triangles.begin(), lifts[s].Triangles.end());
  }
  std::sort(out.JumpTriangles.begin(), out.JumpTriangles.end());
  out.JumpTriangles.erase(
    std::unique(out.JumpTriangles.begin(), out.JumpTriangles.end()), out.JumpTriangles.end());
  out.JumpSlot.assign(nr, -1);
  for (size_t i = 0; i < out.JumpTriangles.size(); ++i)
  {
    out.JumpSlot[out.JumpTriangles[i]] = static_cast<int>(i);
  }
  const std::vector<int>& blocks = system.Laplacian.GetVertexBlocks();
  auto blockOfPoint = [&](int p)
  {
    if (p < arr.NumberOfMeshVertices)
    {
      return blocks[p];
    }
    const SurfacePoint sp = arr.GetPointSurface(mesh, p);
    return blocks[mesh.GetTriangle(sp.Triangle)[0]];
  };
  const int nb = system.Laplacian.GetNumberOfBlocks();
  out.PointBase.assign(ns, std::vector<double>(npts, 0.0));
  out.CornerLift.assign(ns, std::vector<double>(3 * out.JumpTriangles.size(), 0.0));
  out.PointMean.assign(ns, std::vector<double>());
  for (int s = 0; s < ns; ++s)
  {
    const double* u = columns.data() + static_cast<size_t>(s) * nv;
    std::vector<double>& base = out.PointBase[s];
    for (int p = 0; p < npts; ++p)
    {
      base[p] = SmoothAt(mesh, arr, u, p);
    }
    for (size_t i = 0; i < lifts[s].Triangles.size(); ++i)
    {
      const int slot = out.JumpSlot[lifts[s].Triangles[i]];
      for (int k = 0; k < 3; ++k)
      {
        out.CornerLift[s][3 * slot + k] = lifts[s].Values[i][k];
      }
    }

    // The constant per block, from the values it should make integers: those on the free
    // part of its longest boundary loop (where closed curves leave w = 0, the labels' zero
    // plug), else every mesh vertex and jump corner. Their circular mean of fractional parts
    // (robust to the few values a spur or a gap disturbs) makes them as near integers as they
    // can be, and the lowest of them rounds to 0: closed curves get exactly the labels, a
    // curve from boundary to boundary 0 on its right.
    std::unordered_set<int> curvePoints;
    for (const Traversal& e : shapeEdges[s])
    {
      curvePoints.insert(e.From);
      curvePoints.insert(e.To);
    }
    struct Levels
    {
      double Sin = 0, Cos = 0;
      std::vector<double> Values;
      void Add(double x)
      {
        this->Sin += std::sin(2 * Pi * x);
        this->Cos += std::cos(2 * Pi * x);
        this->Values.push_back(x);
      }
      double Constant() const
      {
        if (this->Values.empty())
        {
          return 0.0;
        }
        const double fraction = std::atan2(this->Sin, this->Cos) / (2 * Pi);
        double lowest = std::numeric_limits<double>::infinity();
        for (double x : this->Values)
        {
          lowest = std::min(lowest, std::round(x - fraction));
        }
        return fraction + lowest;
      }
    };
    std::vector<Levels> onLoop(nb), everywhere(nb);
    for (int b = 0; b < nb; ++b)
    {
      const int l = system.BlockLoop[b];
      if (l < 0)
      {
        continue;
      }
      for (int v : system.Topology.BoundaryLoops[l].Vertices)
      {
        if (!curvePoints.count(v))
        {
          onLoop[b].Add(base[v]);
        }
      }
    }
    for (int v = 0; v < nv; ++v)
    {
      if (blocks[v] >= 0 && system.BlockLoop[blocks[v]] < 0)
      {
        everywhere[blocks[v]].Add(base[v]);
      }
    }
    for (size_t i = 0; i < out.JumpTriangles.size(); ++i)
    {
      const Triangle tri = arr.GetTriangle(mesh, out.JumpTriangles[i]);
      for (int k = 0; k < 3; ++k)
      {
        const int b = blockOfPoint(tri[k]);
        if (system.BlockLoop[b] < 0)
        {
          everywhere[b].Add(base[tri[k]] + out.CornerLift[s][3 * i + k]);
        }
      }
    }
    std::vector<double> shift(nb, 0.0);
    for (int b = 0; b < nb; ++b)
    {
      shift[b] = system.BlockLoop[b] >= 0 && !onLoop[b].Values.empty() ? onLoop[b].Constant()
                                                                       : everywhere[b].Constant();
    }
    for (int p = 0; p < npts; ++p)
    {
      const int b = nb == 1 ? 0 : blockOfPoint(p);
      base[p] -= b >= 0 ? shift[b] : 0.0;
    }

    // Point values: the middle of the jump where a point has sides.
    std::vector<double>& mean = out.PointMean[s];
    mean = base;
    std::unordered_map<int, std::pair<double, double>> range;
    for (size_t i = 0; i < out.JumpTriangles.size(); ++i)
    {
      const Triangle tri = arr.GetTriangle(mesh, out.JumpTriangles[i]);
      for (int k = 0; k < 3; ++k)
      {
        const double lift = out.CornerLift[s][3 * i + k];
        const auto it = range.find(tri[k]);
        if (it == range.end())
        {
          range.emplace(tri[k], std::make_pair(lift, lift));
        }
        else
        {
          it->second.first = std::min(it->second.first, lift);
          it->second.second = std::max(it->second.second, lift);
        }
      }
    }
    for (const auto& entry : range)
    {
      mean[entry.first] += 0.5 * (entry.second.first + entry.second.second);
    }
  }
}

std::vector<double> BoundingDegrees(const TriangleMesh& mesh,
  const Arrangement& arr,
  const WindingResult& field,
  int s,
  const std::vector<Traversal>& edges,
  const JumpLift& lift)
{
  // Directed refined edge -> (refined triangle on its left, corner of the edge's start).
  std::unordered_map<std::uint64_t, std::pair<int, int>> leftOf;
  leftOf.reserve(lift.Triangles.size() * 4);
  auto key = [](int a, int b)
  { return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b); };
  for (int r : lift.Triangles)
  {
    const Triangle tri = arr.GetTriangle(mesh, r);
    for (int k = 0; k < 3; ++k)
    {
      leftOf[key(tri[k], tri[(k + 1) % 3])] = std::make_pair(r, k);
    }
  }
  std::unordered_map<std::uint64_t, int> net;
  for (const Traversal& e : edges)
  {
    net[key(e.From, e.To)] += 1;
    net[key(e.To, e.From)] -= 1;
  }
  auto middle = [&](int a, int b, double& value)
  {
    const auto it = leftOf.find(key(a, b));
    if (it == leftOf.end())
    {
      return false;
    }
    const int r = it->second.first, k = it->second.second;
    value = 0.5 * (field.Corner(arr, mesh, s, r, k) + field.Corner(arr, mesh, s, r, (k + 1) % 3));
    return true;
  };
  std::vector<double> degree(edges.size(), 0.0);
  for (size_t i = 0; i < edges.size(); ++i)
  {
    const Traversal& e = edges[i];
    const int jump = net[key(e.From, e.To)];
    double left = 0, right = 0;
    if (jump <= 0 || !middle(e.From, e.To, left))
    {
      continue; // cancelled by a traversal the other way: no jump, bounds nothing
    }
    if (!middle(e.To, e.From, right))
    {
      right = left - jump; // along the open boundary: only the left side exists
    }
    const double level = 0.5 * (left + right - jump);
    degree[i] = std::max(0.0, 1.0 - 2.0 * std::abs(level - std::round(level)));
  }
  return degree;
}

} // namespace boolsurf

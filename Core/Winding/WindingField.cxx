#include "Winding/WindingField.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
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

/// The constant per block of shape s (see BuildField), into out.BlockShift[s].
void ComputeShift(const TriangleMesh& mesh,
  const Arrangement& arr,
  const WindingSystem& system,
  const std::vector<Traversal>& shapeEdges,
  const double* u,
  WindingResult& out,
  int s)
{
  const int nv = mesh.GetNumberOfVertices();
  const std::vector<int>& blocks = system.Laplacian.GetVertexBlocks();
  const int nb = system.Laplacian.GetNumberOfBlocks();
  auto blockOfPoint = [&](int p)
  { return nb == 1 ? 0 : (p < nv ? blocks[p] : out.CurvePointBlock[p - nv]); };
  auto unshifted = [&](int p) { return p < nv ? u[p] : out.CurvePointSmooth[s][p - nv]; };
  // The constant per block, from the values it should make integers: those on the free
  // part of its longest boundary loop (where closed curves leave w = 0, the labels' zero
  // plug), else every mesh vertex and jump corner. Their circular mean of fractional parts
  // (robust to the few values a spur or a gap disturbs) makes them as near integers as they
  // can be, and the lowest of them rounds to 0: closed curves get exactly the labels, a
  // curve from boundary to boundary 0 on its right.
  std::unordered_set<int> curvePoints;
  for (const Traversal& e : shapeEdges)
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
        onLoop[b].Add(u[v]);
      }
    }
  }
  // (A fixed sample of at most ~65k vertices is plenty for a circular mean and a minimum of
  // rounded levels, and keeps this O(1) per edit on large meshes.)
  const int stride = std::max(1, nv / 65536);
  for (int v = 0; v < nv; v += stride)
  {
    if (blocks[v] >= 0 && system.BlockLoop[blocks[v]] < 0)
    {
      everywhere[blocks[v]].Add(u[v]);
    }
  }
  for (size_t i = 0; i < out.JumpTriangles.size(); ++i)
  {
    const Triangle tri = arr.GetTriangle(mesh, out.JumpTriangles[i]);
    for (int k = 0; k < 3; ++k)
    {
      const int b = blockOfPoint(tri[k]);
      if (b >= 0 && system.BlockLoop[b] < 0)
      {
        everywhere[b].Add(unshifted(tri[k]) + out.CornerLift[s][3 * i + k]);
      }
    }
  }
  for (int b = 0; b < nb; ++b)
  {
    out.BlockShift[s][b] = system.BlockLoop[b] >= 0 && !onLoop[b].Values.empty()
      ? onLoop[b].Constant()
      : everywhere[b].Constant();
  }
}

} // namespace

void BuildField(const TriangleMesh& mesh,
  const Arrangement& arr,
  const WindingSystem& system,
  const std::vector<int>& shapes,
  const std::vector<std::vector<Traversal>>& shapeEdges,
  const std::vector<JumpLift>& lifts,
  const std::vector<std::shared_ptr<const std::vector<double>>>& smooth,
  const std::vector<const std::vector<double>*>& knownShift,
  WindingResult& out)
{
  const int ns = static_cast<int>(shapes.size());
  const int nv = mesh.GetNumberOfVertices();
  const int nr = arr.GetNumberOfTriangles();
  const int npts = arr.GetNumberOfPoints();
  out.ShapeIds = shapes;
  out.NumberOfMeshVertices = nv;
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
  const int nb = system.Laplacian.GetNumberOfBlocks();
  out.VertexBlock = std::make_shared<const std::vector<int>>(nb > 1 ? blocks : std::vector<int>());
  out.CurvePointBlock.assign(nb > 1 ? npts - nv : 0, -1);
  for (int p = nv; nb > 1 && p < npts; ++p)
  {
    const SurfacePoint sp = arr.GetPointSurface(mesh, p);
    out.CurvePointBlock[p - nv] = blocks[mesh.GetTriangle(sp.Triangle)[0]];
  }
  out.VertexSmooth = smooth;
  out.CurvePointSmooth.assign(ns, std::vector<double>(npts - nv, 0.0));
  out.BlockShift.assign(ns, std::vector<double>(std::max(1, nb), 0.0));
  out.CornerLift.assign(ns, std::vector<double>(3 * out.JumpTriangles.size(), 0.0));
  out.PointLift.assign(ns, std::vector<std::pair<int, double>>());
  for (int s = 0; s < ns; ++s)
  {
    const double* u = smooth[s]->data();
    for (int p = nv; p < npts; ++p)
    {
      out.CurvePointSmooth[s][p - nv] = SmoothAt(mesh, arr, u, p);
    }
    for (size_t i = 0; i < lifts[s].Triangles.size(); ++i)
    {
      const int slot = out.JumpSlot[lifts[s].Triangles[i]];
      for (int k = 0; k < 3; ++k)
      {
        out.CornerLift[s][3 * slot + k] = lifts[s].Values[i][k];
      }
    }
    if (knownShift[s])
    {
      out.BlockShift[s] = *knownShift[s];
    }
    else
    {
      ComputeShift(mesh, arr, system, shapeEdges[s], u, out, s);
    }

    // Point lifts: the middle of the jump where a point has sides.
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
    std::vector<std::pair<int, double>>& pointLift = out.PointLift[s];
    for (const auto& entry : range)
    {
      const double middle = 0.5 * (entry.second.first + entry.second.second);
      if (middle != 0.0)
      {
        pointLift.emplace_back(entry.first, middle);
      }
    }
    std::sort(pointLift.begin(), pointLift.end());
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
  // The field at both ends of a directed edge, on its left side.
  auto ends = [&](int a, int b, double& va, double& vb)
  {
    const auto it = leftOf.find(key(a, b));
    if (it == leftOf.end())
    {
      return false;
    }
    const int r = it->second.first, k = it->second.second;
    va = field.Corner(arr, mesh, s, r, k);
    vb = field.Corner(arr, mesh, s, r, (k + 1) % 3);
    return true;
  };
  auto degreeAt = [](double left, double right, int jump)
  {
    const double level = 0.5 * (left + right - jump);
    return std::max(0.0, 1.0 - 2.0 * std::abs(level - std::round(level)));
  };
  std::vector<double> degree(edges.size(), 0.0);
  for (size_t i = 0; i < edges.size(); ++i)
  {
    const Traversal& e = edges[i];
    const int jump = net[key(e.From, e.To)];
    double la = 0, lb = 0, ra = 0, rb = 0;
    if (jump <= 0)
    {
      degree[i] = -1.0; // against the net direction, or cancelled: no jump of its own
      continue;
    }
    const bool left = ends(e.From, e.To, la, lb), right = ends(e.To, e.From, rb, ra);
    if (!left && !right)
    {
      degree[i] = -1.0; // no refined triangle on either side (not an edge of the surface)
      continue;
    }
    // Along the open boundary only one side exists: the other is what the jump would make it.
    if (!right)
    {
      ra = la - jump;
      rb = lb - jump;
    }
    if (!left)
    {
      la = ra + jump;
      lb = rb + jump;
    }
    // Read at the ends where the jump is whole: at an open curve's end point it fades to zero
    // (one side), and the edge's other end tells how it bounds; the better of the two counts.
    double best = -1.0;
    if (std::abs(la - ra - jump) <= 0.5)
    {
      best = std::max(best, degreeAt(la, ra, jump));
    }
    if (std::abs(lb - rb - jump) <= 0.5)
    {
      best = std::max(best, degreeAt(lb, rb, jump));
    }
    degree[i] = best >= 0.0 ? best : degreeAt(0.5 * (la + lb), 0.5 * (ra + rb), jump);
  }
  return degree;
}

std::vector<char> CurvesThatBoundNothing(const TriangleMesh& mesh,
  const Arrangement& arr,
  const std::vector<Traversal>& edges,
  const std::vector<double>& degree)
{
  std::map<int, std::pair<double, double>> curveDegree; // curve -> (sum, counted length)
  for (size_t e = 0; e < edges.size(); ++e)
  {
    if (degree[e] >= 0.0)
    {
      const double length =
        Distance(arr.GetPosition(mesh, edges[e].From), arr.GetPosition(mesh, edges[e].To));
      curveDegree[edges[e].Curve].first += length * degree[e];
      curveDegree[edges[e].Curve].second += length;
    }
  }
  std::vector<char> drop(edges.size(), 0);
  for (size_t e = 0; e < edges.size(); ++e)
  {
    const auto it = curveDegree.find(edges[e].Curve);
    drop[e] = it != curveDegree.end() && it->second.second > 0 &&
      it->second.first < 0.5 * it->second.second;
  }
  return drop;
}

std::vector<char> StretchesThatBoundNothing(const TriangleMesh& mesh,
  const Arrangement& arr,
  const std::vector<Traversal>& edges,
  const std::vector<double>& degree)
{
  std::map<int, double> curveLength;
  std::vector<double> length(edges.size());
  for (size_t e = 0; e < edges.size(); ++e)
  {
    length[e] = Distance(arr.GetPosition(mesh, edges[e].From), arr.GetPosition(mesh, edges[e].To));
    curveLength[edges[e].Curve] += length[e];
  }
  auto key = [](int a, int b)
  {
    return (static_cast<std::uint64_t>(std::min(a, b)) << 32) |
      static_cast<std::uint32_t>(std::max(a, b));
  };
  std::unordered_set<std::uint64_t> droppedKeys;
  for (size_t e = 0; e < edges.size();)
  {
    size_t end = e;
    double run = 0;
    while (end < edges.size() && degree[end] >= 0.0 && degree[end] < 0.5 &&
      edges[end].Curve == edges[e].Curve &&
      (end == e || edges[end].Index == edges[end - 1].Index + 1))
    {
      run += length[end];
      ++end;
    }
    if (end > e && run >= 0.05 * curveLength[edges[e].Curve])
    {
      for (size_t i = e; i < end; ++i)
      {
        droppedKeys.insert(key(edges[i].From, edges[i].To));
      }
    }
    e = std::max(end, e + 1);
  }
  std::vector<char> drop(edges.size(), 0);
  for (size_t e = 0; e < edges.size(); ++e)
  {
    drop[e] = droppedKeys.count(key(edges[e].From, edges[e].To)) != 0;
  }
  return drop;
}

} // namespace boolsurf

#include "Geodesic/GeodesicPath.h"

#include <algorithm>
#include <cmath>

namespace boolsurf
{
namespace
{
// Face points with a zero weight and edge points at an edge end are re-expressed in the
// lowest-dimensional form, so "which triangles hold this point" is answered combinatorially.
CanonicalPoint Normalize(const TriangleMesh& mesh, const CanonicalPoint& c)
{
  if (c.Location == PointLocation::Face)
  {
    if (c.U > 0.0 && c.V > 0.0 && 1.0 - c.U - c.V > 0.0)
    {
      return c; // strictly inside: keep the caller's numbers bit for bit
    }
    return Canonicalize(mesh, SurfacePoint{ c.Id, c.U, c.V }, 0.0);
  }
  if (c.Location == PointLocation::Edge && (c.T <= 0.0 || c.T >= 1.0))
  {
    CanonicalPoint v;
    v.Location = PointLocation::Vertex;
    v.Id = mesh.GetEdgeVertices(c.Id)[c.T <= 0.0 ? 0 : 1];
    return v;
  }
  return c;
}
// Canonical point of triangle t with weights w (exact zeros mark edges and vertices).
CanonicalPoint FromWeights(const TriangleMesh& mesh, int t, const std::array<double, 3>& w)
{
  const Triangle& tri = mesh.GetTriangle(t);
  CanonicalPoint c;
  const int zeros = (w[0] <= 0.0) + (w[1] <= 0.0) + (w[2] <= 0.0);
  if (zeros >= 2)
  {
    c.Location = PointLocation::Vertex;
    c.Id = tri[static_cast<int>(std::max_element(w.begin(), w.end()) - w.begin())];
    return c;
  }
  if (zeros == 1)
  {
    const int opposite = w[0] <= 0.0 ? 0 : (w[1] <= 0.0 ? 1 : 2);
    const int localEdge = (opposite + 1) % 3;
    const double wa = w[localEdge], wb = w[(localEdge + 1) % 3];
    const double s = wb / (wa + wb);
    c.Location = PointLocation::Edge;
    c.Id = mesh.GetEdgeId(t, localEdge);
    c.T = mesh.GetEdgeVertices(c.Id)[0] == tri[localEdge] ? s : 1.0 - s;
    return c;
  }
  const double sum = w[0] + w[1] + w[2];
  c.Location = PointLocation::Face;
  c.Id = t;
  c.U = w[1] / sum;
  c.V = w[2] / sum;
  return c;
}
} // namespace

//------------------------------------------------------------------------------
GeodesicPathSolver::GeodesicPathSolver(const TriangleMesh& mesh,
  std::shared_ptr<const TriangleComponents> components)
  : Mesh(mesh)
  , Components(components ? std::move(components) : std::make_shared<TriangleComponents>(mesh))
  , Exact(mesh)
  , Straightener(mesh)
{
  // The edge-path and dual searches are built on first use (Edges(), Dual()): legs the exact
  // search answers need neither, and on millions of triangles they cost seconds to build.
}

//------------------------------------------------------------------------------
GeodesicPathSolver::GeodesicPathSolver(const GeodesicPathSolver& main, HelperTag)
  : Mesh(main.Mesh)
  , Components(main.Components)
  , Exact(main.Mesh)
  , Straightener(main.Mesh)
{
  this->SetOptions(main.Options);
}

//------------------------------------------------------------------------------
DualGraphSearch& GeodesicPathSolver::Dual()
{
  if (!this->Search)
  {
    this->Search = std::make_unique<DualGraphSearch>(this->Mesh);
    this->Search->SetHeuristicWeight(this->Options.HeuristicWeight);
  }
  return *this->Search;
}

//------------------------------------------------------------------------------
EdgeGraphSearch& GeodesicPathSolver::Edges()
{
  if (!this->EdgeSearch)
  {
    this->EdgeSearch = std::make_unique<EdgeGraphSearch>(this->Mesh);
    this->EdgeSearch->SetNumberOfLandmarks(this->Options.NumberOfLandmarks);
    this->EdgeSearch->SetLandmarkBuildThreshold(this->Options.LandmarkBuildThreshold);
  }
  return *this->EdgeSearch;
}

//------------------------------------------------------------------------------
void GeodesicPathSolver::SetOptions(const GeodesicPathOptions& options)
{
  this->Options = options;
  this->Exact.SetPruning(options.ExactPruning);
  // Searches already built take the new settings; an edge search drops its landmark table
  // only when the number of landmarks changes.
  if (this->Search)
  {
    this->Search->SetHeuristicWeight(options.HeuristicWeight);
  }
  if (this->EdgeSearch)
  {
    if (this->EdgeSearch->GetNumberOfLandmarks() != options.NumberOfLandmarks)
    {
      this->EdgeSearch->SetNumberOfLandmarks(options.NumberOfLandmarks);
    }
    this->EdgeSearch->SetLandmarkBuildThreshold(options.LandmarkBuildThreshold);
  }
}

//------------------------------------------------------------------------------
void GeodesicPathSolver::SetPieceReads(std::vector<int>* reads,
  std::function<bool(int)> exact,
  double wallSlack)
{
  this->PieceReads = reads;
  this->Straightener.SetStripRecorder(reads);
  this->Exact.SetPieceTriangles(reads ? std::move(exact) : nullptr, wallSlack);
}

//------------------------------------------------------------------------------
bool GeodesicPathSolver::Compute(const SurfacePoint& start,
  const SurfacePoint& end,
  GeodesicPath& path,
  std::string& error)
{
  const TriangleMesh& mesh = this->GetMesh();
  std::string problem;
  if (!CheckSurfacePoint(mesh, start, problem))
  {
    path = {};
    error = "start point: " + problem;
    return false;
  }
  if (!CheckSurfacePoint(mesh, end, problem))
  {
    path = {};
    error = "end point: " + problem;
    return false;
  }
  return this->Compute(Canonicalize(mesh, start, 0.0), Canonicalize(mesh, end, 0.0), path, error);
}

//------------------------------------------------------------------------------
bool GeodesicPathSolver::Compute(const CanonicalPoint& startIn,
  const CanonicalPoint& endIn,
  GeodesicPath& path,
  std::string& error)
{
  const TriangleMesh& mesh = this->GetMesh();
  this->Statistics = {};
  path.Points.clear();
  path.Length = 0.0;
  std::string problem;
  if (!CheckCanonicalPoint(mesh, startIn, problem))
  {
    error = "start point: " + problem;
    return false;
  }
  if (!CheckCanonicalPoint(mesh, endIn, problem))
  {
    error = "end point: " + problem;
    return false;
  }
  const CanonicalPoint start = Normalize(mesh, startIn);
  const CanonicalPoint end = Normalize(mesh, endIn);
  if (start == end)
  {
    this->Statistics.Exact = true;
    path.Points.push_back(start);
    return true;
  }

  this->Straightener.ForgetUnfolding();
  TrianglesOf(mesh, start, this->StartTriangles);
  TrianglesOf(mesh, end, this->EndTriangles);
  // On a part of a surface, its components are not the surface's: a leg leaving the part is
  // not refused but reads a triangle that is not whole there, which the caller fetches.
  bool connected = this->PieceReads != nullptr;
  if (this->PieceReads)
  {
    this->PieceReads->insert(
      this->PieceReads->end(), this->StartTriangles.begin(), this->StartTriangles.end());
    this->PieceReads->insert(
      this->PieceReads->end(), this->EndTriangles.begin(), this->EndTriangles.end());
  }
  for (int a : this->StartTriangles)
  {
    for (int b : this->EndTriangles)
    {
      connected = connected || this->GetComponent(a) == this->GetComponent(b);
    }
  }
  if (!connected)
  {
    const int ta = this->StartTriangles.front(), tb = this->EndTriangles.front();
    error = "start point " + Describe(start) + " (triangle " + std::to_string(ta) + ", component " +
      std::to_string(this->GetComponent(ta)) + ") and end point " + Describe(end) + " (triangle " +
      std::to_string(tb) + ", component " + std::to_string(this->GetComponent(tb)) +
      ") lie on different connected components of the surface: no path joins them";
    return false;
  }

  // Legs that cost real work are shared through the surface's cache (see GeodesicPathCache).
  // The locally shortest method is not cached: its ties depend on whether the edge search's
  // landmark table exists yet.
  const bool cached = this->Options.Method != GeodesicMethod::LocallyShortest;
  const GeodesicPathCache::Settings settings{ static_cast<int>(this->Options.Method) * 4 +
      (this->Options.UseEdgePathStrip ? 1 : 0) + (this->Options.CorridorRefinement ? 2 : 0),
    this->Options.MaximumWindows,
    this->Options.BoundedWindows,
    this->Options.RouteTolerance };
  if (cached)
  {
    if (!this->Cache)
    {
      this->Cache = GeodesicPathCache::Get(mesh);
    }
    if (this->Cache->Find(start, end, settings, this->CachedLeg))
    {
      path.Points.swap(this->CachedLeg.Points);
      path.Length = this->CachedLeg.Length;
      this->Statistics.Exact = this->CachedLeg.Exact;
      this->Statistics.Routed = this->CachedLeg.Routed;
      this->Statistics.FromCache = true;
      return true;
    }
  }

  const int common = SharedTriangle(mesh, start, end);
  if (common >= 0)
  {
    this->Strip.assign(1, common); // a triangle is convex: the segment is the shortest path
    this->Statistics.Exact = true;
  }
  else if (!this->FindStripByMethod(start, end))
  {
    error = this->PieceReads
      ? "on a piece of the surface, the leg from " + Describe(start) + " to " + Describe(end) +
        " needs more than the exact window search within its budget (the site-graph route, the " +
        "edge path or the dual search, which need the whole surface)"
      : "no triangle strip joins " + Describe(start) + " and " + Describe(end) +
        " although they share a component (corrupt adjacency?)";
    return false;
  }
  if (!this->Straighten(start, end))
  {
    error = "the triangle strip between " + Describe(start) + " and " + Describe(end) +
      " is broken (consecutive triangles are not neighbours)";
    return false;
  }
  this->Statistics.StripTriangles = static_cast<int>(this->Strip.size());

  const std::vector<StripStraightener::PathPoint>& points = this->Straightener.GetPoints();
  path.Points.reserve(points.size());
  for (const StripStraightener::PathPoint& p : points)
  {
    path.Points.push_back(p.Point);
  }
  path.Length = PolylineLength(mesh, path.Points);
  this->Candidates.clear();
  if (this->Statistics.Routed)
  {
    this->ImproveRoutedLeg(start, end, path);
  }
  if (cached &&
    (this->Statistics.Windows >= GeodesicPathCache::MinimumWindows || this->Statistics.Routed))
  {
    this->CachedLeg.Points = path.Points;
    this->CachedLeg.Length = path.Length;
    this->CachedLeg.Exact = this->Statistics.Exact;
    this->CachedLeg.Routed = this->Statistics.Routed;
    this->Cache->Store(start, end, settings, this->CachedLeg);
  }
  return true;
}

//------------------------------------------------------------------------------
// The exact search first (within the Bounded method's budget, unless the leg is plainly too
// far for it), then the Bounded method's site-graph route, then the shortest edge path, then
// the dual search.
bool GeodesicPathSolver::FindStripByMethod(const CanonicalPoint& start, const CanonicalPoint& end)
{
  const TriangleMesh& mesh = this->GetMesh();
  bool haveStrip = false;
  if (this->Options.Method != GeodesicMethod::LocallyShortest &&
    !(this->Options.Method == GeodesicMethod::Bounded && this->ExceedsBoundedWindows(start, end)))
  {
    this->Exact.SetMaximumWindows(this->Options.Method == GeodesicMethod::Bounded
        ? std::min(this->Options.BoundedWindows, this->Options.MaximumWindows)
        : this->Options.MaximumWindows);
    this->Statistics.ExactLength =
      this->Exact.FindStrip(start, this->StartTriangles, end, this->EndTriangles, this->Strip);
    this->Statistics.Windows = this->Exact.GetLastWindowCount();
    haveStrip = this->Statistics.ExactLength >= 0.0;
    this->Statistics.Exact = haveStrip;
    if (this->PieceReads)
    {
      this->Exact.AppendLitTriangles(*this->PieceReads);
    }
  }
  if (this->PieceReads)
  {
    return haveStrip; // the other strips need the whole surface (SetPieceReads)
  }
  if (!haveStrip && this->Options.Method == GeodesicMethod::Bounded)
  {
    this->AvoidSites.clear();
    haveStrip = this->Statistics.Routed = this->StripFromSiteRoute(start, end);
  }
  if (haveStrip || (this->Options.UseEdgePathStrip && this->StripFromEdgePath(start, end)))
  {
    return true;
  }
  if (!this->Dual().FindStrip(this->StartTriangles,
        PositionOf(mesh, start),
        this->EndTriangles,
        PositionOf(mesh, end),
        this->Strip))
  {
    return false;
  }
  this->Statistics.ExpandedTriangles = this->Dual().GetLastExpandedCount();
  return true;
}

//------------------------------------------------------------------------------
bool GeodesicPathSolver::Straighten(const CanonicalPoint& start, const CanonicalPoint& end)
{
  return this->Straightener.Straighten(start,
    end,
    this->Strip,
    this->Options.MaximumStraighteningRounds,
    this->Statistics.StraighteningRounds);
}

//------------------------------------------------------------------------------
// Mesh-edge path ends: the corners of the triangles holding each end point, joined to it by
// the straight segment inside that triangle.
void GeodesicPathSolver::CollectTerminals(const CanonicalPoint& start, const CanonicalPoint& end)
{
  const TriangleMesh& mesh = this->GetMesh();
  auto terminals = [&](const std::vector<int>& triangles,
                     const Vec3& p,
                     std::vector<EdgeGraphSearch::Terminal>& out)
  {
    out.clear();
    for (int t : triangles)
    {
      for (int k = 0; k < 3; ++k)
      {
        const int v = mesh.GetTriangle(t)[k];
        out.push_back({ v, Distance(p, mesh.GetPosition(v)) });
      }
    }
  };
  terminals(this->StartTriangles, PositionOf(mesh, start), this->Sources);
  terminals(this->EndTriangles, PositionOf(mesh, end), this->Targets);
}

//------------------------------------------------------------------------------
bool GeodesicPathSolver::StripFromSiteRoute(const CanonicalPoint& start, const CanonicalPoint& end)
{
  const TriangleMesh& mesh = this->GetMesh();
  if (!this->SiteGraph)
  {
    this->SiteGraph = SurfaceSiteGraph::Get(mesh);
  }
  this->CollectTerminals(start, end);
  const double length = this->SiteGraph->FindRoute(this->Sources,
    PositionOf(mesh, start),
    this->Targets,
    PositionOf(mesh, end),
    this->AvoidSites,
    this->SiteScratch,
    this->VertexPath);
  if (length < 0.0)
  {
    return false;
  }
  this->Statistics.RouteLength = length;
  return this->StripAlongVertexPath(end);
}

//------------------------------------------------------------------------------
// The shortest mesh-edge path (exact bidirectional A*, see EdgeGraphSearch) and the strip
// along it.
bool GeodesicPathSolver::StripFromEdgePath(const CanonicalPoint& start, const CanonicalPoint& end)
{
  const TriangleMesh& mesh = this->GetMesh();
  this->CollectTerminals(start, end);
  EdgeGraphSearch& edges = this->Edges();
  const double length = edges.FindPath(
    this->Sources, PositionOf(mesh, start), this->Targets, PositionOf(mesh, end), this->VertexPath);
  this->Statistics.SettledVertices = edges.GetLastSettledCount();
  if (length < 0.0)
  {
    return false;
  }
  this->Statistics.EdgePathLength = length;
  return this->StripAlongVertexPath(end);
}

//------------------------------------------------------------------------------
// Strip along a mesh-edge path start -> v0 -> ... -> vk -> end: from a start triangle
// holding v0, turn around each vi (inside its fan of triangles) until a triangle holding the
// next vertex (or, after vk, the end point) is reached. The turn goes on the side the strip
// already is, away from the incoming edge, so every vi sits in one contiguous run of strip
// triangles and each path edge is an edge of a strip triangle: the edge path is a curve
// inside the strip. Only if a boundary blocks that side does the turn go the other way
// (across the incoming edge, which keeps the property). Fails on non-manifold fans.
bool GeodesicPathSolver::StripAlongVertexPath(const CanonicalPoint& end)
{
  const TriangleMesh& mesh = this->GetMesh();
  const std::vector<int>& path = this->VertexPath;
  const int k = static_cast<int>(path.size()) - 1;
  int current = -1;
  for (int t : this->StartTriangles)
  {
    if (CornerOf(mesh.GetTriangle(t), path[0]) >= 0)
    {
      current = t;
      break;
    }
  }
  if (current < 0)
  {
    return false;
  }
  this->Strip.assign(1, current);
  for (int i = 0; i <= k; ++i)
  {
    const int v = path[i];
    const int previous = i > 0 ? path[i - 1] : -1;
    auto reached = [&](int t)
    {
      return i < k ? CornerOf(mesh.GetTriangle(t), path[i + 1]) >= 0
                   : TriangleContains(mesh, end, t);
    };
    if (reached(current))
    {
      continue;
    }
    const Triangle& tri = mesh.GetTriangle(current);
    const int kv = CornerOf(tri, v);
    if (kv < 0)
    {
      return false;
    }
    // Local edge kv runs v -> tri[kv + 1], edge kv + 2 runs tri[kv + 2] -> v.
    const int away = tri[(kv + 1) % 3] == previous ? (kv + 2) % 3 : kv;
    const int across = away == kv ? (kv + 2) % 3 : kv;
    const size_t mark = this->Strip.size();
    const int limit = mesh.GetVertexCorners(v).size();
    bool done = false;
    for (int exitEdge : { away, across })
    {
      this->Strip.resize(mark);
      int t = current, edge = exitEdge;
      for (int steps = 0; steps <= limit; ++steps)
      {
        const int next = mesh.GetNeighbor(t, edge);
        if (next < 0)
        {
          break;
        }
        const int entry = mesh.GetNeighborEdge(t, edge);
        const int kn = CornerOf(mesh.GetTriangle(next), v);
        if (kn < 0)
        {
          break;
        }
        this->Strip.push_back(next);
        if (reached(next))
        {
          done = true;
          break;
        }
        edge = entry == kn ? (kn + 2) % 3 : kn;
        t = next;
      }
      if (done)
      {
        break;
      }
    }
    if (!done)
    {
      return false;
    }
    current = this->Strip.back();
  }
  return true;
}

//------------------------------------------------------------------------------
double PolylineLength(const TriangleMesh& mesh, const std::vector<CanonicalPoint>& points)
{
  double length = 0.0;
  for (size_t i = 1; i < points.size(); ++i)
  {
    length += Distance(PositionOf(mesh, points[i - 1]), PositionOf(mesh, points[i]));
  }
  return length;
}

//------------------------------------------------------------------------------
CanonicalPoint PointAlongPath(const TriangleMesh& mesh, const GeodesicPath& path, double t)
{
  const std::vector<CanonicalPoint>& pts = path.Points;
  if (pts.empty())
  {
    return {};
  }
  if (pts.size() == 1 || !(t > 0.0))
  {
    return pts.front();
  }
  if (t >= 1.0)
  {
    return pts.back();
  }
  const double total = PolylineLength(mesh, pts);
  const double target = t * total;
  double walked = 0.0;
  for (size_t i = 1; i < pts.size(); ++i)
  {
    const double segment = Distance(PositionOf(mesh, pts[i - 1]), PositionOf(mesh, pts[i]));
    if (walked + segment < target || segment == 0.0)
    {
      walked += segment;
      continue;
    }
    const double s = (target - walked) / segment;
    if (s <= 0.0)
    {
      return pts[i - 1];
    }
    if (s >= 1.0)
    {
      return pts[i];
    }
    const int tri = SharedTriangle(mesh, pts[i - 1], pts[i]);
    if (tri < 0)
    {
      return pts[i - 1]; // not a traced path; nothing better to offer
    }
    const std::array<double, 3> wa = WeightsInTriangle(mesh, pts[i - 1], tri);
    const std::array<double, 3> wb = WeightsInTriangle(mesh, pts[i], tri);
    std::array<double, 3> w;
    for (int k = 0; k < 3; ++k)
    {
      // A weight zero at both ends stays exactly zero: a point between two points of one
      // edge is on that edge, not 1e-17 inside the triangle.
      w[k] = (wa[k] == 0.0 && wb[k] == 0.0) ? 0.0 : (1.0 - s) * wa[k] + s * wb[k];
    }
    return FromWeights(mesh, tri, w);
  }
  return pts.back();
}

} // namespace boolsurf

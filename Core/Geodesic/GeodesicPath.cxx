#include "Geodesic/GeodesicPath.h"

#include <algorithm>
#include <cmath>

namespace boolsurf
{
namespace
{
constexpr double Pi = 3.14159265358979323846;

// A crossing this close (in edge parameter) to an edge end is the vertex itself: the funnel
// decides collinear cases by the sign of rounded cross products, so a path running through a
// vertex may come out as a crossing at t = 1e-17. Reporting the vertex keeps paths along
// edges and through vertices exact for the arrangement.
constexpr double VertexSnap = 1e-12;

// Vertices whose outside angle is this much below pi get the strip rerouted around them;
// smaller deficits are rounding noise of a straight pass.
constexpr double AngleTolerance = 1e-11;

constexpr int StartId = -2;
constexpr int EndId = -3;

double AngleBetween(const Vec3& a, const Vec3& b)
{
  return std::atan2(Length(Cross(a, b)), Dot(a, b));
}

int CornerOf(const Triangle& tri, int v)
{
  return tri[0] == v ? 0 : (tri[1] == v ? 1 : (tri[2] == v ? 2 : -1));
}

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
const char* GeodesicMethodName(GeodesicMethod method)
{
  switch (method)
  {
    case GeodesicMethod::Bounded:
      return "Bounded";
    case GeodesicMethod::Exact:
      return "Exact";
    case GeodesicMethod::LocallyShortest:
      return "LocallyShortest";
  }
  return "Unknown";
}

//------------------------------------------------------------------------------
GeodesicPathSolver::GeodesicPathSolver(const TriangleMesh& mesh,
  std::shared_ptr<const TriangleComponents> components)
  : Mesh(mesh)
  , Components(components ? std::move(components) : std::make_shared<TriangleComponents>(mesh))
  , Exact(mesh)
{
  // The edge-path and dual searches are built on first use (Edges(), Dual()): legs the exact
  // search answers need neither, and on millions of triangles they cost seconds to build.
}

//------------------------------------------------------------------------------
GeodesicPathSolver::GeodesicPathSolver(const GeodesicPathSolver& main, HelperTag)
  : Mesh(main.Mesh)
  , Components(main.Components)
  , Exact(main.Mesh)
{
  this->CopySettings(main);
}

//------------------------------------------------------------------------------
DualGraphSearch& GeodesicPathSolver::Dual()
{
  if (!this->Search)
  {
    this->Search = std::make_unique<DualGraphSearch>(this->Mesh);
    this->Search->SetHeuristicWeight(this->HeuristicWeight);
  }
  return *this->Search;
}

//------------------------------------------------------------------------------
EdgeGraphSearch& GeodesicPathSolver::Edges()
{
  if (!this->EdgeSearch)
  {
    this->EdgeSearch = std::make_unique<EdgeGraphSearch>(this->Mesh);
    this->EdgeSearch->SetNumberOfLandmarks(this->LandmarkCount);
    this->EdgeSearch->SetLandmarkBuildThreshold(this->LandmarkBuildThreshold);
  }
  return *this->EdgeSearch;
}

//------------------------------------------------------------------------------
void GeodesicPathSolver::SetHeuristicWeight(double w)
{
  this->HeuristicWeight = w;
  if (this->Search)
  {
    this->Search->SetHeuristicWeight(w);
  }
}

//------------------------------------------------------------------------------
void GeodesicPathSolver::SetNumberOfLandmarks(int n)
{
  if (this->EdgeSearch && this->EdgeSearch->GetNumberOfLandmarks() != n)
  {
    this->EdgeSearch->SetNumberOfLandmarks(n); // drops a built table
  }
  this->LandmarkCount = n;
}

//------------------------------------------------------------------------------
void GeodesicPathSolver::SetLandmarkBuildThreshold(double t)
{
  this->LandmarkBuildThreshold = t;
  if (this->EdgeSearch)
  {
    this->EdgeSearch->SetLandmarkBuildThreshold(t);
  }
}

//------------------------------------------------------------------------------
TraceStatus GeodesicPathSolver::Compute(const SurfacePoint& start,
  const SurfacePoint& end,
  GeodesicPath& path)
{
  const TriangleMesh& mesh = this->GetMesh();
  std::string problem;
  if (!CheckSurfacePoint(mesh, start, problem))
  {
    path = {};
    return TraceStatus::Failure("start point: " + problem);
  }
  if (!CheckSurfacePoint(mesh, end, problem))
  {
    path = {};
    return TraceStatus::Failure("end point: " + problem);
  }
  return this->Compute(Canonicalize(mesh, start, 0.0), Canonicalize(mesh, end, 0.0), path);
}

//------------------------------------------------------------------------------
TraceStatus GeodesicPathSolver::Compute(const CanonicalPoint& startIn,
  const CanonicalPoint& endIn,
  GeodesicPath& path)
{
  const TriangleMesh& mesh = this->GetMesh();
  this->Statistics = {};
  path.Points.clear();
  path.Length = 0.0;
  std::string problem;
  if (!CheckCanonicalPoint(mesh, startIn, problem))
  {
    return TraceStatus::Failure("start point: " + problem);
  }
  if (!CheckCanonicalPoint(mesh, endIn, problem))
  {
    return TraceStatus::Failure("end point: " + problem);
  }
  const CanonicalPoint start = Normalize(mesh, startIn);
  const CanonicalPoint end = Normalize(mesh, endIn);
  if (start == end)
  {
    this->Statistics.Exact = true;
    path.Points.push_back(start);
    return TraceStatus::Success();
  }

  this->UnfoldedStrip.clear();
  TrianglesOf(mesh, start, this->StartTriangles);
  TrianglesOf(mesh, end, this->EndTriangles);
  bool connected = false;
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
    return TraceStatus::Failure("start point " + Describe(start) + " (triangle " +
      std::to_string(ta) + ", component " + std::to_string(this->GetComponent(ta)) +
      ") and end point " + Describe(end) + " (triangle " + std::to_string(tb) + ", component " +
      std::to_string(this->GetComponent(tb)) +
      ") lie on different connected components of the surface: no path joins them");
  }

  // Legs that cost real work are shared through the surface's cache (see GeodesicPathCache).
  // The locally shortest method is not cached: its ties depend on whether the edge search's
  // landmark table exists yet.
  const bool cached = this->Method != GeodesicMethod::LocallyShortest;
  const GeodesicPathCache::Settings settings{ static_cast<int>(this->Method) * 4 +
      (this->UseEdgePathStrip ? 1 : 0) + (this->CorridorRefinement ? 2 : 0),
    this->ExactWindows,
    this->BoundedWindows,
    this->RouteTolerance };
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
      return TraceStatus::Success();
    }
  }

  const int common = SharedTriangle(mesh, start, end);
  bool haveStrip = false;
  if (common >= 0)
  {
    this->Strip.assign(1, common); // a triangle is convex: the segment is the shortest path
    haveStrip = true;
    this->Statistics.Exact = true;
  }
  if (!haveStrip && this->Method != GeodesicMethod::LocallyShortest &&
    !(this->Method == GeodesicMethod::Bounded && this->ExceedsBoundedWindows(start, end)))
  {
    this->Exact.SetMaximumWindows(this->Method == GeodesicMethod::Bounded
        ? std::min(this->BoundedWindows, this->ExactWindows)
        : this->ExactWindows);
    this->Statistics.ExactLength =
      this->Exact.FindStrip(start, this->StartTriangles, end, this->EndTriangles, this->Strip);
    this->Statistics.Windows = this->Exact.GetLastWindowCount();
    haveStrip = this->Statistics.ExactLength >= 0.0;
    this->Statistics.Exact = haveStrip;
  }
  if (!haveStrip && this->Method == GeodesicMethod::Bounded)
  {
    this->AvoidSites.clear();
    haveStrip = this->Statistics.Routed = this->StripFromSiteRoute(start, end);
  }
  if (!haveStrip && !(this->UseEdgePathStrip && this->StripFromEdgePath(start, end)))
  {
    if (!this->Dual().FindStrip(this->StartTriangles,
          PositionOf(mesh, start),
          this->EndTriangles,
          PositionOf(mesh, end),
          this->Strip))
    {
      return TraceStatus::Failure("no triangle strip joins " + Describe(start) + " and " +
        Describe(end) + " although they share a component (corrupt adjacency?)");
    }
    this->Statistics.ExpandedTriangles = this->Dual().GetLastExpandedCount();
  }
  if (!this->Straighten(start, end))
  {
    return TraceStatus::Failure("the triangle strip between " + Describe(start) + " and " +
      Describe(end) + " is broken (consecutive triangles are not neighbours)");
  }
  this->Statistics.StripTriangles = static_cast<int>(this->Strip.size());

  path.Points.reserve(this->Points.size());
  for (const PathPoint& p : this->Points)
  {
    path.Points.push_back(p.Point);
  }
  path.Length = PolylineLength(mesh, path.Points);
  this->Candidates.clear();
  if (this->Statistics.Routed)
  {
    this->Candidates.emplace_back(path.Length, path.Points);
    this->TryAlternativeRoutes(start, end, path);
  }
  if (this->Statistics.Routed && mesh.GetNumberOfVertices() <= MaximumVerticesForEdgeCandidate)
  {
    this->TryEdgePathCandidate(start, end, path);
  }
  if (this->Statistics.Routed && this->CorridorRefinement &&
    mesh.GetNumberOfVertices() <= MaximumVerticesForEdgeCandidate)
  {
    this->RefineInCorridor(start, end, path);
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
  return TraceStatus::Success();
}

//------------------------------------------------------------------------------
void GeodesicPathSolver::CopySettings(const GeodesicPathSolver& other)
{
  this->MaximumRounds = other.MaximumRounds;
  this->SetHeuristicWeight(other.HeuristicWeight);
  this->SetNumberOfLandmarks(other.LandmarkCount);
  this->SetLandmarkBuildThreshold(other.LandmarkBuildThreshold);
  this->UseEdgePathStrip = other.UseEdgePathStrip;
  this->Method = other.Method;
  this->ExactWindows = other.ExactWindows;
  this->BoundedWindows = other.BoundedWindows;
  this->RouteTolerance = other.RouteTolerance;
  this->CorridorRefinement = other.CorridorRefinement;
}

//------------------------------------------------------------------------------
// The site graph's lengths are only as accurate as its cells are small (a route zigzags
// through the sites, 1-6 % longer than the geodesic it stands for), so where two local
// geodesics are nearly as long it may pick the longer one: one on each side of a bump (a nose,
// a cheek, a fold of a statue) or the other way round a handle or a hole. Other routes, each
// kept out of a band round the middle of the first, are straightened too when their length is
// within RouteTolerance of the first's, and the shortest path is kept. The bands: the first
// route's sites there and their neighbours (the other side of a handle or a hole; on closed
// genus-0 surfaces it runs beside the first and straightens to the same geodesic, so they skip
// it), then, on meshes up to MaximumVerticesForEdgeCandidate vertices, every site within 2 %,
// 5 % and 12 % of the first route's length of them (the other side of a bump: on face.ply a
// far pair's shortest path ran 29 % of its length away from the first route's, which was
// 0.99 % longer; which band finds such a path varies, hence three).
void GeodesicPathSolver::TryAlternativeRoutes(const CanonicalPoint& start,
  const CanonicalPoint& end,
  GeodesicPath& path)
{
  const SurfaceSiteGraph& graph = *this->SiteGraph;
  const std::vector<int> first = this->SiteScratch.Sites;
  const int n = static_cast<int>(first.size());
  const int margin = std::max(2, n / 8);
  if (!(this->RouteTolerance > 0.0) || n - 2 * margin <= 0)
  {
    return; // the route crosses too few cells to go round anything
  }
  const std::vector<int> middle(first.begin() + margin, first.end() - margin);
  const double firstRoute = this->Statistics.RouteLength;
  constexpr double bands[] = { 0.0, 0.02, 0.05, 0.12 };
  for (const double band : bands)
  {
    // Each band costs a route and a straightening: on meshes above
    // MaximumVerticesForEdgeCandidate vertices a far leg's straightening is most of its cost
    // (on igea_1m the three bands took far legs from 19 to 111 ms median, for legs 0.13 %
    // shorter in sum), so they keep the first.
    if ((band == 0.0 && graph.IsAllSpheres()) ||
      (band > 0.0 && this->GetMesh().GetNumberOfVertices() > MaximumVerticesForEdgeCandidate))
    {
      continue;
    }
    this->AvoidSites.assign(static_cast<std::size_t>(graph.GetNumberOfSites()), 0);
    if (band == 0.0)
    {
      for (const int s : middle)
      {
        graph.FlagNeighbourhood(s, this->AvoidSites);
      }
    }
    else
    {
      graph.FlagWithin(middle, band * firstRoute, this->AvoidSites);
    }
    const GeodesicPathStatistics kept = this->Statistics;
    const bool routed = this->StripFromSiteRoute(start, end);
    const double route = this->Statistics.RouteLength;
    this->AvoidSites.clear();
    if (!routed || route > (1.0 + this->RouteTolerance) * firstRoute ||
      !this->Straighten(start, end))
    {
      this->Statistics = kept;
      continue;
    }
    if (this->KeepShorterCandidate(kept, path))
    {
      this->Statistics.RouteLength = route;
    }
  }
}

//------------------------------------------------------------------------------
// The window search explores about the ellipse {x : |s x| + |x t| < d(s, t)}: at least
// (pi / 4) |st|^2 of surface, about 1.6 (|st| / h)^2 triangles for a mean edge length h, and
// it creates several windows per triangle (6 to 20 measured on scans, as few as 0.2 on the
// short legs of igea_1m, where the geodesic is close to the straight line). A leg whose
// estimate at one window per triangle is already 8 times the budget cannot fit it, so the
// search is not started: far legs skip straight to the site-graph route.
bool GeodesicPathSolver::ExceedsBoundedWindows(const CanonicalPoint& start,
  const CanonicalPoint& end)
{
  const TriangleMesh& mesh = this->GetMesh();
  if (this->MeanEdgeLength < 0.0)
  {
    // An estimate is all this test needs: every edge up to 2^16 of them, else a fixed stride
    // through the edge list (a full pass cost 65 ms per solver on 4.3M triangles).
    const int ne = mesh.GetNumberOfEdges();
    const int stride = std::max(1, ne >> 16);
    double sum = 0.0;
    int count = 0;
    for (int e = 0; e < ne; e += stride, ++count)
    {
      const std::array<int, 2> v = mesh.GetEdgeVertices(e);
      sum += Distance(mesh.GetPosition(v[0]), mesh.GetPosition(v[1]));
    }
    this->MeanEdgeLength = count > 0 ? sum / count : 0.0;
  }
  if (!(this->MeanEdgeLength > 0.0))
  {
    return false;
  }
  const double ratio =
    Distance(PositionOf(mesh, start), PositionOf(mesh, end)) / this->MeanEdgeLength;
  return 1.6 * ratio * ratio > 2.0 * this->BoundedWindows;
}

//------------------------------------------------------------------------------
// A routed leg and the straightened shortest edge path often reach different local geodesics
// (one on each side of a bump), and either may be the shorter: on the shared scans keeping the
// shorter of the two took the far pairs equal to the exact ones from 17 to 29 of 40 on kitten
// and the worst excess from 3.5 % to 0.9 %. The edge search costs O(mesh) for far legs, so
// only meshes up to MaximumVerticesForEdgeCandidate vertices take it (a few milliseconds);
// it runs without landmarks, whose lazily built table would make ties depend on history.
void GeodesicPathSolver::TryEdgePathCandidate(const CanonicalPoint& start,
  const CanonicalPoint& end,
  GeodesicPath& path)
{
  const TriangleMesh& mesh = this->GetMesh();
  if (!this->PlainEdgeSearch)
  {
    this->PlainEdgeSearch = std::make_unique<EdgeGraphSearch>(mesh);
    this->PlainEdgeSearch->SetNumberOfLandmarks(0);
  }
  this->CollectTerminals(start, end);
  const GeodesicPathStatistics kept = this->Statistics;
  const double length = this->PlainEdgeSearch->FindPath(
    this->Sources, PositionOf(mesh, start), this->Targets, PositionOf(mesh, end), this->VertexPath);
  if (length < 0.0 || !this->StripAlongVertexPath(end) || !this->Straighten(start, end))
  {
    this->Statistics = kept;
    return;
  }
  this->KeepShorterCandidate(kept, path);
  this->Statistics.EdgePathLength = length;
}

//------------------------------------------------------------------------------
// A routed leg is a local geodesic, and on a scan others of nearly the same length run beside
// it, one on each side of every small bump: the route's few-percent error cannot tell them
// apart, and the shortest may be any of them (kitten's far pairs: within 2e-4 of the exact
// length, rarely equal to it). The window search restricted to a corridor of triangles around
// the path (CorridorRings rings of vertex-adjacent triangles, at most about
// MaximumCorridorTriangles) is exact inside the corridor: it finds the shortest of them,
// within CorridorWindows windows, and its path is kept when shorter; the other candidates'
// corridors follow (below). Paths outside the corridors are not seen, so the leg is not
// marked exact.
void GeodesicPathSolver::RefineInCorridor(const CanonicalPoint& start,
  const CanonicalPoint& end,
  GeodesicPath& path)
{
  const TriangleMesh& mesh = this->GetMesh();
  const int nt = mesh.GetNumberOfTriangles();
  if (nt <= WholeMeshRefinementTriangles &&
    this->SearchShorterPath(start, end, path, false, CorridorWindows))
  {
    return;
  }
  // The kept path's corridor first; then, with what its search left of the budget, the
  // corridor of each other straightened candidate within CorridorCandidateSlack of the kept
  // length that leaves the corridors searched so far (the other side of a small bump: on
  // armadillo five far pairs from one start point were 0.05 % long, their shortest paths 4 %
  // of their length beside the kept path, outside its corridor, but on a band route's).
  const int before = this->Statistics.CorridorWindows;
  this->BuildCorridor(path.Points);
  const bool complete = this->SearchShorterPath(start, end, path, true, CorridorWindows);
  if (!complete)
  {
    return;
  }
  // Corridors get increasing generations, so the triangles of every corridor searched for
  // this leg are those stamped `first` or later.
  const std::uint32_t first = this->CorridorGeneration;
  // By index, over the candidates so far: a search that finds a shorter path appends it.
  const std::size_t candidates = this->Candidates.size();
  for (std::size_t i = 0; i < candidates; ++i)
  {
    const int left = CorridorWindows - (this->Statistics.CorridorWindows - before);
    if (left < MinimumCandidateCorridorWindows)
    {
      break;
    }
    if (this->Candidates[i].first > (1.0 + CorridorCandidateSlack) * path.Length ||
      this->InsideSearched(this->Candidates[i].second, first))
    {
      continue;
    }
    this->BuildCorridor(this->Candidates[i].second);
    this->SearchShorterPath(start, end, path, true, left);
  }
}

//------------------------------------------------------------------------------
// Corridor (and CorridorStamp == CorridorGeneration): the triangles of `points`, grown by up to
// CorridorRings rings of vertex-adjacent triangles while it holds fewer than
// MaximumCorridorTriangles.
void GeodesicPathSolver::BuildCorridor(const std::vector<CanonicalPoint>& points)
{
  const TriangleMesh& mesh = this->GetMesh();
  const int nt = mesh.GetNumberOfTriangles();
  if (static_cast<int>(this->CorridorStamp.size()) != nt || ++this->CorridorGeneration == 0)
  {
    this->CorridorStamp.assign(static_cast<std::size_t>(nt), 0);
    this->CorridorGeneration = 1;
  }
  const std::uint32_t generation = this->CorridorGeneration;
  std::vector<int>& corridor = this->Corridor;
  corridor.clear();
  const auto add = [&](int t)
  {
    if (this->CorridorStamp[t] != generation)
    {
      this->CorridorStamp[t] = generation;
      corridor.push_back(t);
    }
  };
  for (const CanonicalPoint& p : points)
  {
    TrianglesOf(mesh, p, this->CorridorSeeds);
    for (const int t : this->CorridorSeeds)
    {
      add(t);
    }
  }
  std::size_t ringStart = 0;
  for (int ring = 0;
       ring < CorridorRings && static_cast<int>(corridor.size()) < MaximumCorridorTriangles;
       ++ring)
  {
    const std::size_t ringEnd = corridor.size();
    for (std::size_t i = ringStart; i < ringEnd; ++i)
    {
      const Triangle& tri = mesh.GetTriangle(corridor[i]);
      for (int k = 0; k < 3; ++k)
      {
        for (const int corner : mesh.GetVertexCorners(tri[k]))
        {
          add(corner / 3);
        }
      }
    }
    ringStart = ringEnd;
  }
}

//------------------------------------------------------------------------------
bool GeodesicPathSolver::InsideSearched(const std::vector<CanonicalPoint>& points,
  std::uint32_t first)
{
  for (const CanonicalPoint& p : points)
  {
    TrianglesOf(this->GetMesh(), p, this->CorridorSeeds);
    for (const int t : this->CorridorSeeds)
    {
      if (this->CorridorStamp[t] < first)
      {
        return false;
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
// The exact window search for a path shorter than `path` (kept when found), over the whole
// mesh or only the corridor's triangles (CorridorStamp), within `budget` windows.
// A whole-mesh search that ends within its budget certifies the kept path as the shortest:
// the leg is then marked exact. Returns whether the search ended within its budget.
bool GeodesicPathSolver::SearchShorterPath(const CanonicalPoint& start,
  const CanonicalPoint& end,
  GeodesicPath& path,
  bool inCorridor,
  int budget)
{
  const GeodesicPathStatistics kept = this->Statistics;
  this->Exact.SetMaximumWindows(budget);
  // Only a shorter path is of use: windows that cannot lead to one are not made.
  this->Exact.SetUpperBound(path.Length);
  if (inCorridor)
  {
    const std::uint32_t generation = this->CorridorGeneration;
    this->Exact.SetFieldTriangleFilter(
      [this, generation](int t) { return this->CorridorStamp[t] == generation; });
  }
  const double length =
    this->Exact.FindStrip(start, this->StartTriangles, end, this->EndTriangles, this->Strip);
  this->Exact.SetFieldTriangleFilter(nullptr);
  const int windows = this->Exact.GetLastWindowCount();
  const bool complete = !this->Exact.GetLastBudgetExceeded();
  // Certified: no shorter path exists, or the shorter one found was straightened.
  bool certified = complete && !inCorridor;
  if (length < 0.0 || !this->Straighten(start, end))
  {
    certified = certified && length < 0.0;
    this->Statistics = kept;
  }
  else
  {
    this->KeepShorterCandidate(kept, path);
  }
  this->Statistics.CorridorWindows += windows;
  if (certified)
  {
    this->Statistics.Exact = true;
  }
  return complete;
}

//------------------------------------------------------------------------------
// A candidate strip was just straightened (Points): the statistics go back to the first
// path's (`kept`), with the candidate counted and every funnel run kept, and `path` becomes
// the candidate when it is shorter.
bool GeodesicPathSolver::KeepShorterCandidate(const GeodesicPathStatistics& kept,
  GeodesicPath& path)
{
  this->Alternative.clear();
  for (const PathPoint& p : this->Points)
  {
    this->Alternative.push_back(p.Point);
  }
  const double length = PolylineLength(this->GetMesh(), this->Alternative);
  this->Candidates.emplace_back(length, this->Alternative);
  const int rounds = this->Statistics.StraighteningRounds;
  const int strip = static_cast<int>(this->Strip.size());
  this->Statistics = kept;
  this->Statistics.AlternativeRoutes += 1;
  this->Statistics.StraighteningRounds = rounds;
  if (!(length < path.Length))
  {
    return false;
  }
  path.Points.swap(this->Alternative);
  path.Length = length;
  this->Statistics.StripTriangles = strip;
  return true;
}

//------------------------------------------------------------------------------
bool GeodesicPathSolver::Straighten(const CanonicalPoint& start, const CanonicalPoint& end)
{
  for (;;)
  {
    this->TrimStrip(start, end);
    if (!this->UnfoldStrip(start, end))
    {
      return false;
    }
    this->RunFunnel();
    this->CollectPathPoints(start, end);
    ++this->Statistics.StraighteningRounds;
    if (this->Statistics.StraighteningRounds >= this->MaximumRounds ||
      !this->RerouteAroundVertices())
    {
      return true;
    }
  }
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
// The strip must begin at the last triangle holding the start and end at the first one after
// it holding the end: triangles beyond would make the start or end lie on a portal, which the
// funnel cannot handle, and a strip that comes back to an end point's fan is simply cut short.
void GeodesicPathSolver::TrimStrip(const CanonicalPoint& start, const CanonicalPoint& end)
{
  const TriangleMesh& mesh = this->GetMesh();
  const int n = static_cast<int>(this->Strip.size());
  int first = 0;
  for (int i = 0; i < n; ++i)
  {
    if (TriangleContains(mesh, start, this->Strip[i]))
    {
      first = i;
    }
  }
  int last = n - 1;
  for (int i = first; i < n; ++i)
  {
    if (TriangleContains(mesh, end, this->Strip[i]))
    {
      last = i;
      break;
    }
  }
  this->Strip.erase(this->Strip.begin() + last + 1, this->Strip.end());
  this->Strip.erase(this->Strip.begin(), this->Strip.begin() + first);

  // A strip that comes back to a triangle it already crossed holds a loop (rerouting a
  // vertex next to earlier reroutes can sweep all the way round it). The path can always take
  // the short cut, so cut the loop out. Positions in a hash map of the strip's size: a
  // mesh-sized stamped array per solver touched pages all over the mesh (scattered triangle
  // ids), megabytes on a large mesh for a few hundred triangles per strip.
  EdgeIndex& position = this->StripPosition;
  position.Reset(this->Strip.size());
  size_t kept = 0;
  for (size_t i = 0; i < this->Strip.size(); ++i)
  {
    const int t = this->Strip[i];
    const int seen = position.Find(static_cast<EdgeIndex::Key>(t));
    if (seen >= 0 && seen < static_cast<int>(kept) && this->Strip[seen] == t)
    {
      kept = seen + 1;
      continue;
    }
    position.Set(static_cast<EdgeIndex::Key>(t), static_cast<int>(kept));
    this->Strip[kept++] = t;
  }
  this->Strip.resize(kept);
}

//------------------------------------------------------------------------------
// Each triangle is laid flat next to the previous one across their common edge. Positions of
// the shared vertices are copied, never recomputed, so a vertex has exactly one position per
// strip triangle and portal endpoints agree bit for bit with their triangles' corners.
bool GeodesicPathSolver::UnfoldStrip(const CanonicalPoint& start, const CanonicalPoint& end)
{
  const TriangleMesh& mesh = this->GetMesh();
  const int n = static_cast<int>(this->Strip.size());
  // Unfolded[i] and Portals[i - 1] depend on Strip[0..i] only: keep what the last unfolding
  // of this path computed for the common prefix (a straightening round changes the strip only
  // from its first reroute on), bit for bit the same as unfolding again.
  const int old = static_cast<int>(this->UnfoldedStrip.size());
  int common = 0;
  while (common < n && common < old && this->Strip[common] == this->UnfoldedStrip[common])
  {
    ++common;
  }
  this->UnfoldedStrip.clear(); // valid again only if this unfolding succeeds
  this->Unfolded.resize(n);
  this->Portals.resize(n - 1);
  if (common == 0)
  {
    const int t = this->Strip[0];
    const Vec3 p0 = mesh.GetCornerPosition(t, 0);
    const Vec3 e1 = mesh.GetCornerPosition(t, 1) - p0;
    const Vec3 e2 = mesh.GetCornerPosition(t, 2) - p0;
    const double l1 = Length(e1);
    this->Unfolded[0] = {
      Vec2{ 0.0, 0.0 }, Vec2{ l1, 0.0 }, Vec2{ Dot(e2, e1) / l1, Length(Cross(e1, e2)) / l1 }
    };
  }
  for (int i = std::max(common - 1, 0); i + 1 < n; ++i)
  {
    const int t = this->Strip[i];
    const int next = this->Strip[i + 1];
    int k = 0;
    while (k < 3 && mesh.GetNeighbor(t, k) != next)
    {
      ++k;
    }
    if (k == 3)
    {
      return false;
    }
    const Triangle& tri = mesh.GetTriangle(t);
    const int a = tri[k], b = tri[(k + 1) % 3];
    const Vec2 a2 = this->Unfolded[i][k], b2 = this->Unfolded[i][(k + 1) % 3];
    const Vec2 o2 = this->Unfolded[i][(k + 2) % 3];
    const bool oppositeOnLeft = Cross(b2 - a2, o2 - a2) > 0.0;

    // Third vertex from the 3D triangle: foot along a->b and height, on the side of the
    // shared edge away from the previous triangle.
    const Triangle& nextTri = mesh.GetTriangle(next);
    int c = 0;
    while (nextTri[c] == a || nextTri[c] == b)
    {
      ++c;
    }
    const Vec3 a3 = mesh.GetPosition(a);
    const Vec3 ab3 = mesh.GetPosition(b) - a3;
    const Vec3 ac3 = mesh.GetPosition(nextTri[c]) - a3;
    const double lab = Length(ab3);
    const double along = Dot(ac3, ab3) / lab;
    const double height = Length(Cross(ab3, ac3)) / lab;
    const Vec2 ab2 = b2 - a2;
    const double l2 = Length(ab2);
    const Vec2 dir = (1.0 / l2) * ab2;
    Vec2 normal{ -dir.y, dir.x };
    if (oppositeOnLeft)
    {
      normal = -1.0 * normal;
    }
    const Vec2 c2 = a2 + along * dir + height * normal;
    for (int j = 0; j < 3; ++j)
    {
      this->Unfolded[i + 1][j] = nextTri[j] == a ? a2 : (nextTri[j] == b ? b2 : c2);
    }

    // Walking away from the previous triangle's third vertex, the vertex on the left is b
    // when that vertex lies left of a->b.
    Portal& portal = this->Portals[i];
    portal.Edge = mesh.GetEdgeId(t, k);
    if (oppositeOnLeft)
    {
      portal.Left = b;
      portal.LeftPosition = b2;
      portal.Right = a;
      portal.RightPosition = a2;
    }
    else
    {
      portal.Left = a;
      portal.LeftPosition = a2;
      portal.Right = b;
      portal.RightPosition = b2;
    }
  }
  auto place = [&](const CanonicalPoint& p, int i)
  {
    const std::array<double, 3> w = WeightsInTriangle(mesh, p, this->Strip[i]);
    const std::array<Vec2, 3>& u = this->Unfolded[i];
    return w[0] * u[0] + w[1] * u[1] + w[2] * u[2];
  };
  this->StartPosition = place(start, 0);
  this->EndPosition = place(end, n - 1);
  this->UnfoldedStrip = this->Strip;
  return true;
}

//------------------------------------------------------------------------------
// Funnel algorithm (the "simple stupid" formulation by M. Mononen of Lee-Preparata): the apex
// and the two funnel sides advance portal by portal; when one side crosses the other, the
// crossed side's point becomes a path corner and the scan restarts from it. Funnel portal 0
// is the start, portals 1..n-1 are the strip portals, portal n is the end.
void GeodesicPathSolver::RunFunnel()
{
  const int count = static_cast<int>(this->Portals.size()) + 2;
  auto portalAt = [&](int i, Vec2& left, int& leftId, Vec2& right, int& rightId)
  {
    if (i == 0)
    {
      left = right = this->StartPosition;
      leftId = rightId = StartId;
    }
    else if (i == count - 1)
    {
      left = right = this->EndPosition;
      leftId = rightId = EndId;
    }
    else
    {
      const Portal& p = this->Portals[i - 1];
      left = p.LeftPosition;
      leftId = p.Left;
      right = p.RightPosition;
      rightId = p.Right;
    }
  };

  this->Corners.clear();
  Vec2 apex = this->StartPosition, left = apex, right = apex;
  int apexId = StartId, leftId = StartId, rightId = StartId;
  int apexIndex = 0, leftIndex = 0, rightIndex = 0;
  this->Corners.push_back({ apex, StartId, 0 });
  for (int i = 1; i < count; ++i)
  {
    Vec2 l, r;
    int lId, rId;
    portalAt(i, l, lId, r, rId);

    // A portal holding the apex vertex is crossed at the apex itself and constrains nothing;
    // skipping it walks the fan of triangles around a corner. After a restart both sides sit
    // on the apex and the first portal beyond the fan opens the funnel again. A side moving
    // onto the other side's point (the end, or a shared vertex) closes the funnel on that
    // point without crossing it.
    if (lId == apexId || rId == apexId)
    {
      continue;
    }
    if (Cross(right - apex, r - apex) >= 0.0)
    {
      if (rightId == apexId || rId == leftId || Cross(r - apex, left - apex) > 0.0)
      {
        right = r;
        rightId = rId;
        rightIndex = i;
      }
      else
      {
        apex = left;
        apexId = leftId;
        apexIndex = leftIndex;
        this->Corners.push_back({ apex, apexId, apexIndex });
        right = left = apex;
        rightId = leftId = apexId;
        rightIndex = leftIndex = apexIndex;
        i = apexIndex;
        continue;
      }
    }
    if (Cross(l - apex, left - apex) >= 0.0)
    {
      if (leftId == apexId || lId == rightId || Cross(right - apex, l - apex) > 0.0)
      {
        left = l;
        leftId = lId;
        leftIndex = i;
      }
      else
      {
        apex = right;
        apexId = rightId;
        apexIndex = rightIndex;
        this->Corners.push_back({ apex, apexId, apexIndex });
        right = left = apex;
        rightId = leftId = apexId;
        rightIndex = leftIndex = apexIndex;
        i = apexIndex;
        continue;
      }
    }
  }
  this->Corners.push_back({ this->EndPosition, EndId, count - 1 });
}

//------------------------------------------------------------------------------
void GeodesicPathSolver::EmitVertex(int vertex, int portal)
{
  PathPoint& back = this->Points.back();
  if (back.Point.Location == PointLocation::Vertex && back.Point.Id == vertex)
  {
    if (back.FirstPortal >= 0)
    {
      back.FirstPortal = std::min(back.FirstPortal, portal);
      back.LastPortal = std::max(back.LastPortal, portal);
    }
    return;
  }
  auto holds = [&](int i)
  { return this->Portals[i].Left == vertex || this->Portals[i].Right == vertex; };
  const int n = static_cast<int>(this->Portals.size());
  int first = portal, last = portal;
  while (first > 0 && holds(first - 1))
  {
    --first;
  }
  while (last + 1 < n && holds(last + 1))
  {
    ++last;
  }
  PathPoint p;
  p.Point.Location = PointLocation::Vertex;
  p.Point.Id = vertex;
  p.FirstPortal = first;
  p.LastPortal = last;
  this->Points.push_back(p);
}

//------------------------------------------------------------------------------
// Walks the strip portals in order: portals around a corner vertex are crossed at that vertex;
// any other portal is crossed where the straight segment between the surrounding corners
// meets it.
void GeodesicPathSolver::CollectPathPoints(const CanonicalPoint& start, const CanonicalPoint& end)
{
  const TriangleMesh& mesh = this->GetMesh();
  const int m = static_cast<int>(this->Portals.size());
  const int nc = static_cast<int>(this->Corners.size());
  this->Points.clear();
  this->Points.push_back({ start, -1, -1 });

  // Portal ranges of the interior corners (the run of portals holding the corner vertex).
  thread_local std::vector<std::array<int, 2>> ranges;
  thread_local std::vector<char> emitted;
  ranges.assign(nc, { 0, -1 });
  emitted.assign(nc, 0);
  for (int c = 1; c + 1 < nc; ++c)
  {
    const int v = this->Corners[c].Vertex;
    int first = this->Corners[c].Portal - 1, last = first;
    auto holds = [&](int i) { return this->Portals[i].Left == v || this->Portals[i].Right == v; };
    while (first > 0 && holds(first - 1))
    {
      --first;
    }
    while (last + 1 < m && holds(last + 1))
    {
      ++last;
    }
    ranges[c] = { first, last };
  }

  int j = 0; // current segment: corner j -> corner j + 1
  for (int i = 0; i < m; ++i)
  {
    while (j + 1 < nc - 1 && i > ranges[j + 1][1])
    {
      if (!emitted[j + 1])
      {
        this->EmitVertex(this->Corners[j + 1].Vertex, ranges[j + 1][1]);
      }
      ++j;
    }
    if (j + 1 < nc - 1 && i >= ranges[j + 1][0])
    {
      this->EmitVertex(this->Corners[j + 1].Vertex, i);
      emitted[j + 1] = 1;
      continue;
    }
    const Portal& portal = this->Portals[i];
    const Vec2 a = this->Corners[j].Position;
    const Vec2 d = this->Corners[j + 1].Position - a;
    const Vec2 span = portal.RightPosition - portal.LeftPosition;
    const double denominator = Cross(span, d);
    double t = denominator != 0.0 ? Cross(a - portal.LeftPosition, d) / denominator : 0.0;
    if (!(t > VertexSnap)) // also catches NaN from a degenerate segment
    {
      this->EmitVertex(portal.Left, i);
    }
    else if (t >= 1.0 - VertexSnap)
    {
      this->EmitVertex(portal.Right, i);
    }
    else
    {
      PathPoint p;
      p.Point.Location = PointLocation::Edge;
      p.Point.Id = portal.Edge;
      p.Point.T = mesh.GetEdgeVertices(portal.Edge)[0] == portal.Left ? t : 1.0 - t;
      this->Points.push_back(p);
    }
  }
  for (int c = j + 1; c + 1 < nc; ++c)
  {
    if (!emitted[c])
    {
      this->EmitVertex(this->Corners[c].Vertex, ranges[c][1]);
    }
  }
  if (!(this->Points.back().Point == end))
  {
    this->Points.push_back({ end, -1, -1 });
  }
}

//------------------------------------------------------------------------------
double GeodesicPathSolver::OutsideAngle(int v,
  const Vec3& before,
  const Vec3& after,
  int first,
  int second,
  int last,
  std::vector<int>& swept) const
{
  const TriangleMesh& mesh = this->GetMesh();
  swept.clear();
  const Vec3 center = mesh.GetPosition(v);
  const Vec3 in = before - center;
  const Vec3 out = after - center;
  const Triangle& firstTri = mesh.GetTriangle(first);
  const int kv = CornerOf(firstTri, v);
  if (kv < 0)
  {
    return -1.0;
  }
  // The two edges of `first` at v are local edges kv (v -> next) and kv + 2 (previous -> v);
  // leave through the one that does not lead back into the strip.
  int edge = mesh.GetNeighbor(first, kv) == second ? (kv + 2) % 3 : kv;
  int other = edge == kv ? firstTri[(kv + 1) % 3] : firstTri[(kv + 2) % 3];
  double angle = AngleBetween(in, mesh.GetPosition(other) - center);
  int current = first;
  const int limit = mesh.GetVertexCorners(v).size();
  for (int steps = 0; steps <= limit; ++steps)
  {
    const int next = mesh.GetNeighbor(current, edge);
    if (next < 0)
    {
      return -1.0; // boundary (or non-manifold edge): the outside is not surface
    }
    if (next == last)
    {
      return angle + AngleBetween(mesh.GetPosition(other) - center, out);
    }
    const int entry = mesh.GetNeighborEdge(current, edge);
    const Triangle& tri = mesh.GetTriangle(next);
    const int kn = CornerOf(tri, v);
    if (kn < 0)
    {
      return -1.0;
    }
    const int exit = entry == kn ? (kn + 2) % 3 : kn;
    const int nextOther = exit == kn ? tri[(kn + 1) % 3] : tri[(kn + 2) % 3];
    angle += AngleBetween(mesh.GetPosition(other) - center, mesh.GetPosition(nextOther) - center);
    swept.push_back(next);
    other = nextOther;
    current = next;
    edge = exit;
  }
  return -1.0;
}

//------------------------------------------------------------------------------
bool GeodesicPathSolver::RerouteAroundVertices()
{
  const TriangleMesh& mesh = this->GetMesh();
  this->NewStrip.clear();
  int copied = 0; // Strip[0, copied) is already in NewStrip
  bool changed = false;
  const int np = static_cast<int>(this->Points.size());
  for (int k = 1; k + 1 < np; ++k)
  {
    const PathPoint& p = this->Points[k];
    if (p.Point.Location != PointLocation::Vertex || p.FirstPortal < copied)
    {
      continue;
    }
    const int a = p.FirstPortal, b = p.LastPortal;
    const double angle = this->OutsideAngle(p.Point.Id,
      PositionOf(mesh, this->Points[k - 1].Point),
      PositionOf(mesh, this->Points[k + 1].Point),
      this->Strip[a],
      this->Strip[a + 1],
      this->Strip[b + 1],
      this->Swept);
    if (angle < 0.0 || angle >= Pi - AngleTolerance)
    {
      continue;
    }
    this->NewStrip.insert(
      this->NewStrip.end(), this->Strip.begin() + copied, this->Strip.begin() + a + 1);
    this->NewStrip.insert(this->NewStrip.end(), this->Swept.begin(), this->Swept.end());
    copied = b + 1;
    changed = true;
  }
  if (!changed)
  {
    return false;
  }
  this->NewStrip.insert(this->NewStrip.end(), this->Strip.begin() + copied, this->Strip.end());
  // Two rerouted vertices joined by an edge both sweep across that edge, leaving a spur
  // x, y, x in the strip (a step into y and straight back). Spurs hold no path: drop them.
  this->Strip.clear();
  for (int t : this->NewStrip)
  {
    const size_t n = this->Strip.size();
    if (n >= 2 && this->Strip[n - 2] == t)
    {
      this->Strip.pop_back();
    }
    else if (n == 0 || this->Strip[n - 1] != t)
    {
      this->Strip.push_back(t);
    }
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

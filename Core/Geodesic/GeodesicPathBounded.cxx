// The Bounded method's policy (GeodesicPathSolver, see GeodesicPath.h): when the exact window
// search is not started or runs out of its budget, the leg is routed on the surface's site
// graph and straightened; the other candidates here (other routes, the straightened shortest
// edge path, the exact search inside corridors round them) make it the shortest in practice.
#include "Geodesic/GeodesicPath.h"

#include <algorithm>
#include <cmath>

namespace boolsurf
{

//------------------------------------------------------------------------------
// The candidates of a routed leg, each kept when shorter: other routes, then on meshes up to
// MaximumVerticesForEdgeCandidate vertices the straightened shortest edge path and the exact
// search inside corridors round the candidates.
void GeodesicPathSolver::ImproveRoutedLeg(const CanonicalPoint& start,
  const CanonicalPoint& end,
  GeodesicPath& path)
{
  const bool small = this->GetMesh().GetNumberOfVertices() <= MaximumVerticesForEdgeCandidate;
  this->Candidates.emplace_back(path.Length, path.Points);
  this->TryAlternativeRoutes(start, end, path);
  if (small)
  {
    this->TryEdgePathCandidate(start, end, path);
  }
  if (small && this->Options.CorridorRefinement)
  {
    this->RefineInCorridor(start, end, path);
  }
}

//------------------------------------------------------------------------------
double EstimateMeanEdgeLength(const TriangleMesh& mesh)
{
  // An estimate is all ExceedsBoundedWindows needs: every edge up to 2^16 of them, else a
  // fixed stride through the edge list (a full pass cost 65 ms per solver on 4.3M triangles).
  const int ne = mesh.GetNumberOfEdges();
  const int stride = std::max(1, ne >> 16);
  double sum = 0.0;
  int count = 0;
  for (int e = 0; e < ne; e += stride, ++count)
  {
    const std::array<int, 2> v = mesh.GetEdgeVertices(e);
    sum += Distance(mesh.GetPosition(v[0]), mesh.GetPosition(v[1]));
  }
  return count > 0 ? sum / count : 0.0;
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
    this->MeanEdgeLength = EstimateMeanEdgeLength(mesh);
  }
  if (!(this->MeanEdgeLength > 0.0))
  {
    return false;
  }
  const double ratio =
    Distance(PositionOf(mesh, start), PositionOf(mesh, end)) / this->MeanEdgeLength;
  return 1.6 * ratio * ratio > 2.0 * this->Options.BoundedWindows;
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
  if (!(this->Options.RouteTolerance > 0.0) || n - 2 * margin <= 0)
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
    if (!routed || route > (1.0 + this->Options.RouteTolerance) * firstRoute ||
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
  for (const StripStraightener::PathPoint& p : this->Straightener.GetPoints())
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

} // namespace boolsurf

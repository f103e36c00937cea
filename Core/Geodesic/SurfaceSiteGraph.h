// A coarse graph of a surface that routes far geodesic legs at a bounded cost.
//
// The exact window search (ExactGeodesicSearch) explores the ellipse {x : d(s,x) + |x t| <
// d(s,t)}, which for far points on a closed scan is most of the mesh; the shortest mesh-edge
// path (EdgeGraphSearch) explores a ball around each end. Both cost O(mesh) for far pairs.
// This graph is built once per surface and answers "which way round" in O(sites):
//
// - Sites: a maximal set of mesh vertices pairwise more than `hops` edges apart, chosen
//   greedily in a fixed pseudo-random order (deterministic: the same mesh gives the same
//   graph). Every vertex is within `hops` edges of a site.
// - Cells: each vertex belongs to the site nearest along mesh edges (multi-source Dijkstra),
//   with its parent on that shortest path, so every vertex has a mesh-edge path to its site.
// - Arcs: two cells are adjacent when a mesh edge (u, v) joins them; the arc's length is
//   the shortest site-to-site path through such an edge, d(a, u) + |uv| + d(v, b), and the
//   arc remembers that edge.
//
// A route is an A* search over the sites (straight-line bound to the end point, admissible
// because no step is shorter than the straight distance it spans) expanded into a mesh-edge
// path: start -> a corner of
// its triangle -> up its cell's parents to the site -> along each arc's edge path -> down to
// a corner of the end's triangle -> end, with any loop cut out. The caller straightens it
// (funnel and vertex rerouting), which keeps its homotopy class except across mesh vertices:
// the graph decides the class, the straightening the exact path within it.
//
// Cost: building is a few passes over the mesh (about 16 bytes per vertex); a route costs
// O(S log S) for S sites plus the length of the path, whatever the distance between its ends.
// Steps: an arc to an adjacent cell's site (its straight length), or two arcs at once, a -> m
// -> b, whose length is the two arcs unfolded into m's tangent plane (the angle between them
// seen along the normal of m's cell), never below |ab|. Single arcs turn only where cells
// meet, about every 60 degrees, and a route of them zigzags 5-7 % longer than the geodesic
// (5.5 % on average, 8.5 % at worst between far sites of a jittered flat square); two-arc
// steps turn every 30 degrees or less: 0.9 % on average, 2 % at worst. Unfolding at the middle
// site keeps a step over a ridge as long as its two arcs, where the straight distance would
// cut through the ridge.
//
// What it gives up: a route is still a little longer or shorter than the geodesic it stands
// for, so where two homotopy classes (or the two sides of a bump) differ in length by less
// than that, the route may pick the longer one (see GeodesicPathSolver: it then straightens
// other routes too and keeps the shortest).
#ifndef boolsurf_SurfaceSiteGraph_h
#define boolsurf_SurfaceSiteGraph_h

#include "Geodesic/EdgeGraphSearch.h"
#include "Mesh/TriangleMesh.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace boolsurf
{

class SurfaceSiteGraph
{
public:
  /// Builds the graph of `mesh` (which must outlive it); sites are more than `hops` mesh edges
  /// apart (0: DefaultHops()).
  explicit SurfaceSiteGraph(const TriangleMesh& mesh, int hops = 0);

  /// Hops between sites for a mesh of `vertices` vertices: the cells grow with the mesh (about
  /// sqrt(V) / 40 edges across, at most 8: about 100 vertices per cell on 1M triangles), so a
  /// small mesh still has hundreds of sites and a large one a few thousand.
  static int DefaultHops(int vertices);

  /// The graph of `mesh`, shared by every caller on the same mesh (keyed by the mesh's serial
  /// number, held as long as one caller holds it) and built on first request.
  static std::shared_ptr<const SurfaceSiteGraph> Get(const TriangleMesh& mesh);
  /// The graph of `mesh` if one is held, else null (never builds).
  static std::shared_ptr<const SurfaceSiteGraph> Find(const TriangleMesh& mesh);

  /// Per-caller search state (a graph is shared read-only between threads).
  struct Scratch
  {
    std::vector<double> Cost;
    std::vector<int> Parent, ArcIn, Source;
    std::vector<int> SecondArc; // two-site step: the arc from the middle site, else -1
    std::vector<std::uint32_t> Stamp;
    std::uint32_t Generation = 0;
    std::vector<std::pair<double, int>> Heap;
    std::vector<int> Position; // mesh-sized, for cutting loops
    std::vector<std::uint32_t> PositionStamp;
    std::uint32_t PositionGeneration = 0;
    std::vector<int> Sites; // the last route's sites, start to end
    std::vector<int> Arcs;  // Arcs[i]: the arc into Sites[i] (-1 for the first)
  };

  /// A mesh-edge path from the point `from` (joined to the mesh vertices of `sources`) to the
  /// point `to` (joined to `targets`) along the cheapest route of sites; `vertices` receives
  /// its mesh vertices (consecutive ones share an edge, none repeats). Sites flagged in
  /// `avoid` (size GetNumberOfSites(), or empty) are not crossed, except the cells of the
  /// ends. Returns the route's length (an estimate of the geodesic distance, within a few percent),
  /// or a negative value when the ends are not connected.
  double FindRoute(const std::vector<EdgeGraphSearch::Terminal>& sources,
    const Vec3& from,
    const std::vector<EdgeGraphSearch::Terminal>& targets,
    const Vec3& to,
    const std::vector<char>& avoid,
    Scratch& scratch,
    std::vector<int>& vertices) const;

  /// Sets flags[w] for every site w within `radius` of one of `seeds` along arcs.
  void FlagWithin(const std::vector<int>& seeds, double radius, std::vector<char>& flags) const;

  /// Sets flags[s] and flags[w] for every site w adjacent to site s.
  void FlagNeighbourhood(int s, std::vector<char>& flags) const;

  /// True when every connected component is a closed surface of genus 0 (MeshTopology). There
  /// a second route measured no better than the first (it runs beside it and straightens to
  /// the same geodesic) while doubling the cost; handles and holes are where it pays.
  bool IsAllSpheres() const { return this->AllSpheres; }

  int GetNumberOfSites() const { return static_cast<int>(this->Sites.size()); }
  int GetNumberOfArcs() const { return static_cast<int>(this->ArcTarget.size()); }
  /// The mesh vertex of site s.
  int GetSite(int s) const { return this->Sites[s]; }
  /// The site whose cell holds mesh vertex v (-1 for a vertex of no usable triangle).
  int GetCell(int v) const { return this->Cell[v]; }
  double GetBuildSeconds() const { return this->BuildSeconds; }
  std::size_t GetMemory() const;
  std::uint64_t GetMeshSerial() const { return this->MeshSerial; }
  /// Distinct for every graph built in this process (1, 2, ...): tells a rebuilt graph apart.
  std::uint64_t GetBuildNumber() const { return this->BuildNumber; }

private:
  void ChooseSites(const std::vector<int>& offsets, const std::vector<int>& neighbors, int hops);
  void GrowCells(const std::vector<int>& offsets, const std::vector<int>& neighbors);
  void BuildArcs(const std::vector<int>& offsets, const std::vector<int>& neighbors);
  void ComputeSiteNormals();
  /// Length of the step a -> m -> b over two arcs: the two arcs unfolded into m's tangent plane
  /// (the angle between them as seen along m's normal), never below the straight distance.
  double TwoArcLength(int a, int m, int b) const;
  /// Appends v's parents up to its site (v first), or the reverse (site first) when `down`.
  void AppendChain(int v, bool down, std::vector<int>& out) const;

  const TriangleMesh& Mesh;
  std::uint64_t MeshSerial = 0;
  std::vector<int> Sites;           // site -> mesh vertex
  std::vector<int> Cell;            // mesh vertex -> site (-1: unused vertex)
  std::vector<int> Parent;          // mesh vertex -> next vertex towards its site (-1 at sites)
  std::vector<double> SiteDistance; // mesh vertex -> edge-path distance to its site
  std::vector<int> ArcOffsets;      // CSR over sites
  std::vector<int> ArcTarget;
  std::vector<double> ArcLength;
  std::vector<int> ArcFrom, ArcTo; // the mesh edge (u in the source cell, v in the target's)
  std::vector<Vec3> SiteNormal;    // unit area-weighted normal of the site's cell (0: none)
  double BuildSeconds = 0;
  std::uint64_t BuildNumber = 0;
  bool AllSpheres = false;
};

} // namespace boolsurf

#endif

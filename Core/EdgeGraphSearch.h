// Shortest path along mesh edges between two surface points: the seed of a geodesic path.
//
// The primal graph has one node per mesh vertex and one arc per mesh edge (of usable
// triangles), weighted by the edge length. The start point is joined to the corners of the
// triangles holding it, the corners of the triangles holding the end point are joined to
// it, each by the straight segment inside that triangle. A* with the straight-line distance
// to the end point is exact (the bound is admissible and consistent: every arc is a straight
// segment), so the path found is the shortest edge path, exactly what
// vtkDijkstraGraphGeodesicPath returns between two vertices.
//
// The search is bidirectional (A* from both ends with the average potential of Ikeda et al.,
// which keeps both searches consistent): on a curved surface the straight-line bound is weak
// and each direction settles roughly a ball around its end, so two balls of half the radius
// cost about half of one ball of the full radius.
//
// The search state is sized to the mesh once and stamped per query (nothing mesh-sized is
// cleared per call), so a short path costs what its neighbourhood costs. Internally vertices
// are renumbered along a Morton (Z-order) curve and each one's search state and position
// share a cache line: a long search touches a large part of the mesh, and in file order
// (e.g. after subdivision) neighbours are far apart in memory.
#ifndef boolsurf_EdgeGraphSearch_h
#define boolsurf_EdgeGraphSearch_h

#include "TriangleMesh.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace boolsurf
{

class EdgeGraphSearch
{
public:
  /// Builds the vertex adjacency (compressed rows, edge lengths precomputed) of `mesh`, which
  /// must outlive this object.
  explicit EdgeGraphSearch(const TriangleMesh& mesh);

  /// A graph end: a vertex and the length of the straight segment joining it to the point.
  struct Terminal
  {
    int Vertex = -1;
    double Cost = 0.0;
  };

  /// Shortest path from the point `from` (joined to `sources`) to the point `to` (joined to
  /// `targets`) through mesh edges. `vertices` receives the mesh vertices of the path in order
  /// (at least one). Returns the path length (from `from` to `to`), or a negative value when
  /// no target is reachable.
  double FindPath(const std::vector<Terminal>& sources,
    const Vec3& from,
    const std::vector<Terminal>& targets,
    const Vec3& to,
    std::vector<int>& vertices);

  /// Vertices taken off the open sets by the last FindPath (a measure of its cost).
  int GetLastSettledCount() const { return this->LastSettled; }

  const TriangleMesh& GetMesh() const { return this->Mesh; }

private:
  struct alignas(64) Node
  {
    Vec3 Position;
    double Cost[2];     // from the start point (0) / to the end point (1)
    int Parent[2];      // previous vertex (internal id) towards the start (0) / end (1), or -1
    std::uint32_t Seen; // == Generation: Cost/Parent valid (per direction: SeenMask)
    std::uint8_t SeenMask, ClosedMask;
  };

  void NextGeneration();

  const TriangleMesh& Mesh;
  std::vector<int> Internal, External; // mesh id <-> internal (Morton-ordered) id
  std::vector<int> Offsets;            // size V + 1, internal ids
  std::vector<int> Neighbors;          // Neighbors[Offsets[v] .. Offsets[v + 1])
  std::vector<double> EdgeCosts;       // parallel to Neighbors
  std::vector<Node> Nodes;
  std::uint32_t Generation = 0;
  std::vector<std::pair<double, int>> Heaps[2]; // (key, vertex); min-heaps
  int LastSettled = 0;
};

} // namespace boolsurf

#endif

// Shortest chain of edge-adjacent triangles between two surface points: the initial triangle
// strip of a geodesic path.
//
// The dual graph has one node per triangle (at its centroid) and one arc per manifold edge,
// weighted by the distance between the centroids. A* with the straight-line distance to the
// end point as lower bound explores only a band around the path instead of the whole mesh.
// The search state (costs, parents, visit stamps) is sized to the mesh once and reused: a
// generation counter marks which entries belong to the current search, so nothing mesh-sized
// is cleared or allocated per query and a short path on a 1M-triangle mesh costs what its
// band costs.
#ifndef boolsurf_DualGraphSearch_h
#define boolsurf_DualGraphSearch_h

#include "Mesh/TriangleMesh.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace boolsurf
{

class DualGraphSearch
{
public:
  /// Precomputes the centroids of `mesh`, which must outlive this object.
  explicit DualGraphSearch(const TriangleMesh& mesh);

  /// Shortest dual path from any of `sources` (triangles holding the start point `from`) to
  /// any of `targets` (triangles holding the end point `to`), written to `strip` in order.
  /// Returns false when no target is reachable.
  bool FindStrip(const std::vector<int>& sources,
    const Vec3& from,
    const std::vector<int>& targets,
    const Vec3& to,
    std::vector<int>& strip);

  /// Triangles taken off the open set by the last FindStrip (a measure of its cost).
  int GetLastExpandedCount() const { return this->LastExpanded; }

  const TriangleMesh& GetMesh() const { return this->Mesh; }

  /// Factor on the straight-line bound. 1 keeps A* exact (the cheapest dual chain); above 1
  /// the search goes greedily toward the end point and settles far fewer triangles, at the
  /// price of a strip that may need more straightening rounds.
  void SetHeuristicWeight(double w) { this->HeuristicWeight = w; }
  double GetHeuristicWeight() const { return this->HeuristicWeight; }

private:
  struct Node
  {
    double Cost = 0.0; // from the start point to the centroid
    int Parent = -1;
    std::uint32_t Visited = 0; // == Generation: Cost/Parent are valid in this search
    std::uint32_t Closed = 0;  // == Generation: settled
    std::uint32_t Target = 0;  // == Generation: holds the end point
  };

  void NextGeneration();

  const TriangleMesh& Mesh;
  std::vector<Vec3> Centroids;
  std::vector<Node> Nodes;
  std::uint32_t Generation = 0;
  std::vector<std::pair<double, int>> Heap; // (estimated total cost, triangle); min-heap
  int LastExpanded = 0;
  double HeuristicWeight = 1.0;
};

} // namespace boolsurf

#endif

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
// Landmarks (ALT, Goldberg and Harrelson): a few vertices, chosen farthest-point, with the
// edge-graph distance from each to every vertex, computed once per mesh. By the triangle
// inequality |d_l(v) - d_l(t)| bounds d(v, t) from below; the potential of each direction is
// the largest of these bounds and the straight-line distance. On curved surfaces the landmark
// bound is much tighter than the straight line (it follows the surface), so far fewer
// vertices are settled. Exactness does not depend on the bounds being tight, only on the
// potentials being 1-Lipschitz along every edge (consistent): the distances are stored as
// floats computed by a Dijkstra that rounds every sum down, so d_l(w) <= d_l(u) + |uw| holds
// for the stored values themselves, not only up to float rounding. Each landmark slot holds
// one landmark per connected component (a multi-source search), so every vertex has a finite
// value in every slot. The table is built lazily (see SetLandmarkBuildThreshold).
//
// The search state is sized to the mesh once and stamped per query (nothing mesh-sized is
// cleared per call), so a short path costs what its neighbourhood costs. Internally vertices
// are renumbered along a Morton (Z-order) curve and each one's search state and position
// share a cache line: a long search touches a large part of the mesh, and in file order
// (e.g. after subdivision) neighbours are far apart in memory.
#ifndef boolsurf_EdgeGraphSearch_h
#define boolsurf_EdgeGraphSearch_h

#include "Mesh/TriangleMesh.h"

#include <algorithm>
#include <cstddef>
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

  /// Landmarks per connected component (default 16; 0 disables ALT). Drops a built table.
  void SetNumberOfLandmarks(int n);
  int GetNumberOfLandmarks() const { return this->LandmarkCount; }

  /// Landmarks used per query (default 16, all of them): those with the best bounds on the distance
  /// between its two ends.
  void SetNumberOfActiveLandmarks(int n) { this->ActiveLandmarks = std::max(1, n); }

  /// The landmark table is built once the searches so far have settled this many times as
  /// many vertices as the build does (one full search per landmark, plus one). Default 1: a
  /// session of short paths never pays for the table, and a session of long ones spends at
  /// most as much on searches before it as the build costs (ski rental: never more than twice
  /// the better choice in hindsight). 0 builds on first use.
  void SetLandmarkBuildThreshold(double timesVertices) { this->BuildThreshold = timesVertices; }
  double GetLandmarkBuildThreshold() const { return this->BuildThreshold; }

  /// Builds the landmark table now (no-op when built or disabled).
  void BuildLandmarks();
  bool HasLandmarks() const { return !this->Landmarks.empty(); }
  /// CPU seconds the landmark table took to build (0 until built).
  double GetLandmarkBuildSeconds() const { return this->LandmarkSeconds; }
  /// Bytes held by the landmark table.
  std::size_t GetLandmarkMemory() const { return this->Landmarks.size() * sizeof(float); }

private:
  struct alignas(64) Node
  {
    Vec3 Position;
    double Cost[2];     // from the start point (0) / to the end point (1)
    int Parent[2];      // previous vertex (internal id) towards the start (0) / end (1), or -1
    std::uint32_t Seen; // == Generation: Cost/Parent/Potential valid (per direction: SeenMask)
    std::uint8_t SeenMask, ClosedMask;
    double Potential; // forward potential of this query (the backward one is its negation)
  };

  /// Monotone priority queue of (key, vertex) (a radix heap on the keys' bit patterns): keys
  /// pushed are never below the last key taken off (a consistent potential guarantees that;
  /// rounding noise below it is clamped), push is O(1) and a pop moves each entry down at most
  /// 64 buckets in all. Cheaper than a comparison heap for the long searches.
  class RadixQueue
  {
  public:
    void Clear();
    bool Empty() const { return this->Size == 0; }
    void Push(double key, int vertex);
    /// Smallest entry (the queue must not be empty).
    const std::pair<double, int>& Top();
    void Pop();

  private:
    static std::uint64_t Bits(double key);
    std::vector<std::pair<double, int>> Buckets[65];
    double Last = 0;
    std::uint64_t LastBits = 0;
    std::size_t Size = 0;
  };

  void NextGeneration();
  /// Dijkstra from `sources` (internal ids) over all vertices, rounding sums down to float.
  void LandmarkDistances(const std::vector<int>& sources, std::vector<float>& distance);

  const TriangleMesh& Mesh;
  std::vector<int> Internal, External; // mesh id <-> internal (Morton-ordered) id
  std::vector<int> Offsets;            // size V + 1, internal ids
  std::vector<int> Neighbors;          // Neighbors[Offsets[v] .. Offsets[v + 1])
  std::vector<double> EdgeCosts;       // parallel to Neighbors
  std::vector<Node> Nodes;
  std::uint32_t Generation = 0;
  RadixQueue Heaps[2];
  int LastSettled = 0;

  int LandmarkCount = 16;
  double BuildThreshold = 1.0;
  double SettledSinceStart = 0; // towards BuildThreshold
  double LandmarkSeconds = 0;
  std::vector<float> Landmarks; // Landmarks[v * LandmarkCount + l], internal ids
  int ActiveLandmarks = 16;
  std::vector<int> Active;    // per query: the landmarks used
  std::vector<double> Bounds; // per query: per active landmark, hi/lo of the end, then start
  std::vector<std::pair<double, int>> Scores;
};

} // namespace boolsurf

#endif

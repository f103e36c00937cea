// Triangle mesh with the adjacency every BoolSurf stage relies on.
//
// Conventions (part of the Core API, used by tracing and arrangement):
//  * Corner k of triangle t has the id 3*t + k ("corner id").
//  * Local edge k of triangle t joins corner k to corner (k+1)%3; the half-edge that runs
//    along it has the same id as the corner it starts from.
//  * A surface point inside triangle t has barycentric (u, v): the weights of corners 1 and 2.
//  * Every undirected edge has an id in [0, GetNumberOfEdges()); both triangles sharing it
//    report the same id.
//
// The adjacency is the base of the dual graph of adjacencies (one node per triangle, one arc
// per interior edge). It is built in time linear in the mesh size: vertex -> corners by a
// counting sort, then each half-edge finds its twin among the corners of its first vertex.
#ifndef boolsurf_TriangleMesh_h
#define boolsurf_TriangleMesh_h

#include "Mesh/Vec3.h"

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace boolsurf
{

using Triangle = std::array<int, 3>;

/// Contiguous read-only run of ints (a C++17 stand-in for std::span<const int>).
struct IntRange
{
  const int* First = nullptr;
  const int* Last = nullptr;
  const int* begin() const { return First; }
  const int* end() const { return Last; }
  int size() const { return static_cast<int>(Last - First); }
  int operator[](int i) const { return First[i]; }
};

/// An edge shared by more than two triangles.
struct NonManifoldEdge
{
  int V0 = -1, V1 = -1;       ///< vertex ids of the edge
  std::vector<int> Triangles; ///< every triangle that has this edge
};

/// Two neighbouring triangles that traverse their common edge in the same direction.
struct MisorientedEdge
{
  int V0 = -1, V1 = -1;
  int Triangle0 = -1, Triangle1 = -1;
};

class TriangleMesh
{
public:
  TriangleMesh() = default;

  /// Builds the adjacency. Triangles whose indices are out of range or repeated are kept (so
  /// triangle ids stay those of the input) but take no part in the topology: see IsUsable().
  TriangleMesh(std::vector<Vec3> positions, std::vector<Triangle> triangles);

  /// A number no other mesh built in this process has (0 for an empty default mesh): lets
  /// consumers that keep buffers derived from a mesh tell whether it is still the same one,
  /// where a pointer could be reused by a new mesh at the same address.
  std::uint64_t GetSerial() const { return this->Serial; }

  int GetNumberOfVertices() const { return static_cast<int>(this->Positions.size()); }
  int GetNumberOfTriangles() const { return static_cast<int>(this->Triangles.size()); }
  int GetNumberOfEdges() const { return static_cast<int>(this->EdgeHalfEdge.size()); }

  const std::vector<Vec3>& GetPositions() const { return this->Positions; }
  const std::vector<Triangle>& GetTriangles() const { return this->Triangles; }
  const Vec3& GetPosition(int v) const { return this->Positions[v]; }
  const Triangle& GetTriangle(int t) const { return this->Triangles[t]; }
  /// Position of corner k of triangle t.
  const Vec3& GetCornerPosition(int t, int k) const
  {
    return this->Positions[this->Triangles[t][k]];
  }
  /// Point of triangle t at barycentric (u, v) (weights of corners 1 and 2).
  Vec3 Evaluate(int t, double u, double v) const;

  /// False for triangles with out-of-range or repeated vertex indices.
  bool IsUsable(int t) const { return this->Usable[t] != 0; }

  ///@{
  /// Neighbour across local edge k of triangle t, and the local index of that edge in it;
  /// -1 on a boundary edge, a non-manifold edge, or for an unusable triangle.
  int GetNeighbor(int t, int k) const
  {
    int h = this->Twin[3 * t + k];
    return h < 0 ? -1 : h / 3;
  }
  int GetNeighborEdge(int t, int k) const
  {
    int h = this->Twin[3 * t + k];
    return h < 0 ? -1 : h % 3;
  }
  /// Twin half-edge (corner id) of half-edge h, or -1.
  int GetTwin(int h) const { return this->Twin[h]; }
  ///@}

  ///@{
  /// Undirected edge ids. GetEdgeHalfEdge(e) is the half-edge of the lowest triangle id on e;
  /// GetEdgeVertices(e) follows that half-edge's direction.
  int GetEdgeId(int t, int k) const
  {
    // Derived, not stored (a mesh-sized array, 52 MB on 4.3M triangles): an edge's id is the
    // number of edges whose lowest half-edge is below its own (see EdgeRank).
    const int h = 3 * t + k;
    const int twin = this->Twin[h];
    return twin >= 0 ? this->RankOfOwner(twin < h ? twin : h) : this->GetLooseEdgeId(h);
  }
  int GetEdgeHalfEdge(int e) const { return this->EdgeHalfEdge[e]; }
  std::array<int, 2> GetEdgeVertices(int e) const
  {
    // Inline: the exact geodesic search calls it for every window it creates.
    const int h = this->EdgeHalfEdge[e];
    const Triangle& tri = this->Triangles[h / 3];
    return { tri[h % 3], tri[(h % 3 + 1) % 3] };
  }
  /// Number of triangles on edge e (1 on the boundary, 2 inside, more if non-manifold).
  /// (Derived: 2 where the edge has a twin pair, else 1 or the non-manifold edge's count; no
  /// per-edge array.)
  int GetEdgeValence(int e) const;
  bool IsBoundaryEdge(int e) const { return this->GetEdgeValence(e) == 1; }
  ///@}

  /// Corner ids (3*t + k) at vertex v, in increasing order. Empty for unreferenced vertices.
  IntRange GetVertexCorners(int v) const
  {
    const int* base = this->CornerList.data();
    return { base + this->CornerOffset[v], base + this->CornerOffset[v + 1] };
  }

  ///@{
  /// Problems met while building the adjacency. Non-manifold edges have no neighbours;
  /// misoriented neighbours stay neighbours (the topology is still computable) but the
  /// mesh is unfit for winding numbers.
  const std::vector<NonManifoldEdge>& GetNonManifoldEdges() const { return this->NonManifold; }
  const std::vector<MisorientedEdge>& GetMisorientedEdges() const { return this->Misoriented; }
  ///@}

private:
  void BuildVertexCorners();
  void BuildTwins();
  /// Edge id of a half-edge with no twin: a boundary or non-manifold edge, or -1 in an
  /// unusable triangle.
  int GetLooseEdgeId(int h) const;
  /// Id of the edge whose lowest half-edge is `owner`: the owners below it, counted from
  /// EdgeRank.
  int RankOfOwner(int owner) const
  {
    const OwnerBlock& block = this->EdgeRank[owner >> 6];
    std::uint64_t x = block.Owners & ((std::uint64_t(1) << (owner & 63)) - 1);
    // Bits set, inline (the build does not assume the popcnt instruction).
    x -= (x >> 1) & 0x5555555555555555ULL;
    x = (x & 0x3333333333333333ULL) + ((x >> 2) & 0x3333333333333333ULL);
    x = (x + (x >> 4)) & 0x0f0f0f0f0f0f0f0fULL;
    return block.FirstEdge + static_cast<int>((x * 0x0101010101010101ULL) >> 56);
  }

  /// 64 half-edges: a bit for each that is the lowest half-edge of its edge (edge ids follow
  /// those owners' order), and the id of the first edge owned in the block.
  struct OwnerBlock
  {
    std::uint64_t Owners = 0;
    int FirstEdge = 0;
  };

  std::uint64_t Serial = 0;
  std::vector<Vec3> Positions;
  std::vector<Triangle> Triangles;
  std::vector<char> Usable;
  std::vector<int> CornerOffset;    // size V+1
  std::vector<int> CornerList;      // corner ids grouped by vertex
  std::vector<int> Twin;            // size 3T, -1 when none
  std::vector<OwnerBlock> EdgeRank; // size 3T / 64, rounded up
  std::vector<std::pair<int, int>>
    NonManifoldHalfEdge;         // (half-edge, edge), ascending, owners' partners
  std::vector<int> EdgeHalfEdge; // size E
  std::vector<std::pair<int, int>> NonManifoldValence; // (edge, valence), ascending edges
  std::vector<NonManifoldEdge> NonManifold;
  std::vector<MisorientedEdge> Misoriented;
};

} // namespace boolsurf

#endif

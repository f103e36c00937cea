// One piece of a surface split across processes (the distributed arrangement of
// Docs/Parallel.md, "Plan for a distributed arrangement"): the triangles a piece owns plus one
// ring of ghost triangles owned by other pieces, as a TriangleMesh of its own.
//
// Local numbering keeps the global order: local triangles are the piece's triangles sorted by
// global id, local vertices its points sorted by global id. Every tie the arrangement breaks by
// triangle or vertex id (slot order, the lowest triangle of an edge giving the edge's
// direction, a cell's lowest refined triangle) therefore breaks the same way on a piece as on
// the whole surface, for every triangle whose neighbours the piece has: its owned triangles.
//
// Cost: O(n log n) for the piece's n triangles and points (two sorts), then the TriangleMesh
// adjacency; nothing proportional to the whole surface.
#ifndef boolsurf_PieceMesh_h
#define boolsurf_PieceMesh_h

#include "Mesh/TriangleMesh.h"

#include <string>
#include <vector>

namespace boolsurf
{

/// A piece as it arrives (a process's part of a split surface, e.g. a VTK piece with its
/// GlobalIds and ghost marks): points and triangles in any order, each with its global id.
struct PieceInput
{
  std::vector<Vec3> Positions;
  std::vector<int> PointGlobalIds;    ///< per point
  std::vector<Triangle> Triangles;    ///< corners index Positions
  std::vector<int> TriangleGlobalIds; ///< per triangle
  std::vector<char> Ghost;            ///< per triangle: 1 for a ghost (owned by another piece)
};

struct PieceMesh
{
  TriangleMesh Mesh;
  std::vector<int> GlobalTriangle; ///< per local triangle, ascending
  std::vector<int> GlobalVertex;   ///< per local vertex, ascending
  std::vector<char> Owned;         ///< per local triangle
  int NumberOfOwnedTriangles = 0;
  /// The owned triangles' sides that an arrangement's summary reads on every update, listed
  /// once with the mesh so an edit does not scan the piece for them (half-edges 3 t + k,
  /// ascending): sides facing another piece's triangle (the piece border), and sides on the
  /// surface's own boundary.
  std::vector<int> BorderHalfEdges;
  std::vector<int> SurfaceBoundaryHalfEdges;

  /// Local id of global triangle (vertex) g, -1 when the piece does not have it: a binary
  /// search (no global-sized table).
  int LocalTriangle(int g) const;
  int LocalVertex(int g) const;
};

/// Builds the piece's mesh (and its lists of sides). Fails, naming the ids, on repeated global
/// ids or corners out of range.
bool BuildPieceMesh(const PieceInput& input, PieceMesh& out, std::string& error);

} // namespace boolsurf

#endif

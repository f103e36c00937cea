// The part of a surface a piece holds for tracing (Core/Distributed/PieceTracing): its own
// triangles with their ring of ghosts, plus triangles fetched from the pieces that own them
// while curves are traced, as one PieceMesh in global order.
//
// What makes a leg traced here the whole surface's leg bit for bit is which vertices are
// whole: a vertex is whole when every triangle of the surface round it is held. The piece's
// own corners are whole (its ghost ring holds the rest of their fans), and a fetch names the
// vertices whose fans it brought entire. Local numbering keeps the global order (PieceMesh),
// so wherever the triangles round a vertex are all held, every neighbour query, edge direction
// and corner order there is the surface's, and every tie the searches break by id breaks the
// same way.
#ifndef boolsurf_PartialSurface_h
#define boolsurf_PartialSurface_h

#include "Distributed/PieceMesh.h"

#include <array>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace boolsurf
{

/// Triangles sent to a piece by their owners, named by the surface's global ids.
struct FetchedTriangles
{
  std::vector<int> TriangleGlobalIds;
  std::vector<std::array<int, 3>> Corners; ///< global vertex ids, in the surface's corner order
  std::vector<int> PointGlobalIds;         ///< every corner's position once
  std::vector<Vec3> Positions;
  /// Global vertices whose every triangle is among these (or already held by the asker).
  std::vector<int> WholeVertices;
};

class PartialSurface
{
public:
  /// A piece as it arrives: owned triangles (Ghost 0) and their ring of ghosts. The owned
  /// triangles' corners are whole.
  explicit PartialSurface(const PieceInput& piece);

  /// Adds fetched triangles (those already held are skipped) and whole vertices. Fails,
  /// naming it, on a triangle whose corners differ from the held copy's.
  bool Add(const FetchedTriangles& fetched, std::string& error);

  /// The held triangles as a mesh, rebuilt after an Add (which invalidates the last one).
  bool Build(std::string& error);
  const PieceMesh& GetPiece() const { return this->Piece; }
  /// Whether local vertex v of the built mesh is whole.
  bool IsWhole(int v) const { return this->WholeLocal[v] != 0; }

  /// Whether local triangle t's corners are whole and so are the corners of the triangles
  /// round them: a search reading t reads what it reads on the whole surface.
  bool IsExactTriangle(int t) const;

  /// The global vertices to fetch whole before the reads `reads` (local triangles of the built
  /// mesh, with repeats) are the whole surface's: the corners of every read triangle and of
  /// every triangle round those corners that are not whole yet. Empty: the reads are exact.
  void FindMissing(const std::vector<int>& reads, std::vector<int>& missing) const;

  /// Held triangles, and how many of them were fetched (not the piece's own or its ring).
  int GetNumberOfTriangles() const { return static_cast<int>(this->Triangles.size()); }
  int GetNumberOfFetchedTriangles() const { return this->Fetched; }
  bool HoldsTriangle(int g) const { return this->Triangles.count(g) != 0; }
  bool IsWholeVertex(int g) const { return this->Whole.count(g) != 0; }

private:
  std::unordered_map<int, std::array<int, 3>> Triangles; // global id -> global corners
  std::unordered_map<int, Vec3> Points;
  std::unordered_set<int> Whole;
  std::unordered_set<int> Owned;
  int Fetched = 0;
  bool Built = false;
  PieceMesh Piece;
  std::vector<char> WholeLocal;
  mutable std::vector<char> Seen;  // FindMissing's marks per local triangle and vertex
  mutable std::vector<char> Exact; // per local triangle: 0 not known yet, 1 exact, 2 not
};

} // namespace boolsurf

#endif

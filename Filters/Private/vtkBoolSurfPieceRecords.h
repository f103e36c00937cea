// What each MPI rank tells the first rank about its piece's border, and the union-find that
// joins the pieces into the undistributed surface's components, vertices and boundary loops
// (a private header of the module; used by vtkBoolSurfDistributedCheck).
//
// A rank's record holds nodes and unions. Nodes: its local components (with their smallest
// global cell id and their counts), its vertex fans at points shared with another rank, those
// shared points, and its pieces of boundary (chains, with their first half-edge and length).
// Unions: a node joined with a node of another rank (a component across a shared edge, with
// the parity of their orientations; fans across a shared edge; a shared point; boundary chains
// meeting at a shared point). Each union is recorded by the lower of the two ranks. Records
// grow with the pieces' border, not with the surface.
#ifndef vtkBoolSurfPieceRecords_h
#define vtkBoolSurfPieceRecords_h

#include "Mesh/MeshTopology.h"

#include <string>
#include <vector>

namespace boolsurf
{

enum PieceUnionKind
{
  ComponentUnion = 0,
  FanUnion = 1,
  VertexUnion = 2,
  ChainUnion = 3,
};

/// Values per entry of PieceRecord's lists.
constexpr int ComponentEntry = 5; ///< min gid, triangles, edges, unshared fans, orientable
constexpr int FanEntry = 2;       ///< component, vertex node
constexpr int ChainEntry = 2;     ///< first half-edge key (3 gid + local edge), component
constexpr int UnionEntry = 5;     ///< kind, local node, other rank, its node, parity

struct PieceRecord
{
  std::vector<long long> Components;
  std::vector<long long> Fans;
  long long VertexNodes = 0;
  std::vector<long long> Chains;
  std::vector<double> ChainLengths; ///< sent apart (doubles)
  std::vector<long long> Unions;
  long long NonManifoldVertices = 0; ///< at points no other rank shares
  /// Problems by kind, as global cell ids (pairs for the orientation).
  std::vector<long long> NonFinite, Repeated, Degenerate, NonManifoldEdges, Misoriented;

  /// Every list but ChainLengths in one array, and back.
  std::vector<long long> Flatten() const;
  static PieceRecord Read(const long long* at);
};

/// The first rank's answer: per rank, the global numbers of its components then of its
/// chains' loops; for every rank, the field data.
struct ResolvedPieces
{
  std::vector<std::vector<long long>> PerRank;
  std::vector<ComponentTopology> Components;
  bool IsManifold = true;
  std::vector<double> LoopLengths;
  std::vector<std::string> Problems;
};

/// The union-find over every rank's record; chain lengths of rank r start at
/// lengths[lengthOffsets[r]].
ResolvedPieces ResolvePieces(const std::vector<PieceRecord>& records,
  const std::vector<double>& lengths,
  const std::vector<long long>& lengthOffsets,
  int maxIds);

} // namespace boolsurf

#endif

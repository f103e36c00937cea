// Global topology of a triangle mesh: connected components, vertex fans, ordered boundary
// loops, Euler characteristic and genus per component.
//
// Components are connected through edges (triangles that only share a vertex belong to
// different components). A vertex is counted once per fan of triangles around it, which is
// the Euler characteristic of the surface with its non-manifold vertices pulled apart; for
// manifold meshes that is the usual V - E + F.
#ifndef boolsurf_MeshTopology_h
#define boolsurf_MeshTopology_h

#include "Mesh/TriangleMesh.h"
#include "Mesh/ZeroPageArray.h"

#include <memory>
#include <vector>

namespace boolsurf
{

struct BoundaryLoop
{
  std::vector<int> Vertices;  ///< in order; the surface is on the left of the walk
  std::vector<int> HalfEdges; ///< HalfEdges[i] runs from Vertices[i] to Vertices[i+1]
  int Component = -1;
  double Length = 0; ///< 3D length of the loop
};

struct ComponentTopology
{
  int Vertices = 0; ///< vertex fans in this component
  int Edges = 0;
  int Triangles = 0;
  int BoundaryLoops = 0;
  int EulerCharacteristic = 0;
  bool Orientable = true;
  /// (2 - BoundaryLoops - EulerCharacteristic) / 2 for an orientable component, else -1.
  int Genus = 0;
};

struct MeshTopology
{
  /// Per triangle, -1 for unusable ones. Zero pages (ZeroPageVector): on a surface of one
  /// component only the unusable triangles' entries take memory.
  ZeroPageVector<int> TriangleComponent;
  std::vector<ComponentTopology> Components;
  std::vector<BoundaryLoop> BoundaryLoops;
  /// Per vertex: its boundary loop + 1, 0 inside or unreferenced (zero pages: only boundary
  /// vertices take memory). Read it with GetVertexBoundaryLoop().
  ZeroPageVector<int> VertexBoundaryLoopPlusOne;
  std::vector<int> NonManifoldVertices; ///< vertices with more than one fan

  /// Boundary loop of vertex v, -1 inside or unreferenced.
  int GetVertexBoundaryLoop(int v) const { return this->VertexBoundaryLoopPlusOne[v] - 1; }

  int GetNumberOfComponents() const { return static_cast<int>(this->Components.size()); }
  int GetEulerCharacteristic() const;

  static MeshTopology Compute(const TriangleMesh& mesh);

  /// Offers `topology`, computed by Compute(mesh), to later callers on the same mesh (held
  /// weakly, by the mesh's serial number: as long as the caller keeps it), so that a structure
  /// built later on the surface (the geodesic site graph) does not compute it again. A topology
  /// already offered for `mesh` is kept.
  static void Share(const TriangleMesh& mesh, const std::shared_ptr<const MeshTopology>& topology);
  /// The topology offered for `mesh` and still held, else null.
  static std::shared_ptr<const MeshTopology> FindShared(const TriangleMesh& mesh);
};

/// The boundary half-edge after boundary half-edge h (a -> b) along its boundary loop, as
/// MeshTopology walks the loops (staying in h's fan at a non-manifold vertex), or -1 where the
/// rotation around b is undefined (a misoriented neighbour). It reads only the triangles around
/// b, so a piece of a surface with every triangle around b walks its loops as the whole does.
int NextBoundaryHalfEdge(const TriangleMesh& mesh, int h);

} // namespace boolsurf

#endif

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
  std::vector<int> TriangleComponent; ///< -1 for unusable triangles
  std::vector<ComponentTopology> Components;
  std::vector<BoundaryLoop> BoundaryLoops;
  std::vector<int> VertexBoundaryLoop;  ///< loop of each vertex, -1 inside or unreferenced
  std::vector<int> VertexFans;          ///< number of triangle fans at each vertex
  std::vector<int> NonManifoldVertices; ///< vertices with more than one fan

  int GetNumberOfComponents() const { return static_cast<int>(this->Components.size()); }
  int GetEulerCharacteristic() const;

  static MeshTopology Compute(const TriangleMesh& mesh);
};

} // namespace boolsurf

#endif

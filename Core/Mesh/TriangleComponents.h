// Connected components of a mesh's usable triangles through manifold edges (the arcs of the
// dual graph every geodesic search walks), so "different component" is exactly "no path".
#ifndef boolsurf_TriangleComponents_h
#define boolsurf_TriangleComponents_h

#include "Mesh/TriangleMesh.h"

#include <memory>
#include <vector>

namespace boolsurf
{

struct MeshTopology;

class TriangleComponents
{
public:
  /// Flood fill over TriangleMesh::GetNeighbor, components numbered by their lowest triangle.
  explicit TriangleComponents(const TriangleMesh& mesh);
  /// The same components read from the topology of the same mesh, whose TriangleComponent is
  /// this numbering (a breadth-first pass over GetNeighbor from the lowest unassigned
  /// triangle): its array is shared, not computed again (a mesh-sized array, 17 MB on 4.3M
  /// triangles).
  explicit TriangleComponents(std::shared_ptr<const MeshTopology> topology);

  /// Component of usable triangle t; -1 if unusable.
  int GetComponent(int t) const { return this->Component[t]; }
  int GetNumberOfComponents() const { return this->NumberOfComponents; }

private:
  std::shared_ptr<const void> Owner; ///< what the array Component points into belongs to
  const int* Component = nullptr;
  int NumberOfComponents = 0;
};

} // namespace boolsurf

#endif

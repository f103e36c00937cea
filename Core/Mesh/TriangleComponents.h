// Connected components of a mesh's usable triangles through manifold edges (the arcs of the
// dual graph every geodesic search walks), so "different component" is exactly "no path".
#ifndef boolsurf_TriangleComponents_h
#define boolsurf_TriangleComponents_h

#include "Mesh/TriangleMesh.h"

#include <vector>

namespace boolsurf
{

class TriangleComponents
{
public:
  /// Flood fill over TriangleMesh::GetNeighbor, components numbered by their lowest triangle.
  explicit TriangleComponents(const TriangleMesh& mesh);

  /// Component of usable triangle t; -1 if unusable.
  int GetComponent(int t) const { return this->Component[t]; }
  int GetNumberOfComponents() const { return this->NumberOfComponents; }

private:
  std::vector<int> Component;
  int NumberOfComponents = 0;
};

} // namespace boolsurf

#endif

// Surface points carried onto a 1-to-4 subdivision of a triangle mesh (paper §4.5, last
// paragraph: a result moves to a finer surface).
//
// One subdivision step splits every triangle (a, b, c) into four: three corner triangles
// (a, m_ab, m_ca), (b, m_bc, m_ab), (c, m_ca, m_bc) and the middle one (m_ab, m_bc, m_ca), where
// m_xy is the new vertex of edge xy; the old vertices keep their ids. Linear, Loop and butterfly
// subdivision share this topology and differ only in where vertices go, so a point given by
// barycentric coordinates in its parent goes to the same child, at coordinates fixed by the
// topology alone: on a linear subdivision it keeps its 3D position exactly, on a Loop
// subdivision it moves with the surface.
//
// The map is read from the two meshes' triangles, not from a numbering convention of the
// filter that made the children: each new vertex is recognised as the one shared by the corner
// triangles of its edge's two end vertices, and each child triangle by its vertex set, so any
// order of the children and any rotation of their corners is accepted.
#ifndef boolsurf_SubdivisionMap_h
#define boolsurf_SubdivisionMap_h

#include "Mesh/SurfacePoint.h"
#include "Mesh/TriangleMesh.h"

#include <array>
#include <string>
#include <vector>

namespace boolsurf
{

class SubdivisionMap
{
public:
  /// Reads the 1-to-4 split of `parent` (its first `parentVertices` vertices kept with their
  /// ids) into `child`. False, with a sentence naming the first parent triangle or child vertex
  /// that does not fit, when `child` is not such a split.
  bool Build(const std::vector<Triangle>& parent,
    int parentVertices,
    const std::vector<Triangle>& child,
    std::string& error);

  /// The child triangle and barycentric coordinates of p (a point of the parent mesh). Points
  /// on the line between two children go to the corner child, so the choice is the same for
  /// every point of the line. p must have a valid triangle id of the parent.
  SurfacePoint Map(const SurfacePoint& p) const;

  /// The two coarse vertices of the edge whose midpoint child vertex m is, for every child
  /// vertex id m at or above the coarse vertex count ({-1, -1} below it).
  const std::vector<std::array<int, 2>>& GetEdgeOfNewVertex() const
  {
    return this->EdgeOfNewVertex;
  }

private:
  std::vector<std::array<int, 2>> EdgeOfNewVertex;
  /// Per parent triangle: the child triangles at corners 0, 1, 2, then the middle one.
  std::vector<std::array<int, 4>> Children;
  /// Per parent triangle: the midpoints of edges (0,1), (1,2), (2,0), as child vertex ids.
  std::vector<std::array<int, 3>> Midpoints;
  std::vector<Triangle> ChildTriangles;
  std::vector<Triangle> ParentTriangles;
};

} // namespace boolsurf

#endif

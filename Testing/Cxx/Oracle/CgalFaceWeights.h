// Weights of a point of a mesh triangle in the vertex order CGAL's Surface_mesh gives the same
// face (both oracle tests build the CGAL mesh with the same vertex and face ids).
#ifndef boolsurf_CgalFaceWeights_h
#define boolsurf_CgalFaceWeights_h

#include <array>

/// w: the weights of face f's corners `corners` (as the mesh lists them); returns them in the
/// order source(h), target(h), target(next(h)) of f's halfedge h.
template <class CgalMesh>
std::array<double, 3> InCgalVertexOrder(const CgalMesh& cgal,
  typename CgalMesh::Face_index f,
  const std::array<int, 3>& corners,
  const std::array<double, 3>& w)
{
  const auto h = cgal.halfedge(f);
  const int order[3] = { static_cast<int>(cgal.source(h)),
    static_cast<int>(cgal.target(h)),
    static_cast<int>(cgal.target(cgal.next(h))) };
  std::array<double, 3> b{};
  for (int i = 0; i < 3; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      if (corners[k] == order[i])
      {
        b[i] = w[k];
      }
    }
  }
  return b;
}

#endif

// The refined surface of an arrangement as whole arrays: every point's position, every
// triangle's corners and source triangle, in the arrangement's numbering.
//
// The arrangement itself stores only what the curves add (RefinedTriangles, CurvePositions)
// and reads the rest from the mesh; outputs that hand the whole surface over (the Surface
// Arrangement filter's port 0) write it here. Kept from edit to edit, the arrays are updated,
// not rewritten: on the same mesh only the points past the mesh's vertices and the entries of
// the mesh triangles that the previous arrangement or this one refined are written, and the
// appended pieces.
#ifndef boolsurf_RefinedSurfaceArrays_h
#define boolsurf_RefinedSurfaceArrays_h

#include "Arrangement/Arrangement.h"

#include <cstdint>
#include <vector>

namespace boolsurf
{

struct RefinedSurfaceArrays
{
  std::vector<Vec3> Positions;
  std::vector<Triangle> Triangles; ///< -1 corners for a hole (an unusable mesh triangle)
  std::vector<int> SourceTriangle; ///< -1 for a hole

  /// Rewrites the arrays for `arr`, computed on `mesh`, reusing what they hold when they were
  /// last written for the same mesh.
  void Update(const TriangleMesh& mesh, const Arrangement& arr, int threads = 0);

  /// The arrays of `arr`, written whole.
  static RefinedSurfaceArrays Of(const TriangleMesh& mesh, const Arrangement& arr);

private:
  /// The mesh whose vertices and triangles fill the first entries (0: none), and the mesh
  /// triangles whose entries hold pieces of the last arrangement written.
  std::uint64_t MeshSerial = 0;
  std::vector<int> WrittenRefinedSources;
};

} // namespace boolsurf

#endif

// Traced curves built without the tracing stage, for tests, examples and benchmarks of the
// arrangement:
//  * on a flat mesh (z ignored), straight polygons: a geodesic is a straight line there, so the
//    traced curve is the polygon with a point wherever a side crosses a mesh edge or passes
//    through a vertex (decided with exact predicates, so lines through vertices or along edges
//    come out as Vertex points);
//  * on any mesh, plane sections: each closed loop (or open chain) where a plane cuts the
//    surface, with one point per crossed edge (great circles on a sphere, meridians and
//    parallels on a torus).
#ifndef boolsurf_SyntheticCurves_h
#define boolsurf_SyntheticCurves_h

#include "Geodesic/TracedCurve.h"

#include <memory>
#include <vector>

namespace boolsurf
{

/// Straight polygons on a flat mesh in the z = 0 plane. Builds a uniform bucket grid once, so
/// tracing a polygon costs about the number of triangles it crosses.
class FlatPolygonTracer
{
public:
  explicit FlatPolygonTracer(const TriangleMesh& mesh);
  ~FlatPolygonTracer();

  /// The traced polygon, or false when a vertex lies outside the mesh.
  bool Trace(const std::vector<Vec2>& polygon,
    bool closed,
    int shapeId,
    int curveId,
    TracedCurve& out) const;

  /// Canonical form of a point of the plane (false when outside the mesh).
  bool Locate(Vec2 p, CanonicalPoint& out) const;

private:
  struct Grid;
  const TriangleMesh& Mesh;
  std::unique_ptr<Grid> Buckets;
};

/// Loops where the plane dot(normal, x) = offset cuts the mesh; open chains when the section
/// reaches a mesh boundary. Vertices exactly on the plane count as being on its positive side.
std::vector<TracedCurve> PlaneSectionCurves(const TriangleMesh& mesh,
  Vec3 normal,
  double offset,
  int shapeId,
  int firstCurveId = 0);

} // namespace boolsurf

#endif

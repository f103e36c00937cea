// Straightest geodesics (Polthier & Schmies): from a surface point, walk straight in a given
// direction for a given length, unfolding each triangle onto the next across the edge crossed,
// so the path makes equal angles on both sides of every edge. On a flat mesh it is the straight
// segment; it is the discrete exponential map used to place drawings on the surface.
#ifndef boolsurf_StraightestGeodesic_h
#define boolsurf_StraightestGeodesic_h

#include "Mesh/SurfacePoint.h"

namespace boolsurf
{

struct StraightestWalk
{
  SurfacePoint End;
  double Length = 0;        ///< length walked (less than asked when a boundary stopped it)
  bool HitBoundary = false; ///< the walk left the surface through an open boundary
};

/// Walks from `start` along `direction` (a 3D vector, projected into the plane of the start
/// triangle) for `length`. A walk through a mesh vertex passes beside it (the crossing point is
/// kept a hair away from the edge's ends), which turns it by the vertex's angle defect at most.
StraightestWalk WalkStraightest(const TriangleMesh& mesh,
  const SurfacePoint& start,
  Vec3 direction,
  double length);

/// The unit normal of triangle t.
Vec3 TriangleNormal(const TriangleMesh& mesh, int t);

} // namespace boolsurf

#endif

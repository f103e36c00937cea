// Checks shared by the tests of a triangle's refinement (stage 3): exact rational coordinates
// of local points, computed from their definitions independently of the arrangement's own
// predicates, and the validity of a refined triangle.
#ifndef boolsurf_RefinementChecks_h
#define boolsurf_RefinementChecks_h

#include "Arrangement/SegmentIntersection.h"

#include <gmpxx.h>

#include <array>
#include <random>

namespace boolsurf
{
namespace testing
{

/// Exact rational coordinates of point i, computed here from its definition.
std::array<mpq_class, 2> ExactCoordinates(const LocalArrangement& arr, int i);

/// Exact sign of the orientation of (a, b, c).
int Orientation(const std::array<mpq_class, 2>& a,
  const std::array<mpq_class, 2>& b,
  const std::array<mpq_class, 2>& c);

/// A uniformly random point of the unit triangle, scaled by `scale` and moved by `margin` on
/// both axes: (margin, margin) + scale (u, v) with u, v >= 0 and u + v <= 1.
Vec2 RandomTrianglePoint(std::mt19937& rng, double margin, double scale);

/// Distance from q to the segment (a, b).
double DistanceToSegment(Vec2 a, Vec2 b, Vec2 q);

/// The refined triangle `after` is a triangulation of the unit triangle (counter-clockwise
/// triangles, exactly, whose rounded areas sum to 1/2, every edge used once each way inside and
/// once along the boundary), and every chain of `before` became a path of triangulation edges
/// from its first to its last point, never farther than rounding from the pieces it was drawn
/// as. Non-fatal failures are reported through gtest.
void ExpectValidRefinement(const LocalArrangement& before, const LocalArrangement& after);

} // namespace testing
} // namespace boolsurf

#endif

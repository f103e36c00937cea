// The jump lift of a set of curves on the refined surface: a function v per corner of the
// refined triangles that jumps by J across every curve edge (J: the signed number of times the
// curves run along it, +1 from the right of a curve to its left), is continuous everywhere else
// and is zero outside the mesh triangles whose closure the curves touch.
//
// Per mesh triangle T with corners x_i, v = W - I(W): W is the piecewise constant "local
// winding" of T's refined triangles (what one gains crossing curves on a walk from a corner to
// the piece), I(W) its linear interpolation of the values at T's corners. The walks are fixed
// per refined point, so v is one value per point and side of the curves (a "wedge": the
// corners around a point that no curve separates), which is what makes it continuous:
//  - a mesh vertex x: v(x, wedge) = W(wedge) - W(reference wedge of x);
//  - a point on a mesh edge (A, B) at parameter t: (1 - t)(W - W_A) + t(W - W_B), walking
//    along the edge on the side of its lowest touched triangle;
//  - a point inside T: sum_i lambda_i (W - W_{x_i}), walking among T's pieces.
// For closed curves that bound (consistent jumps around every point and in every triangle) the
// walks do not matter and v = W - I(W) exactly; the winding stage then finds u = I(W) and
// w = v + u = W. At an open curve's end the jumps around the end point do not sum to zero: the
// end point has one wedge, so the jump fades to zero along the last edge, and walks through
// the triangle holding the end fix where the rest of the mismatch goes.
#ifndef boolsurf_JumpLift_h
#define boolsurf_JumpLift_h

#include "Arrangement/Arrangement.h"
#include "Winding/CotanLaplacian.h"

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace boolsurf
{

/// Directed refined edges (from, to) of a set of curves, one entry per traversal.
using CurveEdgeList = std::vector<std::pair<int, int>>;

/// Appends the directed edges of curve `c` of `arr` (closing edge included for a closed curve).
void AppendCurveEdges(const Arrangement& arr, int c, bool closed, CurveEdgeList& edges);

struct JumpLift
{
  /// Refined triangles of the touched mesh triangles, ascending, and v at their 3 corners.
  std::vector<int> Triangles;
  std::vector<std::array<double, 3>> Values;
  /// Mesh triangles touched (ascending), each with the area integral of grad v over its
  /// pieces (the lift's flux: what the right-hand side and the harmonic pairing read).
  std::vector<int> MeshTriangles;
  std::vector<Vec3> Flux;
};

/// The lift of the curves `edges` on `arr` (computed on `mesh`).
void ComputeJumpLift(const TriangleMesh& mesh,
  const Arrangement& arr,
  const CurveEdgeList& edges,
  JumpLift& out);

/// Adds to column `rhs` (one value per mesh vertex) the lift's load: b_i = sum over touched
/// triangles T of grad(hat_i on T) . Flux(T), so that L u = -b minimizes |grad(v + u)|^2.
void AddLiftLoad(const TriangleMesh& mesh, const JumpLift& lift, double* rhs);

} // namespace boolsurf

#endif

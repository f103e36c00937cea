// Surface winding numbers of open, closed and broken curves (Feng, Gillespie and Crane,
// "Winding Numbers on Discrete Surfaces", SIGGRAPH 2023), computed on the refined surface of
// the arrangement, where every curve runs along edges, so the curves are used exactly.
//
// w is harmonic away from the curves and jumps by +1 across each curve from its right to its
// left. Formulation (Docs/WindingNumbers.md says why):
//  - w = v + u per corner of the refined surface. v, the jump lift (Winding/JumpLift.h), is
//    built locally in the mesh triangles the curves touch; it carries every jump exactly and
//    equals W - I(W) where a closed, bounding set of curves has integer winding W (I: linear
//    interpolation of the mesh vertices' values). u is piecewise linear on the *mesh*, the
//    minimizer of the Dirichlet energy of v + u, so its matrix is the mesh's cotan Laplacian
//    whatever the curves: factorized once per surface (Winding/CotanLaplacian.h), an edit of
//    the curves is a right-hand side and a back-substitution. Closed bounding curves give
//    u = I(W) and w = W exactly.
//  - Open boundary: zero normal derivative (Neumann), so the boundary completes curves that
//    end on it: a curve from boundary to boundary bounds the part on its left. The constant:
//    values on the free part of the longest boundary loop (where no curve runs) are made as
//    near integers as they can be and their lowest 0, which is the labels' zero plug for
//    closed curves; on a closed component the same over all its values, as CellLabels are
//    shifted to a minimum of 0.
//  - Genus > 0: a curve that bounds nothing (a torus meridian) would give w a ramp around the
//    handle. Its harmonic coefficients (the L2 projection of its field onto the harmonic fields
//    of the homology generators, Winding/HarmonicBasis.h) are its homology class, integer for
//    closed curves and fractional for broken ones. A shape whose curves sum to a class of norm
//    >= 1/2 drops, greedily, the curves most aligned with the excess until it is below; dropped
//    curves impose no jump and are reported as bounding nothing.
#ifndef boolsurf_SurfaceWinding_h
#define boolsurf_SurfaceWinding_h

#include "Arrangement/Arrangement.h"
#include "Geodesic/TracedCurve.h"

#include <memory>
#include <string>
#include <vector>

namespace boolsurf
{

class WindingSystem;

struct WindingOptions
{
  /// Shape ids to compute, in this order; empty: every shape of the curves, ascending.
  std::vector<int> Shapes;
  /// Drop what bounds nothing: curves whose homology class the shape does not need (genus > 0),
  /// and spurs and overshooting ends (see above).
  bool RemoveNonBounding = true;
  /// Level of the completed region.
  double Threshold = 0.5;
  int Threads = 0; ///< 0: all hardware threads
};

struct WindingCurveReport
{
  int Curve = -1; ///< index into the curves
  int ShapeId = -1, CurveId = -1;
  /// False when the curve was dropped as bounding nothing: by the homology correction
  /// (AroundHandle: its class is not bounded by the shape's other curves) or, as a whole, by
  /// its levels (a spur, an overshooting piece, an isolated arc).
  bool Bounds = true;
  bool AroundHandle = false;
  /// How far the curve is from bounding a region: the length-weighted share of it that does
  /// not sit between integer levels of w (see BoundingDegrees in Winding/WindingField.h). 0
  /// for a closed curve that bounds, small for a broken one, 1 for a dangling spur, an
  /// overshoot's tail, an isolated arc, or a curve that bounds nothing.
  double Residual = 0;
  /// Harmonic coefficients per homology generator (empty on genus 0): the class of a closed
  /// curve, a fraction of it for a broken one.
  std::vector<double> Homology;
};

struct WindingStageTimes
{
  /// Milliseconds: factorization (0 when kept from the last call on the same mesh), the
  /// homology correction, lifts and loads, back-substitutions, field and outputs.
  double Factorization = 0, Lift = 0, Solve = 0, Homology = 0, Outputs = 0, Total = 0;
  /// Columns solved (a shape per solve round; reused shapes none) and curve edges dropped as
  /// bounding nothing (spurs, overshoots).
  int BackSubstitutions = 0, DroppedEdges = 0;
};

/// w of each computed shape on the refined surface of an arrangement.
struct WindingResult
{
  std::vector<int> ShapeIds;              ///< the computed shapes (index s below)
  std::vector<WindingCurveReport> Curves; ///< one per curve of a computed shape, curve order
  /// Refined triangles whose corners carry a lift of some shape, ascending (the triangles where
  /// w may jump across an edge), and each refined triangle's index among them (-1 elsewhere).
  std::vector<int> JumpTriangles;
  std::vector<int> JumpSlot;
  /// Per shape: the lift at the 3 corners of every jump triangle (3 * slot + k).
  std::vector<std::vector<double>> CornerLift;
  /// Per shape: the mean of w over each arrangement cell (area-weighted).
  std::vector<std::vector<double>> CellMean;
  WindingStageTimes Times;

  /// Per shape: u at the mesh vertices (shared with the solve kept for the next edit, not
  /// copied), u at the curve points (entry p - NumberOfMeshVertices), and the constant taken
  /// off per block of the mesh (VertexBlock, CurvePointBlock; one block: no per-point lookup).
  std::vector<std::shared_ptr<const std::vector<double>>> VertexSmooth;
  std::vector<std::vector<double>> CurvePointSmooth;
  std::vector<std::vector<double>> BlockShift;
  std::shared_ptr<const std::vector<int>> VertexBlock;
  std::vector<int> CurvePointBlock;
  int NumberOfMeshVertices = 0;
  /// Per shape: (refined point, mean of its corners' lowest and highest lift) where it has
  /// sides, ascending by point.
  std::vector<std::vector<std::pair<int, double>>> PointLift;

  int GetNumberOfShapes() const { return static_cast<int>(this->ShapeIds.size()); }
  /// The smooth part (u less its constant) of shape s at refined point p.
  double Base(int s, int p) const
  {
    const int nv = this->NumberOfMeshVertices;
    const double u = p < nv ? (*this->VertexSmooth[s])[p] : this->CurvePointSmooth[s][p - nv];
    const std::vector<double>& shift = this->BlockShift[s];
    if (shift.size() == 1)
    {
      return u - shift[0];
    }
    const int b = p < nv ? (*this->VertexBlock)[p] : this->CurvePointBlock[p - nv];
    return b >= 0 ? u - shift[b] : u;
  }
  /// w of shape s at corner k of refined triangle r (corners in GetTriangle's order).
  double Corner(const RefinedTriangles& arr, const TriangleMesh& mesh, int s, int r, int k) const;
  /// w of shape s at refined point p: the middle of its jump where it has sides (1/2 on a
  /// closed curve bounding a region of 1).
  double Point(int s, int p) const;
  /// Point() of every refined point (numberOfPoints values), written in one pass.
  void WritePoints(int s, int numberOfPoints, double* values) const;
  /// w of shape s at the centroid of refined triangle r.
  double Triangle(const RefinedTriangles& arr, const TriangleMesh& mesh, int s, int r) const;
};

/// Computes winding numbers, keeping the factorized Laplacian and the harmonic fields of the
/// last surface for the next call (an edit of the curves on the same mesh).
class SurfaceWinding
{
public:
  SurfaceWinding();
  ~SurfaceWinding();

  /// w of the shapes of `curves` on `arr`, the arrangement of exactly these curves on `mesh`.
  /// False with a message naming the problem: no curve in a requested shape, a shape id that
  /// no curve has, a curve of fewer than two points, a non-finite point, a mesh whose
  /// Laplacian cannot be factorized.
  bool Compute(const TriangleMesh& mesh,
    const Arrangement& arr,
    const std::vector<TracedCurve>& curves,
    const WindingOptions& options,
    WindingResult& out,
    std::string& error);

private:
  std::shared_ptr<WindingSystem> System;
};

} // namespace boolsurf

#endif

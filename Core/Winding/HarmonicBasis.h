// Harmonic fields of a surface's homology generators, to read the homology part of any set of
// curves (closed or broken) on it: the winding stage's homology correction.
//
// Each generator of Homology/HomologyBasis is a closed curve that bounds nothing. Its winding
// field w_g = v_g + u_g (Winding/JumpLift.h + the Laplacian solve) is the jump plus a ramp
// around the handle; the ramp's gradient G_g = grad(v_g + u_g) (taken away from the jump) is
// harmonic and orthogonal to every gradient of the mesh's linear functions. For any curves c
// with lift v_c, <G_c, G_g> = <grad v_c, G_g>, so the coefficients a = M^-1 <grad v_c, G>
// (M: the Gram matrix of the G_g) are the curves' homology class in the generators' basis,
// exactly for closed curves (homologous closed curves have fields that differ by a gradient),
// and the fraction of it a broken curve carries.
#ifndef boolsurf_HarmonicBasis_h
#define boolsurf_HarmonicBasis_h

#include "Winding/CotanLaplacian.h"
#include "Winding/JumpLift.h"

#include <string>
#include <vector>

namespace boolsurf
{

class HarmonicBasis
{
public:
  /// The generators' fields on `mesh` (none on genus 0). False with a message when the
  /// generators cannot be computed or arranged.
  bool Compute(const TriangleMesh& mesh, const CotanLaplacian& laplacian, std::string& error);

  int GetNumberOfGenerators() const { return static_cast<int>(this->Smooth.size()); }

  /// Homology coefficients of the curves whose lift is `lift`.
  std::vector<double> Coefficients(const TriangleMesh& mesh, const JumpLift& lift) const;

private:
  /// Per generator: u_g per mesh vertex, and its lift's flux per touched mesh triangle.
  std::vector<std::vector<double>> Smooth;
  std::vector<JumpLift> Lifts;
  std::vector<double> GramInverse; ///< row-major, generators^2

  /// Mean of G_g over mesh triangle t (zero for a degenerate one).
  Vec3 FieldOn(const TriangleMesh& mesh, int g, int t) const;
};

} // namespace boolsurf

#endif

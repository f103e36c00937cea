// Validation of an input surface before any BoolSurf stage runs on it.
//
// Every problem carries a kind (stable identifier, used by tests and scripts), a severity,
// a message a user can act on, and the ids involved. Errors make the surface unfit for the
// pipeline (winding numbers need an oriented 2-manifold with non-degenerate triangles);
// warnings are informational.
#ifndef boolsurf_SurfaceCheck_h
#define boolsurf_SurfaceCheck_h

#include "Mesh/MeshTopology.h"
#include "Mesh/TriangleMesh.h"

#include <string>
#include <vector>

namespace boolsurf
{

enum class Severity
{
  Warning,
  Error
};

struct SurfaceProblem
{
  std::string Kind; ///< e.g. "NonManifoldEdge"; see SurfaceCheck.cxx for the list
  Severity Level = Severity::Error;
  std::string Message;
  std::vector<long long> Ids; ///< ids named in the message (vertices, triangles, ...)
};

struct SurfaceCheckOptions
{
  /// A triangle is degenerate when twice its area is at most this times its longest squared
  /// edge (scale-free; 0 would only catch exactly collinear corners).
  double DegenerateTolerance = 1e-12;
  /// How many ids a message spells out before "... and N more".
  int MaxIdsInMessage = 10;
};

struct SurfaceCheckResult
{
  std::vector<SurfaceProblem> Problems;
  bool IsManifold = true; ///< no non-manifold edge or vertex

  bool HasErrors() const;
  bool Has(const std::string& kind) const;
  const SurfaceProblem* Find(const std::string& kind) const;
  /// All error messages joined by newlines.
  std::string ErrorSummary() const;
};

/// Formats ids as "1, 2, 3 ... and 7 more".
std::string FormatIds(const std::vector<long long>& ids, int maxIds);

/// Checks geometry (finite coordinates, degenerate triangles), indices and topology
/// (non-manifold edges and vertices, orientation, unreferenced vertices).
SurfaceCheckResult CheckSurface(const TriangleMesh& mesh,
  const MeshTopology& topology,
  const SurfaceCheckOptions& options = SurfaceCheckOptions());

} // namespace boolsurf

#endif

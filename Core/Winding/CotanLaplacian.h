// The cotan Laplacian of a triangle mesh (the stiffness matrix of piecewise-linear functions),
// factorized once so that each right-hand side is a back-substitution.
//
// It is the matrix of the winding numbers' smooth part u (Winding/SurfaceWinding.h): curves
// enter only through right-hand sides, so an edit of the curves never refactorizes. Each
// connected block of vertices has one vertex pinned to 0 (the matrix is singular by the
// constants); callers add their own constant afterwards.
//
// The factorization is CHOLMOD's supernodal Cholesky (through Eigen's CholmodSupport) with the
// AMD ordering: on igea_1m (537k vertices) AMD analyses in 0.6 s and factorizes in 2.9 s on 2
// cores, where CHOLMOD's default (METIS tried too) took 5.8 s and Eigen's SimplicialLDLT 18.5 s.
#ifndef boolsurf_CotanLaplacian_h
#define boolsurf_CotanLaplacian_h

#include "Mesh/TriangleMesh.h"

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace boolsurf
{

/// Gradients of the hat functions of a mesh triangle's corners (constant on it), and the
/// triangle's unit normal and area. All zero for a degenerate or unusable triangle.
struct TriangleGradients
{
  std::array<Vec3, 3> Hat;
  Vec3 Normal;
  double Area = 0;
};
TriangleGradients ComputeTriangleGradients(const TriangleMesh& mesh, int t);

class CotanLaplacian
{
public:
  CotanLaplacian();
  ~CotanLaplacian();

  /// Assembles and factorizes the Laplacian of `mesh` (usable, non-degenerate triangles).
  /// False with a message when the factorization fails (a mesh with NaN positions).
  bool Factorize(const TriangleMesh& mesh, std::string& error);

  std::uint64_t GetMeshSerial() const { return this->MeshSerial; }
  int GetNumberOfVertices() const { return this->NumberOfVertices; }
  /// Connected block of each vertex (vertices joined by a usable triangle's edge), -1 for
  /// vertices of no usable triangle; blocks are numbered by their lowest vertex.
  const std::vector<int>& GetVertexBlocks() const { return this->VertexBlock; }
  int GetNumberOfBlocks() const { return static_cast<int>(this->PinnedVertex.size()); }

  /// Solves L u = rhs for each column (rhs: columns of GetNumberOfVertices() values, stored one
  /// after the other), in place; u is 0 at each block's pinned vertex and at loose vertices.
  void Solve(std::vector<double>& columns, int numberOfColumns) const;

  double GetFactorizationSeconds() const { return this->FactorizationSeconds; }
  /// Nonzeros of the Cholesky factor (memory: 8 bytes each plus indices).
  double GetFactorNonzeros() const;

private:
  struct Factor;
  std::unique_ptr<Factor> Impl;
  std::uint64_t MeshSerial = 0;
  int NumberOfVertices = 0;
  std::vector<int> VertexBlock;
  std::vector<int> PinnedVertex;
  double FactorizationSeconds = 0;
};

} // namespace boolsurf

#endif

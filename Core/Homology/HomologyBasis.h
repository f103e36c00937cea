// Homology generators of a triangle-mesh surface and the homology class of traced curves
// (BoolSurf §4.4, Theorem 1: a shape is consistent exactly when the homology classes of its
// curves sum to zero).
//
// Tree-cotree decomposition (Eppstein 2003) with the greedy choice of Erickson-Whittlesey
// (2005): a shortest-path tree C of the dual graph (triangles, arcs across interior edges)
// from a base triangle per component, then a maximum spanning tree T of the primal graph
// among the edges not crossed by C, weighted by the length of the dual loop each edge closes.
// The 2g leftover edges x give the generators: dual loops that go from one side of x to the
// other along C and cross x. They pass through triangle interiors and cross mesh edges
// strictly inside them (each generator at its own parameter along an edge), never through a
// vertex, so crossings with traced curves and between generators are well defined.
//
// Surfaces with boundary: every boundary loop is capped by a virtual face (the paper's
// virtual shape A0, §3.4), a leaf of C; boundary edges go into T first. So the generators are
// those of the closed surface and a curve homologous to a combination of boundary loops has
// class zero, as the labeling (which closes every loop by a plug, Labeling/BoundaryPlugs.h,
// and takes the longest loop's plug as its zero node) sees it.
//
// The class of a closed curve in the generators' basis is read with the dual basis: for each
// leftover edge x, the primal loop l_x (x plus the T paths from its ends to the root) meets
// generator y once if x == y and never otherwise, so the coefficient of generator x in a
// curve is its signed number of crossings with l_x (a curve crossing an edge of l_x from right
// to left counts +1). A traced curve is first made a walk of triangles (a curve through a
// vertex goes around it, which is homotopic on the surface).
#ifndef boolsurf_HomologyBasis_h
#define boolsurf_HomologyBasis_h

#include "Geodesic/TracedCurve.h"
#include "Mesh/MeshTopology.h"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace boolsurf
{

/// One generator: a closed walk through triangles, crossing one mesh edge between each
/// triangle and the next (the last edge leads back to the first triangle).
struct HomologyGenerator
{
  int Component = -1;
  int CutEdge = -1;               ///< the leftover edge x whose crossing closes the loop
  std::vector<int> Triangles;     ///< visited in order, each once
  std::vector<int> Edges;         ///< Edges[i] joins Triangles[i] and Triangles[i+1] (cyclic)
  double CrossingParameter = 0.5; ///< where it crosses every edge (canonical direction)
  /// The loop as edge points (one per crossed edge, in order): a polyline whose segments are
  /// chords of the triangles between them.
  std::vector<CanonicalPoint> Points;
};

struct HomologyOptions
{
  /// Base triangle per component (index = component); -1 or missing: the component's lowest
  /// triangle. A base triangle of another component is an error.
  std::vector<int> BaseTriangles;
};

class HomologyBasis
{
public:
  /// Computes the generators of every component (2g each). False with a message for unusable
  /// input (non-orientable components, a base triangle out of range or in another component).
  bool Compute(const TriangleMesh& mesh,
    const MeshTopology& topology,
    const HomologyOptions& options,
    std::string& error);

  int GetNumberOfGenerators() const { return static_cast<int>(this->Generators.size()); }
  const std::vector<HomologyGenerator>& GetGenerators() const { return this->Generators; }
  const HomologyGenerator& GetGenerator(int g) const { return this->Generators[g]; }
  /// Serial of the mesh the basis was computed on (TriangleMesh::GetSerial).
  std::uint64_t GetMeshSerial() const { return this->MeshSerial; }
  /// The base triangle used in each component.
  const std::vector<int>& GetBaseTriangles() const { return this->BaseTriangles; }

  /// Class of a closed traced curve: one integer per generator. False with a message when two
  /// consecutive points share no triangle. Open curves have no class: a zero vector.
  bool ClassOf(const TracedCurve& curve, std::vector<int>& homology, std::string& error) const;

  /// Class of a closed walk of triangles, given by the edges it crosses and the triangle it
  /// enters after each crossing.
  void ClassOfWalk(const std::vector<int>& crossedEdges,
    const std::vector<int>& enteredTriangles,
    std::vector<int>& homology) const;

  /// Algebraic intersection number a . b of two generators (+1 where b crosses a from its right
  /// to its left): the generators cross edges at distinct parameters, so chords of the same
  /// triangle cross exactly when their ends interleave on its boundary.
  int Intersection(int a, int b) const;

  /// Every dual arc (mesh edge) of the cut graph: the C paths from each generator's triangles to
  /// its component's base triangle and the leftover edges; cutting the surface along it leaves
  /// one disc per component.
  std::vector<int> CutGraphEdges() const;

private:
  const TriangleMesh* Mesh = nullptr;
  std::uint64_t MeshSerial = 0;
  std::vector<HomologyGenerator> Generators;
  std::vector<int> BaseTriangles;
  std::vector<int> DualParentEdge; ///< per triangle: edge crossed towards the root, -1 at roots
  std::vector<int> DualDepth;
  /// Per edge, the primal cocycles through it: CochainOffset[e]..[e+1] into CochainEntries.
  std::vector<int> CochainOffset;
  std::vector<std::pair<int, int>> CochainEntries; ///< (generator, coefficient)

  void AddCrossing(int edge, int enteredTriangle, std::vector<int>& homology) const;
  bool AroundVertex(int vertex,
    int from,
    int to,
    std::vector<int>& edges,
    std::vector<int>& entered) const;
};

/// Sum of the classes of the curves of each shape (shape index i = shapeIds[i], sorted ids):
/// the generators in excess. `curveHomology[c]` belongs to `curves[c]`.
std::vector<std::vector<int>> HomologyExcess(const std::vector<TracedCurve>& curves,
  const std::vector<std::vector<int>>& curveHomology,
  const std::vector<int>& shapeIds,
  int numberOfGenerators);

} // namespace boolsurf

#endif

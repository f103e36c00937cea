// Surfaces split into pieces as processes would receive them, for the tests and benchmarks of
// the distributed arrangement (Core/Distributed): owners per triangle by slabs or by random
// regions, and each piece with its ring of ghost triangles and global ids.
#ifndef boolsurf_PieceSplits_h
#define boolsurf_PieceSplits_h

#include "Arrangement/Arrangement.h"
#include "Distributed/PieceMesh.h"
#include "Geodesic/TracedCurve.h"
#include "Mesh/ProceduralMeshes.h"

#include <vector>

namespace boolsurf
{
namespace testing
{

/// Owners by slabs of equal triangle counts along `axis` (centroid order, ties by id).
std::vector<int> SlabOwners(const TriangleMesh& mesh, int pieces, int axis);

/// Owners grown breadth-first from random seeds, one triangle per piece in turn; piece
/// `emptyPiece` (when >= 0) gets no triangle.
std::vector<int> RegionOwners(const TriangleMesh& mesh, int pieces, unsigned seed, int emptyPiece);

/// Piece p as a process would receive it: owned triangles plus every triangle sharing a vertex
/// with them (ghosts), points and triangles in an order unrelated to the global one.
PieceInput MakePiece(const TriangleMesh& mesh, const std::vector<int>& owner, int p);

/// Up to `count` random closed geodesic polygons (3 to 5 control points inside random
/// triangles), traced on `mesh`, one shape each: drawings crossing the pieces' borders many
/// times.
std::vector<TracedCurve> RandomGeodesicCurves(const TriangleMesh& mesh, unsigned seed, int count);

/// A sphere (MakeIcosphere(3)) with four round holes of different sizes cut out: an open
/// surface of four boundary loops, which piece borders cut.
MeshData SphereWithHoles();

/// Area of refined triangle r of an arrangement computed on `mesh`.
double RefinedArea(const TriangleMesh& mesh, const Arrangement& arr, int r);

/// Area of each cell of an arrangement computed on `mesh` (the sum of its refined triangles'):
/// what the pieces' merged cell areas must equal.
std::vector<double> CellAreas(const TriangleMesh& mesh, const Arrangement& arr);

} // namespace testing
} // namespace boolsurf

#endif

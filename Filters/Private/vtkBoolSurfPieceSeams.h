// A surface made of the appended pieces of a partitioned dataset, in one process (a private
// header of the module).
//
// VTK's readers of partitioned files (.pvtp) open every piece in a serial session and append
// them without merging the points the pieces share: each piece keeps its own copy of the
// points on its border, so the surface falls apart into as many patches as pieces, whose
// borders are boundary edges, and a piece that touches itself at a corner of its border gives
// a vertex where two separate fans of triangles meet. The same file read by several MPI ranks
// is merged by the gather (vtkBoolSurfRankGather). This is the one-process counterpart: the
// ghost cells a piece holds for its neighbours are dropped, and boundary points at exactly the
// same position are welded, so the surface is the undistributed one.
#ifndef vtkBoolSurfPieceSeams_h
#define vtkBoolSurfPieceSeams_h

#include "Mesh/TriangleMesh.h"

#include <vtkSmartPointer.h>

class vtkPolyData;

namespace boolsurf
{

/// `input` without the cells its ghost array marks as owned elsewhere (duplicate cells of a
/// piece's halo), or null when it has none.
vtkSmartPointer<vtkPolyData> WithoutGhostCells(vtkPolyData* input);

/// `triangles` (whose triangles are `mesh`'s) with the points on boundary or non-manifold
/// edges of different pieces that share their exact position merged into the first of them,
/// the merged copies removed and the triangles put in the order of their global cell ids when
/// they carry them (as the gather of pieces does); null when nothing is welded.
///
/// Pieces are what appending leaves: runs of cells that use runs of points of their own (a cut
/// after a cell where every point used so far comes before every point used after it). A
/// surface stored as one piece is never changed, even where its boundary points coincide (a
/// mesh cut along a seam, its points doubled for texture coordinates, keeps its seam); a closed
/// surface has no boundary point to compare, an open one compares only its boundary points.
vtkSmartPointer<vtkPolyData> WeldPieceSeams(vtkPolyData* triangles, const TriangleMesh& mesh);

} // namespace boolsurf

#endif

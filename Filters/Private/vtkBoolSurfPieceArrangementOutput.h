/**
 * @brief   a rank's part of Surface Arrangement's refined surface, from the distributed
 *          arrangement (vtkBoolSurfPieceArrangement.h)
 *
 * What a rank can write of port 0 by itself (Docs/Parallel.md, "What is left before a filter
 * runs on pieces"): its owned triangles refined (ghost copies are refined by their owners), in
 * global triangle order and, within a triangle, in the one-rank output's order, positions bit
 * for bit the one-rank ones; cell `ArrangementCell` (the merged, canonical cell numbers) and
 * `SourceTriangle` (the global cell id); point `TriangleId` (a global cell id) and
 * `Barycentric` (a mesh vertex may name another of its triangles than the one-rank output
 * does: the same point); field `NumberOfCells` (the merged graph's, the same on every rank). The
 * union over ranks of these triangles is the one-rank output's, per SourceTriangle. Points are the
 * refined points the owned triangles use, in first-use order, so a point on the border between two
 * ranks is in both ranks' outputs.
 */
#ifndef vtkBoolSurfPieceArrangementOutput_h
#define vtkBoolSurfPieceArrangementOutput_h

#include "Distributed/MergedArrangement.h"
#include "Distributed/PieceMesh.h"

#include <vector>

class vtkBoolSurfPieceArrangement;
class vtkFieldData;
class vtkPolyData;

namespace boolsurf
{
/// Fills `output` (emptied first) with refined triangles `triangles` of `run`'s arrangement on
/// `piece`, with their global source triangles and global cells: points, ArrangementCell,
/// SourceTriangle, TriangleId and Barycentric as WritePieceArrangement writes them (a region
/// of the piece: vtkBoolSurfPieceLabels.h).
void WritePieceTriangles(const PieceMesh& piece,
  const vtkBoolSurfPieceArrangement& run,
  const std::vector<int>& triangles,
  const std::vector<int>& sources,
  const std::vector<int>& cells,
  vtkPolyData* output);

/// The plug fields of the one-rank port 0 from the merged graph (message 3, the same on every
/// rank): CellComponent (the cells', then the plugs'), ZeroCellCandidates,
/// NumberOfBoundaryPlugs and BoundaryPlugLinks (the plug crossings without a change; one more
/// pair than the one-rank list where curves of one shape cancel along a boundary stretch).
void WriteMergedPlugFields(const MergedArrangement& merged, vtkFieldData* fd);

/// Fills `output` (emptied first) with the owned refined triangles of `run` on `piece`, with
/// NumberOfCells and the plug fields.
void WritePieceArrangement(const PieceMesh& piece,
  const vtkBoolSurfPieceArrangement& run,
  vtkPolyData* output);
}

#endif

/**
 * @class   vtkBoolSurfArrangement
 * @brief   arrangement of traced curves on a triangle surface: refined surface, cells, patches
 *
 * vtkBoolSurfArrangement computes the surface arrangement of BoolSurf (Riso et al. 2022):
 *
 * 1. a hash map from each triangle to the curve segments inside it, in unit-triangle
 *    coordinates (points on mesh edges and vertices in one canonical form, so both
 *    triangles of an edge agree exactly);
 * 2. every crossing between segments of a triangle (self-intersections, crossings of curves
 *    and shapes) with exact orientation predicates;
 * 3. each crossed triangle replaced by a triangulation of itself that embeds its segments
 *    (in parallel over triangles, result independent of the thread count);
 * 4. a flood fill of the dual graph of adjacencies across arcs that do not cross a closed
 *    curve: each flood is one cell;
 * 5. the curves cut into patches at intersections, and the cell graph: one arc per patch,
 *    from the cell on the right of the curve to the cell on its left.
 *
 * Inputs: port 0 the surface (triangles; other polygons are triangulated), port 1 the traced
 * curves (output of vtkBoolSurfTraceCurves: polylines with point data `TriangleId` and
 * `Barycentric`, cell data `ShapeId`, `CurveId`, `Closed`). Open curves take part in the
 * intersections and are refined into the mesh but do not separate cells.
 *
 * Output port 0, the refined surface: cell data `ArrangementCell` and `SourceTriangle`, point
 * data `TriangleId`/`Barycentric` (each refined point as a point of the input surface), the
 * input surface's own arrays (cell data copied from the source triangle, point data
 * interpolated), and field data: `NumberOfCells`, `NumberOfShapes` (distinct ShapeIds), `ShapeIds`
 * (the distinct ShapeIds, sorted: shape index i in per-shape arrays is ShapeIds[i]),
 * the cell graph `CellGraphArcs` (2 components: right cell, left cell), `CellGraphShape`
 * (the ShapeId of each arc),
 * `CellGraphPatch`, `CellGraphLocation` (arcs of overlapping patches share a location),
 * `CellGraphDirection` (+1/-1: the patch along or against its location's direction; it gives
 * the side of arcs from a cell to itself, so exactly overlapping reversed curves cancel),
 * `NumberOfBoundaryPlugs` (one plug per boundary loop, closing it: plug l is cell graph node
 * NumberOfCells + l; the arcs of closed curves' patches along the boundary join a cell and a
 * plug), `BoundaryPlugLinks` (2 components: a cell and a plug it meets along a stretch of
 * boundary no closed curve covers, one region), `CellComponent` (surface component of each
 * cell, then of each plug), `ZeroCellCandidates` (per component, its zero node: the plug of
 * its longest boundary loop, -1 for closed components), the patches (`PatchOffsets`,
 * `PatchPoints`, `PatchLeftCell`, `PatchRightCell`, `PatchShape`, `PatchCurve`; a patch along
 * the boundary has -1 on its outer side) and
 * `StageTimes` (milliseconds: hash, intersections, refinement, flood fill, cell graph,
 * total), and the homology of the curves (`NumberOfHomologyGenerators`, `CurveHomology`,
 * `CurveHomologyCurveId`, `CurveHomologyShapeId`: each curve's class in the surface's
 * generators, computed once per surface; `HomologyGenerator*` and `HomologyShortGenerator*`:
 * the generators and their shortened loops; see vtkBoolSurfLabeling and Docs/Homology.md).
 * Downstream filters (labeling, Booleans) need only this port.
 *
 * Under MPI, on a surface split across ranks, each rank arranges its own piece (named by the
 * pieces' point and cell GlobalIds, generated with a warning when they carry none: see
 * vtkBoolSurfPieceGlobalIds.h) and port 0 is its part of the refined surface (field data
 * `ArrangementOnPieces`; which arrays it has is in Docs/Parallel.md); Label Arrangement Cells
 * and Surface Boolean then run on the pieces too, and the other filters refuse such an input.
 *
 * Output port 1, the patches as polylines on the refined surface's points, cell data
 * `PatchId`, `ShapeId`, `CurveId`, `LeftCell`, `RightCell`, `Length`.
 *
 * The surface's adjacency is built once and reused while only the curves change.
 *
 * @sa vtkBoolSurfTraceCurves vtkBoolSurfLabeling vtkImprintFilter
 */
#ifndef vtkBoolSurfArrangement_h
#define vtkBoolSurfArrangement_h

#include "BoolSurfFiltersModule.h" // for export macro
#include "vtkBoolSurfAlgorithm.h"
#include "vtkBoolSurfStageSettings.h" // for the thread count's declaration

#include <memory> // for std::unique_ptr

namespace boolsurf
{
struct ArrangementOptions;
}

class BOOLSURFFILTERS_EXPORT vtkBoolSurfArrangement : public vtkBoolSurfAlgorithm
{
public:
  static vtkBoolSurfArrangement* New();
  vtkTypeMacro(vtkBoolSurfArrangement, vtkBoolSurfAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The surface (port 0) and the traced curves (port 1).
  void SetSurfaceConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(0, output); }
  void SetCurvesConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  ///@}

  /// Threads for the intersections and the refinement; 0 (default) uses every hardware
  /// thread. Declared once for every filter that has it (vtkBoolSurfStageSettings.h).
  vtkBoolSurfThreadSettingsMacro();

  /// The patches output (port 1).
  vtkPolyData* GetPatchesOutput();

protected:
  vtkBoolSurfArrangement();
  ~vtkBoolSurfArrangement() override;

  bool Execute(const std::vector<vtkPolyData*>& inputs,
    const std::vector<vtkPolyData*>& outputs,
    std::string& error) override;

  /// On a surface split across ranks (with point and cell GlobalIds, generated if absent), each
  /// rank arranges its piece (vtkBoolSurfPieceArrangementStage.h): port 0 is its part of the
  /// refined surface.
  bool ExecutesOnPieces() const override { return true; }
  bool PiecesNeedGlobalIds() const override { return true; }
  bool ExecutePiece(const std::vector<vtkPolyData*>& locals,
    const std::vector<vtkPolyData*>& outputs,
    std::string& error) override;

  /// The arrangement's settings (the thread count), as the stage takes them.
  std::unique_ptr<boolsurf::ArrangementOptions> ArrangementSettings;

private:
  vtkBoolSurfArrangement(const vtkBoolSurfArrangement&) = delete;
  void operator=(const vtkBoolSurfArrangement&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif

/**
 * @class   vtkBoolSurfTraceCurves
 * @brief   trace geodesic polygons and geodesic Bezier splines on a triangle surface
 *
 * vtkBoolSurfTraceCurves turns control polygons into curves lying on a surface, at a
 * resolution independent of the mesh's:
 *
 * - a geodesic polygon (CurveType 0) joins consecutive control points by shortest paths,
 *   computed as GeodesicMethod says (default: the shortest path in practice at a bounded cost
 *   per leg), each one straightened exactly in its unfolded triangle strip;
 * - a cubic geodesic Bezier spline (CurveType 1; anchor, handle, handle, anchor, ...) is
 *   evaluated by geodesic de Casteljau subdivision (b/Surf, Mancinelli et al. 2022) with
 *   Resolution levels, and the refined control polygon is traced as a geodesic polygon.
 *
 * Inputs: port 0 the surface (triangles; other polygons are triangulated), port 1 the control
 * polygons: one polyline or polygon cell per curve. A polygon cell, or a polyline whose last
 * point repeats its first, is closed. Cell data `ShapeId` (int; default the cell id) groups
 * curves into shapes; cell data `CurveType` (0 or 1; default 0). Control points are projected
 * to the closest surface point, unless point data `TriangleId` + `Barycentric` (weights of the
 * triangle's 2nd and 3rd points) is present: then they are used exactly.
 *
 * Output: one polyline per curve on the surface (closed ones repeat their first point id),
 * with a point at every mesh-edge crossing. Point data `TriangleId`, `Barycentric` (each point
 * as a surface point; points on mesh edges and vertices have an exact zero weight),
 * `CurveParameter` (input segment index + fraction: of the segment's length for polygons, the
 * spline parameter for Beziers), `ControlSegment` (input segment index), `ControlPointId`
 * (input point id of the control point it is, -1 otherwise); cell data `ShapeId`, `CurveId`
 * (input cell id), `Closed`, `CurveType`, `Length`.
 *
 * Errors name the curve (input cell id) and control point (input point id): fewer than 2
 * points, a Bezier with a point count that is not 3n+1 (open) or 3n (closed), a control point
 * farther from the surface than ProjectionTolerance, points on different connected
 * components, invalid TriangleId/Barycentric. On any error the output is empty and field
 * data `TraceErrors` lists every problem.
 *
 * The surface's adjacency and the geodesic search state are built once and reused while
 * only the curves change.
 *
 * Under MPI, on a surface split across ranks whose pieces carry point and cell GlobalIds (the
 * rule of Surface Arrangement on pieces, decided once by every rank), the surface is not
 * gathered: each rank builds its piece with a ring of ghosts and the curves are traced on the
 * pieces (vtkBoolSurfPieceTraceStage.h; control points name triangles by global cell id), each
 * rank fetching from their owners only the triangles its curves' legs read. Every rank's output
 * carries field data PieceCurvesMessage (the bytes the gathered path packs) and
 * PieceTracingTraffic (bytes, rounds, fetched and held triangles); rank 0's output holds the
 * traced polylines, the one-rank output bit for bit, the other ranks' none (curves are small; a
 * gathering filter downstream uses rank 0's as they are). A failing curve fails the update on
 * every rank with the same TraceErrors. The LocallyShortest method, control points given by
 * position, and legs the exact window search does not settle within its budget are traced on
 * the surface gathered to rank 0 instead, with a warning saying why (Docs/Parallel.md).
 * Between updates that change only the curves, the ringed piece, the owner directory and the
 * triangles already fetched are kept.
 *
 * @sa vtkBoolSurfArrangement vtkDijkstraGraphGeodesicPath vtkGeodesicPath
 */
#ifndef vtkBoolSurfTraceCurves_h
#define vtkBoolSurfTraceCurves_h

#include "BoolSurfFiltersModule.h" // for export macro
#include "vtkBoolSurfTracingAlgorithm.h"

#include <memory> // for std::unique_ptr

class BOOLSURFFILTERS_EXPORT vtkBoolSurfTraceCurves : public vtkBoolSurfTracingAlgorithm
{
public:
  static vtkBoolSurfTraceCurves* New();
  vtkTypeMacro(vtkBoolSurfTraceCurves, vtkBoolSurfTracingAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The surface (port 0) and the control polygons (port 1).
  void SetSurfaceConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(0, output); }
  void SetCurvesConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  ///@}

protected:
  vtkBoolSurfTraceCurves();
  ~vtkBoolSurfTraceCurves() override;

  bool Execute(const std::vector<vtkPolyData*>& inputs,
    const std::vector<vtkPolyData*>& outputs,
    std::string& error) override;
  void RecordFailure(const std::string& error, const std::vector<vtkPolyData*>& outputs) override;

  /// On a surface split across ranks with point and cell GlobalIds: traced on each rank's piece.
  bool ExecutesOnPieces() const override { return true; }
  bool PiecesNeedGlobalIds() const override { return true; }
  bool ExecutePiece(const std::vector<vtkPolyData*>& locals,
    const std::vector<vtkPolyData*>& outputs,
    std::string& error) override;

private:
  vtkBoolSurfTraceCurves(const vtkBoolSurfTraceCurves&) = delete;
  void operator=(const vtkBoolSurfTraceCurves&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif

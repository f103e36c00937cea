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
 * @sa vtkBoolSurfArrangement vtkDijkstraGraphGeodesicPath vtkGeodesicPath
 */
#ifndef vtkBoolSurfTraceCurves_h
#define vtkBoolSurfTraceCurves_h

#include "BoolSurfFiltersModule.h" // for export macro
#include "vtkBoolSurfAlgorithm.h"

#include <memory> // for std::unique_ptr

class BOOLSURFFILTERS_EXPORT vtkBoolSurfTraceCurves : public vtkBoolSurfAlgorithm
{
public:
  static vtkBoolSurfTraceCurves* New();
  vtkTypeMacro(vtkBoolSurfTraceCurves, vtkBoolSurfAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The surface (port 0) and the control polygons (port 1).
  void SetSurfaceConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(0, output); }
  void SetCurvesConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  ///@}

  ///@{
  /// De Casteljau subdivision levels of Bezier splines (default 4: 16 pieces per segment).
  vtkSetClampMacro(Resolution, int, 0, 16);
  vtkGetMacro(Resolution, int);
  ///@}

  ///@{
  /// Largest allowed distance from a control point to the surface, as a fraction of the
  /// surface's bounding-box diagonal (default 0.01). Farther points are errors.
  vtkSetClampMacro(ProjectionTolerance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(ProjectionTolerance, double);
  ///@}

  ///@{
  /// How each geodesic leg (between two consecutive points of a geodesic polygon or of a
  /// Bezier spline's refined control polygon) is computed:
  ///
  /// - GEODESIC_BOUNDED (0, default): the shortest path in practice at a bounded cost per leg.
  ///   The exact search is used while it stays small; past that, the leg is straightened in
  ///   the homotopy class of the route found on a coarse graph built once per surface.
  /// - GEODESIC_EXACT (1): the exact polyhedral shortest path (window propagation); it can take
  ///   seconds between far points on large meshes.
  /// - GEODESIC_LOCALLY_SHORTEST (2): the shortest mesh-edge path, straightened: the fastest,
  ///   but with no guarantee of being the shortest (it may pass on the wrong side of a bump, a
  ///   saddle or a handle).
  vtkSetClampMacro(GeodesicMethod, int, GEODESIC_BOUNDED, GEODESIC_LOCALLY_SHORTEST);
  vtkGetMacro(GeodesicMethod, int);
  void SetGeodesicMethodToBounded() { this->SetGeodesicMethod(GEODESIC_BOUNDED); }
  void SetGeodesicMethodToExact() { this->SetGeodesicMethod(GEODESIC_EXACT); }
  void SetGeodesicMethodToLocallyShortest() { this->SetGeodesicMethod(GEODESIC_LOCALLY_SHORTEST); }
  ///@}

  ///@{
  /// @deprecated Use SetGeodesicMethod(). Kept for existing scripts: on sets GeodesicMethod to
  /// GEODESIC_EXACT, off to GEODESIC_LOCALLY_SHORTEST; GetExactGeodesics() is 1 exactly when
  /// GeodesicMethod is GEODESIC_EXACT.
  void SetExactGeodesics(vtkTypeBool exact)
  {
    this->SetGeodesicMethod(exact ? GEODESIC_EXACT : GEODESIC_LOCALLY_SHORTEST);
  }
  vtkTypeBool GetExactGeodesics() { return this->GeodesicMethod == GEODESIC_EXACT ? 1 : 0; }
  void ExactGeodesicsOn() { this->SetExactGeodesics(1); }
  void ExactGeodesicsOff() { this->SetExactGeodesics(0); }
  ///@}

protected:
  vtkBoolSurfTraceCurves();
  ~vtkBoolSurfTraceCurves() override;

  bool Execute(const std::vector<vtkPolyData*>& inputs,
    const std::vector<vtkPolyData*>& outputs,
    std::string& error) override;
  void RecordFailure(const std::string& error, const std::vector<vtkPolyData*>& outputs) override;

  int Resolution = 4;
  double ProjectionTolerance = 0.01;
  int GeodesicMethod = GEODESIC_BOUNDED;

private:
  vtkBoolSurfTraceCurves(const vtkBoolSurfTraceCurves&) = delete;
  void operator=(const vtkBoolSurfTraceCurves&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif

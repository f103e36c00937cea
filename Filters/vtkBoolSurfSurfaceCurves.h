/**
 * @class   vtkBoolSurfSurfaceCurves
 * @brief   control curves drawn on a surface, given as properties
 *
 * vtkBoolSurfSurfaceCurves holds a user's drawing: control points, how they group into
 * curves, and each curve's shape, type and closure, all as properties (so ParaView's undo and
 * redo, state files and Python trace keep them, and an interactive widget can edit them).
 * Its output is the control-curves polydata every BoolSurf filter takes: one polyline per
 * curve (a closed curve repeats its first point), point data `TriangleId`/`Barycentric`
 * (exact surface points), cell data `ShapeId`, `CurveType` (0 geodesic polygon, 1 cubic
 * Bezier), `Closed`.
 *
 * Points: `Points` are 3D positions snapped to the closest point of the input surface,
 * unless `TriangleIds` (and `Barycentrics`, two weights per point: of the triangle's 2nd and
 * 3rd vertex) are given for every point, which place them exactly (a TriangleId of -1 snaps
 * that point's position instead: the curve editor keeps the points it placed exact and snaps
 * the one being dragged); the output positions are then computed from the surface points. Curves:
 * `CurveSizes` gives the number of control points of each curve in order (empty: all points are one
 * curve); per curve, `ShapeIds` (default: the curve's index), `CurveTypes` (default 0) and
 * `ClosedCurves` (default 1) may be shorter than the curve list, the defaults filling the rest.
 *
 * Errors (empty output) name the problem: sizes that do not add up to the number of points,
 * a TriangleId count that is neither 0 nor the number of points, a triangle id that is not a
 * triangle of the surface, barycentric weights outside the triangle, an empty surface.
 *
 * A curve with too few points for its type (one point; a closed Bezier curve whose size is not
 * a multiple of 3, an open one whose size is not 3n+1) is a curve being drawn, not an error:
 * the curve editor writes every click. It is in the output with cell data `Complete` 0, field
 * data `IncompleteCurves` says what each such curve still needs ("curve 2: an open cubic
 * Bezier spline needs 3n+1 control points ...; it has 5: 2 more complete it"), the filters
 * downstream leave it out without a message, and port 1 shows it as far as it is valid (a
 * Bezier curve up to its last complete segment). Every other curve has `Complete` 1.
 *
 * Port 1 gives the same curves traced on the surface (geodesic polygons and Bezier splines
 * with this filter's trace settings (vtkBoolSurfTracingAlgorithm: GeodesicMethod, the others
 * at Trace Surface Curves' defaults), as
 * vtkBoolSurfTraceCurves outputs them), for display:
 * it follows the control points as they are edited, and is empty (no message) while the
 * drawing cannot be traced yet. Filters take port 0.
 *
 * Under MPI the surface is gathered to rank 0, which alone produces the curves (see
 * vtkBoolSurfRankGather): the drawing exists once, not once per rank.
 *
 * @sa vtkBoolSurfTraceCurves vtkBoolSurf vtkBoolSurfSVGMapper
 */
#ifndef vtkBoolSurfSurfaceCurves_h
#define vtkBoolSurfSurfaceCurves_h

#include "BoolSurfFiltersModule.h" // for export macro
#include "vtkBoolSurfTracingAlgorithm.h"

#include <memory> // for std::unique_ptr
#include <vector> // for std::vector

class BOOLSURFFILTERS_EXPORT vtkBoolSurfSurfaceCurves : public vtkBoolSurfTracingAlgorithm
{
public:
  static vtkBoolSurfSurfaceCurves* New();
  vtkTypeMacro(vtkBoolSurfSurfaceCurves, vtkBoolSurfTracingAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Control points as 3D positions (snapped to the surface unless TriangleIds are given).
  void SetNumberOfPoints(int n);
  int GetNumberOfPoints() const { return static_cast<int>(this->Points.size() / 3); }
  void SetPoint(int i, double x, double y, double z);
  ///@}

  ///@{
  /// Exact surface points: a triangle of the surface and the weights of its 2nd and 3rd
  /// vertex, for every point (or none); -1 snaps that point's position.
  void SetNumberOfTriangleIds(int n);
  void SetTriangleId(int i, vtkIdType triangle);
  void SetNumberOfBarycentrics(int n);
  void SetBarycentric(int i, double u, double v);
  ///@}

  ///@{
  /// Per curve, in order: its number of control points, shape, type (0 geodesic polygon, 1
  /// cubic Bezier) and closure (1 closed, 0 open).
  void SetNumberOfCurveSizes(int n);
  void SetCurveSize(int i, int size);
  void SetNumberOfShapeIds(int n);
  void SetShapeId(int i, int shape);
  void SetNumberOfCurveTypes(int n);
  void SetCurveType(int i, int type);
  void SetNumberOfClosedCurves(int n);
  void SetClosedCurve(int i, int closed);
  ///@}

  /// Removes every point and curve.
  void RemoveAllCurves();

  // GeodesicMethod (how each geodesic leg of the traced curves of port 1 is computed) is
  // vtkBoolSurfTracingAlgorithm's, as for every filter that traces; the XML exposes only it.
  // The other trace settings keep Trace Surface Curves' defaults (the XML does not expose them).

protected:
  vtkBoolSurfSurfaceCurves();
  ~vtkBoolSurfSurfaceCurves() override;

  bool Execute(const std::vector<vtkPolyData*>& inputs,
    const std::vector<vtkPolyData*>& outputs,
    std::string& error) override;

  std::vector<double> Points;
  std::vector<vtkIdType> TriangleIds;
  std::vector<double> Barycentrics;
  std::vector<int> CurveSizes;
  std::vector<int> ShapeIds;
  std::vector<int> CurveTypes;
  std::vector<int> ClosedCurves;

private:
  vtkBoolSurfSurfaceCurves(const vtkBoolSurfSurfaceCurves&) = delete;
  void operator=(const vtkBoolSurfSurfaceCurves&) = delete;
  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif

/**
 * @class   vtkBoolSurfOffset
 * @brief   grow or shrink shapes by a geodesic distance: margins, insets and bands on a surface
 *
 * vtkBoolSurfOffset offsets shapes drawn on a triangle surface by a distance measured along the
 * surface (the exact polyhedral geodesic distance). With Distance d > 0 the result is every point
 * within d of the shape ("the region within 5 mm of this lesion"); with d < 0 the shape minus
 * every point within |d| of its boundary ("this area shrunk by 2 mm"); d = 0 gives the shape's
 * boundary back. Open curves of the offset shapes become bands within d of the curve, with
 * round or flat ends (EndStyle); in Bands mode every curve, closed ones too, becomes a band
 * ("a strip of width 2d along this curve", a band around a loop on a handle).
 *
 * The shape offset is a Boolean expression over the input's shapes (Expression, e.g.
 * "S0 | S2 - S1", with FillRule), or the union of the ShapeIds listed in Shapes, or of every
 * shape. Where fronts meet (a concave corner filling, two shapes merging, a hole or a handle
 * closing) the result is the true offset region, never a self-intersecting curve.
 *
 * Inputs are those of vtkBoolSurfTraceCurves: port 0 the surface, port 1 the control curves
 * (one polyline or polygon per curve, cell data ShapeId and CurveType, points projected or
 * given exactly as TriangleId/Barycentric). Curves without a ShapeId array are one shape, so
 * the Boundary output (port 1) of vtkBoolSurf, vtkBoolSurfBoolean or vtkBoolSurfBSC is offset
 * as the region it bounds: margins of any Boolean or BSC result. The output is control curves in
 * that same form, so it chains into vtkBoolSurfTraceCurves or the one-step vtkBoolSurf: the input
 * curves (KeepInputCurves), then the offset boundary as closed geodesic polygons of exact surface
 * points with ShapeId OutputShapeId (-1: one above the largest input ShapeId), one point per mesh
 * edge the boundary crosses plus OutputResolution points inside each crossed triangle. Cell data
 * OffsetCurve is 1 on offset loops, 0 on input curves; field data OffsetDistance,
 * OffsetShapeId, OffsetExpression and OffsetStatistics (boundary points, windows, reached
 * vertices, crossed triangles, slivers dropped, milliseconds).
 *
 * How: the exact distance to the shape's boundary by window propagation (its points as point
 * sources, its straight pieces as line sources), limited to the band the offset sweeps; the
 * level set at d of the signed distance located on mesh edges by bisection on that exact field,
 * with the sharp corners where two fronts meet kept. On a flat mesh growing matches Clipper's
 * offset with round joins. Errors name the problem: a distance that is not finite, a shape id
 * that no curve has, a negative distance larger than the shape (nothing would be left), an
 * inconsistent shape, a malformed expression.
 *
 * @sa vtkBoolSurf vtkBoolSurfTraceCurves vtkBoolSurfResolve
 */
#ifndef vtkBoolSurfOffset_h
#define vtkBoolSurfOffset_h

#include "BoolSurfFiltersModule.h" // for export macro
#include "vtkBoolSurfTracingAlgorithm.h"

#include <string> // for std::string

class BOOLSURFFILTERS_EXPORT vtkBoolSurfOffset : public vtkBoolSurfTracingAlgorithm
{
public:
  static vtkBoolSurfOffset* New();
  vtkTypeMacro(vtkBoolSurfOffset, vtkBoolSurfTracingAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Modes
  {
    REGION = 0, ///< the shape's region (and bands around its open curves)
    BANDS = 1,  ///< bands around every curve of the shape
  };
  enum EndStyles
  {
    ROUND_ENDS = 0,
    FLAT_ENDS = 1,
  };

  ///@{
  /// Geodesic distance in world units: > 0 grows, < 0 shrinks, 0 gives the boundary back.
  vtkSetMacro(Distance, double);
  vtkGetMacro(Distance, double);
  ///@}

  ///@{
  /// ShapeIds to offset (their union), separated by spaces or commas; empty: every shape.
  /// Ignored when Expression is set.
  vtkSetStdStringFromCharMacro(Shapes);
  vtkGetCharFromStdStringMacro(Shapes);
  ///@}

  ///@{
  /// A Boolean expression over the shapes ("S0 | S2 - S1", as in vtkBoolSurfBoolean) whose
  /// region is offset; empty (default): Shapes.
  vtkSetStdStringFromCharMacro(Expression);
  vtkGetCharFromStdStringMacro(Expression);
  ///@}

  ///@{
  /// How winding numbers make a shape's region (vtkBoolSurfBoolean's fill rules; default
  /// NonZero).
  vtkSetClampMacro(FillRule, int, 0, 3);
  vtkGetMacro(FillRule, int);
  ///@}

  ///@{
  /// REGION (default) offsets the shape's region; BANDS draws a band around every curve.
  vtkSetClampMacro(Mode, int, REGION, BANDS);
  vtkGetMacro(Mode, int);
  ///@}

  ///@{
  /// Ends of the bands around open curves: ROUND_ENDS (default) or FLAT_ENDS.
  vtkSetClampMacro(EndStyle, int, ROUND_ENDS, FLAT_ENDS);
  vtkGetMacro(EndStyle, int);
  ///@}

  ///@{
  /// Points of the offset curve inside each mesh triangle it crosses, besides its points on the
  /// mesh edges (default 0: one point per crossed edge). More follow round joins more closely.
  vtkSetClampMacro(OutputResolution, int, 0, 16);
  vtkGetMacro(OutputResolution, int);
  ///@}

  ///@{
  /// ShapeId of the offset curves; -1 (default): one above the largest input ShapeId.
  vtkSetClampMacro(OutputShapeId, int, -1, VTK_INT_MAX);
  vtkGetMacro(OutputShapeId, int);
  ///@}

  ///@{
  /// Copy the input curves to the output before the offset curves (default on), so the output
  /// feeds a Boolean between the offset and the other shapes directly.
  vtkSetMacro(KeepInputCurves, bool);
  vtkGetMacro(KeepInputCurves, bool);
  vtkBooleanMacro(KeepInputCurves, bool);
  ///@}

protected:
  vtkBoolSurfOffset();
  ~vtkBoolSurfOffset() override;

  bool Execute(const std::vector<vtkPolyData*>& inputs,
    const std::vector<vtkPolyData*>& outputs,
    std::string& error) override;

  double Distance = 0.0;
  std::string Shapes;
  std::string Expression;
  int FillRule = 0;
  int Mode = REGION;
  int EndStyle = ROUND_ENDS;
  int OutputResolution = 0;
  int OutputShapeId = -1;
  bool KeepInputCurves = true;

private:
  vtkBoolSurfOffset(const vtkBoolSurfOffset&) = delete;
  void operator=(const vtkBoolSurfOffset&) = delete;
};

#endif

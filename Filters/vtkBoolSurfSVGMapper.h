/**
 * @class   vtkBoolSurfSVGMapper
 * @brief   map an SVG drawing onto a surface as cubic geodesic Bezier curves
 *
 * vtkBoolSurfSVGMapper reads an SVG file (svgpp on libxml2: path data of every command, arcs
 * and quadratics as cubics, basic shapes as paths, transforms of paths and groups, fill-rule)
 * and places it on the input surface with the discrete exponential map around a center point
 * (straightest geodesics from the center: see Core/Svg/SvgSurfaceMap.h and
 * Docs/SvgMapping.md). Its output is control curves in the API's format, ready for
 * vtkBoolSurfTraceCurves or vtkBoolSurf: one polyline per subpath (a closed one repeats its
 * first point), `CurveType` 1 (cubic Bezier), `ShapeId` = the SVG shape element (so a glyph with
 * holes is one shape), `Closed`, exact `TriangleId`/`Barycentric` per control point; each shape's
 * subpaths are oriented so its filled area is on their left. Field data: `SuggestedFillRule`
 * ("EvenOdd" when every shape says evenodd, else "NonZero"), `ShapeEvenOdd` (per shape of the
 * drawing, before ShapeIdOffset),
 * `SvgWarnings`.
 *
 * Placement: the center is CenterTriangleId/CenterBarycentric when CenterTriangleId >= 0, else
 * the surface point closest to Center. Size: Scale (surface length per SVG unit) when > 0, else
 * Radius (the geodesic distance from the center to the farthest corner of the drawing's
 * bounding box; 0 means a tenth of the surface's bounding-box diagonal). Rotation in degrees,
 * counter-clockwise around the surface normal.
 *
 * Errors (empty output): no file name, a missing or malformed file, a drawing without any path,
 * a center triangle that is not a triangle of the surface, an empty surface.
 *
 * @sa vtkBoolSurfTraceCurves vtkBoolSurf
 */
#ifndef vtkBoolSurfSVGMapper_h
#define vtkBoolSurfSVGMapper_h

#include "BoolSurfFiltersModule.h" // for export macro
#include "vtkBoolSurfAlgorithm.h"

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class BOOLSURFFILTERS_EXPORT vtkBoolSurfSVGMapper : public vtkBoolSurfAlgorithm
{
public:
  static vtkBoolSurfSVGMapper* New();
  vtkTypeMacro(vtkBoolSurfSVGMapper, vtkBoolSurfAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The SVG file.
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}

  ///@{
  /// Where the drawing's center goes: the surface point closest to Center, unless
  /// CenterTriangleId >= 0 (default -1), which with CenterBarycentric gives it exactly.
  vtkSetVector3Macro(Center, double);
  vtkGetVector3Macro(Center, double);
  vtkSetMacro(CenterTriangleId, vtkIdType);
  vtkGetMacro(CenterTriangleId, vtkIdType);
  vtkSetVector2Macro(CenterBarycentric, double);
  vtkGetVector2Macro(CenterBarycentric, double);
  ///@}

  ///@{
  /// Size: Scale (surface length per SVG unit) when > 0; else Radius, the geodesic distance
  /// from the center to the drawing's farthest bounding-box corner (0: a tenth of the surface's
  /// bounding-box diagonal).
  vtkSetClampMacro(Scale, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Scale, double);
  vtkSetClampMacro(Radius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Radius, double);
  ///@}

  ///@{
  /// Added to every ShapeId (default 0), so that several drawings appended together keep
  /// their shapes apart.
  vtkSetClampMacro(ShapeIdOffset, int, 0, VTK_INT_MAX / 2);
  vtkGetMacro(ShapeIdOffset, int);
  ///@}

  ///@{
  /// Rotation of the drawing in degrees, counter-clockwise around the surface normal.
  vtkSetMacro(Rotation, double);
  vtkGetMacro(Rotation, double);
  ///@}

protected:
  vtkBoolSurfSVGMapper();
  ~vtkBoolSurfSVGMapper() override;

  bool Execute(const std::vector<vtkPolyData*>& inputs,
    const std::vector<vtkPolyData*>& outputs,
    std::string& error) override;

  std::string FileName;
  double Center[3] = { 0, 0, 0 };
  vtkIdType CenterTriangleId = -1;
  double CenterBarycentric[2] = { 1.0 / 3.0, 1.0 / 3.0 };
  double Scale = 0;
  double Radius = 0;
  double Rotation = 0;
  int ShapeIdOffset = 0;

private:
  vtkBoolSurfSVGMapper(const vtkBoolSurfSVGMapper&) = delete;
  void operator=(const vtkBoolSurfSVGMapper&) = delete;
};

#endif

/**
 * @class   vtkBoolSurfResolve
 * @brief   make inconsistent shapes consistent: add generators, duplicate reversed, remove curves
 *
 * A shape is inconsistent when the homology classes of its curves do not sum to zero (BoolSurf
 * §4.4, Theorem 1): its curves wind around handles of the surface and bound no region, and the
 * labeling cannot give it winding numbers. vtkBoolSurfResolve takes the same inputs as
 * vtkBoolSurfTraceCurves (port 0 the surface, port 1 the control curves: one polyline or
 * polygon per curve, cell data ShapeId and CurveType, points projected or given exactly as
 * TriangleId/Barycentric) and returns control curves in that same form in which every shape
 * with generators in excess is fixed by its strategy (paper Fig. 7, 8):
 *
 * - AddGenerators (0): reversed copies of the homology generators in excess, as many as their
 *   multiplicity; several copies of one generator cross each mesh edge at distinct places, so
 *   they never overlap. The shape becomes the region between its curves and the generators.
 * - DuplicateReversed (1, default): each curve that winds around the surface gets a reversed
 *   copy at distance Offset on its left (control points moved along normal x tangent in the
 *   surface and projected back onto it): the pair bounds a thin solid strip.
 * - RemoveCurves (2): the fewest curves whose removal (or flip, which counts twice) takes away
 *   exactly the excess; the curves left have classes summing to zero. When no such set exists
 *   the shape is left unchanged with a note.
 *
 * Strategy applies to every shape; ShapeStrategies overrides it per shape with a list such as
 * "3:RemoveCurves, 5:AddGenerators" (ShapeId, then a name or number). Consistent shapes are
 * copied unchanged with a note (field data ResolutionNotes).
 *
 * Output: one polyline per curve (closed ones repeat their first point id), point data
 * TriangleId/Barycentric (exact surface points), cell data ShapeId, CurveType, Closed,
 * Resolution (0 kept, 1 added generator, 2 duplicated reversed, 3 flipped), ResolutionSource
 * (input curve id, or generator id for added generators), ResolutionReason (text); field data
 * RemovedCurves + RemovedCurveReasons (curves RemoveCurves left out), TreatedShapes (ShapeIds
 * fixed) and ResolutionNotes (one sentence per shape). Feed it to vtkBoolSurfTraceCurves or the
 * one-step vtkBoolSurf.
 *
 * @sa vtkBoolSurfLabeling vtkBoolSurfTraceCurves vtkBoolSurf
 */
#ifndef vtkBoolSurfResolve_h
#define vtkBoolSurfResolve_h

#include "BoolSurfFiltersModule.h" // for export macro
#include "vtkBoolSurfTracingAlgorithm.h"

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class BOOLSURFFILTERS_EXPORT vtkBoolSurfResolve : public vtkBoolSurfTracingAlgorithm
{
public:
  static vtkBoolSurfResolve* New();
  vtkTypeMacro(vtkBoolSurfResolve, vtkBoolSurfTracingAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Strategies
  {
    ADD_GENERATORS = 0,
    DUPLICATE_REVERSED = 1,
    REMOVE_CURVES = 2,
  };

  ///@{
  /// Strategy for every shape not named in ShapeStrategies (default DuplicateReversed).
  vtkSetClampMacro(Strategy, int, ADD_GENERATORS, REMOVE_CURVES);
  vtkGetMacro(Strategy, int);
  ///@}

  ///@{
  /// Per-shape strategies, e.g. "3:RemoveCurves, 5:AddGenerators" (empty: none).
  vtkSetStdStringFromCharMacro(ShapeStrategies);
  vtkGetCharFromStdStringMacro(ShapeStrategies);
  ///@}

  ///@{
  /// DuplicateReversed: distance between a curve and its reversed copy, in world units; 0
  /// (default) uses a quarter of the mesh's mean edge length.
  vtkSetClampMacro(Offset, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Offset, double);
  ///@}

protected:
  vtkBoolSurfResolve();
  ~vtkBoolSurfResolve() override;

  bool Execute(const std::vector<vtkPolyData*>& inputs,
    const std::vector<vtkPolyData*>& outputs,
    std::string& error) override;

  int Strategy = DUPLICATE_REVERSED;
  std::string ShapeStrategies;
  double Offset = 0;

private:
  vtkBoolSurfResolve(const vtkBoolSurfResolve&) = delete;
  void operator=(const vtkBoolSurfResolve&) = delete;
};

#endif

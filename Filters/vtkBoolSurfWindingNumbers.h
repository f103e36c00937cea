/**
 * @class   vtkBoolSurfWindingNumbers
 * @brief   surface winding numbers of open, closed and broken curves, and the shapes they complete
 *
 * vtkBoolSurfWindingNumbers computes, per shape, the surface winding number w of its curves
 * (Feng, Gillespie and Crane, "Winding Numbers on Discrete Surfaces", SIGGRAPH 2023): a function
 * on the surface that jumps by exactly 1 across every curve, from its right to its left, and is
 * as smooth as it can be elsewhere. For closed curves that bound a region w is the region's
 * label (the winding numbers of vtkBoolSurfLabeling), exactly; for broken curves (gaps, open
 * ends, a sketch that does not quite close) it is a smooth completion of them, and the level set
 * {w = Threshold} closes the gaps. That level set is returned as control curves, so a broken
 * shape goes on to exact Booleans in vtkBoolSurf (or in one step: vtkBoolSurf's
 * CloseBrokenShapes). Docs/WindingNumbers.md explains the method.
 *
 * 1. the control curves are traced (as in vtkBoolSurfTraceCurves) and arranged (as in
 *    vtkBoolSurfArrangement): on the refined surface every curve runs along edges;
 * 2. w of each shape in Shapes: a jump lift built locally in the triangles the curves touch,
 *    plus a piecewise linear function on the mesh from one factorized cotan Laplacian per
 *    surface (an edit of the curves is a back-substitution); on surfaces of genus > 0, with
 *    RemoveNonBounding, curves that bound nothing (a torus meridian) are dropped;
 * 3. the level set {w = Threshold} of each shape, as closed loops of surface points.
 *
 * Inputs: port 0 the surface, port 1 the control curves (as for vtkBoolSurfTraceCurves: the
 * output of Surface Curves, Map SVG onto Surface or the scene reader; cell data ShapeId,
 * CurveType, optional string cell data ShapeName).
 *
 * Output port 0, "Refined Surface": the arrangement's refined surface exactly as
 * vtkBoolSurfArrangement writes it (so labeling and Booleans can take it), plus point data
 * `WindingNumber` (w at each point, one component per computed shape, named by the shape's
 * ShapeName or "Shape <id>"; on a curve the mean of its sides), cell data `WindingNumber` (w at
 * each triangle's centroid) and field data `WindingShapeIds` (the computed shapes, in component
 * order), `CellWindingNumber` (the area-weighted mean of w over each arrangement cell: cells x
 * shapes) and `WindingTimes` (milliseconds: Trace, Arrangement, Factorization, Lift, Solve,
 * Homology, LevelSet, Outputs, Total).
 *
 * Output port 1, "Region": the refined triangles where w >= Threshold for at least one computed
 * shape, with cell data `WindingNumber`, `SourceTriangle`, `ArrangementCell`, point data
 * TriangleId/Barycentric and the input surface's own arrays, as BoolSurf's region.
 *
 * Output port 2, "Completed Curves": the level set of each shape as control curves in the form
 * Surface Curves writes (point data TriangleId/Barycentric; cell data ShapeId, CurveType 0,
 * Closed 1, CurveId, and ShapeName when the input has it): one closed geodesic polygon per loop
 * whose control points are all the loop's points, the region on its left. Feeding it to
 * vtkBoolSurf as its curves gives exact Booleans of the completed shapes.
 *
 * Output port 3, "Curves": the input curves traced (as vtkBoolSurfTraceCurves writes them), with
 * cell data `WindingResidual` (how far the curve is from bounding a region: the
 * length-weighted share of it that does not sit between integer levels of w; 0 for a closed
 * curve that bounds, small for a broken one, 1 for a spur; -1 for a shape not computed) and
 * `BoundsRegion` (1, or 0 for a curve that bounds nothing; -1 for a shape not computed), and
 * field data `NonBoundingCurves` (ShapeId, CurveId of each curve that bounds nothing; absent
 * when there is none). Each such curve is also named in a warning.
 *
 * Errors (empty outputs) name the problem: no curves, a Shapes entry that is not a shape id or
 * that no curve has, a curve that cannot be read or traced (non-finite points, too few points:
 * the checks of vtkBoolSurfTraceCurves), a threshold that is not finite.
 *
 * @sa vtkBoolSurf vtkBoolSurfArrangement vtkBoolSurfLabeling vtkBoolSurfOffset
 */
#ifndef vtkBoolSurfWindingNumbers_h
#define vtkBoolSurfWindingNumbers_h

#include "BoolSurfFiltersModule.h" // for export macro
#include "vtkBoolSurfTracingAlgorithm.h"

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class BOOLSURFFILTERS_EXPORT vtkBoolSurfWindingNumbers : public vtkBoolSurfTracingAlgorithm
{
public:
  static vtkBoolSurfWindingNumbers* New();
  vtkTypeMacro(vtkBoolSurfWindingNumbers, vtkBoolSurfTracingAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The surface (port 0) and the control curves (port 1).
  void SetSurfaceConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(0, output); }
  void SetCurvesConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  ///@}

  ///@{
  /// ShapeIds whose winding numbers are computed, separated by spaces or commas ("0 2");
  /// empty (default): every shape of the curves, ascending.
  vtkSetStdStringFromCharMacro(Shapes);
  vtkGetCharFromStdStringMacro(Shapes);
  ///@}

  ///@{
  /// The level of the completed region {w >= Threshold} and of the completed curves
  /// (default 0.5).
  vtkSetMacro(Threshold, double);
  vtkGetMacro(Threshold, double);
  ///@}

  ///@{
  /// Drop what bounds nothing (default on): on surfaces of genus > 0 the curves whose homology
  /// class the shape does not need (a torus meridian, which would otherwise give w a ramp
  /// around the handle), and spurs and overshooting ends.
  vtkSetMacro(RemoveNonBounding, bool);
  vtkGetMacro(RemoveNonBounding, bool);
  vtkBooleanMacro(RemoveNonBounding, bool);
  ///@}

  /// The region {w >= Threshold} (port 1).
  vtkPolyData* GetRegionOutput() { return this->GetOutput(1); }
  /// The completed curves (port 2).
  vtkPolyData* GetCompletedCurvesOutput() { return this->GetOutput(2); }
  /// The traced input curves with their residuals (port 3).
  vtkPolyData* GetCurvesOutput() { return this->GetOutput(3); }

protected:
  vtkBoolSurfWindingNumbers();
  ~vtkBoolSurfWindingNumbers() override;

  bool Execute(const std::vector<vtkPolyData*>& inputs,
    const std::vector<vtkPolyData*>& outputs,
    std::string& error) override;

  std::string Shapes;
  double Threshold = 0.5;
  bool RemoveNonBounding = true;

private:
  vtkBoolSurfWindingNumbers(const vtkBoolSurfWindingNumbers&) = delete;
  void operator=(const vtkBoolSurfWindingNumbers&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif

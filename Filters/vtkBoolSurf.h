/**
 * @class   vtkBoolSurf
 * @brief   Boolean operations between shapes drawn on a surface, in one filter
 *
 * vtkBoolSurf chains the BoolSurf stages for users who want the answer: trace the control
 * polygons on the surface (vtkBoolSurfTraceCurves), arrange the curves
 * (vtkBoolSurfArrangement), label the cells with winding numbers (vtkBoolSurfLabeling) and
 * select the result of a Boolean operation (vtkBoolSurfBoolean). Its properties are those of
 * the stages; see their documentation for the details. The trace settings (Resolution,
 * ProjectionTolerance, GeodesicMethod, NumberOfThreads) are vtkBoolSurfTracingAlgorithm's:
 * they also trace the curves resolved or offset first and the control points of ports 2 and 3,
 * and NumberOfThreads is the arrangement's too.
 *
 * Inputs: port 0 the surface, port 1 the control polygons (cell data `ShapeId`,
 * `CurveType`; optional point data `TriangleId`/`Barycentric`). Outputs: port 0 the selected
 * region as surface triangles carrying cell data `ArrangementCell`, `SourceTriangle`, point
 * data `TriangleId`/`Barycentric` and the input surface's own arrays, and field data
 * `ShapeIds`, `ShapeConsistent`, `CellLabels` (the labels of every arrangement cell, one
 * component per shape: row ArrangementCell gives a triangle's labels), `Expression` and
 * `StageTimes` (milliseconds of this update per stage: Trace, Hash, Intersections,
 * Refinement, FloodFill, CellGraph, Labeling, Selection, Output, ControlCurves, Total; 0 for
 * the stages reused from the previous update; then the same update's time per output port,
 * Port0Region, Port1Boundary, Port2BoundaryControlCurves, Port3ClippedCurves, each with the
 * one pass that stores its arrays' ranges for ParaView, also counted in Output); port 1 its
 * boundary as oriented polylines (region on the left) with point data `TriangleId`/`Barycentric`.
 *
 * Speed: the surface's adjacency, topology, locator and geodesic search state are built once
 * and reused while only the curves or the operation change; an edit reuses the arrangement's
 * buffers, labels only the cells (never per triangle), and writes only the region, so its cost
 * is the curves' work, the flood fill of the refined surface and the region's size. When only
 * the Boolean properties change, the labeled arrangement is reused and the update costs the
 * selection (once per cell) and the region.
 *
 * Vector output (paper §3.5, §4.5): port 2 gives the region's boundary as control points of
 * sub-curves of the input curves (one polyline per piece of a curve between two intersection
 * points: polygon vertices plus the intersection points, Bezier pieces split by geodesic de
 * Casteljau insertion; cell data BoundaryLoop, SourceCurveId, SourceShapeId, Reversed,
 * ParameterRange, CurveType), so tracing them again gives the boundary; port 3 gives the
 * pieces of open input curves (Closed 0) inside the region, the same way (cell data
 * ClippedPiece). Open curves never bound cells: they are clipped by the region.
 *
 * Selection = BSC (Boundary-Sampled Curves, see vtkBoolSurfBSC) replaces the Boolean by the
 * region chosen by oriented samples: port 2 (optional) holds points with point data
 * `Direction` (and optionally exact `TriangleId`/`Barycentric`); the outputs then carry the
 * BSC field data (`SampleOnBoundary`, `DroppedSamples`, ...) instead of `Expression`. Changing
 * only the samples reuses the labeled arrangement, like a change of the Boolean properties.
 *
 * Under MPI, a surface split across ranks (RedistributeDataSet, D3 or a parallel reader; its
 * pieces' point and cell GlobalIds name the triangles, generated with a warning when the pieces
 * have none) is not gathered: the stages run on each rank's piece as the stage filters do there
 * (Docs/Parallel.md, "What runs on each rank's piece"). Port 0 is then the rank's part of the
 * region (the union over ranks is the one-rank region) with the arrays above and
 * `ArrangementOnPieces`, `StageTimes` and `PieceBytes` the rank's own; port 1 the boundary
 * loops, whole on rank 0; ports 2 and 3 stay empty (a warning on rank 0 says so). Between
 * updates the tracing's and the arrangement's pieces and the labeled arrangement are kept, as
 * the stage filters keep them. Selection BSC, ResolveStrategy, OffsetShape, CloseBrokenShapes and what Trace
 * Surface Curves cannot trace on pieces (the LocallyShortest method, control points given by
 * position) gather the surface to rank 0 instead, with a warning naming why.
 *
 * @sa vtkBoolSurfTraceCurves vtkBoolSurfArrangement vtkBoolSurfLabeling vtkBoolSurfBoolean
 * vtkBoolSurfBSC
 */
#ifndef vtkBoolSurf_h
#define vtkBoolSurf_h

#include "BoolSurfFiltersModule.h"    // for export macro
#include "vtkBoolSurfStageSettings.h" // for the stages' settings
#include "vtkBoolSurfTracingAlgorithm.h"

#include <memory> // for std::unique_ptr
#include <string> // for std::string

namespace boolsurf
{
struct vtkSurfaceInput;
}

class BOOLSURFFILTERS_EXPORT vtkBoolSurf : public vtkBoolSurfTracingAlgorithm
{
public:
  static vtkBoolSurf* New();
  vtkTypeMacro(vtkBoolSurf, vtkBoolSurfTracingAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The surface (port 0) and the control polygons (port 1).
  void SetSurfaceConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(0, output); }
  void SetCurvesConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  /// BSC samples (port 2, optional; read when Selection is BSC).
  void SetSamplesConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(2, output); }
  ///@}

  ///@{
  /// How the region is chosen: 0 Boolean (Operation, ShapeA, ...), 1 BSC (samples on port 2,
  /// see vtkBoolSurfBSC).
  enum Selections
  {
    BOOLEAN_SELECTION = 0,
    BSC_SELECTION = 1,
  };
  vtkSetClampMacro(Selection, int, BOOLEAN_SELECTION, BSC_SELECTION);
  vtkGetMacro(Selection, int);
  void SetSelectionToBoolean() { this->SetSelection(BOOLEAN_SELECTION); }
  void SetSelectionToBSC() { this->SetSelection(BSC_SELECTION); }
  /// BSC: SnapTolerance and MaxSearchStates, as vtkBoolSurfBSC's (declared once in
  /// vtkBoolSurfStageSettings.h, held in the same boolsurf::BscOptions).
  vtkBoolSurfBSCSettingsMacro();
  ///@}

  /// Labeling: ZeroCellMode and ZeroCellPoint, as vtkBoolSurfLabeling's; Boolean: Operation,
  /// ShapeA, ShapeB, Expression, FillRule, as vtkBoolSurfBoolean's (each group declared once in
  /// vtkBoolSurfStageSettings.h and held in the stage's Core options struct,
  /// boolsurf::ZeroCellOptions and boolsurf::BooleanOptions).
  vtkBoolSurfZeroCellSettingsMacro();
  vtkBoolSurfBooleanSettingsMacro();

  // The optional steps' settings below are declared here, not shared with the stage filters
  // (vtkBoolSurfResolve, vtkBoolSurfOffset, vtkBoolSurfWindingNumbers): their names and
  // defaults differ from the stages' on purpose. Each switches its step on, with an "off" value
  // the stage does not have (ResolveStrategy -1, OffsetShape -1, an empty CloseBrokenShapes),
  // and takes one value where the stage takes a list or an expression (OffsetShape for Shapes
  // or Expression; ResolveStrategy for every shape, where Resolve also takes ShapeStrategies).

  ///@{
  /// Inconsistent shapes (curves not null-homologous): -1 (default) labels them as they are,
  /// and Booleans refuse them; 0 AddGenerators, 1 DuplicateReversed, 2 RemoveCurves first
  /// resolve every such shape with that strategy (see vtkBoolSurfResolve), with
  /// ResolveOffset for DuplicateReversed (0: automatic). The region's field data
  /// `ResolutionNotes` then says what was done per shape.
  vtkSetClampMacro(ResolveStrategy, int, -1, 2);
  vtkGetMacro(ResolveStrategy, int);
  vtkSetClampMacro(ResolveOffset, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(ResolveOffset, double);
  ///@}

  ///@{
  /// Optional step before the Boolean: offset shape OffsetShape (its region; -1, the default:
  /// none) by the geodesic distance OffsetDistance (> 0 grows, < 0 shrinks), as
  /// vtkBoolSurfOffset does, and use the offset in its place in the Boolean. The region's
  /// field data OffsetStatistics says what it cost.
  vtkSetClampMacro(OffsetShape, int, -1, VTK_INT_MAX);
  vtkGetMacro(OffsetShape, int);
  vtkSetMacro(OffsetDistance, double);
  vtkGetMacro(OffsetDistance, double);
  ///@}

  ///@{
  /// Optional step after tracing: the curves of the shapes listed in CloseBrokenShapes
  /// (ShapeIds separated by spaces or commas; empty, the default: none) are replaced by their
  /// completed curves, the level set {w = WindingThreshold} (default 0.5) of their surface
  /// winding number, as vtkBoolSurfWindingNumbers computes them, before the arrangement: broken
  /// shapes (gaps, open ends) get exact Booleans with the other shapes. The region's field data
  /// `WindingNotes` names each replaced curve with its residual (also given as text messages);
  /// a curve that bounds nothing is named in a warning.
  vtkSetStdStringFromCharMacro(CloseBrokenShapes);
  vtkGetCharFromStdStringMacro(CloseBrokenShapes);
  vtkSetMacro(WindingThreshold, double);
  vtkGetMacro(WindingThreshold, double);
  ///@}

  ///@{
  /// Whether ports 2 and 3 are computed (default on): the result's boundary and the clipped
  /// open curves as control points of the input curves (see Docs/VectorOutput.md). Off leaves
  /// them empty and saves their cost (geodesic de Casteljau splits of Bezier curves).
  vtkSetMacro(ComputeControlCurves, vtkTypeBool);
  vtkGetMacro(ComputeControlCurves, vtkTypeBool);
  vtkBooleanMacro(ComputeControlCurves, vtkTypeBool);
  ///@}

  /// The boundary output (port 1).
  vtkPolyData* GetBoundaryOutput() { return this->GetOutput(1); }
  /// The boundary as control points of sub-curves of the input curves (port 2).
  vtkPolyData* GetBoundaryControlCurvesOutput() { return this->GetOutput(2); }
  /// The pieces of open input curves inside the region, as control points (port 3).
  vtkPolyData* GetClippedCurvesOutput() { return this->GetOutput(3); }

protected:
  vtkBoolSurf();
  ~vtkBoolSurf() override;

  bool Execute(const std::vector<vtkPolyData*>& inputs,
    const std::vector<vtkPolyData*>& outputs,
    std::string& error) override;
  /// A surface split across ranks with GlobalIds: the stages run on each rank's piece
  /// (vtkBoolSurfPieceOneStep.h), except for the steps StepsNotOnPieces() names.
  bool ExecutesOnPieces() const override { return true; }
  bool PiecesNeedGlobalIds() const override { return true; }
  bool ExecutePiece(const std::vector<vtkPolyData*>& locals,
    const std::vector<vtkPolyData*>& outputs,
    std::string& error) override;

  int Selection = BOOLEAN_SELECTION;
  int ResolveStrategy = -1;
  double ResolveOffset = 0;
  int OffsetShape = -1;
  double OffsetDistance = 0;
  std::string CloseBrokenShapes;
  double WindingThreshold = 0.5;
  vtkTypeBool ComputeControlCurves = 1;

private:
  vtkBoolSurf(const vtkBoolSurf&) = delete;
  void operator=(const vtkBoolSurf&) = delete;

  /// Why the settings need the surface gathered to one rank (empty: they run on pieces).
  std::string StepsNotOnPieces() const;
  /// Trace, arrange and label the curves on the (valid) surface, into Internal.
  bool LabelCurves(const boolsurf::vtkSurfaceInput& surface,
    vtkPolyData* curves,
    std::string& error);
  /// Selected cells from the samples (BSC); false with a named error.
  bool SelectBySamples(const boolsurf::vtkSurfaceInput& surface,
    vtkPolyData* samples,
    vtkPolyData* surfaceInput,
    std::string& error);
  /// The arrangement cell at ZeroCellPoint, or -1 and a message.
  int FindZeroCell(const boolsurf::vtkSurfaceInput& surface, std::string& error);
  /// Expression, labels table and StageTimes on the outputs.
  void WriteFieldData(const std::string& expression,
    bool reused,
    double selectionTime,
    double outputTime,
    vtkPolyData* region,
    vtkPolyData* boundary);

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif

/**
 * @class   vtkBoolSurfBSC
 * @brief   Boundary-Sampled Curves: the region chosen by oriented samples on the curves
 *
 * vtkBoolSurfBSC selects arrangement cells from samples placed on the curves instead of a
 * Boolean expression (BoolSurf §3.2; Du et al. 2021, "Boundary-Sampled Halfspaces"). Each
 * sample is a point on or near a curve with a point-data vector `Direction` pointing to the
 * side that must be inside. The result is the region that keeps every sampled patch on its
 * boundary with the sample's side inside (samples that cannot all be kept are dropped, as few
 * as possible), has the least boundary length among those, and whose every connected piece of
 * a curve on the boundary holds a sample. Labels are not read: inconsistent arrangements
 * (non-contractible curves) work too. A curve that separates nothing (the same cell on both
 * sides, e.g. a lone torus meridian) is ignored and its samples are dropped.
 *
 * Inputs: port 0 the refined surface (port 0 of vtkBoolSurfArrangement, or the output of
 * vtkBoolSurfLabeling); port 1 the samples: points with point data `Direction` (3
 * components). Each sample snaps to the nearest patch within SnapTolerance (a fraction of the
 * surface's bounding-box diagonal).
 *
 * Outputs as vtkBoolSurfBoolean: port 0 the region (triangles with every array of the refined
 * surface), port 1 its boundary as oriented polylines (region on the left, point data
 * `TriangleId`/`Barycentric`, cell data `Closed`). Both carry field data `SamplePatch`,
 * `SampleDistance`, `SampleOnBoundary` (1 when the sample ended on the boundary, 0 dropped),
 * `DroppedSamples` (sample ids), `BoundaryLength`, `BSCCuts` and `Selection` = "BSC".
 *
 * Errors name the sample: no `Direction` array, NaN coordinates or direction, zero-length
 * direction, a direction along the curve, no patch within the tolerance. The output is then
 * empty.
 *
 * @sa vtkBoolSurfBoolean vtkBoolSurfArrangement vtkBoolSurf
 */
#ifndef vtkBoolSurfBSC_h
#define vtkBoolSurfBSC_h

#include "BoolSurfFiltersModule.h" // for export macro
#include "vtkBoolSurfAlgorithm.h"
#include "vtkBoolSurfStageSettings.h" // for the BSC settings

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class BOOLSURFFILTERS_EXPORT vtkBoolSurfBSC : public vtkBoolSurfAlgorithm
{
public:
  static vtkBoolSurfBSC* New();
  vtkTypeMacro(vtkBoolSurfBSC, vtkBoolSurfAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The refined surface (port 0) and the samples (port 1).
  void SetSurfaceConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(0, output); }
  void SetSamplesConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  ///@}

  /// The BSC settings, shared with vtkBoolSurf (see vtkBoolSurfStageSettings.h):
  /// SnapTolerance, how far a sample may be from its patch as a fraction of the surface's
  /// bounding-box diagonal (default 0.01), and MaxSearchStates, the minimum cuts the best-first
  /// search for a sample-connected region may compute before it finishes greedily (default 64).
  vtkBoolSurfBSCSettingsMacro();

  /// The boundary output (port 1).
  vtkPolyData* GetBoundaryOutput() { return this->GetOutput(1); }
  /// The boundary as control points of sub-curves of the input curves (port 2) and the open
  /// curves clipped by the region (port 3), as vtkBoolSurf's ports 2 and 3; empty, with a
  /// warning, when the arrangement's curves were not traced by vtkBoolSurfTraceCurves.
  vtkPolyData* GetBoundaryControlCurvesOutput() { return this->GetOutput(2); }
  vtkPolyData* GetClippedCurvesOutput() { return this->GetOutput(3); }

protected:
  vtkBoolSurfBSC();
  ~vtkBoolSurfBSC() override;

  bool Execute(const std::vector<vtkPolyData*>& inputs,
    const std::vector<vtkPolyData*>& outputs,
    std::string& error) override;

private:
  struct Internals;
  std::unique_ptr<Internals> Internal;

  vtkBoolSurfBSC(const vtkBoolSurfBSC&) = delete;
  void operator=(const vtkBoolSurfBSC&) = delete;
};

#endif

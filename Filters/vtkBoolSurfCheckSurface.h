/**
 * @class   vtkBoolSurfCheckSurface
 * @brief   validate a triangle surface for BoolSurf and report its topology
 *
 * vtkBoolSurfCheckSurface runs the checks every BoolSurf stage relies on and passes the
 * surface through, annotated:
 *
 * - cell data `ComponentId` (int): connected component of each triangle (components are
 *   connected through edges), -1 for triangles that take no part in the topology;
 * - point data `BoundaryLoopId` (int): the boundary loop a point lies on, -1 inside;
 * - field data `Components` (1 value), and per component `Genus`, `BoundaryLoops`,
 *   `EulerCharacteristic`; `IsManifold` (1 value, 0 or 1); `BoundaryLoopLength` (one value
 *   per loop); `Problems` (string array, one entry per problem found, "Error <Kind>: ..."
 *   or "Warning <Kind>: ..."). Per-component and per-loop arrays are absent when there is
 *   no component or no loop (VTK's XML writer cannot store empty numeric arrays).
 *
 * Problems found: empty input, NaN/inf coordinates (point ids), triangles with out-of-range
 * or repeated point ids, degenerate (zero-area) triangles, non-manifold edges (named by their
 * point ids), non-manifold vertices, inconsistently oriented neighbours (triangle pairs),
 * non-orientable components, unreferenced points. Non-triangle polygons and strips are
 * triangulated and vertex/line cells ignored, each with a warning naming how many.
 *
 * Under MPI, a surface split across ranks (RedistributeDataSet, D3, a parallel reader) is
 * checked where it is: each rank outputs its own piece's triangles (ghost cells dropped)
 * annotated with the numbers of the undistributed surface (components by their smallest global
 * cell id, boundary loops by their first half-edge in global cell id order), and the same field
 * data on every rank. Problems then name triangles by global cell id.
 *
 * The filter never fails on a bad surface: it reports. The genus of a component is
 * (2 - boundary loops - Euler characteristic) / 2, or -1 when it is not orientable; a
 * non-manifold vertex is counted once per fan of triangles around it.
 *
 * @sa vtkFeatureEdges vtkPolyDataConnectivityFilter
 */
#ifndef vtkBoolSurfCheckSurface_h
#define vtkBoolSurfCheckSurface_h

#include "BoolSurfFiltersModule.h" // for export macro
#include "vtkBoolSurfAlgorithm.h"

namespace boolsurf
{
struct SurfaceCheckOutput;
}

class BOOLSURFFILTERS_EXPORT vtkBoolSurfCheckSurface : public vtkBoolSurfAlgorithm
{
public:
  static vtkBoolSurfCheckSurface* New();
  vtkTypeMacro(vtkBoolSurfCheckSurface, vtkBoolSurfAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * A triangle is degenerate when twice its area is at most this times its longest squared
   * edge. Scale-free; default 1e-12.
   */
  vtkSetClampMacro(DegenerateTolerance, double, 0.0, 1.0);
  vtkGetMacro(DegenerateTolerance, double);
  ///@}

  ///@{
  /**
   * When on (default), each problem found is also issued as a VTK warning, so that ParaView
   * shows it in its Output Messages window.
   */
  vtkSetMacro(WarnOnProblems, bool);
  vtkGetMacro(WarnOnProblems, bool);
  vtkBooleanMacro(WarnOnProblems, bool);
  ///@}

protected:
  vtkBoolSurfCheckSurface();
  ~vtkBoolSurfCheckSurface() override = default;

  bool Execute(const std::vector<vtkPolyData*>& inputs,
    const std::vector<vtkPolyData*>& outputs,
    std::string& error) override;
  /// Under MPI with the surface split across ranks: each rank checks its own piece and the
  /// topology is combined across the shared border (vtkBoolSurfDistributedCheck.h).
  bool ExecutesOnPieces() const override { return true; }
  bool ExecutePiece(const std::vector<vtkPolyData*>& locals,
    const std::vector<vtkPolyData*>& outputs,
    std::string& error) override;

  double DegenerateTolerance = 1e-12;
  bool WarnOnProblems = true;

private:
  /// The triangles annotated with the check's arrays, into `output`.
  void WriteOutput(vtkPolyData* triangles,
    const boolsurf::SurfaceCheckOutput& check,
    vtkPolyData* output);

  vtkBoolSurfCheckSurface(const vtkBoolSurfCheckSurface&) = delete;
  void operator=(const vtkBoolSurfCheckSurface&) = delete;
};

#endif

/**
 * @class   vtkBoolSurfAlgorithm
 * @brief   base of the BoolSurf filters: inputs gathered to one rank, empty outputs on failure
 *
 * Every BoolSurf filter needs its whole input at once, reports a failure as an error naming the
 * problem, and must then leave empty outputs (never the previous result, which ParaView would
 * keep showing as if it were this one's). vtkBoolSurfAlgorithm does that once for all of them,
 * as TTK's ttkAlgorithm does for TTK's filters:
 *
 * - RequestData gathers the inputs to the computing rank (vtkBoolSurfRankGather: rank 0 under
 *   MPI, the process itself otherwise), empties every output, and calls Execute() there only;
 * - when Execute() returns false, its message is reported with vtkErrorMacro, every output is
 *   emptied again, and RequestData still returns success (vtkBoolSurfErrorReported explains
 *   why: a failed update must not freeze the views downstream);
 * - GetSurface() converts a surface input to the Core mesh once and keeps it while the input
 *   does not change (adjacency, topology, geodesic tracer, homology basis), reporting the
 *   conversion notes (triangulated polygons, dropped lines) as warnings;
 * - GetTracedCurves(), GetArrangement() and GetLabeledArrangement() give a stage's Core result
 *   for an input, as ttkAlgorithm::GetTriangulation gives TTK's triangulation: the one the
 *   upstream stage attached (vtkBoolSurfStageHandoff.h), or one decoded from the input's
 *   arrays when none is attached (a file, a deep copy, an edited array), so each filter has one
 *   body over Core types;
 * - every input port takes vtkPolyData; SetInputPortOptional() marks the optional ones.
 *
 * Subclasses set their port counts in their constructor and implement Execute().
 *
 * @sa vtkBoolSurfRankGather
 */
#ifndef vtkBoolSurfAlgorithm_h
#define vtkBoolSurfAlgorithm_h

#include "BoolSurfFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class vtkBoolSurfPieceGlobalIds;

#include <array>  // for std::array
#include <memory> // for std::unique_ptr
#include <string> // for std::string
#include <vector> // for std::vector

namespace boolsurf
{
class vtkSurfaceCache;
class RebuiltArrangement;
struct vtkSurfaceInput;
struct TracedCurvesResult;
struct ArrangementResult;
struct LabeledArrangementResult;
}

class BOOLSURFFILTERS_EXPORT vtkBoolSurfAlgorithm : public vtkPolyDataAlgorithm
{
public:
  vtkTypeMacro(vtkBoolSurfAlgorithm, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Values of the GeodesicMethod property of the filters that trace geodesics
  /// (vtkBoolSurfTraceCurves, vtkBoolSurf, vtkBoolSurfSurfaceCurves, vtkBoolSurfResolve); see
  /// vtkBoolSurfTraceCurves::SetGeodesicMethod for what each one guarantees and costs.
  enum GeodesicMethods
  {
    GEODESIC_BOUNDED = 0,
    GEODESIC_EXACT = 1,
    GEODESIC_LOCALLY_SHORTEST = 2,
  };
  /// "Bounded", "Exact" or "LocallyShortest" (the names of boolsurf::GeodesicMethod).
  static const char* GetGeodesicMethodName(int method);

protected:
  vtkBoolSurfAlgorithm();
  ~vtkBoolSurfAlgorithm() override;

  /// The filter's work, on the computing rank only. inputs[p] is input port p (gathered; null
  /// for an optional port left unconnected); every output is already empty. Return false with
  /// `error` set to fail: the base class reports it and empties the outputs.
  virtual bool Execute(const std::vector<vtkPolyData*>& inputs,
    const std::vector<vtkPolyData*>& outputs,
    std::string& error) = 0;

  /// A filter that works on each rank's piece of a surface distributed across MPI ranks
  /// (port 0; see vtkBoolSurfSurfacePiece) returns true: when two or more ranks hold triangles
  /// of it, ExecutePiece() runs on every rank instead of gathering the inputs to the first.
  virtual bool ExecutesOnPieces() const { return false; }
  /// A filter on pieces that names the surface by the undistributed surface's ids (the
  /// distributed arrangement, the tracing and the control points on pieces) returns true: when
  /// the pieces carry no point or cell GlobalIds, vtkGenerateGlobalIds gives them (with a
  /// warning; vtkBoolSurfPieceGlobalIds.h says what they number) and locals[0] is the piece
  /// with them.
  virtual bool PiecesNeedGlobalIds() const { return false; }
  /// The work of such a filter on this rank's inputs: locals[p] is this rank's own data on
  /// input port p, not gathered (locals[0] its piece of the surface, possibly empty; null for
  /// an optional port left unconnected). A filter whose other inputs live on one rank only (the
  /// traced curves, on the first) sends what the pieces need itself. Called on every rank,
  /// which must all take part in the same collective calls before anything can fail.
  virtual bool ExecutePiece(const std::vector<vtkPolyData*>& locals,
    const std::vector<vtkPolyData*>& outputs,
    std::string& error);
  /// Called by ExecutePiece() on every rank alike (a decision all ranks share) before it
  /// returns true: the update then gathers the inputs to the first rank and runs Execute()
  /// there, as for a surface held by one rank (Trace Surface Curves, for what its tracing on
  /// pieces cannot do).
  void GatherInsteadOfPieces() { this->PiecesGatherInstead = true; }

  /// Called after a failed Execute(), with the outputs emptied: a filter may record the failure
  /// in them (Trace Surface Curves lists its problems in field data `TraceErrors`).
  virtual void RecordFailure(const std::string& error, const std::vector<vtkPolyData*>& outputs);

  /// The usable surface converted from `input` (cached while the input is unchanged); its
  /// conversion notes are reported as warnings. Null, with every problem in `error`, when the
  /// surface cannot be used.
  const boolsurf::vtkSurfaceInput* GetSurface(vtkPolyData* input, std::string& error);
  /// The cache behind GetSurface(): the surface's tracer, locator and homology live there.
  boolsurf::vtkSurfaceCache& GetSurfaceCache();

  /// The traced curves of `curves` (Trace Surface Curves' output) on `surface`, converted from
  /// `surfaceInput`: the result Trace Surface Curves attached when it traced them on this very
  /// surface, else decoded from the arrays (TriangleId/Barycentric, and the control points when
  /// the arrays carry them; the geodesic method is then Bounded, as the arrays do not say it).
  /// Null, with a message naming the curve and point, when the arrays are not traced curves.
  std::shared_ptr<const boolsurf::TracedCurvesResult> GetTracedCurves(vtkPolyData* curves,
    vtkPolyData* surfaceInput,
    const boolsurf::vtkSurfaceInput& surface,
    std::string& error);
  /// The arrangement of `input` (port 0 of Surface Arrangement or Winding Numbers, or a copy
  /// further down): the one attached to its ArrangementCell array, else computed again from its
  /// field data (vtkBoolSurfArrangementRebuild.h: read from a file, deep-copied or edited
  /// since). Null, with `error` naming what is missing or differs.
  std::shared_ptr<const boolsurf::ArrangementResult> GetArrangement(vtkPolyData* input,
    std::string& error);
  /// The labeled arrangement of `input`: the one Label Arrangement Cells attached to CellLabels,
  /// else GetArrangement() with the labels of the CellLabels table when the input has one, or
  /// labeled with the automatic zero cell as the one-step filter labels it. Null, with `error`,
  /// as for GetArrangement.
  std::shared_ptr<const boolsurf::LabeledArrangementResult> GetLabeledArrangement(
    vtkPolyData* input,
    std::string& error);

  /// Each line as a warning of this filter.
  void ReportWarnings(const std::vector<std::string>& lines);

  /// Optional input ports may be left unconnected (Execute() then gets null).
  void SetInputPortOptional(int port);
  /// Input ports whose pieces are parts of one surface under MPI (coincident points merged when
  /// gathered); default: port 0 only.
  void SetSurfacePorts(const std::vector<int>& ports);

  int FillInputPortInformation(int port, vtkInformation* info) override;
  vtkExecutive* CreateDefaultExecutive() override;
  int RequestData(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) final;

private:
  /// RequestData for a surface distributed across ranks: ExecutePiece() on every rank.
  int RunOnPiece(const std::vector<vtkPolyData*>& locals, vtkInformationVector* outputVector);
  /// A failed Execute or ExecutePiece: empty outputs, RecordFailure, the error reported.
  int Fail(const std::string& error, const std::vector<vtkPolyData*>& outputs);

  std::vector<int> SurfacePorts{ 0 };
  bool PiecesGatherInstead = false;
  std::vector<int> OptionalPorts;
  std::unique_ptr<boolsurf::vtkSurfaceCache> Surface;
  /// The pieces' generated GlobalIds, kept while the pieces are unchanged.
  std::unique_ptr<vtkBoolSurfPieceGlobalIds> PieceIds;
  /// The arrangement GetArrangement() last computed again for an input without one.
  std::unique_ptr<boolsurf::RebuiltArrangement> Rebuilt;
  /// Per output port: how many point, cell and field arrays the last update wrote (the next
  /// update reserves that many slots at once; see RequestData).
  std::vector<std::array<int, 3>> ArrayCounts;

  vtkBoolSurfAlgorithm(const vtkBoolSurfAlgorithm&) = delete;
  void operator=(const vtkBoolSurfAlgorithm&) = delete;
};

#endif

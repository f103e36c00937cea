// The arrangement's data contract in VTK form (a private header of the module): writing the
// refined surface and patches, and reading back what downstream filters need from port 0's
// field data. Array names are part of the public API (see vtkBoolSurfArrangement.h).
#ifndef vtkBoolSurfArrangementOutput_h
#define vtkBoolSurfArrangementOutput_h

#include "Arrangement/Arrangement.h"
#include "Arrangement/RefinedSurfaceArrays.h"
#include "Labeling/CellLabeling.h"
#include "Selection/RegionBoundary.h"
#include "vtkBoolSurfAttributeTransfer.h"
#include "vtkBoolSurfSurfaceAdapter.h"

#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkSmartPointer.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

class vtkDataArray;
class vtkPointData;
class vtkPolyData;

namespace boolsurf
{

/// The memory the refined surface's arrays read in place (vtkBoolSurfArrayView.h): the Core
/// result that owns the arrangement, kept alive and unchanged while any array reads it, and
/// buffers of the result's for what VTK stores in another form than the arrangement: the cell
/// offsets 0, 3, 6, ... (extended only when the surface grows) and each point's TriangleId and
/// Barycentric (the arrangement keeps one struct per point). Buffers keep their capacity
/// between the edits that reuse the result, so an edit touches no fresh memory for them.
struct ArrangementMemory
{
  std::shared_ptr<const void> Owner;
  std::vector<int>* CellOffsets = nullptr;
  std::vector<vtkIdType>* PointTriangle = nullptr;
  std::vector<double>* PointBarycentric = nullptr;
  /// The mesh whose vertices' surface points the two buffers above already hold in their first
  /// entries (0: none), updated here: the arrangement numbers the mesh vertices first and never
  /// changes them, so an edit on the same mesh fills only the curves' points.
  std::uint64_t* PointArraysMeshSerial = nullptr;
  std::vector<int>* TriangleCells = nullptr;
  WrittenTriangleCells* WrittenCells = nullptr;
  /// The refined surface's points, triangles and source triangles, updated per edit.
  RefinedSurfaceArrays* Surface = nullptr;
  /// The input surface's own arrays as carried onto the refined surface, updated per edit
  /// (null: carried whole every time).
  CarriedAttributes* Attributes = nullptr;
};

/// The arrangement stage: computes the arrangement of `curves` into `arrangement` (reusing
/// its buffers) with `options` and writes port 0 (`refined`) and, when not null, port 1
/// (`patches`) with as many threads. False with a message naming the curve and point.
bool ArrangeCurves(const vtkSurfaceInput& surface,
  const std::vector<TracedCurve>& curves,
  const ArrangementOptions& options,
  Arrangement& arrangement,
  const ArrangementMemory& memory,
  vtkPolyData* refined,
  vtkPolyData* patches,
  std::string& error);

struct ArrangementResult;
struct CurveSource;

/// ArrangeCurves of a stage result's curves into its arrangement and the VTK arrays it keeps
/// (the Surface Arrangement and Winding Numbers filters' stage): on failure the message also
/// names the curve point as the user gave it (`sources`, may be empty).
bool ArrangeResult(const std::shared_ptr<ArrangementResult>& result,
  const std::vector<CurveSource>& sources,
  const ArrangementOptions& options,
  vtkPolyData* refined,
  vtkPolyData* patches,
  std::string& error);

/// Polys of `output`: `count` triangles, corner k of triangle t at corners[3 t + k] (a bulk
/// copy into the connectivity array, offsets 0, 3, 6, ...), written on `threads` (0: all).
void SetTriangles(const int* corners, vtkIdType count, vtkPolyData* output, int threads = 0);

/// Point data TriangleId/Barycentric: each point as a point of the input surface (written on
/// `threads`, 0: all).
void AddSurfacePointArrays(const std::vector<SurfacePoint>& points,
  vtkPointData* pointData,
  int threads = 0);

/// Port 0: refined triangles, ArrangementCell/SourceTriangle, TriangleId/Barycentric, the
/// input's arrays, and the cell graph, patches and zero-cell candidates as field data. Points,
/// triangles, ArrangementCell and SourceTriangle read `arrangement` in place (it must live in
/// `memory.Owner`), as do TriangleId/Barycentric, filled by `threads` (0: all) into `memory`.
void WriteArrangementSurface(const vtkSurfaceInput& surface,
  const std::vector<TracedCurve>& curves,
  const Arrangement& arrangement,
  const ArrangementMemory& memory,
  vtkPolyData* output,
  int threads = 0);

/// Port 1: patches as polylines over the refined surface's points.
void WriteArrangementPatches(const Arrangement& arrangement,
  vtkPolyData* refinedSurface,
  vtkPolyData* patches);

/// Cell data `ArrangementCell` as ints (the arrangement writes a vtkIntArray; any other type is
/// converted).
std::vector<int> ReadTriangleCells(vtkDataArray* arrangementCell);

} // namespace boolsurf

#endif

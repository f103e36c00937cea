// The arrangement's data contract in VTK form (a private header of the module): writing the
// refined surface and patches, and reading back what downstream filters need from port 0's
// field data. Array names are part of the public API (see vtkBoolSurfArrangement.h).
#ifndef vtkBoolSurfArrangementOutput_h
#define vtkBoolSurfArrangementOutput_h

#include "Arrangement/Arrangement.h"
#include "Labeling/CellLabeling.h"
#include "Selection/RegionBoundary.h"
#include "vtkBoolSurfSurfaceAdapter.h"

#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkSmartPointer.h>

#include <memory>
#include <string>
#include <vector>

class vtkDataArray;
class vtkPointData;
class vtkPolyData;

namespace boolsurf
{

/// The per-point arrays of a refined surface (TriangleId, Barycentric: the Core arrangement
/// stores them as one struct per point, so they are copies), kept by Surface Arrangement
/// between updates: writing into fresh memory costs a page fault per 4 KB and releasing it an
/// unmap; a set no output holds any more is written again in place instead. A set still
/// referenced downstream is never touched.
class RefinedSurfaceArrays
{
public:
  struct Set
  {
    vtkSmartPointer<vtkIdTypeArray> TriangleId;
    vtkSmartPointer<vtkDoubleArray> Barycentric;
  };
  /// A set of arrays no one else holds (new ones when every kept set is in use).
  Set& Acquire();

private:
  std::vector<Set> Sets;
  std::size_t Next = 0;
};

/// The memory the refined surface's arrays read in place (vtkBoolSurfArrayView.h): the Core
/// result that owns the arrangement, kept alive and unchanged while any array reads it, and a
/// buffer of the result's for the cell offsets 0, 3, 6, ... (grown in place, never shrunk).
struct ArrangementMemory
{
  std::shared_ptr<const void> Owner;
  std::vector<int>* CellOffsets = nullptr;
};

/// The arrangement stage: computes the arrangement of `curves` into `arrangement` (reusing
/// its buffers) and writes port 0 (`refined`) and, when not null, port 1 (`patches`). False
/// with a message naming the curve and point.
bool ArrangeCurves(const vtkSurfaceInput& surface,
  const std::vector<TracedCurve>& curves,
  int threads,
  Arrangement& arrangement,
  const ArrangementMemory& memory,
  RefinedSurfaceArrays& arrays,
  vtkPolyData* refined,
  vtkPolyData* patches,
  std::string& error);

/// Polys of `output`: `count` triangles, corner k of triangle t at corners[3 t + k] (a bulk
/// copy into the connectivity array, offsets 0, 3, 6, ...).
void SetTriangles(const int* corners, vtkIdType count, vtkPolyData* output);

/// Point data TriangleId/Barycentric: each point as a point of the input surface.
void AddSurfacePointArrays(const std::vector<SurfacePoint>& points, vtkPointData* pointData);

/// Port 0: refined triangles, ArrangementCell/SourceTriangle, TriangleId/Barycentric, the
/// input's arrays, and the cell graph, patches and zero-cell candidates as field data. Points,
/// triangles, ArrangementCell and SourceTriangle read `arrangement` in place (it must live in
/// `memory.Owner`); `threads` (0: all) fill the rest concurrently into `arrays`.
void WriteArrangementSurface(const vtkSurfaceInput& surface,
  const std::vector<TracedCurve>& curves,
  const Arrangement& arrangement,
  const ArrangementMemory& memory,
  RefinedSurfaceArrays& arrays,
  vtkPolyData* output,
  int threads = 0);

/// Port 1: patches as polylines over the refined surface's points.
void WriteArrangementPatches(const Arrangement& arrangement,
  vtkPolyData* refinedSurface,
  vtkPolyData* patches);

/// What labeling and Booleans read back from a refined surface.
struct ArrangementFields
{
  int NumberOfCells = 0;
  int NumberOfShapes = 0;
  std::vector<int> ShapeIds; ///< sorted; arcs name shapes by index into it
  std::vector<CellArc> Arcs;
  std::vector<int> CellComponent;
  std::vector<int> ZeroCellCandidates;
  std::vector<BoundaryPatch> Patches;
  std::vector<int> PatchShape, PatchCurve;
  std::vector<int> PatchClosed; ///< 1 a closed curve's patch; empty: all closed (older files)
};

/// Cell data `ArrangementCell` as ints (the arrangement writes a vtkIntArray; any other type is
/// converted).
std::vector<int> ReadTriangleCells(vtkDataArray* arrangementCell);

/// Reads the field data and cell data `ArrangementCell`; false with a message naming the
/// missing array when `input` is not an arrangement output.
bool ReadArrangementFields(vtkPolyData* input, ArrangementFields& out, std::string& error);

} // namespace boolsurf

#endif

// Core results handed from one stage filter to the next (a private header of the module).
//
// Each stage filter writes its result as VTK arrays, for display, files and users' scripts. It
// also attaches its immutable Core result to one of those arrays, the witness: the TriangleId
// point array of Trace Surface Curves, the ArrangementCell cell array of Surface Arrangement,
// the CellLabels field array of Label Arrangement Cells. A downstream stage that finds the
// witness in its input, unchanged, takes the Core result instead of reading the arrays back:
// the stage chain then runs the one-step filter's code on the one-step filter's data, so it
// gives the same answer bit for bit, and skips the round trip through arrays.
//
// The result lives in the witness array's own vtkInformation. Shallow copies share the array,
// so they carry the result; an upstream update writes new arrays with a new result (or arrays
// that nothing but the filter holds any more, see ResultPool), so it never changes
// what a copy already holds. A witness changed since (its MTime or size differs from
// when the result was attached, e.g. edited in a script or deep-copied into another array), or
// an input read from a file, has no usable result: the result is decoded from the arrays (the
// traced curves read, the arrangement computed again: vtkBoolSurfArrangementRebuild.h).
// Filters ask for a result through vtkBoolSurfAlgorithm (GetTracedCurves, GetArrangement,
// GetLabeledArrangement), which finds the attached one here or decodes it.
#ifndef vtkBoolSurfStageHandoff_h
#define vtkBoolSurfStageHandoff_h

#include "Arrangement/Arrangement.h"
#include "Arrangement/RefinedSurfaceArrays.h"
#include "Labeling/CellLabeling.h"
#include "Selection/BoundaryControlPoints.h"
#include "vtkBoolSurfAttributeTransfer.h"
#include "vtkBoolSurfSurfaceAdapter.h"

#include <vtkSmartPointer.h>
#include <vtkStaticCellLocator.h>
#include <vtkType.h>
#include <vtkWeakPointer.h>

#include <memory>
#include <typeinfo>
#include <vector>

class vtkAbstractArray;
class vtkCellArray;
class vtkDataArray;
class vtkPolyData;

namespace boolsurf
{

class CurveTracer;
class GeodesicPathSolver;

/// Which surface a result was computed on: the input's points and polygons, by identity and
/// modification time (the stage filters of one pipeline share the surface's arrays).
class SurfaceIdentity
{
public:
  SurfaceIdentity() = default;
  explicit SurfaceIdentity(vtkPolyData* surface);
  /// True when `surface` has the same point and polygon arrays, unmodified.
  bool Matches(vtkPolyData* surface) const;

private:
  vtkWeakPointer<vtkDataArray> Points;
  vtkWeakPointer<vtkCellArray> Polys;
  vtkMTimeType PointsTime = 0, PolysTime = 0;
  vtkIdType NumberOfPoints = -1, NumberOfPolys = -1;
};

/// Trace Surface Curves -> Surface Arrangement: the traced curves and their control points.
struct TracedCurvesResult
{
  SurfaceIdentity Surface;
  std::vector<TracedCurve> Curves;
  std::vector<CurveSource> Sources;
  /// How the legs were traced; the control points of results are traced the same way.
  GeodesicMethod Method = GeodesicMethod::Bounded;
  /// Under MPI: the curves as the pieces of a split surface need them (message 0,
  /// vtkBoolSurfCurvesMessage.h); empty otherwise.
  std::vector<long long> PieceMessage;
};

/// Surface Arrangement -> labeling and selections: the arrangement with what it was computed
/// from (the converted surface keeps the input's own arrays, carried to regions).
struct ArrangementResult
{
  vtkSurfaceInput Surface;
  std::vector<TracedCurve> Curves;
  std::vector<CurveSource> Sources; ///< empty when the curves came without control points
  /// The traced curves' method (Bounded for curves read from arrays), for the control points.
  GeodesicMethod Method = GeodesicMethod::Bounded;
  boolsurf::Arrangement Arrangement;
  /// What the refined surface's VTK arrays read in place: the points and triangles (Whole), the
  /// cell offsets 0, 3, 6, ... and each point's TriangleId and Barycentric (ArrangementMemory).
  std::vector<int> CellOffsets;
  std::vector<vtkIdType> PointTriangle;
  std::vector<double> PointBarycentric;
  std::uint64_t PointArraysMeshSerial = 0;
  /// Each refined triangle's cell: the arrangement keeps cells per tile of the mesh, the
  /// ArrangementCell array needs one per triangle.
  std::vector<int> TriangleCells;
  WrittenTriangleCells WrittenCells; ///< what TriangleCells holds per tile (edits rewrite less)
  RefinedSurfaceArrays Whole;   ///< port 0's points, triangles and sources (edits rewrite less)
  CarriedAttributes Attributes; ///< port 0's copies of the input's arrays (edits rewrite less)
};

/// Label Arrangement Cells -> Surface Boolean / Boundary Sampled Curves.
struct LabeledArrangementResult
{
  std::shared_ptr<const ArrangementResult> Arranged;
  LabelingResult Labels;
};

/// A cell locator on a surface, built again only when the surface (its identity or MTime)
/// changes.
class SurfaceLocator
{
public:
  vtkStaticCellLocator* Get(vtkPolyData* surface);

private:
  vtkSmartPointer<vtkStaticCellLocator> Locator;
  vtkWeakPointer<vtkPolyData> Surface;
  vtkMTimeType Time = 0;
};

/// A geodesic path solver on a result's mesh for the control points of results, kept while
/// the mesh stays the same.
class ResultPathSolver
{
public:
  ResultPathSolver();
  ~ResultPathSolver();
  /// The solver on `mesh`, set to `method` (the method the result's curves were traced with).
  GeodesicPathSolver& Get(const std::shared_ptr<const TriangleMesh>& mesh, GeodesicMethod method);

private:
  std::shared_ptr<const TriangleMesh> Mesh;
  std::unique_ptr<CurveTracer> Tracer;
};

/// The note of a selection whose arrangement carries no control points of its curves.
extern const char* const NoControlPointsNote;

/// Attaches `result` to `witness` (which must be fully written: its current MTime is recorded).
void AttachStageResult(vtkAbstractArray* witness,
  std::shared_ptr<const void> result,
  const std::type_info& type);

/// The result of type `type` attached to `witness`, or null (no witness, none attached, another
/// type, or the witness changed since).
std::shared_ptr<const void> FindStageResult(vtkAbstractArray* witness, const std::type_info& type);

template <class T>
void AttachStageResult(vtkAbstractArray* witness, std::shared_ptr<const T> result)
{
  AttachStageResult(witness, std::static_pointer_cast<const void>(result), typeid(T));
}

template <class T>
std::shared_ptr<const T> FindStageResult(vtkAbstractArray* witness)
{
  return std::static_pointer_cast<const T>(FindStageResult(witness, typeid(T)));
}

/// Results a filter writes into, reused when no output holds them any more: a chain of filters
/// holds the last one or two downstream, so a few slots let an edit reuse the buffers of the
/// one before (no fresh allocation of a million-triangle arrangement per edit), while a result
/// still referenced is never overwritten.
template <class T>
class ResultPool
{
public:
  /// A result no one else holds (its contents are whatever an earlier update left).
  std::shared_ptr<T> Acquire()
  {
    for (std::shared_ptr<T>& slot : this->Slots)
    {
      if (slot.use_count() == 1)
      {
        return slot;
      }
    }
    auto fresh = std::make_shared<T>();
    if (this->Slots.size() < Capacity)
    {
      this->Slots.push_back(fresh);
    }
    else
    {
      this->Slots[this->Next] = fresh; // the old one lives on in its holders only
      this->Next = (this->Next + 1) % Capacity;
    }
    return fresh;
  }
  void Clear() { this->Slots.clear(); }

private:
  static constexpr std::size_t Capacity = 2;
  std::vector<std::shared_ptr<T>> Slots;
  std::size_t Next = 0;
};

} // namespace boolsurf

#endif

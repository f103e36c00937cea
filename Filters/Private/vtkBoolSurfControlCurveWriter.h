// The one writer of control curves as VTK arrays (a private header of the module), the form
// ReadControlCurves reads back: Surface Curves, the SVG mapper, the resolve and offset stages
// and the winding numbers' completed curves all write through it.
#ifndef vtkBoolSurfControlCurveWriter_h
#define vtkBoolSurfControlCurveWriter_h

#include "Curves/ControlCurve.h"

#include <vtkNew.h>

#include <functional>
#include <string>

class vtkCellArray;
class vtkDoubleArray;
class vtkIdTypeArray;
class vtkIntArray;
class vtkPoints;
class vtkPolyData;
class vtkStringArray;

namespace boolsurf
{

/// Control curves in the form every BoolSurf filter reads (Surface Curves' output): one
/// polyline per curve (a closed curve repeats its first point id), exact surface points (point
/// data TriangleId/Barycentric) and their 3D points, cell data ShapeId, CurveType and Closed,
/// plus an optional int mark per curve (`markName`, e.g. OffsetCurve), optional CurveId and
/// ShapeName cell data. A writer adds its own arrays to the output after Write.
class ControlCurveWriter
{
public:
  /// The 3D point of a surface point.
  using PositionOf = std::function<Vec3(const SurfacePoint&)>;

  /// `markName`: the name of the int cell array holding each curve's mark; null: none.
  /// `curveIds`: write cell data CurveId (each curve's CurveId). `shapeNames`: write cell data
  /// ShapeName.
  explicit ControlCurveWriter(const TriangleMesh& mesh,
    const char* markName = nullptr,
    bool curveIds = false,
    bool shapeNames = false);
  /// Positions from `position`, for a writer without a TriangleMesh (Surface Curves places its
  /// points on the VTK surface itself).
  explicit ControlCurveWriter(PositionOf position);
  ~ControlCurveWriter();

  void Add(const ControlCurve& curve, int mark = 0, const std::string& shapeName = std::string());

  /// Points, lines and arrays into `output` (which should be empty).
  void Write(vtkPolyData* output);

private:
  PositionOf Position;
  vtkNew<vtkPoints> Points;
  vtkNew<vtkCellArray> Lines;
  vtkNew<vtkIdTypeArray> TriangleId;
  vtkNew<vtkDoubleArray> Barycentric;
  vtkNew<vtkIntArray> Shape, Type, Closed, Mark, CurveId;
  vtkNew<vtkStringArray> ShapeName;
  bool WriteMark = false, WriteCurveIds = false, WriteShapeNames = false;
};

} // namespace boolsurf

#endif

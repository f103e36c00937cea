// The one writer of control curves as VTK arrays (a private header of the module), the form
// ReadControlCurves reads back: Surface Curves, the SVG mapper, the scene reader, the resolve
// and offset stages and the winding numbers' completed curves all write through it.
#ifndef vtkBoolSurfControlCurveWriter_h
#define vtkBoolSurfControlCurveWriter_h

#include "Curves/ControlCurve.h"

#include <vtkNew.h>

#include <functional>
#include <string>
#include <vector>

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
  /// points on the VTK surface itself); empty when every curve comes with its positions.
  explicit ControlCurveWriter(PositionOf position,
    const char* markName = nullptr,
    bool curveIds = false,
    bool shapeNames = false);
  ~ControlCurveWriter();

  void Add(const ControlCurve& curve, int mark = 0, const std::string& shapeName = std::string());
  /// `curve` at the 3D points its caller already has (`positions`, one per control point: a
  /// scene's placed points, written as placed).
  void Add(const ControlCurve& curve, const std::vector<Vec3>& positions);

  /// Points, lines and arrays into `output` (which should be empty).
  void Write(vtkPolyData* output);

private:
  void AddCurve(const ControlCurve& curve,
    const std::vector<Vec3>* positions,
    int mark,
    const std::string& shapeName);

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

// Results given back as control curves (a private header of the module): the sub-curves of
// Core's BoundaryControlPoints written as polydata in the control-curves format that
// vtkBoolSurfTraceCurves reads, so they can be traced again, saved as a scene or edited.
#ifndef vtkBoolSurfControlOutput_h
#define vtkBoolSurfControlOutput_h

#include "Selection/BoundaryControlPoints.h"

#include <vtkNew.h>

#include <string>
#include <vector>

class vtkCellArray;
class vtkDoubleArray;
class vtkFieldData;
class vtkIdTypeArray;
class vtkIntArray;
class vtkPoints;
class vtkPolyData;
class vtkStringArray;

namespace boolsurf
{

/// Control curves in the form every BoolSurf filter reads (Surface Curves' output): one
/// polyline per curve (a closed curve repeats its first point id), exact surface points (point
/// data TriangleId/Barycentric), cell data ShapeId, CurveType and Closed, plus an optional int
/// mark per curve (`markName`, e.g. OffsetCurve), optional CurveId and ShapeName cell data.
class ControlCurveWriter
{
public:
  /// `markName`: the name of the int cell array holding each curve's mark; null: none.
  /// `curveIds`: write cell data CurveId. `shapeNames`: write cell data ShapeName.
  explicit ControlCurveWriter(const TriangleMesh& mesh,
    const char* markName = nullptr,
    bool curveIds = false,
    bool shapeNames = false);
  ~ControlCurveWriter();

  void Add(const std::vector<SurfacePoint>& points,
    int shape,
    int type,
    bool closed,
    int mark = 0,
    int curveId = -1,
    const std::string& shapeName = std::string());

  /// Points, lines and arrays into `output` (which should be empty).
  void Write(vtkPolyData* output);

private:
  const TriangleMesh& Mesh;
  vtkNew<vtkPoints> Points;
  vtkNew<vtkCellArray> Lines;
  vtkNew<vtkIdTypeArray> TriangleId;
  vtkNew<vtkDoubleArray> Barycentric;
  vtkNew<vtkIntArray> Shape, Type, Closed, Mark, CurveId;
  vtkNew<vtkStringArray> ShapeName;
  bool WriteMark, WriteCurveIds, WriteShapeNames;
};

/// One polyline per sub-curve (a whole closed curve repeats its first point), point data
/// TriangleId and Barycentric (exact surface points) and 3D points; cell data ShapeId (0 for
/// boundary pieces, which together bound one region; the source shape for clipped pieces),
/// CurveType, Closed, SourceCurveId, SourceShapeId, Reversed, ParameterRange (the source
/// curve's parameters, segment index + fraction) and `groupName` (BoundaryLoop or
/// ClippedPiece) holding each sub-curve's Group.
void WriteControlSubCurves(const std::vector<ControlSubCurve>& curves,
  const char* groupName,
  bool boundary,
  vtkPolyData* output);

/// What the traced curves polydata of vtkBoolSurfTraceCurves says of each curve's control points
/// (field data ControlOffsets/ControlTriangleId/ControlBarycentric, point data CurveParameter,
/// cell data CurveType, Closed, ShapeId, CurveId), in the order of ReadTracedCurves. False when it
/// does not say it (curves traced elsewhere, or an older file).
bool ReadCurveSources(vtkPolyData* traced,
  const std::vector<TracedCurve>& curves,
  std::vector<CurveSource>& out);

/// The sub-curve of every patch (forward along its curve) as field data of `fd`:
/// PatchControlOffsets, PatchControlTriangleId, PatchControlBarycentric, PatchControlPosition,
/// PatchParameterRange and PatchControlInfo (components CurveIndex, CurveType, Segments,
/// CurveClosed, SourceShapeId, SourceCurveId, Whole).
void WritePatchControlCurves(const std::vector<ControlSubCurve>& perPatch, vtkFieldData* fd);

/// Reads what WritePatchControlCurves wrote; false when `fd` does not hold it.
bool ReadPatchControlCurves(vtkFieldData* fd, std::vector<ControlSubCurve>& perPatch);

} // namespace boolsurf

#endif

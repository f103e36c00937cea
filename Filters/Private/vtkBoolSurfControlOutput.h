// Results given back as control curves (a private header of the module): the sub-curves of
// Core's BoundaryControlPoints written as polydata in the control-curves format that
// vtkBoolSurfTraceCurves reads, so they can be traced again, saved as a scene or edited.
#ifndef vtkBoolSurfControlOutput_h
#define vtkBoolSurfControlOutput_h

#include "Selection/BoundaryControlPoints.h"

#include <string>
#include <vector>

class vtkFieldData;
class vtkPolyData;

namespace boolsurf
{

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

} // namespace boolsurf

#endif

// Reading of the "control polygons" input of vtkBoolSurfTraceCurves (a private header of the
// module): one polyline or polygon cell per curve, cell data `ShapeId` and `CurveType`,
// points either projected onto the surface or given exactly as `TriangleId`/`Barycentric`
// point data.
#ifndef vtkBoolSurfControlCurves_h
#define vtkBoolSurfControlCurves_h

#include "Curves/ControlCurve.h"
#include "Mesh/ClosestTriangleGrid.h"
#include "Mesh/SurfacePoint.h"

#include <functional>
#include <string>
#include <vector>

class vtkPolyData;

namespace boolsurf
{

/// A control curve as read from the curves input, with what the input says of it beyond the
/// curve (CurveId is its cell id in the input).
struct InputControlCurve : ControlCurve
{
  /// The input's own cell data `CurveId` for this cell (a scene's polygon index), for messages;
  /// -1 when the input has none.
  long long InputCurveId = -1;
  /// Still being drawn (read as far as it is valid): written with cell data Complete 0.
  bool BeingDrawn = false;
  std::vector<long long> PointIds; ///< input point id of each control point
};

struct ControlCurveOptions
{
  /// Largest allowed distance from a control point to the surface, absolute.
  double MaximumDistance = 0;
  /// Curves still being drawn (cell data Complete 0): read as far as they are valid (a
  /// Bezier curve up to its last complete segment, open) instead of left out.
  bool TraceValidPartOfIncompleteCurves = false;
  /// The surface is split across ranks and `mesh` is empty (Trace Surface Curves on pieces):
  /// control points must be given exactly (see NamesSurfacePoints); their triangles are
  /// checked by the ranks owning them, here only their barycentric coordinates.
  bool TrianglesOnPieces = false;
};

/// Whether the points of `curves` are given exactly as surface points (point data
/// TriangleId/Barycentric, or the control points traced curves carry), so that reading them
/// needs no closest-point search on the surface.
bool NamesSurfacePoints(vtkPolyData* curves);

/// The ShapeIds (sorted, distinct) of the curves of `curves` marked as being drawn (cell data
/// Complete 0); empty when there are none.
std::vector<int> ShapesBeingDrawn(vtkPolyData* curves);

/// Whether `curves` is a drawing (Surface Curves' field data Drawing): curves a user is
/// drawing, where a shape not drawn yet is an empty shape rather than an error.
bool IsDrawing(vtkPolyData* curves);

/// Whether `curves` is a drawing (Surface Curves' field data Drawing) without a complete
/// curve yet: empty, or only curves being drawn. Filters give no region then, without a
/// message (the user is starting to draw).
bool IsDrawingWithoutCurves(vtkPolyData* curves);

/// When `input` is a drawing without a complete curve yet (IsDrawingWithoutCurves: Surface
/// Curves' output as the user starts drawing, or what a stage passed on for it), empties
/// `outputs` and marks each as such (field data Drawing), so that every stage down the chain
/// does the same: no region yet and no message. Returns whether it did.
bool PassOnDrawingStart(vtkPolyData* input, const std::vector<vtkPolyData*>& outputs);
/// Every output emptied and marked as a drawing being started (field data Drawing), as
/// PassOnDrawingStart marks them (a filter on pieces whose curves live on another rank).
void MarkDrawingStart(const std::vector<vtkPolyData*>& outputs);

/// Reads every line and polygon cell of `curves` (vertex cells and strips are ignored with a
/// note in `notes`). A curve marked as being drawn (cell data Complete 0, as Surface Curves
/// writes for a curve with too few points) is left out without a message (see
/// ControlCurveOptions::TraceValidPartOfIncompleteCurves). Each problem met (named by curve id and
/// point id) is appended to `problems`; the curve it concerns is left out of `out`. `closest` gives
/// the closest-point grid of `mesh`; it is asked for only when a control point must be projected,
/// so curves given exactly never build one.
void ReadControlCurves(vtkPolyData* curves,
  const std::function<const ClosestTriangleGrid&()>& closest,
  const TriangleMesh& mesh,
  const ControlCurveOptions& options,
  std::vector<InputControlCurve>& out,
  std::vector<std::string>& problems,
  std::vector<std::string>& notes);

/// What the readers do with a curve once its points are read: a curve being drawn (BeingDrawn)
/// is cut to its valid part (a Bezier curve to its complete segments, open); a curve without
/// two distinct points is left out (with a note unless it is being drawn), a Bezier curve of a
/// count its closedness cannot trace is a problem. Returns whether `curve` is kept.
bool AcceptControlCurve(InputControlCurve& curve,
  std::vector<std::string>& problems,
  std::vector<std::string>& notes);

} // namespace boolsurf

#endif

// Surface winding numbers on VTK data, shared by vtkBoolSurfWindingNumbers ("Winding Numbers")
// and the one-step vtkBoolSurf filter's CloseBrokenShapes option (a private header of the
// module): shape lists and names, the completed curves of broken shapes, and messages.
#ifndef vtkBoolSurfWindingStage_h
#define vtkBoolSurfWindingStage_h

#include "Selection/BoundaryControlPoints.h"
#include "Winding/SurfaceWinding.h"
#include "Winding/WindingLevelSet.h"
#include "vtkBoolSurfControlCurves.h"

#include <map>
#include <string>
#include <vector>

class vtkPolyData;

namespace boolsurf
{

/// Shape ids from a property's text: ids separated by spaces, commas or semicolons, each
/// optionally written S<id> ("0 2", "S0, S2"). False with a message naming `property` and the
/// entry that is not a shape id.
bool ParseShapeList(const std::string& text,
  const char* property,
  std::vector<int>& ids,
  std::string& error);

/// False with a message naming the first id of `requested` that no curve of `curves` has, and
/// the shape ids the curves do have.
bool CheckShapesExist(const std::vector<TracedCurve>& curves,
  const std::vector<int>& requested,
  const char* property,
  std::string& error);

/// The name of each shape: cell data ShapeName of the control curves (`controls` as read from
/// `curves`, whose CurveId is the cell id), the first non-empty name among a shape's curves.
/// Shapes without a name are absent; so is everything when `curves` has no ShapeName.
std::map<int, std::string> ReadShapeNames(vtkPolyData* curves,
  const std::vector<InputControlCurve>& controls);

/// The shape's name, or "Shape <id>" when it has none.
std::string ShapeLabel(int shapeId, const std::map<int, std::string>& names);

/// "curve 3 of shape 1".
std::string DescribeWindingCurve(const WindingCurveReport& report);

/// The level set {w = threshold} of every computed shape of `result` (on `arr`, the arrangement
/// the winding numbers were computed on), shape after shape: loopShape[i] is the index in
/// result.ShapeIds of loops[i]. The shapes are extracted on `threads` threads (0: all), the
/// result the same whatever their number. False with the level set's message, naming the shape.
bool ExtractCompletedLoops(const TriangleMesh& mesh,
  const Arrangement& arr,
  const WindingResult& result,
  double threshold,
  int threads,
  std::vector<LevelSetLoop>& loops,
  std::vector<int>& loopShape,
  std::string& error);

struct CloseShapesOptions
{
  std::vector<int> Shapes; ///< the shapes whose curves are completed (not empty)
  double Threshold = 0.5;
  int Threads = 0;
};

/// BoolSurf's CloseBrokenShapes: the curves of options.Shapes are arranged on their own, their
/// winding numbers computed (SurfaceWinding, the homology correction on) and each shape's
/// curves replaced in `curves` by the loops of its level set {w = Threshold}, closed curves of
/// the same shape with new curve ids (after the largest one in `curves`). `sources` (when not
/// empty, parallel to `curves`) gets the loops as geodesic polygons whose control points are
/// all their points. `notes` gets one line per replaced curve with its residual and one per
/// shape whose level set is empty; `warnings` one line per curve that bounds nothing. False
/// with a message naming the problem (a shape id no curve has, a failed arrangement or
/// solve).
bool CloseBrokenShapes(SurfaceWinding& winding,
  const TriangleMesh& mesh,
  const CloseShapesOptions& options,
  std::vector<TracedCurve>& curves,
  std::vector<CurveSource>& sources,
  std::vector<std::string>& notes,
  std::vector<std::string>& warnings,
  std::string& error);

} // namespace boolsurf

#endif

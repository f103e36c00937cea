// A BoolSurf scene file (.json) as plain values: the curves drawn on a mesh, their shapes and
// the operations between shapes, in the format of the original BoolSurf code's test scenes
// (Docs/VectorOutput.md; ../shared/data/boolsurf-scenes/README.md). Scene/SceneJson reads and
// writes it; Scene/ScenePlacement puts its points on a mesh (or, for a screen-space scene, on
// a flat grid).
#ifndef boolsurf_SceneModel_h
#define boolsurf_SceneModel_h

#include "Mesh/Vec3.h"

#include <optional>
#include <string>
#include <vector>

namespace boolsurf
{

/// A control point `{"face": f, "uv": [u, v]}`: (1-u-v) p0 + u p1 + v p2 of triangle Face.
struct ScenePoint
{
  long long Face = 0;
  /// As in the file (inside the triangle up to InsideTriangleTolerance, Mesh/SurfacePoint.h);
  /// PlaceScenePoints clamps them into it (ClampBarycentric).
  double U = 0, V = 0;
  /// `face` and `uv` as spelled in the file ("1E2", "[2.5E-1,0.25]"), for messages; empty
  /// for points that do not come from a file.
  std::string FaceText, UVText;
  /// The point in 3D: set by PlaceScenePoints or PlaceScreenSpaceScene.
  Vec3 Position;
};

/// A curve: a polygon of the file with at least two points (empty polygons, and a surface
/// scene's one-point polygons, are not curves).
struct ScenePolygon
{
  /// Its index in the file's `polygons` (which counts the empty ones).
  int Index = 0;
  /// Indices into SceneModel::Points, without repeating the first at the end of a closed one.
  /// Empty in a screen-space scene until PlaceScreenSpaceScene.
  std::vector<int> Points;
  bool Closed = true;
  int CurveType = 0; ///< 0 geodesic polygon, 1 cubic Bezier spline (`curve_types`)
  /// The shape listing it in `shapes` (without `shapes`: its index); a curve in no shape has
  /// a shape of its own, numbered from NumberOfShapes on in polygon order.
  int Shape = 0;
  /// Screen-space scenes: the polyline's [x, y] as written (screen y grows downwards).
  std::vector<Vec2> Polyline;
};

/// `{"a": shape, "b": shape, "type": t}`.
struct SceneOperation
{
  int A = 0, B = 0;
  int Type = 0; ///< 0 union, 1 difference, 2 intersection, 3 symmetric difference
};

struct SceneModel
{
  /// `model`: the mesh file, as written (empty for a screen-space scene, or when the caller
  /// names the mesh itself).
  std::string Model;
  std::vector<ScenePoint> Points;
  std::vector<ScenePolygon> Polygons; ///< in file order (the writer: in its curves' order)
  /// Length of the file's `polygons` (when written: at least the largest Index + 1).
  int NumberOfPolygons = 0;
  /// Shapes the file defines: the length of `shapes`, or one per polygon without it (when
  /// written: at least the largest Shape + 1).
  int NumberOfShapes = 0;
  /// `operations`; none when the file has no such key (or null).
  std::optional<std::vector<SceneOperation>> Operations;
  bool ScreenSpace = false; ///< `screenspace: true`: 2D polylines (ScenePolygon::Polyline)
  /// Sentences for the user that are not errors (a one-point polygon skipped, ...).
  std::vector<std::string> Notes;
};

} // namespace boolsurf

#endif

// Scene files (.json) read into a SceneModel, with every check of the file's content, and a
// SceneModel written back as JSON.
//
// Messages name the key and the polygon and point index, and quote values as they are written
// in the file ("1e20" and "[2.5E-1,0.25]", not as a JSON library would print them again):
// "'points'[1].uv = [0.7,0.4] is outside the triangle (needs u >= 0, v >= 0, u + v <= 1)".
#ifndef boolsurf_SceneJson_h
#define boolsurf_SceneJson_h

#include "Scene/SceneModel.h"

#include <functional>
#include <iosfwd>
#include <string>

namespace boolsurf
{

/// The mesh a surface scene's faces index, as SceneParseOptions::FindMesh gives it.
struct SceneMeshInfo
{
  long long NumberOfTriangles = 0;
  std::string Name; ///< for messages (a file name)
};

/// How deep a scene file may nest arrays and objects (the top-level object is level 1; a
/// scene needs 4: the top level, `points`, a point, its `uv`). Deeper is refused before the
/// file is read into values, whose copies and walks recurse once per level: a file nested
/// 10^5 deep would overflow the stack. 256 as for parentheses in Boolean expressions.
constexpr int MaxSceneNestingDepth = 256;

struct SceneParseOptions
{
  /// Whether a surface scene's `model` is required and read. False when the caller names the
  /// mesh itself: `model` is then ignored (and Model left empty).
  bool ReadModel = true;
  /// When set, called for a surface scene once its polygons, shapes and flags are checked and
  /// before its points are read: it finds and reads the mesh (false and a message stop the
  /// reading with that message), and
  /// each point's face is then checked against it as the points are read. So a file is
  /// checked in one order, whatever is wrong with it: the structure of its curves, the mesh,
  /// each point (face, then uv), then the operations. Without it, faces are checked later by
  /// CheckSceneFaces or PlaceScenePoints.
  std::function<bool(const SceneModel& scene, SceneMeshInfo& mesh, std::string& error)> FindMesh;
};

/// Reads a scene into `scene`; false, with one of the messages above in `error`, for a problem
/// with the file.
/// The checks: arrays and objects nested at most MaxSceneNestingDepth levels ("nesting too
/// deep: an array at line 1, column 300 (in 'points') is 257 levels deep; ..."); valid JSON;
/// a JSON object; `polygons` (and for a surface scene `points` and `model`) present; every
/// value of the right type; point, polygon and shape indices that exist; a polygon in at most
/// one shape; uv inside the triangle (IsInsideTriangle); flags `are_closed`, `curve_types` (0
/// or 1), operation types (0..3); at least one curve. A surface scene's one-point polygon is
/// skipped with a note; a screen-space scene's is an error, as is a screen-space scene whose
/// points are all the same.
bool ParseSceneJson(std::istream& in,
  SceneModel& scene,
  std::string& error,
  const SceneParseOptions& options = {});

/// Whether `in` holds a JSON object with a `polygons` key. Reads the file
/// without building its values, so a file nested too deep is still recognized (and refused
/// by ParseSceneJson with its message).
bool LooksLikeSceneJson(std::istream& in);

/// The scene as a file's text (ending with a newline): keys in alphabetical order, `indent`
/// spaces per nesting level (-1: one line), doubles with round-trip precision. `polygons` has
/// NumberOfPolygons entries (at least the largest Index + 1; the others empty, closed),
/// `shapes` NumberOfShapes (at least the largest Shape + 1); `curve_types` only when a curve
/// is a Bezier spline, `operations` when Operations is set. A surface scene writes `model` and
/// `points`; a screen-space scene `screenspace` and its polylines as `polygons` (and `model`
/// only when not empty).
std::string EmitSceneJson(const SceneModel& scene, int indent = 1);

} // namespace boolsurf

#endif

// A scene's points on a surface: on the mesh its faces index (after checking them against
// it), or, for a screen-space scene, its 2D polylines scaled onto a flat grid.
#ifndef boolsurf_ScenePlacement_h
#define boolsurf_ScenePlacement_h

#include "Mesh/ProceduralMeshes.h"
#include "Mesh/SurfacePoint.h"
#include "Scene/SceneModel.h"

#include <string>

namespace boolsurf
{

/// The message for point `index` whose face (as written: `faceText`) is not a triangle of the
/// mesh `meshName` of `numberOfTriangles` triangles.
std::string FaceOutOfRangeMessage(std::size_t index,
  const std::string& faceText,
  const std::string& meshName,
  long long numberOfTriangles);

/// False, with FaceOutOfRangeMessage in `error`, for the first point whose face is not in
/// [0, numberOfTriangles).
bool CheckSceneFaces(const SceneModel& scene,
  long long numberOfTriangles,
  const std::string& meshName,
  std::string& error);

/// Checks the faces (CheckSceneFaces), clamps each point's (U, V) into its triangle
/// (ClampBarycentric) and sets its Position, (1-u-v) p0 + u p1 + v p2. `mesh` holds the
/// triangles `face` indexes; `meshName` names it in messages. False (the faces' message in
/// `error`) when a face is not a triangle of `mesh`.
bool PlaceScenePoints(SceneModel& scene,
  const MeshData& mesh,
  const std::string& meshName,
  std::string& error);

/// How a screen-space scene's polylines go into [0.1, 0.9]^2: (x, y) as written is at
/// (x Scale + Offset[0], -y Scale + Offset[1]) (screen y grows downwards: flipped so that the
/// drawing is upright), the aspect ratio kept and the drawing centred.
struct ScreenSpaceFrame
{
  double Scale = 1;
  double Offset[2] = { 0, 0 };
};

/// The frame of every polyline point of `polygons`; false (with a message) when they hold no
/// two distinct points.
bool FitScreenSpace(const std::vector<ScenePolygon>& polygons,
  ScreenSpaceFrame& frame,
  std::string& error);

/// The point of MakeFlatSquare(n) (the unit square, n quads per side, quad (i, j) split into
/// (p00, p10, p11), (p00, p11, p01)) at (x, y), clamped into [0,1]^2: its triangle and (u, v).
SurfacePoint FlatSquarePoint(int n, double x, double y);

/// A screen-space scene on MakeFlatSquare(resolution): every polyline turned counter-clockwise
/// (BoolSurf's convention: reversed when its signed area, y up, is negative) and placed by
/// FitScreenSpace; one point per polyline point, appended to Points (Face, U, V and Position
/// set) and named by its polygon's Points. Adds a note. `grid` is the flat square; false (with
/// a message naming the polygon) when a polyline has fewer than 2 points.
bool PlaceScreenSpaceScene(SceneModel& scene, int resolution, MeshData& grid, std::string& error);

} // namespace boolsurf

#endif

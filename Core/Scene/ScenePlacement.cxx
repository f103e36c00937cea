#include "Scene/ScenePlacement.h"

#include <algorithm>
#include <array>

namespace boolsurf
{
namespace
{
std::string PolygonName(int index)
{
  return "'polygons'[" + std::to_string(index) + "]";
}
} // namespace

//------------------------------------------------------------------------------
std::string FaceOutOfRangeMessage(std::size_t index,
  const std::string& faceText,
  const std::string& meshName,
  long long numberOfTriangles)
{
  return "'points'[" + std::to_string(index) + "].face = " + faceText + " is out of range: mesh " +
    meshName + " has " + std::to_string(numberOfTriangles) + " triangles";
}

//------------------------------------------------------------------------------
bool CheckSceneFaces(const SceneModel& scene,
  long long numberOfTriangles,
  const std::string& meshName,
  std::string& error)
{
  for (std::size_t k = 0; k < scene.Points.size(); ++k)
  {
    const ScenePoint& p = scene.Points[k];
    if (p.Face < 0 || p.Face >= numberOfTriangles)
    {
      const std::string text = p.FaceText.empty() ? std::to_string(p.Face) : p.FaceText;
      error = FaceOutOfRangeMessage(k, text, meshName, numberOfTriangles);
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool PlaceScenePoints(SceneModel& scene,
  const MeshData& mesh,
  const std::string& meshName,
  std::string& error)
{
  if (!CheckSceneFaces(scene, static_cast<long long>(mesh.Triangles.size()), meshName, error))
  {
    return false;
  }
  for (ScenePoint& p : scene.Points)
  {
    ClampBarycentric(p.U, p.V);
    const double u = p.U, v = p.V;
    const std::array<int, 3>& t = mesh.Triangles[static_cast<std::size_t>(p.Face)];
    const Vec3& p0 = mesh.Positions[t[0]];
    const Vec3& p1 = mesh.Positions[t[1]];
    const Vec3& p2 = mesh.Positions[t[2]];
    p.Position = { (1 - u - v) * p0.x + u * p1.x + v * p2.x,
      (1 - u - v) * p0.y + u * p1.y + v * p2.y,
      (1 - u - v) * p0.z + u * p1.z + v * p2.z };
  }
  return true;
}

//------------------------------------------------------------------------------
bool FitScreenSpace(const std::vector<ScenePolygon>& polygons,
  ScreenSpaceFrame& frame,
  std::string& error)
{
  // The bounds start where VTK_DOUBLE_MAX put them (1e299, not the largest double), so that
  // a drawing out there is framed as it always was.
  constexpr double Far = static_cast<double>(1.0e+299L);
  double lo[2] = { Far, Far }, hi[2] = { -Far, -Far };
  for (const ScenePolygon& polygon : polygons)
  {
    for (const Vec2& p : polygon.Polyline)
    {
      const double xy[2] = { p.x, -p.y };
      for (int c = 0; c < 2; ++c)
      {
        lo[c] = std::min(lo[c], xy[c]);
        hi[c] = std::max(hi[c], xy[c]);
      }
    }
  }
  const double extent = std::max(hi[0] - lo[0], hi[1] - lo[1]);
  if (!(extent > 0))
  {
    error = "'polygons' hold no two distinct points";
    return false;
  }
  // Into [0.1, 0.9]^2, aspect ratio kept, centred.
  frame = ScreenSpaceFrame();
  frame.Scale = 0.8 / extent;
  frame.Offset[0] = 0.5 - 0.5 * (lo[0] + hi[0]) * frame.Scale;
  frame.Offset[1] = 0.5 - 0.5 * (lo[1] + hi[1]) * frame.Scale;
  return true;
}

//------------------------------------------------------------------------------
SurfacePoint FlatSquarePoint(int n, double x, double y)
{
  const double fx = std::min(std::max(x, 0.0), 1.0) * n;
  const double fy = std::min(std::max(y, 0.0), 1.0) * n;
  const int i = std::min(static_cast<int>(fx), n - 1);
  const int j = std::min(static_cast<int>(fy), n - 1);
  const double s = fx - i, t = fy - j;
  const int quad = j * n + i;
  if (s >= t) // (p00, p10, p11): x = p00 + (s - t)(p10 - p00) + t (p11 - p00)
  {
    return { 2 * quad, s - t, t };
  }
  return { 2 * quad + 1, s, t - s }; // (p00, p11, p01)
}

//------------------------------------------------------------------------------
bool PlaceScreenSpaceScene(SceneModel& scene, int resolution, MeshData& grid, std::string& error)
{
  ScreenSpaceFrame frame;
  if (!FitScreenSpace(scene.Polygons, frame, error))
  {
    return false;
  }
  grid = MakeFlatSquare(resolution);
  scene.Points.clear();
  for (ScenePolygon& polygon : scene.Polygons)
  {
    if (polygon.Polyline.size() < 2)
    {
      error = PolygonName(polygon.Index) +
        (polygon.Polyline.empty() ? " is empty" : " has a single point") +
        "; a curve needs at least 2";
      return false;
    }
    // Screen coordinates grow downwards: y flipped so that the drawing is upright.
    std::vector<Vec2> c;
    c.reserve(polygon.Polyline.size());
    for (const Vec2& p : polygon.Polyline)
    {
      c.push_back({ p.x, -p.y });
    }
    double area2 = 0; // BoolSurf turns every curve counter-clockwise
    for (std::size_t k = 0; k < c.size(); ++k)
    {
      const Vec2& p = c[k];
      const Vec2& q = c[(k + 1) % c.size()];
      area2 += p.x * q.y - q.x * p.y;
    }
    if (area2 < 0)
    {
      std::reverse(c.begin(), c.end());
    }
    polygon.Points.clear();
    for (const Vec2& p : c)
    {
      ScenePoint point;
      point.Position = {
        p.x * frame.Scale + frame.Offset[0], p.y * frame.Scale + frame.Offset[1], 0.0
      };
      const SurfacePoint s = FlatSquarePoint(resolution, point.Position.x, point.Position.y);
      point.Face = s.Triangle;
      point.U = s.U;
      point.V = s.V;
      polygon.Points.push_back(static_cast<int>(scene.Points.size()));
      scene.Points.push_back(std::move(point));
    }
  }
  scene.Notes.push_back("screen-space scene: its polylines were placed on a flat grid on [0,1]^2");
  return true;
}

} // namespace boolsurf

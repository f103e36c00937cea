#include "Scene/SceneCurves.h"

namespace boolsurf
{

//------------------------------------------------------------------------------
std::vector<ControlCurve> SceneControlCurves(const SceneModel& scene)
{
  std::vector<ControlCurve> curves;
  curves.reserve(scene.Polygons.size());
  for (const ScenePolygon& polygon : scene.Polygons)
  {
    ControlCurve curve;
    curve.CurveId = polygon.Index;
    curve.ShapeId = polygon.Shape;
    curve.Type = static_cast<CurveType>(polygon.CurveType);
    curve.Closed = polygon.Closed;
    curve.Points.reserve(polygon.Points.size());
    for (int id : polygon.Points)
    {
      const ScenePoint& p = scene.Points[static_cast<std::size_t>(id)];
      curve.Points.push_back({ static_cast<int>(p.Face), p.U, p.V });
    }
    curves.push_back(std::move(curve));
  }
  return curves;
}

} // namespace boolsurf

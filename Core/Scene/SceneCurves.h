// A placed scene's curves in Core's one curve form: what the scene reader writes as control
// curves (through the one writer of their arrays) and what any stage can trace.
#ifndef boolsurf_SceneCurves_h
#define boolsurf_SceneCurves_h

#include "Curves/ControlCurve.h"
#include "Scene/SceneModel.h"

#include <vector>

namespace boolsurf
{

/// One control curve per polygon of `scene`, in its order: CurveId the polygon's Index,
/// ShapeId its Shape, its type and closedness, and each point its scene point's face and
/// (u, v) exactly. The scene must be placed (PlaceScenePoints or PlaceScreenSpaceScene: every
/// polygon names its points, every face a triangle). A point two polygons name becomes a
/// point of each curve: curves share no points.
std::vector<ControlCurve> SceneControlCurves(const SceneModel& scene);

} // namespace boolsurf

#endif

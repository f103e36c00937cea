// Making inconsistent shapes consistent (BoolSurf §4.4, Fig. 7/8): a shape whose curves'
// homology classes do not sum to zero has "generators in excess"; three fixes change its
// control curves so the sum becomes zero.
//  * AddGenerators: a reversed copy of each generator in excess, as many times as its
//    multiplicity; copies of one generator cross every edge at distinct parameters, so they
//    never overlap each other (a geometric offset).
//  * DuplicateReversed: each curve with a nonzero class gets a reversed copy beside it, its
//    control points moved by Offset to the curve's left in the surface (the tangent plane
//    direction normal x tangent, carried from point to point along the control polygon) and
//    projected back onto the surface: the pair bounds a solid strip inside the shape.
//  * RemoveCurves: the fewest curves whose removal (class h) or flip (class 2h) takes away
//    exactly the excess; the remaining curves' classes sum to zero.
// The curves are control curves (as the tracing stage reads them); the caller gives each one's
// class (HomologyBasis::ClassOf on its trace).
#ifndef boolsurf_ShapeResolution_h
#define boolsurf_ShapeResolution_h

#include "Geodesic/CurveTracer.h"
#include "Homology/HomologyBasis.h"

#include <functional>
#include <string>
#include <vector>

namespace boolsurf
{

enum class ResolveStrategy : int
{
  AddGenerators = 0,
  DuplicateReversed = 1,
  RemoveCurves = 2,
};

/// "AddGenerators", "DuplicateReversed", "RemoveCurves".
const char* StrategyName(ResolveStrategy s);

/// Values of the output cell array `Resolution`.
enum class ResolutionAction : int
{
  Kept = 0,
  AddedGenerator = 1,
  DuplicatedReversed = 2,
  Flipped = 3,
  Removed = 4, ///< listed in ResolveResult::Removed only
};

struct ResolvedCurve
{
  ControlCurve Curve;
  ResolutionAction Action = ResolutionAction::Kept;
  /// The input curve id it comes from (kept, duplicated, flipped, removed), or the generator id
  /// (added generators).
  int Source = -1;
  std::string Reason; ///< one sentence for the output (empty for untouched curves)
};

struct ResolveOptions
{
  /// Strategy of each shape (by ShapeId).
  std::function<ResolveStrategy(int shapeId)> StrategyOf = [](int)
  { return ResolveStrategy::DuplicateReversed; };
  /// DuplicateReversed: distance from a curve to its reversed copy; <= 0: a quarter of the mean
  /// edge length of the mesh.
  double Offset = 0;
};

struct ResolveResult
{
  std::vector<ResolvedCurve> Curves;  ///< output, in input order, then added curves
  std::vector<ResolvedCurve> Removed; ///< curves left out by RemoveCurves
  std::vector<std::string> Notes;     ///< per shape: what was done, or why nothing
  std::vector<int> TreatedShapes;     ///< ShapeIds that had generators in excess and were fixed
};

/// Resolves every shape with generators in excess. `classes[i]` is the class of `curves[i]`.
ResolveResult ResolveShapes(const TriangleMesh& mesh,
  const HomologyBasis& basis,
  const std::vector<ControlCurve>& curves,
  const std::vector<std::vector<int>>& classes,
  const ResolveOptions& options);

/// Traces each curve with `tracer` and returns its class in `basis` (zero for open curves).
/// False with a message naming the curve when tracing fails.
bool ClassifyControlCurves(CurveTracer& tracer,
  const HomologyBasis& basis,
  const std::vector<ControlCurve>& curves,
  std::vector<std::vector<int>>& classes,
  std::vector<TracedCurve>* traced,
  std::string& error);

/// The closest point of the surface to `target`, searched among the triangles reachable from
/// `start` without leaving the ball of radius `radius` around `target` (always including
/// `start`).
SurfacePoint ClosestSurfacePointNear(const TriangleMesh& mesh,
  Vec3 target,
  int start,
  double radius);

} // namespace boolsurf

#endif

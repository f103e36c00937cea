#include "Homology/ShapeResolution.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <queue>
#include <unordered_set>

namespace boolsurf
{
namespace
{

bool IsZero(const std::vector<int>& h)
{
  return std::all_of(h.begin(), h.end(), [](int x) { return x == 0; });
}

// Closest point of triangle (a, b, c) to p as barycentric weights (u, v) of b and c
// (Ericson, Real-Time Collision Detection, 5.1.5).
std::array<double, 2> ClosestOnTriangle(Vec3 p, Vec3 a, Vec3 b, Vec3 c)
{
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = Dot(ab, ap), d2 = Dot(ac, ap);
  if (d1 <= 0 && d2 <= 0)
  {
    return { 0, 0 };
  }
  const Vec3 bp = p - b;
  const double d3 = Dot(ab, bp), d4 = Dot(ac, bp);
  if (d3 >= 0 && d4 <= d3)
  {
    return { 1, 0 };
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0)
  {
    return { d1 / (d1 - d3), 0 };
  }
  const Vec3 cp = p - c;
  const double d5 = Dot(ab, cp), d6 = Dot(ac, cp);
  if (d6 >= 0 && d5 <= d6)
  {
    return { 0, 1 };
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0)
  {
    return { 0, d2 / (d2 - d6) };
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
  {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return { 1 - w, w };
  }
  const double denom = 1.0 / (va + vb + vc);
  return { vb * denom, vc * denom };
}

Vec3 Normalized(Vec3 v)
{
  const double l = Length(v);
  return l > 0 ? (1.0 / l) * v : v;
}

double MeanEdgeLength(const TriangleMesh& mesh)
{
  double sum = 0;
  int n = 0;
  for (int e = 0; e < mesh.GetNumberOfEdges(); ++e)
  {
    const auto v = mesh.GetEdgeVertices(e);
    sum += Distance(mesh.GetPosition(v[0]), mesh.GetPosition(v[1]));
    ++n;
  }
  return n ? sum / n : 0;
}

// The same closed curve walked the other way, starting at the same point (for Bezier splines
// the anchors stay anchors: p0, p[n-1], ..., p1).
std::vector<SurfacePoint> Reversed(const std::vector<SurfacePoint>& points, bool closed)
{
  std::vector<SurfacePoint> out(points.rbegin(), points.rend());
  if (closed && !out.empty())
  {
    std::rotate(out.begin(), out.end() - 1, out.end());
  }
  return out;
}

std::string ClassText(const std::vector<int>& h)
{
  std::string text;
  for (size_t g = 0; g < h.size(); ++g)
  {
    if (h[g] != 0)
    {
      text += (text.empty() ? "" : ", ") + std::string(h[g] > 0 ? "+" : "") + std::to_string(h[g]) +
        " x G" + std::to_string(g);
    }
  }
  return text.empty() ? "no generator" : text;
}

// Fewest curves (then fewest flips) whose removal (weight 1) or flip (weight 2) takes away
// `excess`; exhaustive over the given candidates.
bool FindRemovals(const std::vector<std::vector<int>>& classes,
  const std::vector<int>& candidates,
  const std::vector<int>& excess,
  std::vector<int>& choice) // per candidate: 0 keep, 1 remove, 2 flip
{
  const int k = static_cast<int>(candidates.size());
  const int ng = static_cast<int>(excess.size());
  std::vector<int> current(k, 0), sum(ng, 0);
  int bestChanged = k + 1, bestFlips = k + 1;
  std::function<void(int, int, int)> search = [&](int i, int changed, int flips)
  {
    if (changed > bestChanged || (changed == bestChanged && flips >= bestFlips))
    {
      return;
    }
    if (sum == excess)
    {
      bestChanged = changed;
      bestFlips = flips;
      choice = current;
      return;
    }
    if (i == k)
    {
      return;
    }
    const std::vector<int>& h = classes[candidates[i]];
    for (int w : { 0, 1, 2 })
    {
      current[i] = w;
      for (int g = 0; g < ng; ++g)
      {
        sum[g] += w * h[g];
      }
      search(i + 1, changed + (w != 0), flips + (w == 2));
      for (int g = 0; g < ng; ++g)
      {
        sum[g] -= w * h[g];
      }
    }
    current[i] = 0;
  };
  search(0, 0, 0);
  return bestChanged <= k;
}

} // namespace

//------------------------------------------------------------------------------
const char* StrategyName(ResolveStrategy s)
{
  switch (s)
  {
    case ResolveStrategy::AddGenerators:
      return "AddGenerators";
    case ResolveStrategy::DuplicateReversed:
      return "DuplicateReversed";
    case ResolveStrategy::RemoveCurves:
      return "RemoveCurves";
  }
  return "?";
}

//------------------------------------------------------------------------------
SurfacePoint ClosestSurfacePointNear(const TriangleMesh& mesh,
  Vec3 target,
  int start,
  double radius)
{
  SurfacePoint best{ start, 0, 0 };
  double bestDistance = HUGE_VAL;
  std::unordered_set<int> seen{ start };
  std::queue<int> queue;
  queue.push(start);
  while (!queue.empty())
  {
    const int t = queue.front();
    queue.pop();
    const auto uv = ClosestOnTriangle(target,
      mesh.GetCornerPosition(t, 0),
      mesh.GetCornerPosition(t, 1),
      mesh.GetCornerPosition(t, 2));
    const double d = Distance(target, mesh.Evaluate(t, uv[0], uv[1]));
    if (d < bestDistance)
    {
      bestDistance = d;
      best = { t, uv[0], uv[1] };
    }
    if (d > radius && t != start)
    {
      continue; // outside the ball: do not spread from here
    }
    for (int k = 0; k < 3; ++k)
    {
      const int n = mesh.GetNeighbor(t, k);
      if (n >= 0 && seen.insert(n).second)
      {
        queue.push(n);
      }
    }
  }
  return best;
}

//------------------------------------------------------------------------------
bool ClassifyControlCurves(CurveTracer& tracer,
  const HomologyBasis& basis,
  const std::vector<ControlCurve>& curves,
  std::vector<std::vector<int>>& classes,
  std::vector<TracedCurve>* traced,
  std::string& error)
{
  classes.assign(curves.size(), std::vector<int>(basis.GetNumberOfGenerators(), 0));
  if (traced)
  {
    traced->assign(curves.size(), TracedCurve());
  }
  CurveTrace trace;
  for (size_t i = 0; i < curves.size(); ++i)
  {
    const ControlCurve& c = curves[i];
    std::string traceError;
    if (!tracer.Trace(c.Points, c.Type, c.Closed, trace, traceError, c.CurveId))
    {
      error = "curve " + std::to_string(c.CurveId) + ": " + traceError;
      return false;
    }
    trace.Curve.ShapeId = c.ShapeId;
    trace.Curve.CurveId = c.CurveId;
    if (!basis.ClassOf(trace.Curve, classes[i], error))
    {
      return false;
    }
    if (traced)
    {
      (*traced)[i] = trace.Curve;
    }
  }
  return true;
}

namespace
{
/// The shape's resolution by AddGenerators: `copies` copies of each generator in excess, walked
/// backwards where the excess is positive, appended to `added`.
void AddGeneratorCopies(const TriangleMesh& mesh,
  const HomologyBasis& basis,
  int shapeId,
  const std::string& shapeName,
  const std::vector<int>& excess,
  const std::string& excessText,
  int& nextCurveId,
  std::vector<ResolvedCurve>& added)
{
  const int ng = basis.GetNumberOfGenerators();
  for (int g = 0; g < ng; ++g)
  {
    const int copies = std::abs(excess[g]);
    if (copies == 0)
    {
      continue;
    }
    const HomologyGenerator& gen = basis.GetGenerator(g);
    // Copies cross every edge between this generator's parameter and the next one's.
    int inComponent = 0;
    for (const HomologyGenerator& other : basis.GetGenerators())
    {
      inComponent += other.Component == gen.Component;
    }
    const double step = 0.5 / ((inComponent + 1.0) * copies);
    for (int k = 0; k < copies; ++k)
    {
      std::vector<SurfacePoint> points;
      for (CanonicalPoint p : gen.Points)
      {
        p.T = gen.CrossingParameter + k * step;
        points.push_back(ToSurfacePoint(mesh, p));
      }
      ResolvedCurve r;
      r.Curve.CurveId = nextCurveId++;
      r.Curve.ShapeId = shapeId;
      r.Curve.Closed = true;
      // Generator g has class +1 at G g: walk it backwards where the excess is positive.
      r.Curve.Points = excess[g] > 0 ? Reversed(points, true) : points;
      r.Action = ResolutionAction::AddedGenerator;
      r.Source = g;
      r.Reason = shapeName + " had " + excessText +
        " in excess: " + (excess[g] > 0 ? "reversed " : "") + "copy " + std::to_string(k + 1) +
        " of " + std::to_string(copies) + " of generator G" + std::to_string(g);
      added.push_back(std::move(r));
    }
  }
}

/// Control point j of `c` moved `offset` to its left (less near control points closer than the
/// offset), on the surface.
SurfacePoint OffsetToTheLeft(const TriangleMesh& mesh, const ControlCurve& c, int j, double offset)
{
  const int n = static_cast<int>(c.Points.size());
  const SurfacePoint& p = c.Points[j];
  const Vec3 x = mesh.Evaluate(p.Triangle, p.U, p.V);
  // Neighbours along the polygon, skipping control points (almost) on this one.
  auto neighbour = [&](int step)
  {
    Vec3 y = x;
    for (int k = 1; k < n && Distance(x, y) <= 1e-3 * offset; ++k)
    {
      const int at =
        c.Closed ? ((j + step * k) % n + n) % n : std::min(std::max(j + step * k, 0), n - 1);
      const SurfacePoint& q = c.Points[at];
      y = mesh.Evaluate(q.Triangle, q.U, q.V);
    }
    return y;
  };
  const Vec3 before = x - neighbour(-1);
  const Vec3 after = neighbour(+1) - x;
  // Bisector of the two sides: the offset stays on the left of both.
  const Vec3 tangent = Normalized(before) + Normalized(after);
  const Vec3 a = mesh.GetCornerPosition(p.Triangle, 0);
  const Vec3 normal = Normalized(
    Cross(mesh.GetCornerPosition(p.Triangle, 1) - a, mesh.GetCornerPosition(p.Triangle, 2) - a));
  // Left of the curve seen from where the normal points: normal x tangent. Near
  // control points closer than the offset, a third of their distance, so the copy
  // cannot reach across a tight turn.
  const Vec3 left = Normalized(Cross(normal, tangent));
  double distance = offset;
  for (double side : { Length(before), Length(after) })
  {
    if (side > 0)
    {
      distance = std::min(distance, side / 3);
    }
  }
  const double d = distance;
  return ClosestSurfacePointNear(mesh, x + d * left, p.Triangle, 3 * d);
}

/// The shape's resolution by DuplicateReversed: a reversed copy of each of its winding curves
/// on its left, appended to `added` (the original keeps its place, with a reason).
void DuplicateWindingCurvesReversed(const TriangleMesh& mesh,
  const std::vector<ControlCurve>& curves,
  const std::vector<std::vector<int>>& classes,
  const std::vector<int>& members,
  const std::string& shapeName,
  const std::string& excessText,
  double offset,
  int& nextCurveId,
  std::vector<ResolutionAction>& action,
  std::vector<std::string>& reason,
  std::vector<ResolvedCurve>& added)
{
  for (int i : members)
  {
    if (IsZero(classes[i]))
    {
      continue;
    }
    const ControlCurve& c = curves[i];
    const int n = static_cast<int>(c.Points.size());
    std::vector<SurfacePoint> moved(n);
    for (int j = 0; j < n; ++j)
    {
      moved[j] = OffsetToTheLeft(mesh, c, j, offset);
    }
    ResolvedCurve r;
    r.Curve = c;
    r.Curve.CurveId = nextCurveId++;
    r.Curve.Points = Reversed(moved, c.Closed);
    r.Action = ResolutionAction::DuplicatedReversed;
    r.Source = c.CurveId;
    r.Reason = shapeName + " had " + excessText + " in excess: reversed copy of curve " +
      std::to_string(c.CurveId) + " (winding " + ClassText(classes[i]) + ") at distance " +
      std::to_string(offset) + " on its left, a solid strip";
    action[i] = ResolutionAction::Kept;
    reason[i] = "duplicated reversed as curve " + std::to_string(r.Curve.CurveId);
    added.push_back(std::move(r));
  }
}

/// The shape's resolution by RemoveCurves: the winding curves to remove or flip so that the
/// excess cancels, marked in `action` and `reason`, with a note. False (a note says why) when
/// no such set is found or there are too many curves to search: the shape is left unchanged.
bool RemoveOrFlipCurves(const std::vector<ControlCurve>& curves,
  const std::vector<std::vector<int>>& classes,
  const std::vector<int>& members,
  const std::vector<int>& excess,
  const std::string& shapeName,
  const std::string& excessText,
  std::vector<ResolutionAction>& action,
  std::vector<std::string>& reason,
  std::vector<std::string>& notes)
{
  std::vector<int> candidates;
  for (int i : members)
  {
    if (!IsZero(classes[i]))
    {
      candidates.push_back(i);
    }
  }
  std::vector<int> choice;
  if (candidates.size() > 12)
  {
    notes.push_back(shapeName + ": " + std::to_string(candidates.size()) +
      " curves wind around the surface, too many to search for RemoveCurves; shape left "
      "unchanged (use AddGenerators or DuplicateReversed)");
    return false;
  }
  if (!FindRemovals(classes, candidates, excess, choice))
  {
    notes.push_back(shapeName +
      ": no set of its curves removed or flipped has the "
      "class " +
      excessText + "; shape left unchanged (use AddGenerators or DuplicateReversed)");
    return false;
  }
  std::string removed, flipped;
  for (size_t k = 0; k < candidates.size(); ++k)
  {
    const int i = candidates[k];
    const std::string id = std::to_string(curves[i].CurveId);
    if (choice[k] == 1)
    {
      action[i] = ResolutionAction::Removed;
      reason[i] = shapeName + " had " + excessText + " in excess: curve " + id + " (winding " +
        ClassText(classes[i]) + ") removed";
      removed += (removed.empty() ? "" : ", ") + id;
    }
    else if (choice[k] == 2)
    {
      action[i] = ResolutionAction::Flipped;
      reason[i] = shapeName + " had " + excessText + " in excess: curve " + id + " (winding " +
        ClassText(classes[i]) + ") flipped, which takes it away twice";
      flipped += (flipped.empty() ? "" : ", ") + id;
    }
  }
  notes.push_back(shapeName + ": " + excessText + " in excess; " +
    (removed.empty() ? "" : "removed curve(s) " + removed) +
    (!removed.empty() && !flipped.empty() ? ", " : "") +
    (flipped.empty() ? "" : "flipped curve(s) " + flipped) + " (RemoveCurves)");
  return true;
}
} // namespace

//------------------------------------------------------------------------------
ResolveResult ResolveShapes(const TriangleMesh& mesh,
  const HomologyBasis& basis,
  const std::vector<ControlCurve>& curves,
  const std::vector<std::vector<int>>& classes,
  const ResolveOptions& options)
{
  ResolveResult result;
  const int ng = basis.GetNumberOfGenerators();
  std::map<int, std::vector<int>> shapeCurves; // ShapeId -> curve indices
  for (size_t i = 0; i < curves.size(); ++i)
  {
    shapeCurves[curves[i].ShapeId].push_back(static_cast<int>(i));
  }
  std::vector<ResolutionAction> action(curves.size(), ResolutionAction::Kept);
  std::vector<std::string> reason(curves.size());
  std::vector<ResolvedCurve> added;
  const double offset = options.Offset > 0 ? options.Offset : 0.25 * MeanEdgeLength(mesh);
  int nextCurveId = 0;
  for (const ControlCurve& c : curves)
  {
    nextCurveId = std::max(nextCurveId, c.CurveId + 1);
  }

  for (const auto& [shapeId, members] : shapeCurves)
  {
    const ResolveStrategy strategy = options.StrategyOf(shapeId);
    const std::string shapeName = "shape S" + std::to_string(shapeId);
    std::vector<int> excess(ng, 0);
    bool open = false;
    for (int i : members)
    {
      open = open || !curves[i].Closed;
      for (int g = 0; g < ng; ++g)
      {
        excess[g] += classes[i][g];
      }
    }
    if (IsZero(excess))
    {
      result.Notes.push_back(shapeName +
        (ng == 0 ? ": the surface has no homology generators" : ": no generators in excess") +
        ", nothing to do for " + StrategyName(strategy) +
        (open ? " (its open curves are not a homology problem: close them)" : ""));
      continue;
    }
    const std::string excessText = ClassText(excess);
    switch (strategy)
    {
      case ResolveStrategy::AddGenerators:
      {
        AddGeneratorCopies(mesh, basis, shapeId, shapeName, excess, excessText, nextCurveId, added);
        result.Notes.push_back(shapeName + ": " + excessText +
          " in excess, cancelled by adding the generators (AddGenerators)");
        break;
      }
      case ResolveStrategy::DuplicateReversed:
      {
        DuplicateWindingCurvesReversed(mesh,
          curves,
          classes,
          members,
          shapeName,
          excessText,
          offset,
          nextCurveId,
          action,
          reason,
          added);
        result.Notes.push_back(shapeName + ": " + excessText +
          " in excess, each winding curve duplicated reversed (DuplicateReversed)");
        break;
      }
      case ResolveStrategy::RemoveCurves:
      {
        if (!RemoveOrFlipCurves(curves,
              classes,
              members,
              excess,
              shapeName,
              excessText,
              action,
              reason,
              result.Notes))
        {
          continue;
        }
        break;
      }
    }
    result.TreatedShapes.push_back(shapeId);
  }

  for (size_t i = 0; i < curves.size(); ++i)
  {
    ResolvedCurve r;
    r.Curve = curves[i];
    r.Action = action[i];
    r.Source = curves[i].CurveId;
    r.Reason = reason[i];
    if (action[i] == ResolutionAction::Flipped)
    {
      r.Curve.Points = Reversed(r.Curve.Points, r.Curve.Closed);
    }
    (action[i] == ResolutionAction::Removed ? result.Removed : result.Curves)
      .push_back(std::move(r));
  }
  result.Curves.insert(result.Curves.end(),
    std::make_move_iterator(added.begin()),
    std::make_move_iterator(added.end()));
  return result;
}

} // namespace boolsurf

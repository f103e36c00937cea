#include "Selection/BoundarySamples.h"

#include "Arrangement/Arrangement.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace boolsurf
{

//------------------------------------------------------------------------------
PatchSnapper::PatchSnapper(PointPositions positionOf,
  const std::vector<const std::vector<int>*>& patchPoints)
  : PositionOf(std::move(positionOf))
  , Points(patchPoints)
{
  const double inf = std::numeric_limits<double>::infinity();
  this->BoxMin.assign(patchPoints.size(), Vec3{ inf, inf, inf });
  this->BoxMax.assign(patchPoints.size(), Vec3{ -inf, -inf, -inf });
  for (std::size_t i = 0; i < patchPoints.size(); ++i)
  {
    for (int p : *patchPoints[i])
    {
      const Vec3 x = this->PositionOf(p);
      Vec3& lo = this->BoxMin[i];
      Vec3& hi = this->BoxMax[i];
      lo = { std::min(lo.x, x.x), std::min(lo.y, x.y), std::min(lo.z, x.z) };
      hi = { std::max(hi.x, x.x), std::max(hi.y, x.y), std::max(hi.z, x.z) };
    }
  }
}

//------------------------------------------------------------------------------
PatchSnap PatchSnapper::Snap(Vec3 query, double tolerance) const
{
  PatchSnap best;
  double bestD2 = tolerance * tolerance;
  for (std::size_t i = 0; i < this->Points.size(); ++i)
  {
    // Distance to the patch's box: a lower bound of its segments' distances.
    const Vec3 lo = this->BoxMin[i], hi = this->BoxMax[i];
    const double dx = std::max({ lo.x - query.x, 0.0, query.x - hi.x });
    const double dy = std::max({ lo.y - query.y, 0.0, query.y - hi.y });
    const double dz = std::max({ lo.z - query.z, 0.0, query.z - hi.z });
    if (dx * dx + dy * dy + dz * dz > bestD2)
    {
      continue;
    }
    const std::vector<int>& pts = *this->Points[i];
    for (std::size_t s = 0; s + 1 < pts.size(); ++s)
    {
      const Vec3 a = this->PositionOf(pts[s]), b = this->PositionOf(pts[s + 1]);
      const Vec3 ab = b - a;
      const double len2 = Dot(ab, ab);
      double t = len2 > 0 ? Dot(query - a, ab) / len2 : 0;
      t = std::min(1.0, std::max(0.0, t));
      const Vec3 d = query - (a + t * ab);
      const double d2 = Dot(d, d);
      // Strictly closer wins: ties keep the lower patch and segment.
      if (d2 < bestD2 || (best.Patch < 0 && d2 == bestD2))
      {
        bestD2 = d2;
        best.Patch = static_cast<int>(i);
        best.Segment = static_cast<int>(s);
      }
    }
  }
  best.Distance = best.Patch >= 0 ? std::sqrt(bestD2) : 0;
  return best;
}

//------------------------------------------------------------------------------
int SideOfDirection(Vec3 direction, Vec3 tangent, Vec3 normal)
{
  const Vec3 left = Cross(normal, tangent);
  const double scale = Length(direction) * Length(left);
  const double s = Dot(direction, left);
  if (!(scale > 0) || !std::isfinite(s) || std::abs(s) <= 1e-9 * scale)
  {
    return 0;
  }
  return s > 0 ? 1 : -1;
}

//------------------------------------------------------------------------------
bool SnapSamples(const PatchSnapper& snapper,
  const std::vector<SampleQuery>& queries,
  double tolerance,
  std::vector<PatchSnap>& snaps,
  std::string& error)
{
  snaps.assign(queries.size(), PatchSnap());
  for (std::size_t k = 0; k < queries.size(); ++k)
  {
    const SampleQuery& q = queries[k];
    const std::string name = "sample " + std::to_string(k);
    if (!IsFinite(q.Position))
    {
      error = name + ": its position is not a finite number (NaN or infinite)";
      return false;
    }
    if (!IsFinite(q.Direction))
    {
      error = name + ": its Direction is not a finite number (NaN or infinite)";
      return false;
    }
    if (!(Length(q.Direction) > 0))
    {
      error = name + ": its Direction has zero length, so it names no side";
      return false;
    }
    snaps[k] = snapper.Snap(q.Position, tolerance);
    if (snaps[k].Patch < 0)
    {
      error = name + " at (" + std::to_string(q.Position.x) + ", " + std::to_string(q.Position.y) +
        ", " + std::to_string(q.Position.z) + ") is farther than the tolerance " +
        std::to_string(tolerance) + " from every patch";
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
std::vector<BscPatch> BscPatchesOf(const Arrangement& arrangement)
{
  std::vector<BscPatch> out(arrangement.Patches.size());
  for (std::size_t i = 0; i < out.size(); ++i)
  {
    const ArrangementPatch& p = arrangement.Patches[i];
    BscPatch& b = out[i];
    b.LeftCell = p.Closed ? p.LeftCell : -1; // open curves clip, they bound nothing
    b.RightCell = p.Closed ? p.RightCell : -1;
    b.Curve = p.Curve;
    b.Length = p.Length;
    if (!p.Points.empty())
    {
      b.FirstPoint = p.Points.front();
      b.LastPoint = p.Points.back();
    }
  }
  return out;
}

//------------------------------------------------------------------------------
Vec3 UnitTriangleNormal(Vec3 a, Vec3 b, Vec3 c)
{
  const Vec3 n = Cross(b - a, c - a);
  const double length = Length(n);
  return length > 0 ? (1 / length) * n : Vec3();
}

//------------------------------------------------------------------------------
bool SelectBySamples(const PointPositions& positionOf,
  const std::vector<const std::vector<int>*>& patchPoints,
  const std::function<Vec3(int)>& normalOf,
  const std::vector<SampleQuery>& queries,
  double tolerance,
  BscInput& input,
  std::vector<PatchSnap>& snaps,
  BscResult& result,
  std::string& error)
{
  const PatchSnapper snapper(positionOf, patchPoints);
  if (!SnapSamples(snapper, queries, tolerance, snaps, error) ||
    !OrientSamples(positionOf, patchPoints, queries, snaps, normalOf, input.Samples, error))
  {
    return false;
  }
  return SelectBoundarySampledCells(input, result, error);
}

//------------------------------------------------------------------------------
bool SelectBySamples(const TriangleMesh& mesh,
  const Arrangement& arr,
  const std::vector<SampleQuery>& queries,
  double tolerance,
  int maxSearchStates,
  std::vector<PatchSnap>& snaps,
  BscResult& result,
  std::string& error,
  const std::function<bool()>& abort)
{
  std::vector<const std::vector<int>*> points;
  for (const ArrangementPatch& p : arr.Patches)
  {
    points.push_back(&p.Points);
  }
  // The surface normal at a refined point: that of the mesh triangle its surface point names,
  // so the cost is per sample, not per triangle.
  auto normalOf = [&](int p)
  {
    const int t = arr.GetPointSurface(mesh, p).Triangle;
    if (t < 0 || t >= arr.NumberOfMeshTriangles || arr.GetSourceTriangle(mesh, t) < 0)
    {
      return Vec3();
    }
    const Triangle r = arr.GetTriangle(mesh, t); // t itself or its first piece
    return UnitTriangleNormal(
      arr.GetPosition(mesh, r[0]), arr.GetPosition(mesh, r[1]), arr.GetPosition(mesh, r[2]));
  };
  BscInput input;
  input.NumberOfCells = arr.NumberOfCells;
  input.Patches = BscPatchesOf(arr);
  input.MaxSearchStates = maxSearchStates;
  input.Abort = abort;
  return SelectBySamples([&](int p) { return arr.GetPosition(mesh, p); },
    points,
    normalOf,
    queries,
    tolerance,
    input,
    snaps,
    result,
    error);
}

//------------------------------------------------------------------------------
bool SelectBySamples(const TriangleMesh& mesh,
  const Arrangement& arr,
  const std::vector<SampleQuery>& queries,
  const BscOptions& options,
  double diagonal,
  std::vector<PatchSnap>& snaps,
  BscResult& result,
  std::string& error,
  const std::function<bool()>& abort)
{
  return SelectBySamples(mesh,
    arr,
    queries,
    options.SnapTolerance * diagonal,
    options.MaxSearchStates,
    snaps,
    result,
    error,
    abort);
}

} // namespace boolsurf

// Placing Boundary-Sampled Curves samples (BoolSurf §4.6): each user sample (a point and a
// direction) snaps to the nearest patch segment and becomes "the cell on this patch's left (or
// right) is inside", read against the surface normal there. Also the whole BSC stage on a Core
// arrangement (snap, orient, select), used by the one-step filter.
#ifndef boolsurf_BoundarySamples_h
#define boolsurf_BoundarySamples_h

#include "Mesh/Vec3.h"
#include "Selection/BoundarySampledCurves.h"

#include <functional>
#include <string>
#include <vector>

namespace boolsurf
{

/// The nearest point of a set of patch polylines to a query point.
struct PatchSnap
{
  int Patch = -1;
  int Segment = -1; ///< segment index along the patch (points Segment, Segment + 1)
  double Distance = 0;
};

/// The position of a point given by its id (a refined point of an arrangement, a point of a
/// polydata).
using PointPositions = std::function<Vec3(int)>;

/// Nearest patch segment to a point, among patch polylines given as point-id lists. Each
/// patch's bounding box is built once, so a query reads the segments of the patches near it.
class PatchSnapper
{
public:
  /// patchPoints[i]: patch i's point ids (it must outlive the snapper); positionOf(id): the
  /// point's position.
  PatchSnapper(PointPositions positionOf, const std::vector<const std::vector<int>*>& patchPoints);

  /// Patch = -1 when no segment is within `tolerance`. Ties go to the lower patch, then
  /// segment.
  PatchSnap Snap(Vec3 query, double tolerance) const;

private:
  PointPositions PositionOf;
  std::vector<const std::vector<int>*> Points;
  std::vector<Vec3> BoxMin, BoxMax;
};

/// Which side of a patch segment a direction points to, on a surface with normal `normal`
/// there: +1 left (normal x tangent), -1 right, 0 when it runs along the curve (within 1e-9 of
/// its length) or is degenerate.
int SideOfDirection(Vec3 direction, Vec3 tangent, Vec3 normal);

/// A sample as the user gives it: a point on or near a patch and a direction pointing to the
/// side that must be inside.
struct SampleQuery
{
  Vec3 Position;
  Vec3 Direction;
};

/// Snaps each query to its nearest patch segment within `tolerance`. False with a message
/// naming the first bad sample: NaN position or direction, zero-length direction, no patch
/// within the tolerance.
bool SnapSamples(const PatchSnapper& snapper,
  const std::vector<SampleQuery>& queries,
  double tolerance,
  std::vector<PatchSnap>& snaps,
  std::string& error);

/// The BSC samples of snapped queries: normalOf(point id) is the surface normal at a refined
/// point (only the end points of the snapped segments are asked for). False with a message
/// naming the sample whose direction runs along its curve.
template <class NormalOf>
bool OrientSamples(const PointPositions& positionOf,
  const std::vector<const std::vector<int>*>& patchPoints,
  const std::vector<SampleQuery>& queries,
  const std::vector<PatchSnap>& snaps,
  NormalOf normalOf,
  std::vector<BscSample>& samples,
  std::string& error)
{
  samples.assign(queries.size(), BscSample());
  for (std::size_t k = 0; k < queries.size(); ++k)
  {
    const std::vector<int>& pts = *patchPoints[snaps[k].Patch];
    const int a = pts[snaps[k].Segment], b = pts[snaps[k].Segment + 1];
    const int side = SideOfDirection(
      queries[k].Direction, positionOf(b) - positionOf(a), normalOf(a) + normalOf(b));
    if (side == 0)
    {
      error = "sample " + std::to_string(k) + ": its Direction runs along patch " +
        std::to_string(snaps[k].Patch) + " (or the surface normal there is undefined), so it " +
        "names no side";
      return false;
    }
    samples[k].Patch = snaps[k].Patch;
    samples[k].LeftInside = side > 0;
  }
  return true;
}

/// The unit normal of triangle (a, b, c), zero when it is degenerate. BSC reads the surface
/// normal at a refined point as that of its source triangle, through one of the source
/// triangle's refined triangles (which keep its orientation); every path computes it here, so
/// that a selection made from arrays gives the one made from a Core arrangement.
Vec3 UnitTriangleNormal(Vec3 a, Vec3 b, Vec3 c);

/// The BSC stage on patches given as polylines of points: snap `queries` to the patches'
/// segments (within `tolerance`), orient them with normalOf(point) (asked only at the snapped
/// segments' ends), select. `input` holds the patches (in the order of `patchPoints`), the
/// number of cells and the search settings; its samples are filled here. False with a message
/// naming the bad sample.
bool SelectBySamples(const PointPositions& positionOf,
  const std::vector<const std::vector<int>*>& patchPoints,
  const std::function<Vec3(int)>& normalOf,
  const std::vector<SampleQuery>& queries,
  double tolerance,
  BscInput& input,
  std::vector<PatchSnap>& snaps,
  BscResult& result,
  std::string& error);

struct Arrangement;
class TriangleMesh;

/// BSC's view of an arrangement's patches.
std::vector<BscPatch> BscPatchesOf(const Arrangement& arrangement);

/// The whole BSC stage on a Core arrangement: snap `queries` to its patches (within
/// `tolerance`), orient them with the refined surface's normals, select. snaps[k] is where
/// sample k landed. False with a message naming the bad sample. `mesh` is the mesh the
/// arrangement was computed on.
bool SelectBySamples(const TriangleMesh& mesh,
  const Arrangement& arrangement,
  const std::vector<SampleQuery>& queries,
  double tolerance,
  int maxSearchStates,
  std::vector<PatchSnap>& snaps,
  BscResult& result,
  std::string& error,
  const std::function<bool()>& abort = {});

/// The BSC settings the BSC and one-step filters hold (SnapTolerance, MaxSearchStates).
struct BscOptions
{
  /// How far a sample may be from its patch, as a fraction of the surface's bounding-box
  /// diagonal.
  double SnapTolerance = 0.01;
  /// Minimum cuts the best-first search computes before it finishes greedily
  /// (BscInput::MaxSearchStates).
  int MaxSearchStates = 64;
};

/// SelectBySamples above with the filters' settings: the snap tolerance is
/// options.SnapTolerance times `diagonal`, the bounding-box diagonal of the surface.
bool SelectBySamples(const TriangleMesh& mesh,
  const Arrangement& arrangement,
  const std::vector<SampleQuery>& queries,
  const BscOptions& options,
  double diagonal,
  std::vector<PatchSnap>& snaps,
  BscResult& result,
  std::string& error,
  const std::function<bool()>& abort = {});

} // namespace boolsurf

#endif

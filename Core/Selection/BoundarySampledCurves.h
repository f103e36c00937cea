// Boundary-Sampled Curves (BoolSurf §3.2, §4.6; after Du et al. 2021, "Boundary-Sampled
// Halfspaces"): a region of the arrangement chosen by oriented samples on the curves instead of
// a Boolean expression. No labels are read, so it works on inconsistent arrangements too.
//
// The result is the set of arrangement cells that
//  (a) never has a sampled patch on its boundary with the sample's inside on the wrong side,
//  (d) leaves the fewest samples off its boundary,
//  (c) among those, has the least total boundary length,
//  (b) is sample-connected: every connected piece of one curve's patches on its boundary holds
//      a sample.
// (a, c, d) is one directed minimum cut on the cell graph (Boost Graph's Boykov-Kolmogorov max
// flow): a patch between cells L and R costs its length when exactly one of them is selected; a
// sampled patch is forbidden (infinite cost) with its inside unselected and its outside
// selected, and costs a penalty larger than every length together when it is not on the
// boundary at all, so keeping samples on the boundary comes first and length second. (b) is
// reached by a best-first search over sets of forbidden patch pieces: an unsampled piece on the
// boundary of a cut is forbidden (its two sides must agree) and the cut is computed again;
// states are expanded in order of energy, ties by fewer forbidden patches, then by creation
// order, so the result does not depend on anything but the input. After MaxSearchStates cuts
// the search turns greedy (forbids every unsampled piece of the best state found at once),
// which always ends: with every unsampled patch forbidden the boundary holds only sampled ones.
//
// Patches with the same cell on both sides (non-contractible curves on their own, open curves)
// or with a side beyond an open mesh boundary separate nothing and are ignored; samples on them
// are dropped (reported), never an error.
#ifndef boolsurf_BoundarySampledCurves_h
#define boolsurf_BoundarySampledCurves_h

#include "Mesh/Vec3.h"

#include <functional>
#include <string>
#include <vector>

namespace boolsurf
{

/// What BSC reads of a patch: its two cells, its curve and end points (to find the connected
/// pieces of a curve on the boundary), and its length (the cost of cutting it).
struct BscPatch
{
  int LeftCell = -1, RightCell = -1;
  int Curve = -1;
  int FirstPoint = -1, LastPoint = -1; ///< refined point ids of the patch's ends
  double Length = 0;
};

struct BscSample
{
  int Patch = -1;
  bool LeftInside = true; ///< the cell on the patch's left must be inside
};

struct BscInput
{
  int NumberOfCells = 0;
  std::vector<BscPatch> Patches;
  std::vector<BscSample> Samples;
  /// Minimum cuts the best-first search computes before it turns greedy.
  int MaxSearchStates = 64;
  /// Asked between cuts: true stops the search (the selection then fails with "aborted").
  std::function<bool()> Abort;
};

struct BscResult
{
  std::vector<char> Selected;         ///< per cell
  std::vector<char> SampleOnBoundary; ///< per sample: 1 kept (on the boundary, right side)
  std::vector<int> ForbiddenPatches;  ///< unsampled patches the search kept off the boundary
  double BoundaryLength = 0;
  int Cuts = 0;        ///< minimum cuts computed
  bool Greedy = false; ///< the search hit MaxSearchStates and finished greedily
};

/// Selects the cells; false with a message naming the sample whose patch is out of range.
bool SelectBoundarySampledCells(const BscInput& input, BscResult& result, std::string& error);

/// True when a patch can bound a region (two distinct cells on its sides).
inline bool IsSeparatingPatch(const BscPatch& p)
{
  return p.LeftCell >= 0 && p.RightCell >= 0 && p.LeftCell != p.RightCell;
}

/// The nearest point of a set of patch polylines to a query point.
struct PatchSnap
{
  int Patch = -1;
  int Segment = -1; ///< segment index along the patch (points Segment, Segment + 1)
  double Distance = 0;
};

/// Nearest patch segment to a point, among patch polylines given as point-id lists. Each
/// patch's bounding box is built once, so a query reads the segments of the patches near it.
class PatchSnapper
{
public:
  /// patchPoints[i]: patch i's point ids into `positions` (both must outlive the snapper).
  PatchSnapper(const std::vector<Vec3>& positions,
    const std::vector<const std::vector<int>*>& patchPoints);

  /// Patch = -1 when no segment is within `tolerance`. Ties go to the lower patch, then
  /// segment.
  PatchSnap Snap(Vec3 query, double tolerance) const;

private:
  const std::vector<Vec3>& Positions;
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
bool OrientSamples(const std::vector<Vec3>& positions,
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
    const int side =
      SideOfDirection(queries[k].Direction, positions[b] - positions[a], normalOf(a) + normalOf(b));
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

/// Area-weighted normals at the refined points with wanted[p] != 0, from one pass over the
/// triangles (corner(t, k) = point id, positions indexed by point id). Others stay zero.
template <class CornerOf>
void WantedPointNormals(std::size_t numberOfTriangles,
  CornerOf corner,
  const std::vector<Vec3>& positions,
  const std::vector<char>& wanted,
  std::vector<Vec3>& normals)
{
  normals.assign(positions.size(), Vec3());
  for (std::size_t t = 0; t < numberOfTriangles; ++t)
  {
    const int a = corner(t, 0), b = corner(t, 1), c = corner(t, 2);
    if (!wanted[a] && !wanted[b] && !wanted[c])
    {
      continue;
    }
    const Vec3 n = Cross(positions[b] - positions[a], positions[c] - positions[a]);
    for (int p : { a, b, c })
    {
      if (wanted[p])
      {
        normals[p] = normals[p] + n;
      }
    }
  }
}

struct Arrangement;

/// BSC's view of an arrangement's patches.
std::vector<BscPatch> BscPatchesOf(const Arrangement& arrangement);

/// The whole BSC stage on a Core arrangement: snap `queries` to its patches (within
/// `tolerance`), orient them with the refined surface's normals, select. snaps[k] is where
/// sample k landed. False with a message naming the bad sample.
bool SelectBySamples(const Arrangement& arrangement,
  const std::vector<SampleQuery>& queries,
  double tolerance,
  int maxSearchStates,
  std::vector<PatchSnap>& snaps,
  BscResult& result,
  std::string& error,
  const std::function<bool()>& abort = {});

} // namespace boolsurf

#endif

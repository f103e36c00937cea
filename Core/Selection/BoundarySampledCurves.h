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
// are dropped (reported), never an error. Placing the user's samples on patches:
// Selection/BoundarySamples.h.
#ifndef boolsurf_BoundarySampledCurves_h
#define boolsurf_BoundarySampledCurves_h

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

} // namespace boolsurf

#endif

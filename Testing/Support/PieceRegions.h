// The labels and a Boolean's region of the distributed arrangement against the whole surface's
// stages, for the Core and MPI tests of Core/Distributed: the Boolean operations they run, and
// a region summed per source triangle (what the union of the pieces' regions must equal).
#ifndef boolsurf_PieceRegions_h
#define boolsurf_PieceRegions_h

#include "Arrangement/Arrangement.h"
#include "Distributed/PieceMesh.h"
#include "Distributed/PieceRegionBoundary.h"
#include "Distributed/PieceSelection.h"
#include "Selection/BooleanOptions.h"

#include <map>
#include <string>
#include <vector>

namespace boolsurf
{
namespace testing
{

/// A region's refined triangles of one source triangle: how many, and their area.
struct SourceShare
{
  int Triangles = 0;
  double Area = 0;
};

/// Union of all shapes, intersection and difference of the first two, their symmetric
/// difference by the even-odd rule, and an expression: the operations the tests compare.
std::vector<BooleanOptions> TestBooleanOptions(const std::vector<int>& shapeIds);

/// The whole surface's region of `selected` cells per source triangle.
std::map<int, SourceShare> WholeRegionBySource(const TriangleMesh& mesh,
  const Arrangement& arr,
  const std::vector<char>& selected);

/// A piece's region per (global) source triangle.
std::map<int, SourceShare> PieceRegionBySource(const PieceMesh& piece,
  const Arrangement& arr,
  const PieceRegion& region);

/// Where two regions per source triangle differ (other triangles, or areas beyond
/// 1e-12 x max(1, area)): empty when they agree. `owned` (when not null) restricts `whole` to
/// the source triangles it marks (a piece's share of the whole region).
std::string CompareRegions(const std::map<int, SourceShare>& mine,
  const std::map<int, SourceShare>& whole,
  const std::vector<char>* owned = nullptr);

/// Where the region boundary chained from the pieces' runs differs from the whole surface's
/// (ExtractRegionBoundary on `arr`'s patches): empty when they agree. The same directed
/// segments (positions bit for bit) always; the same loops as point sequences up to where each
/// starts (and in any order) unless a point lies on the boundary twice, where the two may group
/// the segments into loops otherwise.
std::string CompareRegionBoundaries(const std::vector<BoundaryRun>& mine,
  const TriangleMesh& mesh,
  const Arrangement& arr,
  const std::vector<char>& selected);

} // namespace testing
} // namespace boolsurf

#endif

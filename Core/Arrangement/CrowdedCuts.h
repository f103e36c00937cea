// Arrangement stage 2 in a crowded triangle: where its segments must be cut, found per pair of
// lines instead of per pair of segments.
//
// A triangle crowded with segments (a detailed drawing at small scale; a drawing whose curves
// run along shared lines) meets each crossing once per pair of segments through it, and its
// pairs of segments are quadratic in their number when they all overlap in x. Here collinear
// overlapping segments are first grouped into lines. Along a line, its segments' end points are
// sorted once; each segment is cut at the end points strictly inside it (collinear overlaps),
// and every elementary interval between two consecutive end points knows the segments covering
// it. For a pair of lines whose x-ranges overlap, a binary search along each line, on the exact
// orientations of its end points to the other line (they change sign once along a line), finds
// where the other line meets it: nowhere in its span, at one of its end points, or strictly
// inside an elementary interval. A proper crossing (inside an interval on both lines, each
// covered) is made once and put on every segment covering it; an end point of one line inside
// an interval of the other is put on the segments covering that interval (T-junctions). The
// work per pair of lines is logarithmic, plus the cuts it reports.
//
// Every decision is an exact orientation of explicit points; the crossings are kept exact
// (ExactCrossings.h), defined by one segment of each line (the lines are what define them).
#ifndef boolsurf_CrowdedCuts_h
#define boolsurf_CrowdedCuts_h

#include "Arrangement/SegmentIntersection.h"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace boolsurf
{

/// The root of x in a union-find forest (with path halving).
inline int FindRoot(std::vector<int>& parent, int x)
{
  while (parent[x] != x)
  {
    x = parent[x] = parent[parent[x]];
  }
  return x;
}

/// Calls visit(i, j) once for every pair of items 0..n-1 whose x-ranges [xmin, xmax] overlap
/// (a sweep over x; `order` is scratch, left sorted by xmin, ties by index). i comes first in
/// that order.
template <class XMin, class XMax, class Visit>
void ForEachXOverlappingPair(std::vector<int>& order, XMin&& xmin, XMax&& xmax, Visit&& visit)
{
  std::sort(order.begin(),
    order.end(),
    [&](int i, int j) { return xmin(i) != xmin(j) ? xmin(i) < xmin(j) : i < j; });
  const std::size_t n = order.size();
  for (std::size_t oi = 0; oi < n; ++oi)
  {
    const int i = order[oi];
    const double reach = xmax(i);
    for (std::size_t oj = oi + 1; oj < n && xmin(order[oj]) <= reach; ++oj)
    {
      visit(i, order[oj]);
    }
  }
}

/// For the segments from point endA[i] to point endB[i] of `out` (explicit points): appends to
/// hits[i] every point strictly inside segment i where it must be cut, adding the crossings to
/// out.Points and out.Crossings. The same cuts as testing every pair of segments; each cut
/// appears once per segment.
void CutCrowdedSegments(LocalArrangement& out,
  const std::vector<int>& endA,
  const std::vector<int>& endB,
  std::vector<std::vector<int>>& hits);

} // namespace boolsurf

#endif

// The selected region as a small mesh of its own (BoolSurf step 7): the triangles of the
// selected cells and the points they use, renumbered. The cost is the size of the region:
// the triangles come from each cell's contents (clean tiles and loose triangles), and the
// per-point map is kept between calls and reset only where it was written. A large region's
// triangles and corners are gathered on several threads (reading the refined triangles is the
// cost); its points are numbered on one thread, in order of first use.
#ifndef boolsurf_RegionExtraction_h
#define boolsurf_RegionExtraction_h

#include "Arrangement/Arrangement.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <cstddef>
#include <vector>

namespace boolsurf
{

struct RegionMesh
{
  std::vector<int> Triangles;    ///< triangle ids of the source surface, grouped by cell
  std::vector<int> Points;       ///< source point ids used, in order of first use
  std::vector<int> Connectivity; ///< 3 per triangle: indices into Points
};

class RegionExtractor
{
public:
  /// Regions with fewer triangles than this are written on the calling thread (waking other
  /// threads costs more than the work).
  static constexpr std::size_t ParallelTriangles = 1 << 13;

  /// The refined triangles of the cells with selected[c] != 0, cell after cell, each cell's
  /// clean tiles then its loose triangles (from the cells' contents: the cost is the
  /// selection's size). `threads`: at most that many threads (0: all).
  static void SelectedTriangles(const std::vector<char>& selected,
    const Arrangement& arrangement,
    std::vector<int>& triangles,
    int threads = 0);

  /// Renumbers the points of `triangles` (corner(t, k) = point id of corner k of triangle t,
  /// below numberOfPoints) into `out`. `corner` is called from several threads on a large
  /// region, so it must not write shared state.
  template <class CornerOf>
  void Extract(const std::vector<int>& triangles,
    int numberOfPoints,
    CornerOf corner,
    RegionMesh& out,
    int threads = 0)
  {
    out.Triangles = triangles;
    out.Connectivity.resize(3 * triangles.size());
    int* corners = out.Connectivity.data();
    const auto gather = [&](std::size_t first, std::size_t last)
    {
      for (std::size_t i = first; i < last; ++i)
      {
        for (int k = 0; k < 3; ++k)
        {
          corners[3 * i + k] = corner(triangles[i], k);
        }
      }
    };
    if (triangles.size() < ParallelTriangles)
    {
      gather(0, triangles.size());
    }
    else
    {
      tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
      arena.execute(
        [&]
        {
          tbb::parallel_for(tbb::blocked_range<std::size_t>(0, triangles.size(), 1024),
            [&](const tbb::blocked_range<std::size_t>& r) { gather(r.begin(), r.end()); });
        });
    }
    this->RenumberCorners(numberOfPoints, out);
  }

  /// `out.Connectivity` holds the point ids (below numberOfPoints) of the corners of
  /// out.Triangles; replaces them by indices into out.Points, the ids in order of first use.
  void RenumberCorners(int numberOfPoints, RegionMesh& out);

private:
  void EnsurePointMap(int numberOfPoints);

  std::vector<int> PointMap; ///< -1 everywhere between calls
};

} // namespace boolsurf

#endif

// The selected region as a small mesh of its own (BoolSurf step 7): the triangles of the
// selected cells and the points they use, renumbered. The cost is the size of the region:
// the triangles come from each cell's contents (clean tiles and loose triangles), and the
// per-point map is kept between calls and reset only where it was written. A large region's
// triangles and corners are gathered on several threads (reading the refined triangles is the
// cost); its points are numbered on one thread, in order of first use.
#ifndef boolsurf_RegionExtraction_h
#define boolsurf_RegionExtraction_h

#include "Arrangement/Arrangement.h"
#include "Mesh/ParallelRange.h"

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

  /// Renumbers the points of `triangles` (cornersOf(t) = the point ids of triangle t's
  /// corners, below numberOfPoints) into `out`. `cornersOf` is called from several threads on a
  /// large region, so it must not write shared state.
  template <class CornersOf>
  void Extract(const std::vector<int>& triangles,
    int numberOfPoints,
    CornersOf cornersOf,
    RegionMesh& out,
    int threads = 0)
  {
    out.Triangles = triangles;
    out.Connectivity.resize(3 * triangles.size());
    int* corners = out.Connectivity.data();
    ParallelRange(
      threads,
      triangles.size() >= ParallelTriangles,
      static_cast<int>(triangles.size()),
      [&](int i)
      {
        const auto v = cornersOf(triangles[i]);
        for (int k = 0; k < 3; ++k)
        {
          corners[3 * i + k] = v[k];
        }
      },
      1024);
    this->RenumberCorners(numberOfPoints, out);
  }

  /// `out.Connectivity` holds the point ids (below numberOfPoints) of the corners of
  /// out.Triangles; replaces them by indices into out.Points, the ids in order of first use.
  void RenumberCorners(int numberOfPoints, RegionMesh& out);

private:
  void EnsurePointMap(int numberOfPoints);

  /// Region point id + 1 of each refined point, 0 (unmapped) everywhere between calls: zero
  /// pages, so its memory is the part of the surface regions reach.
  ZeroPageVector<int> PointMap;
};

} // namespace boolsurf

#endif

// The selected region as a small mesh of its own (BoolSurf step 7): the triangles of the
// selected cells and the points they use, renumbered. The cost is the size of the region:
// the triangles come from each cell's contents (clean tiles and loose triangles),
// and the point map is kept between calls and reset only where it was written.
#ifndef boolsurf_RegionExtraction_h
#define boolsurf_RegionExtraction_h

#include "Arrangement/Arrangement.h"

#include <array>
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
  /// The refined triangles of the cells with selected[c] != 0 (from the cells' contents: the
  /// cost is the selection's size).
  static void SelectedTriangles(const std::vector<char>& selected,
    const Arrangement& arrangement,
    std::vector<int>& triangles);

  /// Renumbers the points of `triangles` (corner(t, k) = point id of corner k of triangle t,
  /// below numberOfPoints) into `out`.
  template <class CornerOf>
  void Extract(const std::vector<int>& triangles,
    int numberOfPoints,
    CornerOf corner,
    RegionMesh& out)
  {
    if (static_cast<int>(this->PointMap.size()) < numberOfPoints)
    {
      this->PointMap.resize(numberOfPoints, -1);
    }
    out.Triangles = triangles;
    out.Points.clear();
    out.Connectivity.resize(3 * triangles.size());
    int* map = this->PointMap.data();
    for (std::size_t i = 0; i < triangles.size(); ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        const int p = corner(triangles[i], k);
        int& m = map[p];
        if (m < 0)
        {
          m = static_cast<int>(out.Points.size());
          out.Points.push_back(p);
        }
        out.Connectivity[3 * i + k] = m;
      }
    }
    for (int p : out.Points)
    {
      map[p] = -1;
    }
  }

private:
  std::vector<int> PointMap; ///< -1 everywhere between calls
};

} // namespace boolsurf

#endif

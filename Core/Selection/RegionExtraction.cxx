#include "Selection/RegionExtraction.h"

#include <algorithm>

namespace boolsurf
{

//------------------------------------------------------------------------------
void RegionExtractor::SelectedTriangles(const std::vector<char>& selected,
  const Arrangement& arrangement,
  std::vector<int>& triangles)
{
  triangles.clear();
  const int cells = std::min(static_cast<int>(selected.size()), arrangement.NumberOfCells);
  for (int c = 0; c < cells; ++c)
  {
    if (selected[c])
    {
      ForEachCellTriangle(arrangement, c, [&](int r) { triangles.push_back(r); });
    }
  }
}

} // namespace boolsurf

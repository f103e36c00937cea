#include "Selection/RegionExtraction.h"

namespace boolsurf
{

//------------------------------------------------------------------------------
void RegionExtractor::SelectedTriangles(const std::vector<char>& selected,
  const std::vector<int>& cellOffsets,
  const std::vector<int>& cellTriangles,
  std::vector<int>& triangles)
{
  triangles.clear();
  const int cells = static_cast<int>(selected.size());
  for (int c = 0; c < cells && c + 1 < static_cast<int>(cellOffsets.size()); ++c)
  {
    if (selected[c])
    {
      triangles.insert(triangles.end(),
        cellTriangles.begin() + cellOffsets[c],
        cellTriangles.begin() + cellOffsets[c + 1]);
    }
  }
}

} // namespace boolsurf

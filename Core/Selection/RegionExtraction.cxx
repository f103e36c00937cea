#include "Selection/RegionExtraction.h"

#include "Arrangement/EditBuffers.h"

#include <algorithm>

namespace boolsurf
{
//------------------------------------------------------------------------------
void RegionExtractor::SelectedTriangles(const std::vector<char>& selected,
  const Arrangement& arrangement,
  std::vector<int>& triangles,
  int threads)
{
  triangles.clear();
  const int cells = std::min(static_cast<int>(selected.size()), arrangement.NumberOfCells);
  // The region as runs of consecutive ids: a clean tile's members, or a cell's loose
  // triangles; each run's place in the output, then the runs copied in parallel.
  struct Run
  {
    const int* First;
    int Count;
    std::size_t At;
  };
  std::vector<Run> runs;
  std::size_t total = 0;
  const auto add = [&](const int* first, int count)
  {
    if (count > 0)
    {
      runs.push_back({ first, count, total });
      total += count;
    }
  };
  for (int c = 0; c < cells; ++c)
  {
    if (selected[c])
    {
      ForEachCellRun(arrangement, c, add);
    }
  }
  triangles.resize(total);
  ParallelRange(
    threads,
    total >= ParallelTriangles,
    static_cast<int>(runs.size()),
    [&](int i) { std::copy_n(runs[i].First, runs[i].Count, triangles.data() + runs[i].At); },
    16);
}

//------------------------------------------------------------------------------
void RegionExtractor::EnsurePointMap(int numberOfPoints)
{
  const std::size_t n = static_cast<std::size_t>(numberOfPoints);
  // Room for an eighth more points: an edit adds or removes a few (EditBuffers.h).
  if (this->PointMap.size() < n)
  {
    ResizeDiscardingForEdits(this->PointMap, n); // zero, or reset by the last call
  }
}

//------------------------------------------------------------------------------
void RegionExtractor::RenumberCorners(int numberOfPoints, RegionMesh& out)
{
  this->EnsurePointMap(numberOfPoints);
  std::vector<int>& points = out.Points;
  points.clear();
  int* map = this->PointMap.data();
  // One thread, in corner order. Renumbering on several threads (each point's first corner as an
  // atomic minimum, then numbered block by block) gave the same ids but read the per-point maps
  // four times instead of once, and was slower on two threads (Docs/Benchmarks.md).
  for (int& corner : out.Connectivity)
  {
    int& idPlusOne = map[corner];
    if (idPlusOne == 0)
    {
      points.push_back(corner);
      idPlusOne = static_cast<int>(points.size());
    }
    corner = idPlusOne - 1;
  }
  for (int p : points)
  {
    map[p] = 0;
  }
}

} // namespace boolsurf

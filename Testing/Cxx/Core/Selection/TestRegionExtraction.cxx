// The selected region as a mesh of its own (RegionExtractor): on regions large enough to be
// gathered on several threads, the triangles are exactly those of the selected cells, cell after
// cell, the same for any thread count, and the points are numbered as a plain serial
// renumbering in order of first use numbers them.
#include "../Arrangement/ArrangementTestUtils.h"

#include "Selection/RegionExtraction.h"

#include <gtest/gtest.h>

#include <map>

using namespace boolsurf;
using namespace boolsurf::testing;

namespace
{

// A flat square of 2 * 120^2 = 28,800 triangles cut by random polygons: many cells, some of
// them far larger than RegionExtractor::ParallelTriangles.
Arrangement CutSquare(const TriangleMesh& mesh, std::uint32_t seed)
{
  FlatPolygonTracer tracer(mesh);
  std::mt19937 rng(seed);
  std::vector<TracedCurve> curves;
  for (int i = 0; i < 4; ++i)
  {
    curves.push_back(TraceOrDie(tracer, RandomPolygon(rng, 7, 0.05, 0.95), true, i, i));
  }
  return ArrangeOrDie(mesh, curves);
}

// The oracle: a std::map from point id to its index, filled corner after corner.
void ExpectSerialNumbering(const TriangleMesh& mesh,
  const Arrangement& arr,
  const RegionMesh& region)
{
  std::map<int, int> index;
  std::vector<int> points;
  ASSERT_EQ(region.Connectivity.size(), 3 * region.Triangles.size());
  for (std::size_t i = 0; i < region.Triangles.size(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int p = arr.GetTriangle(mesh, region.Triangles[i])[k];
      const auto inserted = index.emplace(p, static_cast<int>(points.size()));
      if (inserted.second)
      {
        points.push_back(p);
      }
      ASSERT_EQ(region.Connectivity[3 * i + k], inserted.first->second)
        << "triangle " << i << " corner " << k;
    }
  }
  EXPECT_EQ(region.Points, points);
}

} // namespace

TEST(RegionExtraction, LargeRegionsMatchTheirCellsAndASerialNumbering)
{
  const TriangleMesh mesh = MeshOf(MakeFlatSquare(120, 1.0, 0.2, 5));
  for (std::uint32_t seed = 1; seed <= 3; ++seed)
  {
    const Arrangement arr = CutSquare(mesh, seed);
    ASSERT_GT(arr.NumberOfCells, 3);
    std::vector<int> cellOf;
    WriteTriangleCells(arr, cellOf);
    // Three selections: every cell, the even cells, only the largest cell.
    std::vector<int> cellSize(arr.NumberOfCells, 0);
    for (int c : cellOf)
    {
      ++cellSize[c];
    }
    const int largest =
      static_cast<int>(std::max_element(cellSize.begin(), cellSize.end()) - cellSize.begin());
    ASSERT_GE(cellSize[largest], static_cast<int>(RegionExtractor::ParallelTriangles));
    for (int which = 0; which < 3; ++which)
    {
      std::vector<char> selected(arr.NumberOfCells);
      for (int c = 0; c < arr.NumberOfCells; ++c)
      {
        selected[c] = which == 0 || (which == 1 && c % 2 == 0) || (which == 2 && c == largest);
      }
      // Expected: every triangle of a selected cell once, cells in increasing order.
      std::vector<int> expected;
      for (std::size_t r = 0; r < cellOf.size(); ++r)
      {
        if (selected[cellOf[r]])
        {
          expected.push_back(static_cast<int>(r));
        }
      }
      std::vector<int> one, all;
      RegionExtractor::SelectedTriangles(selected, arr, one, 1);
      RegionExtractor::SelectedTriangles(selected, arr, all, 0);
      EXPECT_EQ(one, all) << "seed " << seed << ", selection " << which;
      ASSERT_EQ(all.size(), expected.size());
      for (std::size_t i = 1; i < all.size(); ++i)
      {
        ASSERT_LE(cellOf[all[i - 1]], cellOf[all[i]]) << "cells out of order at " << i;
      }
      std::vector<int> sorted = all;
      std::sort(sorted.begin(), sorted.end());
      EXPECT_EQ(sorted, expected);

      RegionExtractor extractor; // reused: its point map must be clean after each call
      for (int threads : { 1, 2, 0 })
      {
        RegionMesh region;
        extractor.Extract(
          all,
          arr.GetNumberOfPoints(),
          [&](int t) { return arr.GetTriangle(mesh, t); },
          region,
          threads);
        EXPECT_EQ(region.Triangles, all);
        ExpectSerialNumbering(mesh, arr, region);
      }
    }
  }
}

#include "Arrangement/TriangleRefinement.h"

#include "Arrangement/Predicates.h"
#include "Arrangement/SweepTriangulation.h"
#include "Mesh/EdgeIndex.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace boolsurf
{
namespace
{

using EdgeKey = std::uint64_t;

/// Ear clipping of the convex polygons the chords cut the triangle into (the fast path).
class ChordTriangulation
{
public:
  explicit ChordTriangulation(LocalArrangement& arrangement)
    : Arr(arrangement)
  {
  }

  int Orient(int a, int b, int c) const
  {
    const std::vector<LocalPoint>& p = this->Arr.Points;
    return Orient2dSign(p[a].P, p[b].P, p[c].P);
  }

  bool Fail(const std::string& why)
  {
    if (this->Arr.Error.empty())
    {
      this->Arr.Error = "triangle " + std::to_string(this->Arr.Triangle) + ": " + why;
    }
    return false;
  }

  /// Triangulates a simple counter-clockwise polygon by ear clipping. An ear needs a strictly
  /// convex tip and no other polygon vertex in its closed triangle. Consumes `poly`.
  bool EarClip(std::vector<int>& poly)
  {
    while (poly.size() > 3)
    {
      const int n = static_cast<int>(poly.size());
      bool clipped = false;
      for (int i = 0; i < n && !clipped; ++i)
      {
        const int a = poly[(i + n - 1) % n], b = poly[i], c = poly[(i + 1) % n];
        if (this->Orient(a, b, c) <= 0)
        {
          continue;
        }
        bool empty = true;
        for (int j = 0; j < n && empty; ++j)
        {
          const int v = poly[j];
          if (v == a || v == b || v == c)
          {
            continue;
          }
          empty = !(
            this->Orient(a, b, v) >= 0 && this->Orient(b, c, v) >= 0 && this->Orient(c, a, v) >= 0);
        }
        if (empty)
        {
          this->Arr.Triangles.push_back({ a, b, c });
          poly.erase(poly.begin() + i);
          clipped = true;
        }
      }
      if (!clipped)
      {
        return this->Fail("a polygon has no ear (degenerate local geometry)");
      }
    }
    if (this->Orient(poly[0], poly[1], poly[2]) <= 0)
    {
      return this->Fail("a polygon degenerates to a flat triangle");
    }
    this->Arr.Triangles.push_back({ poly[0], poly[1], poly[2] });
    return true;
  }

  LocalArrangement& Arr;
};

// Fast path: chords only. Each chord splits the one convex polygon that holds both of its
// endpoints (non-adjacent); a chord already present as a polygon side is a duplicate.
bool SplitByChords(ChordTriangulation& tri, const LocalArrangement& arr)
{
  // The polygons (the first `count`) in vectors kept per thread: an edit refines thousands of
  // triangles, and allocating these small vectors anew was most of the fast path's time.
  struct Scratch
  {
    std::vector<std::vector<int>> Polygons;
    std::vector<int> First, Second;
  };
  thread_local Scratch scratch; // one thread-local lookup per call
  std::vector<std::vector<int>>& polygons = scratch.Polygons;
  std::vector<int>& first = scratch.First;
  std::vector<int>& second = scratch.Second;
  if (polygons.empty())
  {
    polygons.resize(1);
  }
  polygons[0].assign(arr.Boundary.begin(), arr.Boundary.end());
  std::size_t count = 1;
  for (const std::vector<int>& chain : arr.Chains)
  {
    const int a = chain.front(), b = chain.back();
    for (size_t pi = 0; pi < count; ++pi)
    {
      std::vector<int>& poly = polygons[pi];
      const int n = static_cast<int>(poly.size());
      const int ia = static_cast<int>(std::find(poly.begin(), poly.end(), a) - poly.begin());
      const int ib = static_cast<int>(std::find(poly.begin(), poly.end(), b) - poly.begin());
      if (ia == n || ib == n)
      {
        continue;
      }
      if ((ia + 1) % n == ib || (ib + 1) % n == ia)
      {
        break; // already a side
      }
      first.clear();
      second.clear();
      for (int i = ia;; i = (i + 1) % n)
      {
        first.push_back(poly[i]);
        if (i == ib)
          break;
      }
      for (int i = ib;; i = (i + 1) % n)
      {
        second.push_back(poly[i]);
        if (i == ia)
          break;
      }
      poly.swap(first);
      if (polygons.size() == count)
      {
        polygons.emplace_back();
      }
      polygons[count].swap(second);
      ++count;
      break;
    }
  }
  for (std::size_t pi = 0; pi < count; ++pi)
  {
    if (!tri.EarClip(polygons[pi]))
    {
      return false;
    }
  }
  return true;
}

} // namespace

//------------------------------------------------------------------------------
namespace
{
/// Sub-edges on closed curves block the flood fill: Blocked per sub-triangle.
void MarkClosedEdges(LocalArrangement& arr)
{
  thread_local std::vector<EdgeKey> closedEdges;
  closedEdges.clear();
  for (size_t c = 0; c < arr.Chains.size(); ++c)
  {
    if (arr.ChainClosed[c])
    {
      const std::vector<int>& path = arr.Chains[c];
      for (size_t i = 0; i + 1 < path.size(); ++i)
      {
        closedEdges.push_back(UndirectedPointPair(path[i], path[i + 1]));
      }
    }
  }
  std::sort(closedEdges.begin(), closedEdges.end());
  arr.Blocked.assign(arr.Triangles.size(), 0);
  for (size_t t = 0; t < arr.Triangles.size(); ++t)
  {
    const std::array<int, 3>& v = arr.Triangles[t];
    for (int j = 0; j < 3; ++j)
    {
      if (std::binary_search(
            closedEdges.begin(), closedEdges.end(), UndirectedPointPair(v[j], v[(j + 1) % 3])))
      {
        arr.Blocked[t] |= static_cast<unsigned char>(1u << j);
      }
    }
  }
}
} // namespace

bool RefineTriangle(LocalArrangement& arr)
{
  if (!arr.Error.empty())
  {
    return false;
  }
  const int n = static_cast<int>(arr.Points.size());
  bool hasInterior = false;
  for (int i = 0; i < n && !hasInterior; ++i)
  {
    hasInterior = arr.Points[i].Where < 0;
  }
  arr.Triangles.clear();
  if (hasInterior)
  {
    if (!SweepTriangulate(arr))
    {
      return false;
    }
  }
  else
  {
    arr.Alias.resize(n);
    for (int i = 0; i < n; ++i)
    {
      arr.Alias[i] = i;
    }
    ChordTriangulation chords(arr);
    if (!SplitByChords(chords, arr))
    {
      return false;
    }
  }
  // The pieces, at the positions they are written with, must cover the unit triangle once:
  // their unsigned areas add up to its area. A curve that nearly retraces itself inside a
  // triangle (a spike whose sides are about 1e-7 apart) can make the sweep fold pieces over
  // each other (the fuzz target found one whose pieces covered the triangle 1.01 times: the
  // region there was silently wrong). Such a fold is refused with a message. The bound is
  // 1e-4 of the triangle: a crowded triangle of thousands of lattice segments
  // (CrowdedLatticeDrawings, its smaller drawing) still folds by 2.7e-5 of its area, a known
  // defect of the sweep on near-degenerate input (Docs/Fuzzing.md) that this check does not
  // hide behind a refusal of valid drawings.
  double covered = 0;
  for (const std::array<int, 3>& t : arr.Triangles)
  {
    const Vec2 a = arr.Points[t[0]].P, b = arr.Points[t[1]].P, c = arr.Points[t[2]].P;
    covered += 0.5 * std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  }
  if (std::abs(covered - 0.5) > 0.5e-4)
  {
    arr.Error = "triangle " + std::to_string(arr.Triangle) +
      ": the refinement folds over itself where curves nearly retrace each other (within "
      "about 1e-7 of the triangle's size); move a control point slightly";
    return false;
  }
  MarkClosedEdges(arr);
  arr.NumberOfNewPoints = 0;
  for (int i = 0; i < n; ++i)
  {
    if (arr.Points[i].Where < 0 && arr.Alias[i] == i)
    {
      ++arr.NumberOfNewPoints;
    }
  }
  return true;
}

} // namespace boolsurf

#include "Arrangement/CrowdedCuts.h"

#include "Arrangement/Predicates.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace boolsurf
{
namespace
{

/// A line of the drawing: the collinear overlapping segments on it and its end points in order.
struct DrawnLine
{
  std::vector<int> Segments;
  int Axis = 0;                 ///< the coordinate that grows along it
  std::vector<double> Position; ///< distinct end-point coordinates along Axis, increasing
  std::vector<int> PointAt;     ///< one end point at each of them
  /// Segments covering elementary interval k (Position[k], Position[k + 1]):
  /// CoverIds[CoverStart[k] .. CoverStart[k + 1]).
  std::vector<int> CoverStart, CoverIds;
  double XMin = 0.0, XMax = 0.0;
};

/// Where a line meets another inside its span: nowhere, at end point `Index`, or strictly
/// inside elementary interval `Index`.
struct Meeting
{
  enum Kind
  {
    None,
    AtPoint,
    InInterval
  } What = None;
  int Index = -1;
};

class CrowdedCutter
{
public:
  CrowdedCutter(LocalArrangement& out,
    const std::vector<int>& endA,
    const std::vector<int>& endB,
    std::vector<std::vector<int>>& hits)
    : Out(out)
    , EndA(endA)
    , EndB(endB)
    , Hits(hits)
  {
  }

  void Run()
  {
    this->GroupIntoLines();
    for (DrawnLine& line : this->Lines)
    {
      this->CutAlong(line);
    }
    this->CutPointSegments();
    this->CutLinePairs();
  }

private:
  Vec2 P(int point) const { return this->Out.Points[point].P; }
  bool NoLength(int i) const
  {
    const Vec2 a = this->P(this->EndA[i]), b = this->P(this->EndB[i]);
    return a.x == b.x && a.y == b.y;
  }
  double Coordinate(int point, int axis) const
  {
    return axis == 0 ? this->P(point).x : this->P(point).y;
  }

  /// Segments of no length are points, not lines; the others are grouped by exact
  /// collinearity over the pairs whose x-ranges overlap.
  void GroupIntoLines()
  {
    const int count = static_cast<int>(this->EndA.size());
    std::vector<int> order;
    std::vector<int> parent(count);
    for (int i = 0; i < count; ++i)
    {
      parent[i] = i;
      if (this->NoLength(i))
      {
        this->PointSegments.push_back(i);
      }
      else
      {
        order.push_back(i);
      }
    }
    const auto xmin = [&](int i)
    { return std::min(this->P(this->EndA[i]).x, this->P(this->EndB[i]).x); };
    const auto xmax = [&](int i)
    { return std::max(this->P(this->EndA[i]).x, this->P(this->EndB[i]).x); };
    ForEachXOverlappingPair(order,
      xmin,
      xmax,
      [&](int i, int j)
      {
        const Vec2 p0 = this->P(this->EndA[i]), p1 = this->P(this->EndB[i]);
        if (Orient2dSign(p0, p1, this->P(this->EndA[j])) == 0 &&
          Orient2dSign(p0, p1, this->P(this->EndB[j])) == 0)
        {
          parent[FindRoot(parent, i)] = FindRoot(parent, j);
        }
      });
    std::vector<int> lineOfRoot(count, -1);
    for (const int i : order)
    {
      const int root = FindRoot(parent, i);
      if (lineOfRoot[root] < 0)
      {
        lineOfRoot[root] = static_cast<int>(this->Lines.size());
        this->Lines.emplace_back();
      }
      this->Lines[lineOfRoot[root]].Segments.push_back(i);
    }
  }

  /// The end points of a line in order, each segment cut at those strictly inside it, and the
  /// segments covering each elementary interval.
  void CutAlong(DrawnLine& line)
  {
    const int s0 = line.Segments.front();
    const Vec2 a = this->P(this->EndA[s0]), b = this->P(this->EndB[s0]);
    line.Axis = std::abs(b.x - a.x) >= std::abs(b.y - a.y) ? 0 : 1;
    std::vector<std::pair<double, int>> ends;
    line.XMin = a.x;
    line.XMax = a.x;
    for (const int s : line.Segments)
    {
      for (const int p : { this->EndA[s], this->EndB[s] })
      {
        ends.push_back({ this->Coordinate(p, line.Axis), p });
        line.XMin = std::min(line.XMin, this->P(p).x);
        line.XMax = std::max(line.XMax, this->P(p).x);
      }
    }
    std::sort(ends.begin(), ends.end());
    for (std::size_t k = 0; k < ends.size(); ++k)
    {
      if (k == 0 || ends[k].first != ends[k - 1].first)
      {
        line.Position.push_back(ends[k].first);
        line.PointAt.push_back(ends[k].second);
      }
    }
    // Collinear overlaps: every end point strictly inside a segment cuts it.
    const int intervals = static_cast<int>(line.Position.size()) - 1;
    std::vector<int> first(line.Segments.size()), last(line.Segments.size());
    line.CoverStart.assign(intervals + 2, 0);
    for (std::size_t k = 0; k < line.Segments.size(); ++k)
    {
      const int s = line.Segments[k];
      double lo = this->Coordinate(this->EndA[s], line.Axis);
      double hi = this->Coordinate(this->EndB[s], line.Axis);
      if (lo > hi)
      {
        std::swap(lo, hi);
      }
      const auto from = std::upper_bound(ends.begin(), ends.end(), std::make_pair(lo, 1 << 30));
      const auto to = std::lower_bound(ends.begin(), ends.end(), std::make_pair(hi, -1));
      for (auto it = from; it < to; ++it)
      {
        this->Hits[s].push_back(it->second);
      }
      first[k] = static_cast<int>(
        std::lower_bound(line.Position.begin(), line.Position.end(), lo) - line.Position.begin());
      last[k] = static_cast<int>(
        std::lower_bound(line.Position.begin(), line.Position.end(), hi) - line.Position.begin());
      for (int q = first[k]; q < last[k]; ++q)
      {
        ++line.CoverStart[q + 1];
      }
    }
    for (int q = 0; q <= intervals; ++q)
    {
      line.CoverStart[q + 1] += line.CoverStart[q];
    }
    line.CoverIds.resize(line.CoverStart.back());
    std::vector<int> fill(line.CoverStart.begin(), line.CoverStart.end() - 1);
    for (std::size_t k = 0; k < line.Segments.size(); ++k)
    {
      for (int q = first[k]; q < last[k]; ++q)
      {
        line.CoverIds[fill[q]++] = line.Segments[k];
      }
    }
  }

  /// A segment of no length is a point: it cuts every segment it lies strictly inside.
  void CutPointSegments()
  {
    for (const int z : this->PointSegments)
    {
      const int p = this->EndA[z];
      for (std::size_t i = 0; i < this->EndA.size(); ++i)
      {
        const int a = this->EndA[i], b = this->EndB[i];
        if (!this->NoLength(static_cast<int>(i)) && p != a && p != b &&
          StrictlyInsideSegment(this->P(a), this->P(b), this->P(p)))
        {
          this->Hits[i].push_back(p);
        }
      }
    }
  }

  /// Where line `other` (through points u and v) meets `line` within its span: the signs of
  /// the orientations of its end points to `other` change once along it, found by bisection.
  Meeting Locate(const DrawnLine& line, Vec2 u, Vec2 v) const
  {
    const auto side = [&](int k) { return Orient2dSign(u, v, this->P(line.PointAt[k])); };
    const int n = static_cast<int>(line.PointAt.size());
    const int first = side(0);
    if (first == 0)
    {
      return { Meeting::AtPoint, 0 };
    }
    const int lastSide = side(n - 1);
    if (lastSide == 0)
    {
      return { Meeting::AtPoint, n - 1 };
    }
    if (lastSide == first)
    {
      return {};
    }
    int lo = 0, hi = n - 1; // side(lo) == first, side(hi) != first
    while (hi - lo > 1)
    {
      const int mid = (lo + hi) / 2;
      const int s = side(mid);
      if (s == 0)
      {
        return { Meeting::AtPoint, mid };
      }
      (s == first ? lo : hi) = mid;
    }
    return { Meeting::InInterval, lo };
  }

  void CutLinePairs()
  {
    std::vector<int> order(this->Lines.size());
    for (std::size_t l = 0; l < order.size(); ++l)
    {
      order[l] = static_cast<int>(l);
    }
    ForEachXOverlappingPair(
      order,
      [&](int l) { return this->Lines[l].XMin; },
      [&](int l) { return this->Lines[l].XMax; },
      [&](int a, int b) { this->CutPair(this->Lines[a], this->Lines[b]); });
  }

  void CutPair(const DrawnLine& l1, const DrawnLine& l2)
  {
    const int r1 = l1.Segments.front(), r2 = l2.Segments.front();
    const Vec2 p0 = this->P(this->EndA[r1]), p1 = this->P(this->EndB[r1]);
    const Vec2 q0 = this->P(this->EndA[r2]), q1 = this->P(this->EndB[r2]);
    const Meeting m1 = this->Locate(l1, q0, q1);
    if (m1.What == Meeting::None)
    {
      return;
    }
    const Meeting m2 = this->Locate(l2, p0, p1);
    if (m2.What == Meeting::None)
    {
      return;
    }
    if (m1.What == Meeting::InInterval && m2.What == Meeting::InInterval)
    {
      if (l1.CoverStart[m1.Index] == l1.CoverStart[m1.Index + 1] ||
        l2.CoverStart[m2.Index] == l2.CoverStart[m2.Index + 1])
      {
        return; // the lines meet where one of them has no segment
      }
      const int id = AddCrossingPoint(this->Out, p0, p1, q0, q1);
      this->CutCovering(l1, m1.Index, id);
      this->CutCovering(l2, m2.Index, id);
    }
    else if (m1.What == Meeting::AtPoint && m2.What == Meeting::InInterval)
    {
      this->CutCovering(l2, m2.Index, l1.PointAt[m1.Index]);
    }
    else if (m1.What == Meeting::InInterval && m2.What == Meeting::AtPoint)
    {
      this->CutCovering(l1, m1.Index, l2.PointAt[m2.Index]);
    }
    // Both at an end point: the lines meet at a point both end at; nothing is cut.
  }

  void CutCovering(const DrawnLine& line, int interval, int point)
  {
    for (int k = line.CoverStart[interval]; k < line.CoverStart[interval + 1]; ++k)
    {
      this->Hits[line.CoverIds[k]].push_back(point);
    }
  }

  LocalArrangement& Out;
  const std::vector<int>& EndA;
  const std::vector<int>& EndB;
  std::vector<std::vector<int>>& Hits;
  std::vector<DrawnLine> Lines;
  std::vector<int> PointSegments;
};

} // namespace

void CutCrowdedSegments(LocalArrangement& out,
  const std::vector<int>& endA,
  const std::vector<int>& endB,
  std::vector<std::vector<int>>& hits)
{
  CrowdedCutter(out, endA, endB, hits).Run();
}

} // namespace boolsurf

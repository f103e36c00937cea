// Checks of one lattice drawing answered by the Core chain (FlatDrawingOracle.h): every cell's
// labels against the planar winding numbers, and every operation and fill rule's area against
// the exact sweep and Clipper, on flat meshes with or without an axis-aligned hole.
#ifndef boolsurf_LatticeDrawingChecks_h
#define boolsurf_LatticeDrawingChecks_h

#include "FlatDrawingOracle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace boolsurf
{
namespace testing
{

/// How often Clipper agreed with the exact sweep (it mishandles some overlapping edges).
struct ClipperTally
{
  int Comparisons = 0, Disagreements = 0;
};

inline bool Evaluate(int op, bool a, bool b)
{
  switch (op)
  {
    case 0:
      return a || b;
    case 1:
      return a && b;
    case 2:
      return a && !b;
    default:
      return a != b;
  }
}

/// Winding number of shape `shape`'s polygons around q (exact for integer polygons and a
/// point off their sides; the sign tests are exact products of small integers and q's
/// coordinates up to rounding far below the distances involved).
inline int WindingNumber(const std::vector<LatticePolygon>& drawing, int shape, Vec2 q)
{
  int w = 0;
  for (const auto& p : drawing)
  {
    if (p.Shape != shape)
      continue;
    const size_t n = p.Points.size();
    for (size_t i = 0; i < n; ++i)
    {
      const Vec2 a{ double(p.Points[i][0]), double(p.Points[i][1]) };
      const Vec2 b{ double(p.Points[(i + 1) % n][0]), double(p.Points[(i + 1) % n][1]) };
      const double side = (b.x - a.x) * (q.y - a.y) - (q.x - a.x) * (b.y - a.y);
      if (a.y <= q.y && b.y > q.y && side > 0)
        ++w;
      else if (a.y > q.y && b.y <= q.y && side < 0)
        --w;
    }
  }
  return w;
}

/// Independent of Clipper: every cell's labels are the winding numbers of the input polygons
/// at the centroid of the cell's largest refined triangle.
inline void ExpectLabelsAreWindingNumbers(const TriangleMesh& mesh,
  const FlatDrawingAnswer& a,
  const std::vector<LatticePolygon>& drawing,
  const std::string& meshName,
  int& failures)
{
  std::vector<int> best(a.Arr.NumberOfCells, -1);
  std::vector<double> bestArea(a.Arr.NumberOfCells, 0.0);
  for (size_t r = 0; r < static_cast<size_t>(a.Arr.GetNumberOfTriangles()); ++r)
  {
    const auto& t = a.Arr.GetTriangle(mesh, r);
    const Vec3 &p = a.Arr.GetPosition(mesh, t[0]), &q = a.Arr.GetPosition(mesh, t[1]),
               &s = a.Arr.GetPosition(mesh, t[2]);
    const double area = 0.5 * ((q.x - p.x) * (s.y - p.y) - (q.y - p.y) * (s.x - p.x));
    const int c = a.Arr.CellOfTriangle(static_cast<int>(r));
    if (area > bestArea[c])
    {
      bestArea[c] = area;
      best[c] = static_cast<int>(r);
    }
  }
  for (int c = 0; c < a.Arr.NumberOfCells; ++c)
  {
    if (best[c] < 0 || bestArea[c] < 1e-6)
      continue; // a sliver: its centroid is too close to the curves to decide
    const auto& t = a.Arr.GetTriangle(mesh, best[c]);
    const Vec3 &p0 = a.Arr.GetPosition(mesh, t[0]), &p1 = a.Arr.GetPosition(mesh, t[1]),
               &p2 = a.Arr.GetPosition(mesh, t[2]);
    const Vec2 g{ (p0.x + p1.x + p2.x) / 3.0, (p0.y + p1.y + p2.y) / 3.0 };
    for (int s = 0; s < a.Labels.NumberOfShapes; ++s)
    {
      const int expected = WindingNumber(drawing, a.Labels.ShapeIdOf(s), g);
      if (a.Labels.GetLabel(c, s) != expected)
      {
        ADD_FAILURE() << meshName << ": cell " << c << " has label " << a.Labels.GetLabel(c, s)
                      << " for shape " << a.Labels.ShapeIdOf(s) << ", winding number " << expected
                      << ", in " << DescribeDrawing(drawing);
        ++failures;
        return;
      }
    }
  }
}

inline void CheckDrawing(const TriangleMesh& mesh,
  const std::vector<LatticePolygon>& drawing,
  const std::string& meshName,
  int& failures,
  ClipperTally& tally,
  const FlatHole& hole = FlatHole())
{
  const FlatDrawingAnswer a = AnswerDrawing(mesh, drawing);
  if (!a.Ok)
  {
    ADD_FAILURE() << meshName << " refused " << DescribeDrawing(drawing) << ": " << a.Error;
    ++failures;
    return;
  }
  ExpectLabelsAreWindingNumbers(mesh, a, drawing, meshName, failures);
  // Shape index of each user shape (shapes without polygons are empty).
  auto indexOf = [&](int shape) { return ShapeIndexOf(a.Labels.ShapeIds, shape); };
  const int i0 = indexOf(0), i1 = indexOf(1);
  const ClipperLib::Paths pa = ClipperPathsOf(drawing, 0), pb = ClipperPathsOf(drawing, 1);
  const ClipperLib::ClipType ops[] = {
    ClipperLib::ctUnion, ClipperLib::ctIntersection, ClipperLib::ctDifference, ClipperLib::ctXor
  };
  const ClipperLib::PolyFillType rules[] = {
    ClipperLib::pftNonZero, ClipperLib::pftEvenOdd, ClipperLib::pftPositive, ClipperLib::pftNegative
  };
  double total = 0;
  for (double c : a.CellArea)
    total += c;
  for (int rule = 0; rule < 4; ++rule)
  {
    const FillRule fill = static_cast<FillRule>(rule);
    auto in = [&](const std::vector<int>& l, int index)
    { return index >= 0 && IsInside(l[index], fill); };
    double areas[4];
    auto clip = [&](int op, const ClipperLib::Paths& subject, const ClipperLib::Paths& clipPaths)
    {
      ClipperLib::Clipper clipper;
      clipper.AddPaths(subject, ClipperLib::ptSubject, true);
      clipper.AddPaths(clipPaths, ClipperLib::ptClip, true);
      ClipperLib::Paths solution;
      clipper.Execute(ops[op], solution, rules[rule], rules[rule]);
      return ClipperAreaOf(solution);
    };
    for (int op = 0; op < 4; ++op)
    {
      // Clipper's own xor mishandles edges shared by both operands (it drops the strip along
      // them); A - B and B - A are disjoint, so their areas add up to the xor's.
      const auto selects = [&](const std::vector<int>& w)
      { return Evaluate(op, IsInside(w[0], fill), IsInside(w[1], fill)); };
      // A hole holds no curve: the winding numbers are constant in it, and what the plane
      // selects there is not on the surface.
      const double inHole = hole.Empty() ||
          !selects(
            { WindingNumber(drawing, 0, hole.Center()), WindingNumber(drawing, 1, hole.Center()) })
        ? 0.0
        : hole.Area();
      const double expected =
        (op == 3 ? clip(2, pa, pb) + clip(2, pb, pa) : clip(op, pa, pb)) - inHole;
      areas[op] = SelectedArea(
        a, [&](const std::vector<int>& l) { return Evaluate(op, in(l, i0), in(l, i1)); });
      // Winding numbers of user shapes 0 and 1 (the sweep names shapes by user id).
      const double swept = SweepArea(drawing, 2, selects) - inHole;
      if (std::abs(areas[op] - swept) > 1e-9 * total)
      {
        ADD_FAILURE() << meshName << " op " << op << " rule " << rule << ": area " << areas[op]
                      << ", exact " << swept << ", Clipper " << expected << " for "
                      << DescribeDrawing(drawing);
        ++failures;
        return;
      }
      // Clipper agrees except where it mishandles overlapping edges; such cases are counted
      // (and must stay a small minority: they are Clipper's, the sweep above is exact).
      ++tally.Comparisons;
      if (std::abs(expected - swept) > 1e-9 * total)
        ++tally.Disagreements;
      else
        EXPECT_NEAR(areas[op], expected, 1e-9 * total) << DescribeDrawing(drawing);
    }
    // Inclusion-exclusion and complement, on the chain's own answers.
    const double sa = SelectedArea(a, [&](const std::vector<int>& l) { return in(l, i0); });
    const double sb = SelectedArea(a, [&](const std::vector<int>& l) { return in(l, i1); });
    const double notA = SelectedArea(a, [&](const std::vector<int>& l) { return !in(l, i0); });
    EXPECT_NEAR(areas[0] + areas[1], sa + sb, 1e-9 * total) << DescribeDrawing(drawing);
    EXPECT_NEAR(sa + notA, total, 1e-9 * total) << DescribeDrawing(drawing);
  }
}

} // namespace testing
} // namespace boolsurf

#endif

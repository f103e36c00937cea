#include "Homology/InconsistencyExplanation.h"

#include "Homology/HomologyBasis.h"

#include <algorithm>

namespace boolsurf
{
namespace
{
std::string Signed(int x)
{
  return (x > 0 ? "+" : "") + std::to_string(x);
}

} // namespace

//------------------------------------------------------------------------------
bool ComputeCurveClasses(const HomologyBasis& basis,
  const std::vector<TracedCurve>& curves,
  HomologyFields& out,
  std::string& error)
{
  out = HomologyFields();
  out.Present = true;
  out.NumberOfGenerators = basis.GetNumberOfGenerators();
  std::vector<int> h;
  for (const TracedCurve& c : curves)
  {
    if (!basis.ClassOf(c, h, error))
    {
      return false;
    }
    out.CurveIds.push_back(c.CurveId);
    out.CurveShapeIds.push_back(c.ShapeId);
    out.CurveClasses.push_back(h);
  }
  return true;
}

//------------------------------------------------------------------------------
std::vector<std::vector<int>> ShapeExcess(const HomologyFields& h, const std::vector<int>& shapeIds)
{
  std::vector<std::vector<int>> excess(shapeIds.size(), std::vector<int>(h.NumberOfGenerators, 0));
  for (size_t r = 0; r < h.CurveClasses.size(); ++r)
  {
    const auto it = std::lower_bound(shapeIds.begin(), shapeIds.end(), h.CurveShapeIds[r]);
    if (it != shapeIds.end() && *it == h.CurveShapeIds[r])
    {
      std::vector<int>& sum = excess[it - shapeIds.begin()];
      for (int g = 0; g < h.NumberOfGenerators; ++g)
      {
        sum[g] += h.CurveClasses[r][g];
      }
    }
  }
  return excess;
}

//------------------------------------------------------------------------------
std::string DescribeClass(const std::vector<int>& homology)
{
  std::string text;
  for (size_t g = 0; g < homology.size(); ++g)
  {
    if (homology[g] != 0)
    {
      text += (text.empty() ? "" : ", ") + Signed(homology[g]) + " x G" + std::to_string(g);
    }
  }
  return text.empty() ? "no generator" : text;
}

//------------------------------------------------------------------------------
std::string ExplainInconsistency(const LabelingResult& labels, const HomologyFields& h)
{
  std::string text;
  for (int s = 0; s < labels.NumberOfShapes; ++s)
  {
    if (labels.ShapeConsistent[s])
    {
      continue;
    }
    const int shapeId = labels.ShapeIdOf(s);
    std::string curves;
    std::vector<int> excess(h.NumberOfGenerators, 0);
    std::vector<int> offending;
    for (size_t r = 0; r < h.CurveClasses.size(); ++r)
    {
      if (h.CurveShapeIds[r] != shapeId)
      {
        continue;
      }
      const std::vector<int>& c = h.CurveClasses[r];
      for (int g = 0; g < h.NumberOfGenerators; ++g)
      {
        excess[g] += c[g];
      }
      if (std::any_of(c.begin(), c.end(), [](int x) { return x != 0; }))
      {
        offending.push_back(h.CurveIds[r]);
        curves += (curves.empty() ? "" : "; ") + std::string("curve ") +
          std::to_string(h.CurveIds[r]) + " winds " + DescribeClass(c);
      }
    }
    text += (text.empty() ? "" : "\n") + std::string("Shape S") + std::to_string(shapeId) + ": ";
    if (offending.empty())
    {
      text += "no curve winds around a handle of the surface (an open curve, or curves meeting "
              "within rounding, keep the labels from agreeing).";
      continue;
    }
    std::string ids;
    for (int id : offending)
    {
      ids += (ids.empty() ? "" : ", ") + std::to_string(id);
    }
    text += curves + ". Generators in excess: " + DescribeClass(excess) +
      " (drawn by the second output of Label Arrangement Cells). Its curves do not bound a "
      "region. Fixes (Resolve Inconsistent Shapes, Strategy): AddGenerators adds a reversed "
      "copy of each generator in excess so the shape closes across the handles; "
      "DuplicateReversed turns each offending curve (" +
      ids +
      ") into a thin solid strip with a reversed copy beside it; RemoveCurves drops (or flips) "
      "curves whose windings add up to the excess.";
  }
  return text;
}

} // namespace boolsurf

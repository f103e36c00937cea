#include "Support/PieceRegions.h"

#include "Selection/RegionExtraction.h"
#include "Support/PieceSplits.h"

#include <algorithm>
#include <cmath>

namespace boolsurf
{
namespace testing
{

//------------------------------------------------------------------------------
std::vector<BooleanOptions> TestBooleanOptions(const std::vector<int>& shapeIds)
{
  std::vector<BooleanOptions> options;
  if (shapeIds.empty())
  {
    return options;
  }
  const int a = shapeIds[0], b = shapeIds.size() > 1 ? shapeIds[1] : shapeIds[0];
  BooleanOptions o;
  o.Operation = BooleanOperation::Union;
  o.ShapeA = -1;
  options.push_back(o);
  o.Operation = BooleanOperation::Intersection;
  o.ShapeA = a;
  o.ShapeB = b;
  options.push_back(o);
  o.Operation = BooleanOperation::Difference;
  options.push_back(o);
  o.Operation = BooleanOperation::SymmetricDifference;
  o.Rule = FillRule::EvenOdd;
  options.push_back(o);
  o.Operation = BooleanOperation::Expression;
  o.Rule = FillRule::Positive;
  o.Expression = "S" + std::to_string(b) + " & !S" + std::to_string(a);
  options.push_back(o);
  return options;
}

//------------------------------------------------------------------------------
std::map<int, SourceShare> WholeRegionBySource(const TriangleMesh& mesh,
  const Arrangement& arr,
  const std::vector<char>& selected)
{
  std::vector<int> triangles;
  RegionExtractor::SelectedTriangles(selected, arr, triangles, 1);
  std::map<int, SourceShare> shares;
  for (const int r : triangles)
  {
    SourceShare& s = shares[arr.GetSourceTriangle(mesh, r)];
    ++s.Triangles;
    s.Area += RefinedArea(mesh, arr, r);
  }
  return shares;
}

//------------------------------------------------------------------------------
std::map<int, SourceShare> PieceRegionBySource(const PieceMesh& piece,
  const Arrangement& arr,
  const PieceRegion& region)
{
  std::map<int, SourceShare> shares;
  for (size_t i = 0; i < region.Triangles.size(); ++i)
  {
    SourceShare& s = shares[region.SourceTriangles[i]];
    ++s.Triangles;
    s.Area += RefinedArea(piece.Mesh, arr, region.Triangles[i]);
  }
  return shares;
}

//------------------------------------------------------------------------------
std::string CompareRegions(const std::map<int, SourceShare>& mine,
  const std::map<int, SourceShare>& whole,
  const std::vector<char>* owned)
{
  std::map<int, SourceShare> expected;
  for (const auto& w : whole)
  {
    if (!owned || (w.first < static_cast<int>(owned->size()) && (*owned)[w.first]))
    {
      expected.insert(w);
    }
  }
  if (mine.size() != expected.size())
  {
    return std::to_string(mine.size()) + " source triangles selected, expected " +
      std::to_string(expected.size());
  }
  auto e = expected.cbegin();
  for (auto m = mine.cbegin(); m != mine.cend(); ++m, ++e)
  {
    if (m->first != e->first)
    {
      return "source triangle " + std::to_string(m->first) + " selected, expected " +
        std::to_string(e->first);
    }
    if (m->second.Triangles != e->second.Triangles ||
      std::abs(m->second.Area - e->second.Area) > 1e-12 * std::max(1.0, e->second.Area))
    {
      return "source triangle " + std::to_string(m->first) + ": " +
        std::to_string(m->second.Triangles) + " refined triangles of area " +
        std::to_string(m->second.Area) + ", expected " + std::to_string(e->second.Triangles) +
        " of area " + std::to_string(e->second.Area);
    }
  }
  return std::string();
}

} // namespace testing
} // namespace boolsurf

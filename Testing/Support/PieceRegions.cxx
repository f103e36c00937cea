#include "Support/PieceRegions.h"

#include "Selection/RegionBoundary.h"
#include "Selection/RegionExtraction.h"
#include "Support/PieceSplits.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

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

namespace
{
using Position = std::tuple<double, double, double>;
struct Line
{
  std::vector<Position> Points;
  bool Closed = false;
};

Position PositionOf(const Vec3& x)
{
  return { x.x, x.y, x.z };
}

/// A closed loop started at its lowest point (then the lowest point after it).
void Rotate(Line& line)
{
  if (!line.Closed || line.Points.empty())
  {
    return;
  }
  const std::size_t m = line.Points.size();
  std::size_t best = 0;
  for (std::size_t k = 1; k < m; ++k)
  {
    const auto key = std::make_pair(line.Points[k], line.Points[(k + 1) % m]);
    if (key < std::make_pair(line.Points[best], line.Points[(best + 1) % m]))
    {
      best = k;
    }
  }
  std::rotate(line.Points.begin(), line.Points.begin() + best, line.Points.end());
}

std::map<std::pair<Position, Position>, int> Segments(const std::vector<Line>& lines)
{
  std::map<std::pair<Position, Position>, int> count;
  for (const Line& line : lines)
  {
    const std::size_t m = line.Points.size();
    for (std::size_t k = 0; k + 1 < m + (line.Closed ? 1 : 0); ++k)
    {
      ++count[{ line.Points[k], line.Points[(k + 1) % m] }];
    }
  }
  return count;
}

std::vector<std::pair<bool, std::vector<Position>>> Sorted(std::vector<Line> lines)
{
  std::vector<std::pair<bool, std::vector<Position>>> out;
  for (Line& line : lines)
  {
    Rotate(line);
    out.emplace_back(line.Closed, line.Points);
  }
  std::sort(out.begin(), out.end());
  return out;
}
} // namespace

//------------------------------------------------------------------------------
std::string CompareRegionBoundaries(const std::vector<BoundaryRun>& mine,
  const TriangleMesh& mesh,
  const Arrangement& arr,
  const std::vector<char>& selected)
{
  std::vector<Line> theirs, ours;
  std::map<Position, int> visits;
  bool twice = false;
  for (const BoundaryPolyline& polyline : ExtractRegionBoundary(arr.Patches, selected))
  {
    Line line;
    line.Closed = polyline.Closed;
    for (int p : polyline.Points)
    {
      line.Points.push_back(PositionOf(arr.GetPosition(mesh, p)));
      twice = ++visits[line.Points.back()] > 1 || twice;
    }
    theirs.push_back(std::move(line));
  }
  for (const BoundaryRun& run : mine)
  {
    Line line;
    line.Closed = run.Closed;
    for (const BoundaryPointRecord& p : run.Points)
    {
      line.Points.push_back(PositionOf(p.Position));
    }
    ours.push_back(std::move(line));
  }
  const auto a = Segments(ours), b = Segments(theirs);
  if (a != b)
  {
    int missing = 0, extra = 0;
    for (const auto& s : b)
    {
      const auto f = a.find(s.first);
      missing += std::max(0, s.second - (f == a.end() ? 0 : f->second));
    }
    for (const auto& s : a)
    {
      const auto f = b.find(s.first);
      extra += std::max(0, s.second - (f == b.end() ? 0 : f->second));
    }
    return "boundary segments differ: " + std::to_string(missing) + " of the whole's missing, " +
      std::to_string(extra) + " extra, of " + std::to_string(b.size());
  }
  if (!twice && Sorted(ours) != Sorted(theirs))
  {
    return "boundary loops differ: " + std::to_string(ours.size()) + " loops, the whole has " +
      std::to_string(theirs.size());
  }
  return std::string();
}

} // namespace testing
} // namespace boolsurf

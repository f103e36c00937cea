#include "vtkBoolSurfWindingStage.h"

#include "Mesh/ParallelRange.h"

#include "vtkBoolSurfArrayNames.h"

#include <vtkCellData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkType.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>
#include <sstream>

namespace boolsurf
{

//------------------------------------------------------------------------------
bool ParseShapeList(const std::string& text,
  const char* property,
  std::vector<int>& ids,
  std::string& error)
{
  ids.clear();
  std::string list = text;
  for (char& c : list)
  {
    c = (c == ',' || c == ';') ? ' ' : c;
  }
  std::istringstream in(list);
  std::string token;
  while (in >> token)
  {
    const std::string given = token;
    if (token[0] == 'S' || token[0] == 's')
    {
      token = token.substr(1);
    }
    char* end = nullptr;
    const long id = std::strtol(token.c_str(), &end, 10);
    if (token.empty() || *end != '\0' || id < 0 || id > VTK_INT_MAX)
    {
      error = std::string(property) + " entry '" + given + "' is not a ShapeId";
      return false;
    }
    if (std::find(ids.begin(), ids.end(), static_cast<int>(id)) == ids.end())
    {
      ids.push_back(static_cast<int>(id));
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool CheckShapesExist(const std::vector<TracedCurve>& curves,
  const std::vector<int>& requested,
  const char* property,
  std::string& error)
{
  std::set<int> known;
  for (const TracedCurve& c : curves)
  {
    known.insert(c.ShapeId);
  }
  for (int id : requested)
  {
    if (!known.count(id))
    {
      std::string list;
      for (int k : known)
      {
        list += (list.empty() ? "" : ", ") + std::to_string(k);
      }
      error = std::string(property) + " names shape " + std::to_string(id) +
        ", which no curve has (the curves' ShapeIds: " + (list.empty() ? "none" : list) + ")";
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
std::map<int, std::string> ReadShapeNames(vtkPolyData* curves,
  const std::vector<InputControlCurve>& controls)
{
  std::map<int, std::string> names;
  auto* given = curves
    ? vtkStringArray::SafeDownCast(curves->GetCellData()->GetAbstractArray(names::ShapeName))
    : nullptr;
  if (!given)
  {
    return names;
  }
  for (const InputControlCurve& c : controls)
  {
    if (c.CurveId < 0 || c.CurveId >= given->GetNumberOfValues() || names.count(c.ShapeId))
    {
      continue;
    }
    const std::string name = given->GetValue(c.CurveId);
    if (!name.empty())
    {
      names[c.ShapeId] = name;
    }
  }
  return names;
}

//------------------------------------------------------------------------------
std::string ShapeLabel(int shapeId, const std::map<int, std::string>& names)
{
  const auto found = names.find(shapeId);
  return found != names.end() ? found->second : "Shape " + std::to_string(shapeId);
}

//------------------------------------------------------------------------------
std::string DescribeWindingCurve(const WindingCurveReport& report)
{
  return "curve " + std::to_string(report.CurveId) + " of shape " + std::to_string(report.ShapeId);
}

//------------------------------------------------------------------------------
bool ExtractCompletedLoops(const TriangleMesh& mesh,
  const Arrangement& arr,
  const WindingResult& result,
  double threshold,
  int threads,
  std::vector<LevelSetLoop>& loops,
  std::vector<int>& loopShape,
  std::string& error)
{
  loops.clear();
  loopShape.clear();
  // The shapes' level sets are independent: extracted on the threads, gathered in shape order.
  const int ns = result.GetNumberOfShapes();
  std::vector<std::vector<LevelSetLoop>> shapeLoops(ns);
  std::vector<std::string> errors(ns);
  ParallelBlocks(
    threads,
    ns > 1,
    ns,
    [&](int first, int last)
    {
      for (int s = first; s < last; ++s)
      {
        LevelSetInput input;
        input.Threshold = threshold;
        input.CornerValue = [&](int r, int k) { return result.Corner(arr, mesh, s, r, k); };
        input.JumpTriangles = &result.JumpTriangles;
        if (!ExtractLevelSet(mesh, arr, input, shapeLoops[s], errors[s]))
        {
          errors[s] =
            "the level set of shape " + std::to_string(result.ShapeIds[s]) + ": " + errors[s];
        }
      }
    },
    1);
  for (int s = 0; s < ns; ++s)
  {
    if (!errors[s].empty())
    {
      error = errors[s];
      return false;
    }
    for (LevelSetLoop& loop : shapeLoops[s])
    {
      loops.push_back(std::move(loop));
      loopShape.push_back(s);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool CloseBrokenShapes(SurfaceWinding& winding,
  const TriangleMesh& mesh,
  const CloseShapesOptions& options,
  std::vector<TracedCurve>& curves,
  std::vector<CurveSource>& sources,
  std::vector<std::string>& notes,
  std::vector<std::string>& warnings,
  std::string& error)
{
  if (!std::isfinite(options.Threshold))
  {
    error = "WindingThreshold is not a finite number";
    return false;
  }
  if (!CheckShapesExist(curves, options.Shapes, "CloseBrokenShapes", error))
  {
    return false;
  }
  const std::set<int> closing(options.Shapes.begin(), options.Shapes.end());
  std::vector<TracedCurve> broken;
  int nextCurveId = 0;
  for (const TracedCurve& c : curves)
  {
    nextCurveId = std::max(nextCurveId, c.CurveId + 1);
    if (closing.count(c.ShapeId))
    {
      broken.push_back(c);
    }
  }
  // Their winding numbers, on the arrangement of their curves alone.
  Arrangement arrangement;
  ArrangementOptions arrangementOptions;
  arrangementOptions.Threads = options.Threads;
  if (!ComputeArrangement(mesh, broken, arrangementOptions, arrangement, error))
  {
    error = "CloseBrokenShapes: the arrangement of the shapes' curves failed: " + error;
    return false;
  }
  WindingOptions windingOptions;
  windingOptions.Shapes = options.Shapes;
  windingOptions.Threshold = options.Threshold;
  windingOptions.Threads = options.Threads;
  WindingResult result;
  if (!winding.Compute(mesh, arrangement, broken, windingOptions, result, error))
  {
    error = "CloseBrokenShapes: " + error;
    return false;
  }
  std::vector<LevelSetLoop> loops;
  std::vector<int> loopShape;
  if (!ExtractCompletedLoops(
        mesh, arrangement, result, options.Threshold, options.Threads, loops, loopShape, error))
  {
    error = "CloseBrokenShapes: " + error;
    return false;
  }
  for (const WindingCurveReport& report : result.Curves)
  {
    std::ostringstream line;
    line << "CloseBrokenShapes: " << DescribeWindingCurve(report) << " replaced by its shape's "
         << "completed curves (residual " << report.Residual << ")";
    notes.push_back(line.str());
    if (!report.Bounds)
    {
      warnings.push_back("CloseBrokenShapes: " + DescribeWindingCurve(report) +
        (report.AroundHandle
            ? " bounds nothing (its homology class is not bounded by the shape's other curves)"
            : " bounds nothing (a spur, an overshooting piece or an isolated arc)") +
        ": it takes no part in the completed shape");
    }
  }
  std::vector<int> loopCount(result.ShapeIds.size(), 0);
  for (int s : loopShape)
  {
    ++loopCount[s];
  }
  for (std::size_t s = 0; s < loopCount.size(); ++s)
  {
    if (loopCount[s] == 0)
    {
      std::ostringstream line;
      line << "CloseBrokenShapes: shape " << result.ShapeIds[s] << " has no region where its "
           << "winding number reaches " << options.Threshold << ": it is empty";
      notes.push_back(line.str());
    }
  }

  // The shapes' curves replaced by their loops.
  const bool withSources = !sources.empty();
  std::vector<TracedCurve> kept;
  std::vector<CurveSource> keptSources;
  for (std::size_t c = 0; c < curves.size(); ++c)
  {
    if (closing.count(curves[c].ShapeId))
    {
      continue;
    }
    kept.push_back(std::move(curves[c]));
    if (withSources)
    {
      keptSources.push_back(std::move(sources[c]));
    }
  }
  for (std::size_t i = 0; i < loops.size(); ++i)
  {
    TracedCurve loop;
    loop.Points = loops[i].Points;
    loop.Closed = true;
    loop.ShapeId = result.ShapeIds[loopShape[i]];
    loop.CurveId = nextCurveId++;
    if (withSources)
    {
      // A geodesic polygon through every point of the loop: traced point k is control point k.
      CurveSource source;
      source.Points = loops[i].SurfacePoints;
      source.Parameter.resize(loop.Points.size());
      for (std::size_t k = 0; k < loop.Points.size(); ++k)
      {
        source.Parameter[k] = static_cast<double>(k);
      }
      source.Type = CurveType::GeodesicPolygon;
      source.Closed = true;
      source.ShapeId = loop.ShapeId;
      source.CurveId = loop.CurveId;
      keptSources.push_back(std::move(source));
    }
    kept.push_back(std::move(loop));
  }
  curves = std::move(kept);
  sources = std::move(keptSources);
  return true;
}

} // namespace boolsurf

#include "vtkBoolSurfOffsetStage.h"

#include "vtkBoolSurfArrayNames.h"

#include "Arrangement/Arrangement.h"
#include "Labeling/ArrangementLabelingInput.h"
#include "Labeling/CellLabeling.h"
#include "Offset/OffsetRegionOfCells.h"
#include "Selection/BooleanOptions.h"
#include "vtkBoolSurfControlCurveWriter.h"
#include "vtkBoolSurfTraceStage.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <algorithm>
#include <chrono>
#include <set>

namespace boolsurf
{
namespace
{

using Clock = std::chrono::steady_clock;

// An offset loop as control points: each point written in a triangle it shares with the next
// one, so the geodesic polygon through them is the loop itself.
std::vector<SurfacePoint> LoopControlPoints(const TriangleMesh& mesh,
  const std::vector<CanonicalPoint>& loop)
{
  std::vector<SurfacePoint> points;
  points.reserve(loop.size());
  for (size_t i = 0; i < loop.size(); ++i)
  {
    const int shared = SharedTriangle(mesh, loop[i], loop[(i + 1) % loop.size()]);
    points.push_back(WriteSurfacePoint(mesh, loop[i], shared));
  }
  return points;
}

void AddStatistics(const OffsetStatistics& s, double total, vtkFieldData* fd)
{
  const char* names[] = { "BoundaryPoints",
    "Windows",
    "FieldVertices",
    "CrossedTriangles",
    "DroppedSlivers",
    "FieldMilliseconds",
    "ContourMilliseconds",
    "TotalMilliseconds" };
  const double values[] = { static_cast<double>(s.Sources),
    static_cast<double>(s.Windows),
    static_cast<double>(s.FieldVertices),
    static_cast<double>(s.CrossedTriangles),
    static_cast<double>(s.DroppedSlivers),
    s.FieldMilliseconds,
    s.ContourMilliseconds,
    total };
  vtkNew<vtkDoubleArray> stats;
  stats->SetName(boolsurf::names::OffsetStatistics);
  stats->SetNumberOfComponents(8);
  for (int k = 0; k < 8; ++k)
  {
    stats->SetComponentName(k, names[k]);
  }
  stats->InsertNextTuple(values);
  fd->AddArray(stats);
}

} // namespace

//------------------------------------------------------------------------------
bool OffsetControlCurves(vtkSurfaceCache& cache,
  vtkPolyData* curves,
  const OffsetStageOptions& options,
  vtkPolyData* output,
  std::vector<std::string>& notes,
  std::string& error)
{
  const Clock::time_point start = Clock::now();
  const vtkSurfaceInput& surface = cache.GetCurrent();
  const TriangleMesh& mesh = *surface.Mesh;
  if (!std::isfinite(options.Distance))
  {
    error = "Distance is not a finite number";
    return false;
  }
  // 1. the control curves (kept for the output) and their traces, read once
  std::vector<InputControlCurve> controls;
  std::vector<std::string> problems;
  std::vector<TracedCurve> traced;
  if (!TraceControlCurves(cache,
        curves,
        options.Trace,
        nullptr,
        traced,
        nullptr,
        problems,
        notes,
        nullptr,
        &controls))
  {
    error = "Cannot trace the curves:" + JoinLines(problems);
    return false;
  }
  // Curves without ShapeIds are one shape: the loops of a Boolean or BSC result's Boundary
  // output (region on their left, holes turning the other way) offset as the region they bound.
  if (!curves->GetCellData()->GetArray(names::ShapeId))
  {
    for (TracedCurve& c : traced)
    {
      c.ShapeId = 0;
    }
    for (InputControlCurve& c : controls)
    {
      c.ShapeId = 0;
    }
  }
  std::set<int> idSet;
  for (const TracedCurve& c : traced)
  {
    idSet.insert(c.ShapeId);
  }
  const std::vector<int> ids(idSet.begin(), idSet.end());
  if (ids.empty())
  {
    error = "the curves input has no curves to offset";
    return false;
  }

  // 2. which shapes: the expression's, or the listed ones, or all
  std::string text = options.Expression;
  if (text.empty())
  {
    const std::vector<int>& listed = options.Shapes.empty() ? ids : options.Shapes;
    for (int id : listed)
    {
      if (!idSet.count(id))
      {
        std::string known;
        for (int k : ids)
        {
          known += (known.empty() ? "" : ", ") + std::to_string(k);
        }
        error = "Shapes names shape " + std::to_string(id) +
          ", which no curve has (the curves' ShapeIds: " + known + ")";
        return false;
      }
      text += (text.empty() ? "S" : " | S") + std::to_string(id);
    }
  }
  BooleanExpression expression;
  if (!expression.Parse(text, ids, error))
  {
    error = "Expression '" + text + "': " + error;
    return false;
  }
  std::set<int> operands;
  for (int index : expression.GetShapes())
  {
    operands.insert(ids[index]);
  }

  // 3. the region (arrangement, labels, selection) and the bands
  OffsetWorkspace& workspace = cache.GetOffsetWorkspace();
  Arrangement& arrangement = workspace.Shapes;
  LabelingResult labels;
  std::vector<char> selected;
  OffsetRegion region;
  // The operands' curves make the arrangement, open ones too: a shape of open curves only is
  // then a shape whose region is empty (labels 0), so an expression naming it still reads.
  std::vector<TracedCurve> arranged;
  bool anyClosed = false;
  for (const TracedCurve& c : traced)
  {
    if (!operands.count(c.ShapeId))
    {
      continue;
    }
    if (options.Bands || !c.Closed)
    {
      region.Bands.push_back(c);
    }
    if (!options.Bands)
    {
      arranged.push_back(c);
      anyClosed = anyClosed || c.Closed;
    }
  }
  if (anyClosed)
  {
    ArrangementOptions arrangementOptions;
    arrangementOptions.Threads = options.Trace.Threads;
    if (!ComputeArrangement(mesh, arranged, arrangementOptions, arrangement, error))
    {
      error = "Arrangement of the shapes to offset failed: " + error;
      return false;
    }
    labels = LabelCells(MakeLabelingInput(mesh, *surface.Topology, arranged, arrangement));
    BooleanOptions boolean;
    boolean.Operation = BooleanOperation::Expression;
    boolean.Expression = text;
    boolean.Rule = static_cast<FillRule>(options.FillRule);
    std::string ran;
    if (!SelectBooleanCells(labels, boolean, selected, ran, error))
    {
      return false;
    }
    const OffsetRegion cells = MakeOffsetRegion(mesh, arrangement, selected);
    region.Boundary = cells.Boundary;
    region.InsideVertex = cells.InsideVertex;
    region.TriangleSide = cells.TriangleSide;
  }

  // 4. the offset
  OffsetOptions offset;
  offset.Distance = options.Distance;
  offset.Ends = options.Ends;
  offset.Resolution = options.OutputResolution;
  std::vector<std::vector<CanonicalPoint>> loops;
  OffsetStatistics statistics;
  if (region.Boundary.empty() && region.Bands.empty())
  {
    error = "'" + text + "' is empty: there is nothing to offset";
    return false;
  }
  if (!ComputeGeodesicOffset(
        mesh, *surface.Topology, region, offset, loops, error, &statistics, &workspace.Buffers))
  {
    error = "Cannot offset '" + text + "' by " + std::to_string(options.Distance) + ": " + error;
    return false;
  }

  // 5. the output control curves
  const int outputShape = options.OutputShapeId >= 0 ? options.OutputShapeId : ids.back() + 1;
  if (options.KeepInputCurves && !options.ReplaceShapes && idSet.count(outputShape))
  {
    notes.push_back("OutputShapeId " + std::to_string(outputShape) +
      " is also an input shape: the offset loops join that shape's curves");
  }
  ControlCurveWriter writer(mesh, boolsurf::names::OffsetCurve);
  if (options.KeepInputCurves)
  {
    for (const InputControlCurve& c : controls)
    {
      if (options.ReplaceShapes && operands.count(c.ShapeId))
      {
        continue;
      }
      writer.Add(c, 0);
    }
  }
  for (const auto& loop : loops)
  {
    ControlCurve offsetLoop;
    offsetLoop.ShapeId = outputShape;
    offsetLoop.Type = CurveType::GeodesicPolygon;
    offsetLoop.Closed = true;
    offsetLoop.Points = LoopControlPoints(mesh, loop);
    writer.Add(offsetLoop, 1);
  }
  output->Initialize();
  writer.Write(output);
  vtkFieldData* fd = output->GetFieldData();
  vtkNew<vtkDoubleArray> distance;
  distance->SetName(boolsurf::names::OffsetDistance);
  distance->InsertNextValue(options.Distance);
  fd->AddArray(distance);
  vtkNew<vtkIntArray> shape;
  shape->SetName(boolsurf::names::OffsetShapeId);
  shape->InsertNextValue(outputShape);
  fd->AddArray(shape);
  vtkNew<vtkStringArray> what;
  what->SetName(boolsurf::names::OffsetExpression);
  what->InsertNextValue(options.Bands ? "bands around " + text : text);
  fd->AddArray(what);
  AddStatistics(
    statistics, std::chrono::duration<double, std::milli>(Clock::now() - start).count(), fd);
  return true;
}

} // namespace boolsurf

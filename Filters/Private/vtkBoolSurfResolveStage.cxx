#include "vtkBoolSurfResolveStage.h"

#include "vtkBoolSurfArrayNames.h"

#include "vtkBoolSurfControlCurveWriter.h"
#include "vtkBoolSurfTraceStage.h"

#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

namespace boolsurf
{
namespace
{

std::string Trim(const std::string& s)
{
  const size_t a = s.find_first_not_of(" \t\n");
  const size_t b = s.find_last_not_of(" \t\n");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

bool StrategyFromText(std::string text, ResolveStrategy& out)
{
  std::transform(
    text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  for (ResolveStrategy s : { ResolveStrategy::AddGenerators,
         ResolveStrategy::DuplicateReversed,
         ResolveStrategy::RemoveCurves })
  {
    std::string name = StrategyName(s);
    std::transform(
      name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::tolower(c); });
    if (text == name || text == std::to_string(static_cast<int>(s)))
    {
      out = s;
      return true;
    }
  }
  return false;
}

void WriteResolved(const TriangleMesh& mesh, const ResolveResult& result, vtkPolyData* output)
{
  ControlCurveWriter writer(mesh);
  vtkNew<vtkIntArray> action, source;
  action->SetName(boolsurf::names::ResolutionAction);
  source->SetName(boolsurf::names::ResolutionSource);
  vtkNew<vtkStringArray> reason;
  reason->SetName(boolsurf::names::ResolutionReason);
  for (const ResolvedCurve& r : result.Curves)
  {
    writer.Add(r.Curve);
    action->InsertNextValue(static_cast<int>(r.Action));
    source->InsertNextValue(r.Source);
    reason->InsertNextValue(r.Reason);
  }
  writer.Write(output);
  vtkCellData* cd = output->GetCellData();
  for (vtkAbstractArray* a : { static_cast<vtkAbstractArray*>(action),
         static_cast<vtkAbstractArray*>(source),
         static_cast<vtkAbstractArray*>(reason) })
  {
    cd->AddArray(a);
  }
  vtkNew<vtkIntArray> removed, treated;
  removed->SetName(boolsurf::names::RemovedCurves);
  treated->SetName(boolsurf::names::TreatedShapes);
  vtkNew<vtkStringArray> notes, removedReason;
  notes->SetName(boolsurf::names::ResolutionNotes);
  removedReason->SetName(boolsurf::names::RemovedCurveReasons);
  for (const ResolvedCurve& r : result.Removed)
  {
    removed->InsertNextValue(r.Source);
    removedReason->InsertNextValue(r.Reason);
  }
  for (int s : result.TreatedShapes)
  {
    treated->InsertNextValue(s);
  }
  for (const std::string& n : result.Notes)
  {
    notes->InsertNextValue(n);
  }
  vtkFieldData* fd = output->GetFieldData();
  if (removed->GetNumberOfTuples() > 0) // no empty arrays: the XML reader cannot read them
  {
    fd->AddArray(removed);
    fd->AddArray(removedReason);
  }
  if (treated->GetNumberOfTuples() > 0)
  {
    fd->AddArray(treated);
  }
  if (notes->GetNumberOfTuples() > 0)
  {
    fd->AddArray(notes);
  }
}

} // namespace

//------------------------------------------------------------------------------
bool ParseShapeStrategies(const std::string& text,
  std::map<int, ResolveStrategy>& out,
  std::string& error)
{
  out.clear();
  std::string entry;
  std::string normalized = text;
  std::replace(normalized.begin(), normalized.end(), ';', ',');
  std::istringstream in(normalized);
  while (std::getline(in, entry, ','))
  {
    entry = Trim(entry);
    if (entry.empty())
    {
      continue;
    }
    const size_t sep = entry.find_first_of(":=");
    std::string id = sep == std::string::npos ? entry : Trim(entry.substr(0, sep));
    if (!id.empty() && (id[0] == 'S' || id[0] == 's'))
    {
      id = id.substr(1);
    }
    ResolveStrategy strategy;
    char* end = nullptr;
    const long value = id.empty() ? 0 : std::strtol(id.c_str(), &end, 10);
    if (sep == std::string::npos || id.empty() || *end != '\0' || value < 0 ||
      value > 2147483647L || !StrategyFromText(Trim(entry.substr(sep + 1)), strategy))
    {
      error = "ShapeStrategies entry '" + entry +
        "' is not <ShapeId>:<AddGenerators|DuplicateReversed|RemoveCurves>";
      return false;
    }
    out[static_cast<int>(value)] = strategy;
  }
  return true;
}

//------------------------------------------------------------------------------
bool ResolveControlCurves(vtkSurfaceCache& cache,
  vtkPolyData* curves,
  const ResolveStageOptions& options,
  vtkPolyData* output,
  std::vector<std::string>& notes,
  std::string& error)
{
  const vtkSurfaceInput& surface = cache.GetCurrent();
  const TriangleMesh& mesh = *surface.Mesh;
  std::vector<InputControlCurve> controls;
  std::vector<std::string> problems;
  TraceOptions reading;
  reading.ProjectionTolerance = options.Trace.ProjectionTolerance;
  ReadSurfaceControlCurves(cache, curves, reading, controls, problems, notes);
  if (!problems.empty())
  {
    error = "Invalid control curves:" + JoinLines(problems);
    return false;
  }
  const HomologyBasis* basis = cache.GetHomology(error);
  if (!basis)
  {
    return false;
  }
  const std::vector<ControlCurve> input(controls.begin(), controls.end()); // the curves alone
  CurveTracer& tracer = cache.GetTracer();
  tracer.SetResolution(options.Trace.Resolution);
  GeodesicPathOptions pathOptions = tracer.GetPathSolver().GetOptions();
  pathOptions.Method = options.Trace.Method;
  tracer.GetPathSolver().SetOptions(pathOptions);
  std::vector<std::vector<int>> classes;
  if (!ClassifyControlCurves(tracer, *basis, input, classes, nullptr, error))
  {
    error = "Cannot trace the curves: " + error;
    return false;
  }
  ResolveOptions resolve;
  resolve.Offset = options.Offset;
  resolve.StrategyOf = [&options](int shapeId)
  {
    const auto it = options.PerShape.find(shapeId);
    return it == options.PerShape.end() ? options.Strategy : it->second;
  };
  const ResolveResult result = ResolveShapes(mesh, *basis, input, classes, resolve);
  for (const auto& [shapeId, strategy] : options.PerShape)
  {
    if (std::none_of(input.begin(),
          input.end(),
          [id = shapeId](const ControlCurve& c) { return c.ShapeId == id; }))
    {
      notes.push_back("ShapeStrategies names shape S" + std::to_string(shapeId) +
        ", which has no curve (" + StrategyName(strategy) + " ignored)");
    }
  }
  output->Initialize();
  WriteResolved(mesh, result, output);
  return true;
}

} // namespace boolsurf

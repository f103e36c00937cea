#include "vtkBoolSurf.h"

#include "vtkBoolSurfArrayNames.h"
#include "vtkBoolSurfArrayRanges.h"

#include "Geodesic/CurveTracer.h"
#include "Labeling/ArrangementLabelingInput.h"
#include "Selection/RegionExtraction.h"
#include "vtkBoolSurfBSCStage.h"
#include "vtkBoolSurfBooleanStage.h"
#include "vtkBoolSurfControlOutput.h"
#include "vtkBoolSurfHomologyOutput.h"
#include "vtkBoolSurfLabelingStage.h"
#include "vtkBoolSurfOffsetStage.h"
#include "vtkBoolSurfPieceBoolean.h"
#include "vtkBoolSurfPieceOneStep.h"
#include "vtkBoolSurfRegionOutput.h"
#include "vtkBoolSurfResolveStage.h"
#include "vtkBoolSurfSelectionOutput.h"
#include "vtkBoolSurfStageSettingsDefinitions.h"
#include "vtkBoolSurfTraceStage.h"
#include "vtkBoolSurfWindingStage.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkGenericCell.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStaticCellLocator.h>
#include <vtkStringArray.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <set>
#include <tuple>

vtkStandardNewMacro(vtkBoolSurf);

namespace
{
using Clock = std::chrono::steady_clock;
double Milliseconds(Clock::time_point from, Clock::time_point to)
{
  return std::chrono::duration<double, std::milli>(to - from).count();
}
} // namespace

// The one-step filter works on Core data end to end: the refined surface is never written as a
// whole in VTK form, labels stay a cells x shapes table, and only the selected region becomes
// polydata. Everything below is kept between updates, so an edit reuses every buffer.
struct vtkBoolSurf::Internals
{

  // The labeled arrangement of the last run, reused when only the Boolean properties
  // (operation, operands, expression, fill rule) change.
  bool HasLabels = false;
  std::vector<boolsurf::TracedCurve> Curves;
  std::vector<boolsurf::CurveSource> Sources; ///< control points and parameters of Curves
  boolsurf::Arrangement Arrangement;
  boolsurf::LabelingResult Labels;
  // Selection buffers.
  std::vector<char> Selected;
  boolsurf::SelectionOutputBuffers Output;
  // BSC: where each sample landed and what became of it.
  std::vector<boolsurf::PatchSnap> Snaps;
  boolsurf::BscResult Bsc;
  double ControlCurvesTime = 0;
  /// Milliseconds of the last update per output port (see SelectionOutputTimes::Ports).
  std::array<double, 4> PortTimes{};
  /// Milliseconds of the stages of the last labeled arrangement (tracing, labeling).
  double TraceTime = 0, LabelingTime = 0;
  /// What the resolution of inconsistent shapes did (ResolveStrategy >= 0), one note per shape.
  std::vector<std::string> ResolutionNotes;
  /// The offset step's statistics (OffsetShape >= 0), for the region's field data.
  vtkSmartPointer<vtkDataArray> OffsetStatistics;
  /// CloseBrokenShapes: the winding numbers' factorization of the surface (kept for edits), and
  /// one note per replaced curve with its residual.
  boolsurf::SurfaceWinding Winding;
  std::vector<std::string> WindingNotes;

  /// What the labeled arrangement was computed from (the inputs by identity and time, and the
  /// tracing and labeling properties).
  struct Key
  {
    vtkPolyData* Surface = nullptr;
    vtkMTimeType SurfaceTime = 0;
    vtkPolyData* Curves = nullptr;
    vtkMTimeType CurvesTime = 0;
    int Resolution = 0;
    int GeodesicMethod = GEODESIC_BOUNDED;
    double ProjectionTolerance = 0;
    int ZeroCellMode = 0;
    std::array<double, 3> ZeroCellPoint{};
    int NumberOfThreads = 0;
    int ResolveStrategy = -1;
    double ResolveOffset = 0;
    int OffsetShape = -1;
    double OffsetDistance = 0;
    std::string CloseBrokenShapes;
    double WindingThreshold = 0.5;

    bool operator==(const Key& o) const
    {
      if (this->CloseBrokenShapes != o.CloseBrokenShapes ||
        (!this->CloseBrokenShapes.empty() && !(this->WindingThreshold == o.WindingThreshold)))
      {
        return false;
      }
      if (this->ResolveStrategy != o.ResolveStrategy || this->ResolveOffset != o.ResolveOffset ||
        this->OffsetShape != o.OffsetShape ||
        (this->OffsetShape >= 0 && !(this->OffsetDistance == o.OffsetDistance)))
      {
        return false;
      }
      return std::tie(this->Surface,
               this->SurfaceTime,
               this->Curves,
               this->CurvesTime,
               this->Resolution,
               this->GeodesicMethod,
               this->ProjectionTolerance,
               this->ZeroCellMode,
               this->ZeroCellPoint,
               this->NumberOfThreads) ==
        std::tie(o.Surface,
          o.SurfaceTime,
          o.Curves,
          o.CurvesTime,
          o.Resolution,
          o.GeodesicMethod,
          o.ProjectionTolerance,
          o.ZeroCellMode,
          o.ZeroCellPoint,
          o.NumberOfThreads);
    }
  };
  Key LabeledKey;
  /// The inputs and settings the labels depend on, for `surface` and `curves`.
  static Key MakeKey(vtkBoolSurf& self, vtkPolyData* surface, vtkPolyData* curves)
  {
    const boolsurf::ZeroCellOptions& zeroCell = *self.ZeroCellSettings;
    return Key{ surface,
      surface ? surface->GetMTime() : 0,
      curves,
      curves ? curves->GetMTime() : 0,
      self.GetResolution(),
      self.GetGeodesicMethod(),
      self.GetProjectionTolerance(),
      static_cast<int>(zeroCell.Mode),
      zeroCell.Point,
      self.GetNumberOfThreads(),
      self.ResolveStrategy,
      self.ResolveOffset,
      self.OffsetShape,
      self.OffsetDistance,
      self.CloseBrokenShapes,
      self.WindingThreshold };
  }

  /// On each rank's piece of a split surface: what the stage filters keep between updates,
  /// and the key of the labeled arrangement kept there.
  boolsurf::OneStepPieceState Pieces;
  Key PiecesKey;
};

//------------------------------------------------------------------------------
vtkBoolSurf::vtkBoolSurf()
  : Internal(new Internals)
{
  // The stages' settings, as the stage filters hold them.
  this->BscSettings.reset(new boolsurf::BscOptions);
  this->ZeroCellSettings.reset(new boolsurf::ZeroCellOptions);
  this->BooleanSettings.reset(new boolsurf::BooleanOptions);
  this->SetNumberOfInputPorts(3);
  this->SetInputPortOptional(2); // BSC samples
  this->SetNumberOfOutputPorts(4);
}

//------------------------------------------------------------------------------
vtkBoolSurf::~vtkBoolSurf() = default;

//------------------------------------------------------------------------------
vtkBoolSurfBSCSettingsDefinitions(vtkBoolSurf);
vtkBoolSurfZeroCellSettingsDefinitions(vtkBoolSurf);
vtkBoolSurfBooleanSettingsDefinitions(vtkBoolSurf);

//------------------------------------------------------------------------------
bool vtkBoolSurf::Execute(const std::vector<vtkPolyData*>& inputs,
  const std::vector<vtkPolyData*>& outputs,
  std::string& error)
{
  vtkPolyData* surfaceInput = inputs[0];
  vtkPolyData* curvesInput = inputs[1];
  vtkPolyData* region = outputs[0];
  vtkPolyData* boundary = outputs[1];
  vtkPolyData* boundaryControls = outputs[2];
  vtkPolyData* clipped = outputs[3];

  // 1. surface (cached)
  const boolsurf::vtkSurfaceInput* surface = this->GetSurface(surfaceInput, error);
  if (!surface)
  {
    return false;
  }
  this->UpdateProgress(0.05);

  // 2-4. tracing, arrangement, labeling: reused while only the Boolean properties change.
  // Inputs and properties the labeled arrangement depends on; the surface's cached
  // conversion is keyed separately.
  Internals& in = *this->Internal;
  const Internals::Key key = Internals::MakeKey(*this, surfaceInput, curvesInput);
  const bool reuse = in.HasLabels && key == in.LabeledKey;
  if (!reuse)
  {
    in.HasLabels = false;
    if (!this->LabelCurves(*surface, curvesInput, error))
    {
      return false;
    }
    in.HasLabels = true;
    in.LabeledKey = key;
  }
  this->UpdateProgress(0.8);

  // 5. Boolean: once per cell, then only the region's triangles are written.
  const Clock::time_point selectStart = Clock::now();
  std::string text;
  const bool bsc = this->Selection == BSC_SELECTION;
  if (bsc)
  {
    if (!this->SelectBySamples(*surface, inputs[2], surfaceInput, error))
    {
      return false;
    }
  }
  else if (!boolsurf::SelectBooleanCells(
             in.Labels, *this->BooleanSettings, in.Selected, text, error))
  {
    return false;
  }
  boolsurf::SelectionOutputTimes times;
  // The control points are traced as the curves were (the tracer is shared with the cache's
  // other users, which set their own method).
  boolsurf::GeodesicPathSolver* solver = nullptr;
  std::vector<boolsurf::GeodesicPathSolver*> cutSolvers; // the Bezier cuts, on every thread
  if (this->ComputeControlCurves)
  {
    boolsurf::CurveTracer& tracer = this->GetSurfaceCache().GetTracer();
    solver = &tracer.GetPathSolver();
    boolsurf::GeodesicPathOptions pathOptions = solver->GetOptions();
    pathOptions.Method = this->GetTraceOptions().Method;
    solver->SetOptions(pathOptions);
    cutSolvers = tracer.GetSolvers(this->GetNumberOfThreads());
  }
  in.Output.Threads = this->GetNumberOfThreads();
  if (!boolsurf::WriteSelectedCells(*surface,
        in.Arrangement,
        in.Sources,
        in.Selected,
        solver,
        in.Output,
        region,
        boundary,
        boundaryControls,
        clipped,
        error,
        &times,
        cutSolvers))
  {
    return false;
  }
  // ParaView reads every array's ranges after the update: each output's arrays carry them,
  // found in one pass per array here rather than in VTK's pass per component and kind.
  const std::array<vtkPolyData*, 4> ports{ region, boundary, boundaryControls, clipped };
  for (std::size_t p = 0; p < ports.size(); ++p)
  {
    const Clock::time_point start = Clock::now();
    boolsurf::CacheDataRanges(ports[p], this->GetNumberOfThreads());
    const double ranges = Milliseconds(start, Clock::now());
    times.Ports[p] += ranges;
    times.Output += ranges;
  }
  in.ControlCurvesTime = times.ControlCurves;
  std::copy(std::begin(times.Ports), std::end(times.Ports), in.PortTimes.begin());
  const Clock::time_point selected = Clock::now();
  this->WriteFieldData(text,
    reuse,
    Milliseconds(selectStart, selected) - times.Output - times.ControlCurves,
    times.Output + times.ControlCurves,
    region,
    boundary);
  if (bsc)
  {
    boolsurf::AddSampleFields(in.Snaps, in.Bsc, region);
    boolsurf::AddSampleFields(in.Snaps, in.Bsc, boundary);
  }
  // The field arrays written since (the label table has a component per shape); the arrays
  // that hold their ranges already are skipped.
  boolsurf::CacheDataRanges(region);
  boolsurf::CacheDataRanges(boundary);
  return true;
}

//------------------------------------------------------------------------------
bool vtkBoolSurf::ExecutePiece(const std::vector<vtkPolyData*>& locals,
  const std::vector<vtkPolyData*>& outputs,
  std::string& error)
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  Internals& in = *this->Internal;
  boolsurf::OneStepPieceOptions options;
  options.Trace = this->GetTraceOptions();
  options.Arrangement.Threads = this->GetNumberOfThreads();
  options.ZeroCell = *this->ZeroCellSettings;
  options.Boolean = *this->BooleanSettings;
  options.NotOnPieces = this->StepsNotOnPieces();
  options.ControlCurves = this->ComputeControlCurves != 0;
  const Internals::Key key = Internals::MakeKey(*this, locals[0], locals[1]);
  options.SameLabels = key == in.PiecesKey;
  std::vector<std::string> warnings;
  std::string reason;
  const boolsurf::OneStepPieceOutcome outcome = boolsurf::RunOneStepOnPieces(
    controller, locals[0], locals[1], options, in.Pieces, outputs, error, warnings, reason);
  this->ReportWarnings(warnings);
  const bool first = controller->GetLocalProcessId() == 0;
  switch (outcome)
  {
    case boolsurf::OneStepPieceOutcome::Done:
      in.PiecesKey = key;
      if (first)
      {
        vtkWarningMacro("ran on each rank's piece of the surface: "
          << boolsurf::PieceBooleanPortsNote
          << "; the labels carry no homology explanation of inconsistent shapes and no "
             "GeodesicSiteGraph is written");
      }
      return true;
    case boolsurf::OneStepPieceOutcome::DrawingStart:
      // As on one rank: no region yet, and no message.
      error.clear();
      return false;
    case boolsurf::OneStepPieceOutcome::Gather:
      if (first)
      {
        vtkWarningMacro(
          "ran on the surface gathered to rank 0, not on each rank's piece: " << reason);
      }
      this->GatherInsteadOfPieces(); // decided alike on every rank
      return true;
    case boolsurf::OneStepPieceOutcome::Failed:
      break;
  }
  return false;
}

//------------------------------------------------------------------------------
std::string vtkBoolSurf::StepsNotOnPieces() const
{
  if (this->Selection == BSC_SELECTION)
  {
    return "Selection BSC chooses the region by samples snapped to the whole arrangement's "
           "patches, not selected on pieces yet";
  }
  if (this->ResolveStrategy >= 0)
  {
    return "ResolveStrategy resolves inconsistent shapes with the homology basis and "
           "geodesics of the whole surface";
  }
  if (this->OffsetShape >= 0)
  {
    return "OffsetShape offsets a shape by geodesic distances on the whole surface";
  }
  if (this->CloseBrokenShapes.find_first_not_of(" ,\t") != std::string::npos)
  {
    return "CloseBrokenShapes completes shapes with winding numbers factored on the whole "
           "surface";
  }
  return std::string();
}

//------------------------------------------------------------------------------
bool vtkBoolSurf::SelectBySamples(const boolsurf::vtkSurfaceInput& surface,
  vtkPolyData* samples,
  vtkPolyData* surfaceInput,
  std::string& error)
{
  Internals& in = *this->Internal;
  std::vector<boolsurf::SampleQuery> queries;
  if (!boolsurf::ReadSampleQueries(samples, surface.Mesh.get(), queries, error) ||
    !boolsurf::SelectBySamples(*surface.Mesh,
      in.Arrangement,
      queries,
      *this->BscSettings,
      surfaceInput->GetLength(),
      in.Snaps,
      in.Bsc,
      error,
      [this] { return this->CheckAbort(); }))
  {
    error = "BSC: " + error;
    return false;
  }
  in.Selected = in.Bsc.Selected;
  return true;
}

//------------------------------------------------------------------------------
bool vtkBoolSurf::LabelCurves(const boolsurf::vtkSurfaceInput& surface,
  vtkPolyData* curvesInput,
  std::string& error)
{
  Internals& in = *this->Internal;
  std::vector<std::string> problems;
  if (boolsurf::IsDrawingWithoutCurves(curvesInput))
  {
    // A drawing not started yet or whose curves are all still being drawn (the first clicks):
    // no region yet, and no message either (it would open ParaView's message window over the
    // view being clicked).
    error.clear();
    return false;
  }
  // 2. tracing
  const Clock::time_point traceStart = Clock::now();
  boolsurf::TraceOptions traceOptions = this->GetTraceOptions();
  std::vector<std::string> notes;
  // Optional first step: resolve inconsistent shapes, then trace the resolved curves.
  in.ResolutionNotes.clear();
  vtkNew<vtkPolyData> resolved;
  if (this->ResolveStrategy >= 0 && curvesInput)
  {
    boolsurf::ResolveStageOptions resolve;
    resolve.Strategy = static_cast<boolsurf::ResolveStrategy>(this->ResolveStrategy);
    resolve.Offset = this->ResolveOffset;
    resolve.Trace = traceOptions;
    if (!boolsurf::ResolveControlCurves(
          this->GetSurfaceCache(), curvesInput, resolve, resolved, notes, error))
    {
      error = "Cannot resolve inconsistent shapes: " + error;
      return false;
    }
    if (auto* list = vtkStringArray::SafeDownCast(
          resolved->GetFieldData()->GetAbstractArray(boolsurf::names::ResolutionNotes)))
    {
      for (vtkIdType i = 0; i < list->GetNumberOfValues(); ++i)
      {
        in.ResolutionNotes.push_back(list->GetValue(i));
      }
    }
    curvesInput = resolved;
  }
  // Optional step: the offset shape replaces the shape.
  in.OffsetStatistics = nullptr;
  vtkNew<vtkPolyData> offset;
  if (this->OffsetShape >= 0 && curvesInput)
  {
    boolsurf::OffsetStageOptions options;
    options.Distance = this->OffsetDistance;
    options.Shapes = { this->OffsetShape };
    options.OutputShapeId = this->OffsetShape;
    options.ReplaceShapes = true;
    options.Trace = traceOptions;
    if (!boolsurf::OffsetControlCurves(
          this->GetSurfaceCache(), curvesInput, options, offset, notes, error))
    {
      error = "OffsetShape: " + error;
      return false;
    }
    in.OffsetStatistics = offset->GetFieldData()->GetArray(boolsurf::names::OffsetStatistics);
    curvesInput = offset;
  }
  const bool ok = boolsurf::TraceControlCurves(this->GetSurfaceCache(),
    curvesInput,
    traceOptions,
    nullptr,
    in.Curves,
    nullptr,
    problems,
    notes,
    &in.Sources);
  for (const std::string& n : notes)
  {
    vtkWarningMacro(<< n);
  }
  if (!ok)
  {
    error = "Cannot trace the curves:" + boolsurf::JoinLines(problems);
    return false;
  }
  // Optional step: broken shapes replaced by their completed curves.
  in.WindingNotes.clear();
  std::vector<int> closing;
  if (!boolsurf::ParseShapeList(this->CloseBrokenShapes, "CloseBrokenShapes", closing, error))
  {
    return false;
  }
  if (boolsurf::IsDrawing(curvesInput))
  {
    // In a drawing, a shape not drawn yet has no curves to complete (no error while the user
    // draws, as for the operation's shapes).
    std::set<int> drawn;
    for (const boolsurf::TracedCurve& c : in.Curves)
    {
      drawn.insert(c.ShapeId);
    }
    closing.erase(
      std::remove_if(closing.begin(), closing.end(), [&](int id) { return drawn.count(id) == 0; }),
      closing.end());
  }
  if (!closing.empty())
  {
    this->UpdateProgress(0.2);
    boolsurf::CloseShapesOptions close;
    close.Shapes = closing;
    close.Threshold = this->WindingThreshold;
    close.Threads = this->GetNumberOfThreads();
    std::vector<std::string> warnings;
    if (!boolsurf::CloseBrokenShapes(in.Winding,
          *surface.Mesh,
          close,
          in.Curves,
          in.Sources,
          in.WindingNotes,
          warnings,
          error))
    {
      return false;
    }
    this->ReportWarnings(warnings);
    for (const std::string& note : in.WindingNotes)
    {
      vtkOutputWindowDisplayText((note + "\n").c_str());
    }
  }
  in.TraceTime = Milliseconds(traceStart, Clock::now());
  this->UpdateProgress(0.3);
  if (this->CheckAbort())
  {
    error = "aborted";
    return false;
  }

  // 3. arrangement, into the buffers of the previous edit
  boolsurf::ArrangementOptions options;
  options.Threads = this->GetNumberOfThreads();
  if (!boolsurf::ComputeArrangement(*surface.Mesh, in.Curves, options, in.Arrangement, error))
  {
    error = "Arrangement failed: " + error;
    if (in.Arrangement.FailedCurve >= 0)
    {
      error += "\n  (at " +
        boolsurf::DescribeCurvePoint(
          in.Curves, in.Sources, in.Arrangement.FailedCurve, in.Arrangement.FailedPoint) +
        ")";
    }
    return false;
  }
  this->UpdateProgress(0.7);
  if (this->CheckAbort())
  {
    error = "aborted";
    return false;
  }

  // 4. labeling, on the cell graph only
  const Clock::time_point labelStart = Clock::now();
  const boolsurf::Arrangement& arr = in.Arrangement;
  boolsurf::LabelingInput labeling =
    boolsurf::MakeLabelingInput(*surface.Mesh, *surface.Topology, in.Curves, arr);
  // A shape whose curves are all still being drawn (a new shape's first clicks), or, in a
  // drawing, a shape the operation names but not drawn yet, is a shape without a region yet:
  // no error while the user draws.
  boolsurf::AddShapesWithoutCurves(labeling, boolsurf::ShapesBeingDrawn(curvesInput));
  if (boolsurf::IsDrawing(curvesInput))
  {
    boolsurf::AddShapesWithoutCurves(labeling, boolsurf::ShapesNamed(*this->BooleanSettings));
  }
  if (this->ZeroCellSettings->Mode == boolsurf::ZeroCellMode::Point)
  {
    const int zero = this->FindZeroCell(surface, error);
    if (zero < 0)
    {
      return false;
    }
    labeling.SetZeroCell(zero);
  }
  in.Labels = boolsurf::LabelCells(labeling);
  std::string warning = boolsurf::InconsistencyWarning(in.Labels);
  if (!warning.empty())
  {
    // Explain with the generators in excess (computed once per surface, only when needed).
    boolsurf::HomologyFields homology;
    std::string homologyError;
    const boolsurf::HomologyBasis* basis = this->GetSurfaceCache().GetHomology(homologyError);
    if (basis && boolsurf::ComputeCurveClasses(*basis, in.Curves, homology, homologyError))
    {
      warning += "\n" + boolsurf::ExplainInconsistency(in.Labels, homology);
    }
    vtkWarningMacro(<< warning);
  }
  in.LabelingTime = Milliseconds(labelStart, Clock::now());
  return true;
}

//------------------------------------------------------------------------------
int vtkBoolSurf::FindZeroCell(const boolsurf::vtkSurfaceInput& surface, std::string& error)
{
  // The closest point of the input surface, then the refined triangle holding it.
  return boolsurf::ZeroCellAt(this->GetSurfaceCache().GetLocator(),
    *surface.Mesh,
    this->Internal->Arrangement,
    this->ZeroCellSettings->Point.data(),
    error);
}

//------------------------------------------------------------------------------
void vtkBoolSurf::WriteFieldData(const std::string& expression,
  bool reused,
  double selectionTime,
  double outputTime,
  vtkPolyData* region,
  vtkPolyData* boundary)
{
  const Internals& in = *this->Internal;
  boolsurf::AddExpressionField(region, expression);
  boolsurf::AddExpressionField(boundary, expression);
  vtkFieldData* fd = region->GetFieldData();
  // The labels of the arrangement's cells (rows: ArrangementCell), for coloring the region by a
  // shape without per-triangle label arrays.
  boolsurf::AddLabelTable(in.Labels, fd);
  if (in.OffsetStatistics)
  {
    fd->AddArray(in.OffsetStatistics);
  }
  if (!in.WindingNotes.empty())
  {
    vtkNew<vtkStringArray> notes;
    notes->SetName(boolsurf::names::WindingNotes);
    for (const std::string& n : in.WindingNotes)
    {
      notes->InsertNextValue(n);
    }
    fd->AddArray(notes);
  }
  if (!in.ResolutionNotes.empty())
  {
    vtkNew<vtkStringArray> notes;
    notes->SetName(boolsurf::names::ResolutionNotes);
    for (const std::string& n : in.ResolutionNotes)
    {
      notes->InsertNextValue(n);
    }
    fd->AddArray(notes);
  }
  // Milliseconds per stage of this update (0 for the stages reused from the previous one).
  const boolsurf::ArrangementStageTimes& t = in.Arrangement.Times;
  const char* names[] = { "Trace",
    "Hash",
    "Intersections",
    "Refinement",
    "FloodFill",
    "CellGraph",
    "Labeling",
    "Selection",
    "Output",
    "ControlCurves",
    "Total",
    "Port0Region",
    "Port1Boundary",
    "Port2BoundaryControlCurves",
    "Port3ClippedCurves" };
  // The ports' times after Total: a split of Selection's extraction, Output and ControlCurves.
  std::array<double, 15> times{ in.TraceTime,
    t.Hash,
    t.Intersections,
    t.Refinement,
    t.FloodFill,
    t.CellGraph,
    in.LabelingTime,
    selectionTime,
    outputTime - in.ControlCurvesTime,
    in.ControlCurvesTime,
    0,
    in.PortTimes[0],
    in.PortTimes[1],
    in.PortTimes[2],
    in.PortTimes[3] };
  if (reused)
  {
    std::fill(times.begin(), times.begin() + 7, 0.0);
  }
  for (int k = 0; k < 10; ++k)
  {
    times[10] += times[k];
  }
  vtkNew<vtkDoubleArray> stageTimes;
  stageTimes->SetName(boolsurf::names::StageTimes);
  stageTimes->SetNumberOfComponents(static_cast<int>(times.size()));
  for (int k = 0; k < static_cast<int>(times.size()); ++k)
  {
    stageTimes->SetComponentName(k, names[k]);
  }
  stageTimes->InsertNextTypedTuple(times.data());
  fd->AddArray(stageTimes);
  boolsurf::AddSiteGraphField(*this->GetSurfaceCache().GetCurrent().Mesh, fd);
}

//------------------------------------------------------------------------------
void vtkBoolSurf::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Operation: " << this->GetOperation() << "\n";
  os << indent << "ShapeA: " << this->GetShapeA() << " ShapeB: " << this->GetShapeB() << "\n";
  os << indent << "Expression: " << this->GetExpression() << "\n";
  os << indent << "FillRule: " << this->GetFillRule() << "\n";
  os << indent << "Selection: " << (this->Selection == BSC_SELECTION ? "BSC" : "Boolean") << "\n";
  os << indent << "SnapTolerance: " << this->GetSnapTolerance() << "\n";
  os << indent << "OffsetShape: " << this->OffsetShape
     << " OffsetDistance: " << this->OffsetDistance << "\n";
  os << indent << "CloseBrokenShapes: " << this->CloseBrokenShapes
     << " WindingThreshold: " << this->WindingThreshold << "\n";
}

#include "vtkBoolSurfPieceTraceStage.h"

#include "vtkBoolSurfArrayNames.h"
#include "vtkBoolSurfControlCurves.h"
#include "vtkBoolSurfCurvesMessage.h"
#include "vtkBoolSurfRingedPiece.h"
#include "vtkBoolSurfStageHandoff.h"
#include "vtkBoolSurfTraceStage.h"

#include "Distributed/PieceWire.h"

#include <vtkCommunicator.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <memory>

namespace boolsurf
{
namespace
{
/// What rank 0 says of its curves before them.
constexpr long long ReadCurves = 0;
constexpr long long DrawingStart = 1;
constexpr long long GatherLocallyShortest = 2;
constexpr long long GatherProjected = 3;

/// Reads a WireBuffer front to back; past its end it gives 0.
struct Reader
{
  const WireBuffer& In;
  std::size_t At = 0;
  long long Next() { return this->At < this->In.size() ? this->In[this->At++] : 0; }
  int Int() { return static_cast<int>(this->Next()); }
  double Double() { return WireDoubleOf(this->Next()); }
  std::string String()
  {
    const long long n = std::max(0LL, this->Next());
    std::string s;
    for (long long i = 0; i < n && this->At < this->In.size(); ++i)
    {
      s.push_back(static_cast<char>(this->Next()));
    }
    return s;
  }
};

void PackString(const std::string& s, WireBuffer& out)
{
  out.push_back(static_cast<long long>(s.size()));
  out.insert(out.end(), s.begin(), s.end());
}

/// Collective: rank 0's `buffer` on every rank.
void Broadcast(vtkMultiProcessController* controller, WireBuffer& buffer)
{
  long long length = static_cast<long long>(buffer.size());
  controller->Broadcast(&length, 1, 0);
  buffer.resize(static_cast<std::size_t>(length));
  if (length > 0)
  {
    controller->Broadcast(buffer.data(), length, 0);
  }
}

/// On rank 0: the status, the reading's problems and the curves to trace, as one buffer.
WireBuffer ReadOnFirstRank(vtkPolyData* curves,
  const TraceOptions& options,
  std::vector<InputControlCurve>& controls,
  std::vector<std::string>& notes)
{
  WireBuffer out;
  if (IsDrawingWithoutCurves(curves))
  {
    return { DrawingStart };
  }
  if (options.Method == GeodesicMethod::LocallyShortest)
  {
    return { GatherLocallyShortest };
  }
  if (curves && curves->GetNumberOfCells() > 0 && !NamesSurfacePoints(curves))
  {
    return { GatherProjected };
  }
  ControlCurveOptions read;
  read.TraceValidPartOfIncompleteCurves = options.TraceValidPartOfIncompleteCurves;
  read.TrianglesOnPieces = true;
  const TriangleMesh none;                      // the triangles are checked by their owners
  std::unique_ptr<ClosestTriangleGrid> nowhere; // never asked: the points are named exactly
  std::vector<std::string> problems;
  ReadControlCurves(
    curves,
    [&]() -> const ClosestTriangleGrid&
    {
      if (!nowhere)
      {
        nowhere = std::make_unique<ClosestTriangleGrid>(none);
      }
      return *nowhere;
    },
    none,
    read,
    controls,
    problems,
    notes);
  out.push_back(ReadCurves);
  out.push_back(static_cast<long long>(problems.size()));
  for (const std::string& p : problems)
  {
    PackString(p, out);
  }
  out.push_back(static_cast<long long>(controls.size()));
  for (const InputControlCurve& c : controls)
  {
    out.insert(out.end(),
      { c.ShapeId,
        c.CurveId,
        static_cast<long long>(c.Type),
        c.Closed ? 1 : 0,
        static_cast<long long>(c.Points.size()) });
    for (const SurfacePoint& p : c.Points)
    {
      out.insert(out.end(), { p.Triangle, WireBitsOf(p.U), WireBitsOf(p.V) });
    }
  }
  return out;
}

/// The traces rank 0 got, as the CurveTraces the one-rank writer takes (written forms only).
std::vector<CurveTrace> AsWrittenTraces(const std::vector<GlobalCurveTrace>& traces)
{
  std::vector<CurveTrace> out(traces.size());
  for (std::size_t c = 0; c < traces.size(); ++c)
  {
    const GlobalCurveTrace& g = traces[c];
    CurveTrace& t = out[c];
    t.Curve.Points.resize(g.Points.size());
    t.Curve.Closed = g.Closed;
    t.Curve.ShapeId = g.ShapeId;
    t.Curve.CurveId = g.CurveId;
    t.Segment = g.Segment;
    t.ControlPoint = g.ControlPoint;
    t.Parameter = g.Parameter;
    t.OnCurve = g.OnCurve;
    t.Length = g.Length;
    t.Positions = g.Positions;
    t.Written = g.Written;
  }
  return out;
}

/// Whether `message`, a failure of the tracing on pieces, is a leg only the whole surface's
/// structures settle (PieceCurveTracer's wording, Core/Geodesic/GeodesicPath.cxx).
bool NeedsWholeSurface(const std::string& message)
{
  return message.find("which need the whole surface") != std::string::npos;
}
} // namespace

//------------------------------------------------------------------------------
void AddPieceTracingTraffic(const vtkBoolSurfPieceTracing::Traffic& t, vtkPolyData* output)
{
  const std::vector<std::pair<const char*, double>> values{
    { "DirectorySent", static_cast<double>(t.DirectorySent) },
    { "DirectoryReceived", static_cast<double>(t.DirectoryReceived) },
    { "FetchSent", static_cast<double>(t.FetchSent) },
    { "FetchReceived", static_cast<double>(t.FetchReceived) },
    { "TracesSent", static_cast<double>(t.TracesSent) },
    { "TracesReceived", static_cast<double>(t.TracesReceived) },
    { "Rounds", static_cast<double>(t.Rounds) },
    { "OwnRounds", static_cast<double>(t.OwnRounds) },
    { "TracedCurves", static_cast<double>(t.TracedCurves) },
    { "FetchedTriangles", static_cast<double>(t.FetchedTriangles) },
    { "HeldTriangles", static_cast<double>(t.HeldTriangles) },
    { "RingedTriangles", static_cast<double>(t.RingedTriangles) },
    { "ReusedPiece", t.ReusedPiece ? 1.0 : 0.0 },
    { "RecalledCurves", static_cast<double>(t.RecalledCurves) },
    { "SharedPiece", t.SharedPiece ? 1.0 : 0.0 },
  };
  vtkNew<vtkDoubleArray> array;
  array->SetName(names::PieceTracingTraffic);
  array->SetNumberOfComponents(static_cast<int>(values.size()));
  array->SetNumberOfTuples(1);
  for (std::size_t k = 0; k < values.size(); ++k)
  {
    array->SetComponentName(static_cast<vtkIdType>(k), values[k].first);
    array->SetComponent(0, static_cast<int>(k), values[k].second);
  }
  output->GetFieldData()->AddArray(array);
}

//------------------------------------------------------------------------------
bool UpdateRingedPiece(vtkMultiProcessController* controller,
  vtkPolyData* local,
  PieceTraceState& state,
  std::string& problem)
{
  int same =
    state.HasPiece && local == state.Surface && local && local->GetMTime() == state.SurfaceTime ? 1
                                                                                                : 0;
  int allSame = 0;
  controller->AllReduce(&same, &allSame, 1, vtkCommunicator::MIN_OP);
  if (allSame)
  {
    return true;
  }
  state.HasPiece = false;
  state.Traced = false;
  state.Users.clear();
  std::string error;
  int ok = BuildRingedPiece(controller, local, state.Ringed, error) ? 1 : 0, allOk = 0;
  controller->AllReduce(&ok, &allOk, 1, vtkCommunicator::MIN_OP);
  if (!allOk)
  {
    problem = ok ? "another rank's piece cannot be used"
                 : "rank " + std::to_string(controller->GetLocalProcessId()) + ": " + error;
    return false;
  }
  state.HasPiece = true;
  ++state.Builds;
  state.Surface = local;
  state.SurfaceTime = local ? local->GetMTime() : 0;
  return true;
}

//------------------------------------------------------------------------------
PieceTraceOutcome TraceOnPieces(vtkMultiProcessController* controller,
  vtkPolyData* local,
  vtkPolyData* curves,
  const TraceOptions& options,
  PieceTraceState& state,
  vtkPolyData* output,
  std::vector<std::string>& problems,
  std::vector<std::string>& notes,
  std::string& reason,
  const void* user)
{
  const int rank = controller->GetLocalProcessId();
  const char* method = GeodesicMethodName(options.Method);

  // Rank 0's curves, to every rank (the pieces' ranks hold no control curves).
  std::vector<InputControlCurve> controls;
  WireBuffer read;
  if (rank == 0)
  {
    read = ReadOnFirstRank(curves, options, controls, notes);
  }
  Broadcast(controller, read);
  Reader in{ read };
  const long long status = in.Next();
  if (status == DrawingStart)
  {
    return PieceTraceOutcome::DrawingStart;
  }
  if (status == GatherLocallyShortest)
  {
    reason = "the LocallyShortest geodesic method does not trace on pieces (its edge search "
             "reads landmark distances built from the whole surface)";
    return PieceTraceOutcome::Gather;
  }
  if (status == GatherProjected)
  {
    reason = "the control points are given by position, and projecting them onto the surface "
             "needs a closest-point search over the whole surface (curves whose points carry "
             "TriangleId and Barycentric, as Surface Curves gives them, trace on pieces)";
    return PieceTraceOutcome::Gather;
  }
  const int readProblems = in.Int();
  for (int i = 0; i < readProblems; ++i)
  {
    problems.push_back(in.String());
  }
  std::vector<vtkBoolSurfPieceTracing::Curve> list(static_cast<std::size_t>(in.Int()));
  for (vtkBoolSurfPieceTracing::Curve& c : list)
  {
    c.ShapeId = in.Int();
    c.CurveId = in.Int();
    c.Type = static_cast<CurveType>(in.Int());
    c.Closed = in.Int() != 0;
    c.Points.resize(static_cast<std::size_t>(std::max(0, in.Int())));
    for (SurfacePoint& p : c.Points)
    {
      p.Triangle = in.Int();
      p.U = in.Double();
      p.V = in.Double();
    }
  }

  // The ringed piece: kept while every rank's piece is the same, unmodified.
  std::string problem;
  if (!UpdateRingedPiece(controller, local, state, problem))
  {
    problems.push_back("tracing on pieces: " + problem);
    return PieceTraceOutcome::Failed;
  }

  // The curves traced on the pieces, message 0 on every rank.
  vtkBoolSurfPieceTracing& tracing = state.Tracing;
  GeodesicPathOptions pathOptions;
  pathOptions.Method = options.Method;
  tracing.SetOptions(pathOptions);
  tracing.SetResolution(options.Resolution);
  tracing.SetKeepWrittenForms(true);
  tracing.SetReusePiece(state.Traced);
  WireBuffer message0;
  std::string error;
  const bool traced = tracing.Run(controller, state.Ringed, list, message0, error);
  state.Traced = true;
  vtkBoolSurfPieceTracing::Traffic traffic = tracing.GetTraffic();
  const bool ownBefore =
    std::find(state.Users.begin(), state.Users.end(), user) != state.Users.end();
  traffic.SharedPiece = traffic.ReusedPiece && !ownBefore;
  traffic.ReusedPiece = traffic.ReusedPiece && ownBefore;
  if (!ownBefore)
  {
    state.Users.push_back(user);
  }
  AddPieceTracingTraffic(traffic, output);
  if (!traced)
  {
    // A leg only the whole surface settles: every rank has the same failures, so every rank
    // gathers alike, and the one-rank tracer gives its answer.
    for (const auto& failure : tracing.GetFailures())
    {
      if (NeedsWholeSurface(failure.second))
      {
        reason = std::string("with the ") + method + " geodesic method, " + failure.second;
        return PieceTraceOutcome::Gather;
      }
    }
    for (const auto& failure : tracing.GetFailures())
    {
      problems.push_back(failure.second);
    }
    return PieceTraceOutcome::Failed;
  }
  if (!problems.empty())
  {
    return PieceTraceOutcome::Failed; // the reading's, as one rank fails after tracing the rest
  }
  if (rank == 0)
  {
    WriteTracedCurves(nullptr, controls, AsWrittenTraces(tracing.GetTraces()), output);
  }
  AddPieceCurvesField(message0, output->GetFieldData());
  if (vtkDataArray* triangleId = output->GetPointData()->GetArray(names::TriangleId))
  {
    // For Surface Arrangement on pieces, which reads it on rank 0 (no whole-surface curves).
    auto result = std::make_shared<TracedCurvesResult>();
    result->Method = options.Method;
    result->PieceMessage = std::move(message0);
    AttachStageResult<TracedCurvesResult>(triangleId, std::move(result));
  }
  return PieceTraceOutcome::Traced;
}

}

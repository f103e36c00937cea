// Tracing on pieces on real MPI ranks (Filters/Private/vtkBoolSurfPieceTracing): run as
// `mpiexec -np P BoolSurfMpiTracingTests`. Every rank builds the same surface and curves, keeps
// its piece (owned triangles as VTK data, its ring of ghosts from vtkGhostCellsGenerator), and
// the ranks trace the curves together, each fetching from the others only what its legs read.
// Every rank must end with message 0 equal, byte for byte, to PackTracedCurves of the whole
// surface's traces: random closed geodesic polygons and closed Bezier splines on a sphere, a
// torus and the genus-2 eight.ply split in slabs and in random regions (one with an empty
// rank), with the Exact and the Bounded methods. Short curves on a larger sphere: no rank
// holds or receives anything near the surface. A control point on a triangle no rank has: the
// same error, naming the curve, on every rank. Prints the rounds and bytes of every rank.
#include "vtkBoolSurfPieceEdgeLength.h"
#include "vtkBoolSurfPieceTracing.h"
#include "vtkBoolSurfRingedPiece.h"

#include "OwnedTriangles.h"

#include "Distributed/PieceWire.h"
#include "Geodesic/CurveTracer.h"
#include "Mesh/PlyReader.h"
#include "Mesh/ProceduralMeshes.h"
#include "Support/PieceSplits.h"
#include "Support/SourceTree.h"

#include <vtkCommunicator.h>
#include <vtkMPIController.h>
#include <vtkNew.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

using namespace boolsurf;
using Curve = vtkBoolSurfPieceTracing::Curve;

namespace
{

int failures = 0;
constexpr int Resolution = 2; // the Core test's Bezier resolution

void Fail(int rank, const std::string& what)
{
  if (++failures <= 10)
  {
    std::printf("rank %d: FAILED %s\n", rank, what.c_str());
  }
}

SurfacePoint RandomPointIn(int t, std::mt19937& random)
{
  std::uniform_real_distribution<double> unit(0.05, 0.95);
  double u = unit(random), v = unit(random);
  if (u + v > 0.95)
  {
    u = 0.95 - u * 0.5;
    v = 0.95 - u - 0.01;
  }
  return { t, u, v };
}

/// Triangles within `rings` vertex rings of triangle `center`.
std::vector<int> TrianglesNear(const TriangleMesh& mesh, int center, int rings)
{
  std::vector<char> in(mesh.GetNumberOfTriangles(), 0);
  std::vector<int> out{ center };
  in[center] = 1;
  std::size_t begin = 0;
  for (int ring = 0; ring < rings && begin < out.size(); ++ring)
  {
    const std::size_t end = out.size();
    for (std::size_t i = begin; i < end; ++i)
    {
      for (int v : mesh.GetTriangle(out[i]))
      {
        for (int corner : mesh.GetVertexCorners(v))
        {
          if (!in[corner / 3])
          {
            in[corner / 3] = 1;
            out.push_back(corner / 3);
          }
        }
      }
    }
    begin = end;
  }
  return out;
}

/// Closed polygons of 3 to 5 points and, every third curve, a closed Bezier spline of two
/// segments, their control points within `rings` rings of a random triangle.
std::vector<Curve> RandomCurves(const TriangleMesh& mesh, unsigned seed, int count, int rings)
{
  std::mt19937 random(seed);
  std::vector<Curve> curves;
  for (int c = 0; c < count; ++c)
  {
    const int center = static_cast<int>(random() % mesh.GetNumberOfTriangles());
    const std::vector<int> near = TrianglesNear(mesh, center, rings);
    Curve curve;
    curve.Type = c % 3 == 2 ? CurveType::CubicBezier : CurveType::GeodesicPolygon;
    const int n = curve.Type == CurveType::CubicBezier ? 6 : 3 + static_cast<int>(random() % 3);
    for (int i = 0; i < n; ++i)
    {
      curve.Points.push_back(RandomPointIn(near[random() % near.size()], random));
    }
    curves.push_back(curve);
  }
  return curves;
}

/// Message 0 of the whole surface's traces (PackTracedCurves), or empty when one fails.
WireBuffer WholeMessage(const TriangleMesh& mesh,
  const std::vector<Curve>& curves,
  GeodesicMethod method)
{
  CurveTracer tracer(mesh);
  tracer.SetResolution(Resolution);
  GeodesicPathOptions options;
  options.Method = method;
  tracer.GetPathSolver().SetOptions(options);
  std::vector<TracedCurve> traced;
  for (std::size_t c = 0; c < curves.size(); ++c)
  {
    CurveTrace trace;
    std::string error;
    if (!tracer.Trace(
          curves[c].Points, curves[c].Type, curves[c].Closed, trace, error, static_cast<int>(c)))
    {
      return {};
    }
    traced.push_back(trace.Curve);
  }
  WireBuffer out;
  PackTracedCurves(traced, mesh, {}, {}, out);
  return out;
}

/// The ranks trace `curves` on the split `owner`; false (after a failure) when they did not.
bool TraceOnPieces(vtkMultiProcessController* controller,
  const TriangleMesh& mesh,
  const std::vector<Curve>& curves,
  const std::vector<int>& owner,
  GeodesicMethod method,
  WireBuffer& message,
  vtkBoolSurfPieceTracing& tracing,
  std::string& error)
{
  const int rank = controller->GetLocalProcessId();
  PieceInput ringed;
  if (!BuildRingedPiece(controller, testing::OwnedTriangles(mesh, owner, rank), ringed, error))
  {
    return false;
  }
  GeodesicPathOptions options;
  options.Method = method;
  tracing.SetOptions(options);
  tracing.SetResolution(Resolution);
  if (!tracing.Run(controller, ringed, curves, message, error))
  {
    return false;
  }
  // Computed from the pieces, it must be the one-rank estimate bit for bit.
  if (tracing.GetMeanEdgeLength() != EstimateMeanEdgeLength(mesh))
  {
    error = "the pieces' mean edge length is not the one-rank estimate";
    return false;
  }
  return true;
}

void Report(vtkMultiProcessController* controller,
  const std::string& what,
  const vtkBoolSurfPieceTracing& tracing)
{
  const vtkBoolSurfPieceTracing::Traffic& t = tracing.GetTraffic();
  std::printf("%s, rank %d of %d: %d curves traced, %d rounds (%d asking), %d triangles held "
              "(%d fetched); bytes sent/received: directory %zu/%zu, fetches %zu/%zu, traces "
              "%zu/%zu\n",
    what.c_str(),
    controller->GetLocalProcessId(),
    controller->GetNumberOfProcesses(),
    t.TracedCurves,
    t.Rounds,
    t.OwnRounds,
    t.HeldTriangles,
    t.FetchedTriangles,
    t.DirectorySent,
    t.DirectoryReceived,
    t.FetchSent,
    t.FetchReceived,
    t.TracesSent,
    t.TracesReceived);
  std::fflush(stdout);
}

/// Curves traced again on the kept piece (SetReusePiece): an edit of one curve traces that
/// curve alone, the same curves again trace none, other settings trace every curve; message 0
/// is each time the whole surface's traces.
void CheckEdits(vtkMultiProcessController* controller,
  const TriangleMesh& mesh,
  const std::vector<Curve>& curves,
  const std::vector<int>& owner,
  GeodesicMethod method,
  vtkBoolSurfPieceTracing& tracing,
  const std::string& what)
{
  const int rank = controller->GetLocalProcessId();
  std::vector<Curve> edited = curves;
  edited[1] = RandomCurves(mesh, 99, 1, 100)[0];
  const GeodesicMethod other =
    method == GeodesicMethod::Exact ? GeodesicMethod::Bounded : GeodesicMethod::Exact;
  struct Step
  {
    const char* Name;
    const std::vector<Curve>* Curves;
    GeodesicMethod Method;
    int Traced; ///< curves traced, summed over the ranks
  };
  const int n = static_cast<int>(curves.size());
  for (const Step& step : { Step{ "curve 1 edited", &edited, method, 1 },
         Step{ "the same curves again", &edited, method, 0 },
         Step{ "another method", &edited, other, n } })
  {
    const std::string here = what + ", " + step.Name;
    const WireBuffer expected = WholeMessage(mesh, *step.Curves, step.Method);
    tracing.SetReusePiece(true);
    WireBuffer message;
    std::string error;
    if (!TraceOnPieces(controller, mesh, *step.Curves, owner, step.Method, message, tracing, error))
    {
      Fail(rank, here + ": " + error);
      return;
    }
    if (message != expected)
    {
      Fail(rank, here + ": message 0 differs from the whole surface's traces");
    }
    const vtkBoolSurfPieceTracing::Traffic& t = tracing.GetTraffic();
    int traced = 0;
    controller->AllReduce(&t.TracedCurves, &traced, 1, vtkCommunicator::SUM_OP);
    if (!t.ReusedPiece || traced != step.Traced || t.RecalledCurves != n - step.Traced)
    {
      Fail(rank,
        here + ": " + std::to_string(traced) + " curves traced, " +
          std::to_string(t.RecalledCurves) + " recalled, piece " +
          (t.ReusedPiece ? "kept" : "built") + "; expected " + std::to_string(step.Traced) +
          " traced on the kept piece");
    }
  }
}

void RunSplit(vtkMultiProcessController* controller,
  const TriangleMesh& mesh,
  const std::vector<Curve>& curves,
  const std::vector<int>& owner,
  const std::string& split)
{
  const int rank = controller->GetLocalProcessId();
  for (GeodesicMethod method : { GeodesicMethod::Exact, GeodesicMethod::Bounded })
  {
    const std::string what = split + ", " + GeodesicMethodName(method);
    const WireBuffer expected = WholeMessage(mesh, curves, method);
    if (expected.empty())
    {
      Fail(rank, what + ": the whole surface's traces failed");
      continue;
    }
    vtkBoolSurfPieceTracing tracing;
    WireBuffer message;
    std::string error;
    if (!TraceOnPieces(controller, mesh, curves, owner, method, message, tracing, error))
    {
      Fail(rank, what + ": " + error);
      continue;
    }
    if (message != expected)
    {
      Fail(rank, what + ": message 0 differs from the whole surface's traces");
    }
    Report(controller, what, tracing);
    CheckEdits(controller, mesh, curves, owner, method, tracing, what);
  }
}

void RunSurface(vtkMultiProcessController* controller, const MeshData& data, const char* name)
{
  const TriangleMesh mesh(data.Positions, data.Triangles);
  const int ranks = controller->GetNumberOfProcesses();
  const std::vector<Curve> curves = RandomCurves(mesh, 7, 6, 100);
  for (int axis : { 0, 2 })
  {
    RunSplit(controller,
      mesh,
      curves,
      testing::SlabOwners(mesh, ranks, axis),
      std::string(name) + ", slabs along axis " + std::to_string(axis));
  }
  RunSplit(controller,
    mesh,
    curves,
    testing::RegionOwners(mesh, ranks, 3, -1),
    std::string(name) + ", random regions");
  if (ranks >= 2)
  {
    RunSplit(controller,
      mesh,
      curves,
      testing::RegionOwners(mesh, ranks, 4, ranks - 1),
      std::string(name) + ", random regions, last rank empty");
  }
}

/// Short curves on a 20,480-triangle sphere: every rank holds and receives a small part of it.
void RunLargeSphere(vtkMultiProcessController* controller)
{
  const int rank = controller->GetLocalProcessId();
  const int ranks = controller->GetNumberOfProcesses();
  const MeshData data = MakeIcosphere(5);
  const TriangleMesh mesh(data.Positions, data.Triangles);
  const std::vector<Curve> curves = RandomCurves(mesh, 11, 8, 6);
  const std::string what = "large sphere, slabs, Bounded";
  const WireBuffer expected = WholeMessage(mesh, curves, GeodesicMethod::Bounded);
  vtkBoolSurfPieceTracing tracing;
  WireBuffer message;
  std::string error;
  if (!TraceOnPieces(controller,
        mesh,
        curves,
        testing::SlabOwners(mesh, ranks, 0),
        GeodesicMethod::Bounded,
        message,
        tracing,
        error))
  {
    Fail(rank, what + ": " + error);
    return;
  }
  if (expected.empty() || message != expected)
  {
    Fail(rank, what + ": message 0 differs from the whole surface's traces");
  }
  Report(controller, what, tracing);
  const vtkBoolSurfPieceTracing::Traffic& t = tracing.GetTraffic();
  // The surface as the fetches would send it: per triangle 5 numbers, per vertex 4.
  const std::size_t surfaceBytes = 8 *
    (5 * static_cast<std::size_t>(mesh.GetNumberOfTriangles()) +
      4 * static_cast<std::size_t>(mesh.GetNumberOfVertices()));
  if (ranks >= 2 && t.HeldTriangles >= mesh.GetNumberOfTriangles())
  {
    Fail(rank, what + ": holds " + std::to_string(t.HeldTriangles) + " triangles");
  }
  if (t.FetchedTriangles >= mesh.GetNumberOfTriangles() / 10 ||
    t.FetchReceived >= surfaceBytes / 10)
  {
    Fail(rank,
      what + ": fetched " + std::to_string(t.FetchedTriangles) + " triangles, " +
        std::to_string(t.FetchReceived) + " bytes");
  }
}

/// The mean edge length on a surface of more than 2^17 edges (the estimate samples every
/// other edge), split in random regions: the one-rank estimate bit for bit.
void RunSampledMeanEdgeLength(vtkMultiProcessController* controller)
{
  const int rank = controller->GetLocalProcessId();
  const int ranks = controller->GetNumberOfProcesses();
  const MeshData data = MakeTorus(1.0, 0.4, 300, 150);
  const TriangleMesh mesh(data.Positions, data.Triangles);
  PieceInput ringed;
  PieceMesh piece;
  std::string error;
  if (!BuildRingedPiece(controller,
        testing::OwnedTriangles(mesh, testing::RegionOwners(mesh, ranks, 5, -1), rank),
        ringed,
        error) ||
    !BuildPieceMesh(ringed, piece, error))
  {
    Fail(rank, "sampled mean edge length: " + error);
    return;
  }
  const double length = PieceMeanEdgeLength(controller, piece);
  if (length != EstimateMeanEdgeLength(mesh))
  {
    Fail(rank, "sampled mean edge length differs from the one-rank estimate");
  }
}

/// Curves that cannot be traced: every rank fails with the same message naming the curve
/// (`curve`), and none is left waiting.
void ExpectSameFailure(vtkMultiProcessController* controller,
  const TriangleMesh& mesh,
  const std::vector<Curve>& curves,
  GeodesicMethod method,
  const std::string& curve,
  const std::string& what)
{
  const int rank = controller->GetLocalProcessId();
  const int ranks = controller->GetNumberOfProcesses();
  vtkBoolSurfPieceTracing tracing;
  WireBuffer message;
  std::string error;
  if (TraceOnPieces(controller,
        mesh,
        curves,
        testing::RegionOwners(mesh, ranks, 3, -1),
        method,
        message,
        tracing,
        error))
  {
    Fail(rank, what + " was traced");
    return;
  }
  if (error.find(curve) == std::string::npos)
  {
    Fail(rank, what + ": the error does not name " + curve + ": " + error);
  }
  std::vector<char> first(error.begin(), error.end());
  long long length = static_cast<long long>(first.size());
  controller->Broadcast(&length, 1, 0);
  first.resize(static_cast<std::size_t>(length));
  controller->Broadcast(first.data(), length, 0);
  if (std::string(first.begin(), first.end()) != error)
  {
    Fail(rank, "not rank 0's error: " + error);
  }
  if (rank == 0)
  {
    std::printf("%s, every rank: %s\n", what.c_str(), error.c_str());
  }
}

void RunBadInput(vtkMultiProcessController* controller)
{
  const MeshData data = MakeTorus(1.0, 0.4, 40, 20);
  const TriangleMesh mesh(data.Positions, data.Triangles);
  std::vector<Curve> curves = RandomCurves(mesh, 5, 3, 100);
  ExpectSameFailure(controller,
    mesh,
    curves,
    GeodesicMethod::LocallyShortest,
    "curve 0",
    "the LocallyShortest method");
  curves[1].Points[2].Triangle = mesh.GetNumberOfTriangles() + 7;
  ExpectSameFailure(
    controller, mesh, curves, GeodesicMethod::Bounded, "curve 1", "a missing triangle");
}

} // namespace

int main(int argc, char* argv[])
{
  vtkNew<vtkMPIController> controller;
  controller->Initialize(&argc, &argv);
  vtkMultiProcessController::SetGlobalController(controller);
  RunSurface(controller, MakeIcosphere(3), "sphere");
  RunSurface(controller, MakeTorus(1.0, 0.4, 40, 20), "torus");
  MeshData eight;
  std::string error;
  if (ReadPly((testing::SourceTree() / "Data" / "eight.ply").string(), eight, error))
  {
    RunSurface(controller, eight, "eight.ply");
  }
  else
  {
    Fail(controller->GetLocalProcessId(), "eight.ply: " + error);
  }
  RunLargeSphere(controller);
  RunSampledMeanEdgeLength(controller);
  RunBadInput(controller);
  int all = 0;
  controller->AllReduce(&failures, &all, 1, vtkCommunicator::SUM_OP);
  if (controller->GetLocalProcessId() == 0)
  {
    std::printf("%s: %d failures on %d ranks\n",
      all == 0 ? "PASSED" : "FAILED",
      all,
      controller->GetNumberOfProcesses());
  }
  controller->Finalize();
  return all == 0 ? 0 : 1;
}

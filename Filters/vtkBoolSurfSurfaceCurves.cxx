#include "vtkBoolSurfSurfaceCurves.h"

#include "vtkBoolSurfArrayNames.h"
#include "vtkBoolSurfArrayRanges.h"
#include "vtkBoolSurfClosestTriangles.h"
#include "vtkBoolSurfControlCurveWriter.h"
#include "vtkBoolSurfControlCurves.h"
#include "vtkBoolSurfPieceSnapping.h"
#include "vtkBoolSurfPieceTraceStage.h"
#include "vtkBoolSurfPropertyVector.h"
#include "vtkBoolSurfSharedPieceTrace.h"
#include "vtkBoolSurfSurfaceCache.h"
#include "vtkBoolSurfTraceStage.h"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <vtkTriangle.h>

#include <algorithm>
#include <numeric>
#include <sstream>
#include <string>
#include <unordered_map>

vtkStandardNewMacro(vtkBoolSurfSurfaceCurves);

/// What is kept between edits while the surface is unchanged.
struct vtkBoolSurfSurfaceCurves::Internals
{
  boolsurf::vtkSurfaceCache Traced; // the surface's adjacency and tracer for port 1
  /// The closest triangles of the surface, or on pieces of this rank's own triangles.
  boolsurf::ClosestTriangles Closest;
  /// On pieces: the ringed piece and the tracing of port 1, kept between edits and shared with
  /// the other filters tracing on the same piece (Trace Surface Curves).
  std::shared_ptr<boolsurf::PieceTraceState> Pieces;
  /// Whether the split surface is closed, for the ringed piece of build ClosedBuild of the
  /// state ClosedState (compared, never dereferenced).
  bool PieceClosed = false;
  unsigned long long ClosedBuild = 0;
  const boolsurf::PieceTraceState* ClosedState = nullptr;

  /// Whether every edge of `surface` has a triangle on each side (cached with the surface's
  /// adjacency). Only then is a facet facing away from the camera hidden by the surface.
  bool IsClosed(vtkPolyData* surface)
  {
    std::vector<std::string> warnings;
    std::string error;
    const boolsurf::vtkSurfaceInput* input = this->Traced.GetUsable(surface, warnings, error);
    if (!input)
    {
      return false;
    }
    if (input != this->ClosedOf || surface->GetMTime() != this->ClosedTime)
    {
      const boolsurf::TriangleMesh& mesh = *input->Mesh;
      this->Closed = true;
      for (int h = 0; h < 3 * mesh.GetNumberOfTriangles() && this->Closed; ++h)
      {
        this->Closed = mesh.GetTwin(h) >= 0;
      }
      this->ClosedOf = input;
      this->ClosedTime = surface->GetMTime();
    }
    return this->Closed;
  }
  const boolsurf::vtkSurfaceInput* ClosedOf = nullptr;
  vtkMTimeType ClosedTime = 0;
  bool Closed = false;
};

namespace
{
/// The value of a per-curve property, or its default past the property's end.
int PerCurve(const std::vector<int>& values, size_t curve, int fallback)
{
  return curve < values.size() ? values[curve] : fallback;
}

/// Collective: rank 0's verdict `ok` and its `error` on every rank (every rank fails alike).
bool ShareVerdict(vtkMultiProcessController* controller, bool ok, std::string& error)
{
  long long length = ok ? -1 : static_cast<long long>(error.size());
  controller->Broadcast(&length, 1, 0);
  if (length < 0)
  {
    return true;
  }
  error.resize(static_cast<size_t>(length));
  if (length > 0)
  {
    controller->Broadcast(&error[0], length, 0);
  }
  return false;
}

/// Writes the curves held, traced on the surface, to `traced` (port 1; empty when they cannot
/// be traced). Port 1 shows the drawing as the filters downstream will use it (the curves
/// traced with this filter's trace settings), so it follows
/// a drag in the curve editor: the held curves go through what the readers of port 0 do with
/// them (a polyline whose ends meet is closed, a curve being drawn is shown as far as it is
/// valid, every point checked on the surface), without reading port 0 back. The port is left
/// empty, without a message, while the drawing cannot be traced: the filters that use the
/// curves say why.
void TraceForDisplay(boolsurf::vtkSurfaceCache& cache,
  vtkPolyData* surface,
  const std::vector<boolsurf::InputControlCurve>& held,
  boolsurf::TraceOptions options,
  vtkPolyData* traced)
{
  std::vector<std::string> warnings, problems, notes;
  std::string error;
  if (held.empty() || !cache.GetUsable(surface, warnings, error))
  {
    return;
  }
  const boolsurf::TriangleMesh& mesh = *cache.GetCurrent().Mesh;
  std::vector<boolsurf::InputControlCurve> controls;
  for (boolsurf::InputControlCurve curve : held)
  {
    if (boolsurf::CloseWhereEndsMeet(curve))
    {
      curve.PointIds.pop_back();
    }
    for (const boolsurf::SurfacePoint& p : curve.Points)
    {
      if (!boolsurf::CheckSurfacePoint(mesh, p, error))
      {
        traced->Initialize();
        return;
      }
    }
    if (boolsurf::AcceptControlCurve(curve, problems, notes))
    {
      controls.push_back(std::move(curve));
    }
  }
  options.TraceValidPartOfIncompleteCurves = true;
  std::vector<boolsurf::TracedCurve> paths;
  if (!problems.empty() ||
    !boolsurf::TraceInputCurves(cache, controls, options, nullptr, paths, traced, problems))
  {
    traced->Initialize();
  }
}
} // namespace

//------------------------------------------------------------------------------
vtkBoolSurfSurfaceCurves::vtkBoolSurfSurfaceCurves()
  : Internal(new Internals)
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(2);
}

vtkBoolSurfSurfaceCurves::~vtkBoolSurfSurfaceCurves() = default;

// Property setters: each marks the filter modified only when a value changes.
void vtkBoolSurfSurfaceCurves::SetNumberOfPoints(int n)
{
  if (boolsurf::ResizeProperty(this->Points, 3 * static_cast<size_t>(std::max(0, n)), 0.0))
  {
    this->Modified();
  }
}

void vtkBoolSurfSurfaceCurves::SetPoint(int i, double x, double y, double z)
{
  if (boolsurf::SetPropertyElements(
        this->Points, 3 * static_cast<size_t>(std::max(0, i)), { x, y, z }))
  {
    this->Modified();
  }
}

void vtkBoolSurfSurfaceCurves::SetNumberOfTriangleIds(int n)
{
  if (boolsurf::ResizeProperty(
        this->TriangleIds, static_cast<size_t>(std::max(0, n)), vtkIdType(-1)))
  {
    this->Modified();
  }
}

void vtkBoolSurfSurfaceCurves::SetTriangleId(int i, vtkIdType triangle)
{
  if (boolsurf::SetPropertyElements(
        this->TriangleIds, static_cast<size_t>(std::max(0, i)), { triangle }))
  {
    this->Modified();
  }
}

void vtkBoolSurfSurfaceCurves::SetNumberOfBarycentrics(int n)
{
  if (boolsurf::ResizeProperty(this->Barycentrics, 2 * static_cast<size_t>(std::max(0, n)), 0.0))
  {
    this->Modified();
  }
}

void vtkBoolSurfSurfaceCurves::SetBarycentric(int i, double u, double v)
{
  if (boolsurf::SetPropertyElements(
        this->Barycentrics, 2 * static_cast<size_t>(std::max(0, i)), { u, v }))
  {
    this->Modified();
  }
}

#define BOOLSURF_PER_CURVE_PROPERTY(Count, Element, Vector, Fill)                                  \
  void vtkBoolSurfSurfaceCurves::Count(int n)                                                      \
  {                                                                                                \
    if (boolsurf::ResizeProperty(this->Vector, static_cast<size_t>(std::max(0, n)), Fill))         \
    {                                                                                              \
      this->Modified();                                                                            \
    }                                                                                              \
  }                                                                                                \
  void vtkBoolSurfSurfaceCurves::Element(int i, int value)                                         \
  {                                                                                                \
    if (boolsurf::SetPropertyElements(                                                             \
          this->Vector, static_cast<size_t>(std::max(0, i)), { value }))                           \
    {                                                                                              \
      this->Modified();                                                                            \
    }                                                                                              \
  }
BOOLSURF_PER_CURVE_PROPERTY(SetNumberOfCurveSizes, SetCurveSize, CurveSizes, 0)
BOOLSURF_PER_CURVE_PROPERTY(SetNumberOfShapeIds, SetShapeId, ShapeIds, 0)
BOOLSURF_PER_CURVE_PROPERTY(SetNumberOfCurveTypes, SetCurveType, CurveTypes, 0)
BOOLSURF_PER_CURVE_PROPERTY(SetNumberOfClosedCurves, SetClosedCurve, ClosedCurves, 1)
#undef BOOLSURF_PER_CURVE_PROPERTY

void vtkBoolSurfSurfaceCurves::RemoveAllCurves()
{
  this->Points.clear();
  this->TriangleIds.clear();
  this->Barycentrics.clear();
  this->CurveSizes.clear();
  this->ShapeIds.clear();
  this->CurveTypes.clear();
  this->ClosedCurves.clear();
  this->Modified();
}

//------------------------------------------------------------------------------
bool vtkBoolSurfSurfaceCurves::GetCurveSizes(std::vector<int>& sizes, std::string& error) const
{
  const vtkIdType points = this->GetNumberOfPoints();
  sizes = this->CurveSizes;
  if (sizes.empty() && points > 0)
  {
    sizes.push_back(static_cast<int>(points));
  }
  for (size_t c = 0; c < sizes.size(); ++c)
  {
    if (sizes[c] < 1)
    {
      std::ostringstream message;
      message << "Curve " << c << " has " << sizes[c] << " control points (CurveSizes).";
      error = message.str();
      return false;
    }
  }
  const long long total = std::accumulate(sizes.begin(), sizes.end(), 0LL);
  if (total != points)
  {
    std::ostringstream message;
    message << "CurveSizes add up to " << total << " control points, but " << points
            << " Points are given.";
    error = message.str();
    return false;
  }
  // TriangleIds: none (every point snapped) or one per point, -1 marking a point to snap (the
  // curve editor stores the points it has placed exactly and snaps the one being dragged).
  if (!this->TriangleIds.empty() &&
    (static_cast<vtkIdType>(this->TriangleIds.size()) != points ||
      static_cast<vtkIdType>(this->Barycentrics.size()) != 2 * points))
  {
    std::ostringstream message;
    message << "Exact surface points need a TriangleId and a Barycentric pair for each of the "
            << points << " Points; got " << this->TriangleIds.size() << " TriangleIds and "
            << this->Barycentrics.size() / 2 << " Barycentrics.";
    error = message.str();
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
std::vector<boolsurf::PointQuery> vtkBoolSurfSurfaceCurves::GetPointQueries() const
{
  std::vector<boolsurf::PointQuery> queries(static_cast<size_t>(this->GetNumberOfPoints()));
  for (size_t i = 0; i < queries.size(); ++i)
  {
    boolsurf::PointQuery& q = queries[i];
    q.Named = !this->TriangleIds.empty() && this->TriangleIds[i] != -1;
    q.Triangle = q.Named ? this->TriangleIds[i] : -1;
    std::copy(&this->Points[3 * i], &this->Points[3 * i] + 3, q.X);
  }
  return queries;
}

//------------------------------------------------------------------------------
bool vtkBoolSurfSurfaceCurves::WriteControlCurves(const std::vector<int>& sizes,
  const std::vector<boolsurf::PlacedPoint>& placed,
  long long triangles,
  bool closedSurface,
  vtkPolyData* output,
  std::vector<boolsurf::InputControlCurve>& curves,
  std::string& error) const
{
  // Surface points: given exactly, or the closest surface point of each position.
  const vtkIdType points = this->GetNumberOfPoints();
  std::vector<boolsurf::SurfacePoint> surfacePoints(static_cast<size_t>(points));
  // The facet's unit normal at each control point of a closed surface (zero on a surface with
  // a boundary, whose back may be in view): the curve editor hides the markers of points on
  // the far side (named apart from "Normals", which ParaView would take for the lines' shading
  // normals).
  vtkNew<vtkDoubleArray> facetNormal;
  facetNormal->SetName(boolsurf::names::SurfaceNormal);
  facetNormal->SetNumberOfComponents(3);
  facetNormal->SetNumberOfTuples(points);
  // The corners of each triangle a point lies on, for the positions written.
  std::unordered_map<int, const boolsurf::PlacedPoint*> cornersOf;
  size_t curve = 0;
  vtkIdType curveEnd = sizes.empty() ? 0 : sizes[0];
  for (vtkIdType i = 0; i < points; ++i)
  {
    while (i >= curveEnd && curve + 1 < sizes.size())
    {
      curveEnd += sizes[++curve];
    }
    const boolsurf::PlacedPoint& at = placed[static_cast<size_t>(i)];
    vtkIdType triangle = at.Triangle;
    double u = 0, v = 0;
    const bool given = !this->TriangleIds.empty() && this->TriangleIds[i] != -1;
    if (given)
    {
      triangle = this->TriangleIds[i];
      u = this->Barycentrics[2 * i];
      v = this->Barycentrics[2 * i + 1];
      if (!at.Found)
      {
        std::ostringstream message;
        message << "Curve " << curve << ", point " << i << ": TriangleId " << triangle
                << " is not a triangle of the surface (it has " << triangles << ").";
        error = message.str();
        return false;
      }
      if (!boolsurf::IsInsideTriangle(u, v))
      {
        std::ostringstream message;
        message << "Curve " << curve << ", point " << i << ": Barycentric (" << u << ", " << v
                << ") is outside triangle " << triangle << ".";
        error = message.str();
        return false;
      }
    }
    if (at.Corners != 3)
    {
      std::ostringstream message;
      message << "Curve " << curve << ", point " << i << ": cell " << triangle
              << " of the surface has " << at.Corners
              << " points, not 3: triangulate the surface first.";
      error = message.str();
      return false;
    }
    const double(&p)[3][3] = at.P;
    if (!given)
    {
      // In 3D: vtkTriangle::BarycentricCoords reads only x and y, so on a triangle standing
      // upright (a wall, a cylinder's side) it had no solution or the wrong one.
      auto vec = [](const double* q) { return boolsurf::Vec3{ q[0], q[1], q[2] }; };
      boolsurf::BarycentricInTriangle(vec(p[0]), vec(p[1]), vec(p[2]), vec(at.Closest), u, v);
    }
    double normal[3] = { 0, 0, 0 };
    if (closedSurface)
    {
      double corners[3][3];
      std::copy(&p[0][0], &p[0][0] + 9, &corners[0][0]);
      vtkTriangle::ComputeNormal(corners[0], corners[1], corners[2], normal);
    }
    facetNormal->SetTuple(i, normal);
    surfacePoints[static_cast<size_t>(i)] = { static_cast<int>(triangle), u, v };
    cornersOf.emplace(static_cast<int>(triangle), &at);
  }

  // The curves this filter holds; written as control curves (one polyline per curve, a closed
  // curve repeating its first point).
  curves.assign(sizes.size(), boolsurf::InputControlCurve());
  vtkNew<vtkIntArray> complete;
  vtkNew<vtkStringArray> incomplete;
  complete->SetName(boolsurf::names::Complete);
  incomplete->SetName(boolsurf::names::IncompleteCurves);
  vtkIdType first = 0;
  for (size_t c = 0; c < sizes.size(); ++c)
  {
    const int type = PerCurve(this->CurveTypes, c, 0);
    const bool isClosed = PerCurve(this->ClosedCurves, c, 1) != 0;
    const int shape = PerCurve(this->ShapeIds, c, static_cast<int>(c));
    if (type != 0 && type != 1)
    {
      std::ostringstream message;
      message << "Curve " << c << ": CurveType " << type
              << " is neither 0 (geodesic polygon) nor 1 (cubic Bezier).";
      error = message.str();
      return false;
    }
    if (shape < 0)
    {
      std::ostringstream message;
      message << "Curve " << c << ": ShapeId " << shape << " is negative.";
      error = message.str();
      return false;
    }
    const int size = sizes[c];
    // A curve with too few points for its type is one being drawn (the curve editor writes
    // every click): no error, but marked, so that filters leave it out without a message,
    // and said in the field data (the editor's panel says it too).
    const std::string needs = boolsurf::WhatCurveNeeds(type == 1, isClosed, size);
    complete->InsertNextValue(needs.empty() ? 1 : 0);
    if (!needs.empty())
    {
      incomplete->InsertNextValue("curve " + std::to_string(c) + ": " + needs);
    }
    boolsurf::InputControlCurve& curve = curves[c];
    curve.CurveId = static_cast<int>(c);
    curve.ShapeId = shape;
    curve.Type = static_cast<boolsurf::CurveType>(type);
    curve.Closed = isClosed;
    curve.BeingDrawn = !needs.empty();
    curve.Points.assign(surfacePoints.begin() + first, surfacePoints.begin() + first + size);
    for (int k = 0; k < size; ++k)
    {
      curve.PointIds.push_back(first + k);
    }
    first += size;
  }
  // Positions from the corners of the surface's own triangles (the curves are written even
  // when the surface is not one the tracing can use).
  boolsurf::ControlCurveWriter writer(
    [&cornersOf](const boolsurf::SurfacePoint& sp)
    {
      const double(&p)[3][3] = cornersOf.at(sp.Triangle)->P;
      double x[3];
      for (int k = 0; k < 3; ++k)
      {
        x[k] = (1 - sp.U - sp.V) * p[0][k] + sp.U * p[1][k] + sp.V * p[2][k];
      }
      return boolsurf::Vec3{ x[0], x[1], x[2] };
    });
  for (const boolsurf::InputControlCurve& curve : curves)
  {
    writer.Add(curve);
  }
  writer.Write(output);
  output->GetPointData()->AddArray(facetNormal);
  output->GetCellData()->AddArray(complete);
  if (incomplete->GetNumberOfValues() > 0)
  {
    output->GetFieldData()->AddArray(incomplete);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkBoolSurfSurfaceCurves::MarkDrawing(vtkPolyData* output, vtkPolyData* traced)
{
  for (vtkPolyData* port : { output, traced })
  {
    vtkNew<vtkIntArray> drawing;
    drawing->SetName(boolsurf::names::Drawing);
    drawing->InsertNextValue(1);
    port->GetFieldData()->AddArray(drawing);
    // The ranges ParaView reads after every edit (see vtkBoolSurfArrayRanges.h).
    boolsurf::CacheDataRanges(port, this->GetNumberOfThreads());
  }
}

//------------------------------------------------------------------------------
bool vtkBoolSurfSurfaceCurves::Execute(const std::vector<vtkPolyData*>& inputs,
  const std::vector<vtkPolyData*>& outputs,
  std::string& error)
{
  vtkPolyData* surface = inputs[0];
  vtkPolyData* output = outputs[0];
  vtkPolyData* traced = outputs[1];
  if (!surface || surface->GetNumberOfCells() == 0)
  {
    error = "The surface is empty: curves are drawn on a triangle surface.";
    return false;
  }
  std::vector<int> sizes;
  if (!this->GetCurveSizes(sizes, error))
  {
    return false;
  }
  // Each point on the triangle it names, or on the closest one (ties to the lowest cell id).
  const std::vector<boolsurf::PointQuery> queries = this->GetPointQueries();
  this->Internal->Closest.SetSurface(surface, false);
  std::vector<boolsurf::PlacedPoint> placed;
  placed.reserve(queries.size());
  for (const boolsurf::PointQuery& query : queries)
  {
    placed.push_back(this->Internal->Closest.Place(query));
  }
  const bool closedSurface = !queries.empty() && this->Internal->IsClosed(surface);
  std::vector<boolsurf::InputControlCurve> curves;
  if (!this->WriteControlCurves(
        sizes, placed, surface->GetNumberOfCells(), closedSurface, output, curves, error))
  {
    return false;
  }
  TraceForDisplay(this->Internal->Traced, surface, curves, this->GetTraceOptions(), traced);
  this->MarkDrawing(output, traced);
  return true;
}

//------------------------------------------------------------------------------
bool vtkBoolSurfSurfaceCurves::ExecutePiece(const std::vector<vtkPolyData*>& locals,
  const std::vector<vtkPolyData*>& outputs,
  std::string& error)
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const bool first = controller->GetLocalProcessId() == 0;
  Internals& internal = *this->Internal;
  vtkPolyData* local = locals[0];
  vtkPolyData* output = outputs[0];
  vtkPolyData* traced = outputs[1];
  // The drawing exists once: rank 0's properties, checked there, the verdict on every rank.
  std::vector<int> sizes;
  if (!ShareVerdict(controller, !first || this->GetCurveSizes(sizes, error), error))
  {
    return false;
  }
  // Each point placed by the ranks owning its triangle or the closest ones (rank 0 gets them).
  internal.Closest.SetSurface(local, true);
  std::vector<boolsurf::PlacedPoint> placed;
  long long triangles = 0;
  boolsurf::SnappingTraffic traffic;
  boolsurf::PlaceOnPieces(controller,
    internal.Closest,
    first ? this->GetPointQueries() : std::vector<boolsurf::PointQuery>(),
    placed,
    triangles,
    traffic);
  // Whether the surface is closed, from the ringed pieces (kept for port 1's tracing).
  const bool drawn = traffic.Points > 0;
  internal.Pieces = boolsurf::SharedPieceTraceState(local, std::move(internal.Pieces));
  std::string problem;
  bool closedSurface = false;
  if (drawn && boolsurf::UpdateRingedPiece(controller, local, *internal.Pieces, problem))
  {
    // Decided alike on every rank: the state and its builds are the same on every rank.
    if (internal.ClosedState != internal.Pieces.get() ||
      internal.ClosedBuild != internal.Pieces->Builds)
    {
      internal.PieceClosed = boolsurf::IsClosedOnPieces(controller, internal.Pieces->Ringed);
      internal.ClosedBuild = internal.Pieces->Builds;
      internal.ClosedState = internal.Pieces.get();
    }
    closedSurface = internal.PieceClosed;
  }
  std::vector<boolsurf::InputControlCurve> curves;
  if (!ShareVerdict(controller,
        !first ||
          this->WriteControlCurves(sizes, placed, triangles, closedSurface, output, curves, error),
        error))
  {
    return false;
  }
  boolsurf::AddPieceSnapping(traffic, output);
  // Port 1: port 0's curves traced on the pieces, as Trace Surface Curves traces them there
  // (the one-rank polylines on rank 0); empty, without a message, when they cannot be traced.
  if (drawn)
  {
    boolsurf::TraceOptions options = this->GetTraceOptions();
    options.TraceValidPartOfIncompleteCurves = true;
    std::vector<std::string> problems, notes;
    std::string reason;
    switch (boolsurf::TraceOnPieces(controller,
      local,
      first ? output : nullptr,
      options,
      *internal.Pieces,
      traced,
      problems,
      notes,
      reason,
      this))
    {
      case boolsurf::PieceTraceOutcome::Gather:
        if (first)
        {
          vtkWarningMacro("the curves were drawn on the surface gathered to rank 0, not on each "
                          "rank's piece: "
            << reason);
        }
        this->GatherInsteadOfPieces(); // decided alike on every rank
        return true;
      case boolsurf::PieceTraceOutcome::Failed:
        traced->Initialize();
        break;
      case boolsurf::PieceTraceOutcome::Traced:
      case boolsurf::PieceTraceOutcome::DrawingStart:
        break;
    }
  }
  if (first)
  {
    this->MarkDrawing(output, traced);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkBoolSurfSurfaceCurves::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Points: " << this->GetNumberOfPoints()
     << (this->TriangleIds.empty() ? " (snapped)" : " (exact)") << "\n";
  os << indent
     << "Curves: " << std::max<size_t>(this->CurveSizes.size(), this->GetNumberOfPoints() > 0)
     << "\n";
}

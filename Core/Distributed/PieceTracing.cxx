#include "Distributed/PieceTracing.h"

#include "Geodesic/WrittenCurvePoints.h"

#include <map>
#include <utility>

namespace boolsurf
{

//------------------------------------------------------------------------------
GlobalCurveTrace ToGlobalTrace(const CurveTrace& trace,
  const TriangleMesh& mesh,
  const std::vector<int>& vertexGlobalId,
  const std::vector<int>& triangleGlobalId)
{
  auto vertex = [&](int v) { return vertexGlobalId.empty() ? v : vertexGlobalId[v]; };
  GlobalCurveTrace out;
  out.Points.reserve(trace.Curve.Points.size());
  for (const CanonicalPoint& c : trace.Curve.Points)
  {
    GlobalCurvePoint g;
    g.Location = c.Location;
    g.U = c.U; // as they are, whatever the location: PackGlobalTraces sends them
    g.V = c.V;
    g.T = c.T;
    if (c.Location == PointLocation::Vertex)
    {
      g.Id = vertex(c.Id);
    }
    else if (c.Location == PointLocation::Edge)
    {
      const std::array<int, 2> ends = mesh.GetEdgeVertices(c.Id);
      g.Id = vertex(ends[0]);
      g.Second = vertex(ends[1]);
    }
    else
    {
      g.Id = triangleGlobalId.empty() ? c.Id : triangleGlobalId[c.Id];
    }
    out.Points.push_back(g);
  }
  out.Closed = trace.Curve.Closed;
  out.ShapeId = trace.Curve.ShapeId;
  out.CurveId = trace.Curve.CurveId;
  out.Segment = trace.Segment;
  out.ControlPoint = trace.ControlPoint;
  out.Parameter = trace.Parameter;
  out.OnCurve = trace.OnCurve;
  out.Length = trace.Length;
  return out;
}

//------------------------------------------------------------------------------
// PackTracedCurves' layout: curves, then the table of the edges named, in the order the
// points first name them (an edge by its global vertices, in its parameter's direction).
void PackGlobalTraces(const std::vector<GlobalCurveTrace>& traces, WireBuffer& out)
{
  out.clear();
  std::map<std::pair<int, int>, int> edgeIndex;
  WireBuffer edges;
  out.push_back(static_cast<long long>(traces.size()));
  for (const GlobalCurveTrace& c : traces)
  {
    out.insert(out.end(),
      { c.Closed ? 1 : 0, c.ShapeId, c.CurveId, static_cast<long long>(c.Points.size()) });
    for (const GlobalCurvePoint& p : c.Points)
    {
      long long id = p.Id;
      if (p.Location == PointLocation::Edge)
      {
        const auto found =
          edgeIndex.emplace(std::make_pair(p.Id, p.Second), static_cast<int>(edgeIndex.size()));
        if (found.second)
        {
          edges.push_back(p.Id);
          edges.push_back(p.Second);
        }
        id = found.first->second;
      }
      out.insert(out.end(),
        { static_cast<long long>(p.Location),
          id,
          WireBitsOf(p.U),
          WireBitsOf(p.V),
          WireBitsOf(p.T) });
    }
  }
  out.push_back(static_cast<long long>(edges.size() / 2));
  out.insert(out.end(), edges.begin(), edges.end());
}

//------------------------------------------------------------------------------
PieceCurveTracer::PieceCurveTracer(const PieceInput& piece, TriangleFetcher& fetcher)
  : Surface(piece)
  , Fetcher(fetcher)
{
}

//------------------------------------------------------------------------------
PieceCurveTracer::~PieceCurveTracer() = default;

//------------------------------------------------------------------------------
void PieceCurveTracer::SetOptions(const GeodesicPathOptions& options)
{
  this->Options = options;
  if (this->Tracer)
  {
    this->Tracer->GetPathSolver().SetOptions(options);
  }
}

//------------------------------------------------------------------------------
void PieceCurveTracer::SetResolution(int levels)
{
  this->Resolution = levels;
  if (this->Tracer)
  {
    this->Tracer->SetResolution(levels);
  }
}

//------------------------------------------------------------------------------
void PieceCurveTracer::SetMeanEdgeLength(double length)
{
  this->MeanEdgeLength = length;
  if (this->Tracer)
  {
    this->Tracer->GetPathSolver().SetMeanEdgeLength(length);
  }
}

//------------------------------------------------------------------------------
// The held triangles' mesh, and a tracer on it when the mesh is new (its remembered curves
// and cached legs belong to the old one).
bool PieceCurveTracer::Prepare(std::string& error)
{
  if (!this->Surface.Build(error))
  {
    return false;
  }
  const TriangleMesh& mesh = this->Surface.GetPiece().Mesh;
  if (!this->Tracer || &this->Tracer->GetPathSolver().GetMesh() != &mesh ||
    this->TracedSerial != mesh.GetSerial())
  {
    this->Tracer = std::make_unique<CurveTracer>(mesh);
    this->Tracer->SetResolution(this->Resolution);
    GeodesicPathSolver& solver = this->Tracer->GetPathSolver();
    solver.SetOptions(this->Options);
    if (this->MeanEdgeLength >= 0.0)
    {
      solver.SetMeanEdgeLength(this->MeanEdgeLength);
    }
    // A search that meets a triangle not whole yet goes on a margin's width further (walls
    // there too), so one round fetches what the next search would meet next.
    const double edge =
      this->MeanEdgeLength >= 0.0 ? this->MeanEdgeLength : EstimateMeanEdgeLength(mesh);
    const PartialSurface& surface = this->Surface;
    solver.SetPieceReads(
      &this->Reads,
      [&surface](int t) { return surface.IsExactTriangle(t); },
      this->MarginRings * edge);
    this->TracedSerial = mesh.GetSerial();
  }
  return true;
}

//------------------------------------------------------------------------------
bool PieceCurveTracer::FetchAndAdd(const std::vector<int>& vertices,
  const std::vector<int>& triangles,
  std::string& error)
{
  FetchedTriangles fetched;
  if (!this->Fetcher.Fetch(vertices, triangles, this->MarginRings, fetched, error) ||
    !this->Surface.Add(fetched, error))
  {
    return false;
  }
  ++this->Statistics.Rounds;
  this->Statistics.RequestedVertices += static_cast<int>(vertices.size());
  this->Statistics.FetchedTriangles += static_cast<int>(fetched.TriangleGlobalIds.size());
  // Each round must make what it asked for whole, or the next one would ask again forever.
  for (int v : vertices)
  {
    if (!this->Surface.IsWholeVertex(v))
    {
      error = "the fan of vertex " + std::to_string(v) + " was asked for but not sent whole";
      return false;
    }
  }
  for (int t : triangles)
  {
    if (!this->Surface.HoldsTriangle(t))
    {
      error = "no piece holds triangle " + std::to_string(t);
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool PieceCurveTracer::Trace(const std::vector<SurfacePoint>& points,
  CurveType type,
  bool closed,
  GlobalCurveTrace& out,
  std::string& error,
  int curveId)
{
  this->Statistics = {};
  out = {};
  const std::string label = "curve " + std::to_string(curveId) + ": ";
  for (;;)
  {
    // The control points' triangles first (a curve may start on another piece).
    this->Absent.clear();
    for (const SurfacePoint& p : points)
    {
      if (!this->Surface.HoldsTriangle(p.Triangle))
      {
        this->Absent.push_back(p.Triangle);
      }
    }
    if (!this->Absent.empty())
    {
      if (!this->FetchAndAdd({}, this->Absent, error))
      {
        error = label + error;
        return false;
      }
      continue;
    }
    if (!this->Prepare(error))
    {
      error = label + error;
      return false;
    }
    const PieceMesh& piece = this->Surface.GetPiece();
    this->LocalPoints = points;
    this->Reads.clear();
    for (SurfacePoint& p : this->LocalPoints)
    {
      p.Triangle = piece.LocalTriangle(p.Triangle);
      this->Reads.push_back(p.Triangle); // its edges' directions decide the canonical point
    }
    CurveTrace trace;
    std::string traceError;
    ++this->Statistics.Traces;
    const bool traced =
      this->Tracer->Trace(this->LocalPoints, type, closed, trace, traceError, curveId);
    this->Surface.FindMissing(this->Reads, this->Missing);
    if (this->Missing.empty())
    {
      if (!traced)
      {
        error = traceError; // names the curve; points by the piece's local ids
        return false;
      }
      out = ToGlobalTrace(trace, piece.Mesh, piece.GlobalVertex, piece.GlobalTriangle);
      if (this->KeepWrittenForms)
      {
        // As Trace Surface Curves writes them: a control point in its own triangle.
        const std::size_t n = trace.Curve.Points.size();
        out.Positions.resize(n);
        out.Written.resize(n);
        for (std::size_t i = 0; i < n; ++i)
        {
          const int k = trace.ControlPoint[i];
          const int own = k >= 0 && k < static_cast<int>(this->LocalPoints.size())
            ? this->LocalPoints[k].Triangle
            : -1;
          out.Positions[i] = PositionOf(piece.Mesh, trace.Curve.Points[i]);
          out.Written[i] = WrittenCurvePoint(piece.Mesh, trace.Curve, i, own);
          out.Written[i].Triangle = piece.GlobalTriangle[out.Written[i].Triangle];
        }
      }
      return true;
    }
    if (!this->FetchAndAdd(this->Missing, {}, error))
    {
      error = label + error;
      return false;
    }
  }
}

} // namespace boolsurf

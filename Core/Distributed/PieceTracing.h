// Tracing curves on a piece of a surface split across processes (Docs/Parallel.md, "Tracing
// on pieces"): no piece ever holds the whole surface, and every traced curve is, bit for bit,
// the curve CurveTracer traces on the whole surface.
//
// A curve is traced on the piece's PartialSurface (its triangles in global order) by a
// CurveTracer whose solver records every triangle its legs read (SetPieceReads). When one of
// them, or a triangle round one of its corners, is not whole there, the reads may differ from
// the surface's: the piece fetches the fans of the vertices that are not whole (with a margin of
// rings) from their owners through a TriangleFetcher, rebuilds its mesh and traces the curve
// again, until every read is whole (bulk-synchronous rounds: one fetch per round). The leg's
// computation then read only triangles whose neighbourhood is the surface's, in the same order,
// so it made the same operations on the same numbers.
//
// Methods: Exact, and Bounded legs settled by the exact window search within the Bounded
// budget. A Bounded leg routed on the surface's site graph, an Exact leg past its window
// budget and the LocallyShortest method need structures of the whole surface (the site graph,
// the edge search's landmarks): their curves fail with a message saying so.
#ifndef boolsurf_PieceTracing_h
#define boolsurf_PieceTracing_h

#include "Distributed/PartialSurface.h"
#include "Distributed/PieceWire.h"
#include "Geodesic/CurveTracer.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace boolsurf
{

/// Where a piece gets the triangles it does not hold: in one process, a view of the whole
/// surface (the tests); across processes, messages to the triangles' owners.
class TriangleFetcher
{
public:
  virtual ~TriangleFetcher() = default;
  /// Appends to `out` every triangle within `rings` rings (1: the fan) of the global vertices
  /// `vertices` and of the corners of the global triangles `triangles`, with their corners'
  /// positions, and names whole every vertex whose fan it sent entire (at least the requested
  /// vertices and corners). False, with a message naming it, when one does not exist.
  virtual bool Fetch(const std::vector<int>& vertices,
    const std::vector<int>& triangles,
    int rings,
    FetchedTriangles& out,
    std::string& error) = 0;
};

/// A traced point named by the surface's global ids: a vertex (Id), a point on the edge from
/// vertex Id to vertex Second at parameter T, or a point of triangle Id at barycentrics U, V.
struct GlobalCurvePoint
{
  PointLocation Location = PointLocation::Face;
  int Id = -1;
  int Second = -1;
  double U = 0, V = 0, T = 0;
  bool operator==(const GlobalCurvePoint& o) const
  {
    return this->Location == o.Location && this->Id == o.Id && this->Second == o.Second &&
      this->U == o.U && this->V == o.V && this->T == o.T;
  }
};

/// A CurveTrace with its points on global ids (its provenance as it is).
struct GlobalCurveTrace
{
  std::vector<GlobalCurvePoint> Points;
  bool Closed = true;
  int ShapeId = 0, CurveId = 0;
  std::vector<int> Segment, ControlPoint;
  std::vector<double> Parameter;
  std::vector<char> OnCurve;
  double Length = 0.0;
  /// Filled when the tracer keeps written forms (PieceCurveTracer::SetKeepWrittenForms): each
  /// point's position and its form in output arrays (WrittenCurvePoint, a control point in its
  /// own triangle), the triangle a global id. The whole surface's numbers bit for bit: every
  /// point lies on triangles the trace read, whose neighbourhoods the piece holds whole.
  std::vector<Vec3> Positions;
  std::vector<SurfacePoint> Written;
};

/// `trace`, traced on `mesh`, on global ids: vertexGlobalId[v] and triangleGlobalId[t] for the
/// mesh's vertex v and triangle t (empty: the mesh's own ids).
GlobalCurveTrace ToGlobalTrace(const CurveTrace& trace,
  const TriangleMesh& mesh,
  const std::vector<int>& vertexGlobalId,
  const std::vector<int>& triangleGlobalId);

/// Message 0 of PieceWire (the traced curves, to every piece) from traces on global ids: the
/// very buffer PackTracedCurves gives for the same curves traced on the whole surface, so
/// UnpackTracedCurves and RestrictCurvesToPiece read it as they are.
void PackGlobalTraces(const std::vector<GlobalCurveTrace>& traces, WireBuffer& out);

/// What the last PieceCurveTracer::Trace did.
struct PieceTracingStatistics
{
  int Rounds = 0;            ///< fetches (one message round each)
  int FetchedTriangles = 0;  ///< triangles added by them
  int RequestedVertices = 0; ///< vertices whose fans were asked for
  int Traces = 0;            ///< curve traces, the last one exact
};

class PieceCurveTracer
{
public:
  /// `piece`: the piece's own triangles and ring (Ghost marks the ring). `fetcher` must outlive
  /// the tracer.
  PieceCurveTracer(const PieceInput& piece, TriangleFetcher& fetcher);
  ~PieceCurveTracer();

  /// The solver's settings (GeodesicPathSolver::SetOptions) and the tracer's Bezier resolution.
  void SetOptions(const GeodesicPathOptions& options);
  void SetResolution(int levels);
  /// The whole surface's EstimateMeanEdgeLength (the Bounded method's budget test).
  void SetMeanEdgeLength(double length);
  /// Rings fetched round each vertex that must become whole, and the width (in mean edge
  /// lengths) a search goes on past the first triangle it finds missing (default 3: 2.3 rounds
  /// per short curve on a 20k-triangle sphere, against 4.5 with 2 and 8.7 with 1, for as many
  /// triangles).
  void SetMarginRings(int rings) { this->MarginRings = rings < 1 ? 1 : rings; }
  /// Whether Trace() also fills GlobalCurveTrace::Positions and Written (for a writer of the
  /// traced polylines, which holds no mesh).
  void SetKeepWrittenForms(bool keep) { this->KeepWrittenForms = keep; }

  /// CurveTracer::Trace of control points on global triangle ids, on this piece, fetching
  /// what it needs: `out` is the whole surface's trace. Messages name the curve.
  bool Trace(const std::vector<SurfacePoint>& points,
    CurveType type,
    bool closed,
    GlobalCurveTrace& out,
    std::string& error,
    int curveId = 0);

  const PartialSurface& GetSurface() const { return this->Surface; }
  const PieceTracingStatistics& GetLastStatistics() const { return this->Statistics; }

private:
  bool FetchAndAdd(const std::vector<int>& vertices,
    const std::vector<int>& triangles,
    std::string& error);
  bool Prepare(std::string& error);

  PartialSurface Surface;
  TriangleFetcher& Fetcher;
  GeodesicPathOptions Options;
  int Resolution = 4;
  double MeanEdgeLength = -1.0;
  int MarginRings = 3;
  bool KeepWrittenForms = false;
  std::unique_ptr<CurveTracer> Tracer; // on Surface's mesh, rebuilt with it
  std::uint64_t TracedSerial = 0;
  std::vector<int> Reads, Missing, Absent;
  std::vector<SurfacePoint> LocalPoints;
  PieceTracingStatistics Statistics;
};

} // namespace boolsurf

#endif

// Exact polyhedral shortest path between two surface points, by window propagation.
//
// Chen-Han's continuous Dijkstra with the filtering of Xin and Wang ("ICH"): a window is an
// interval of a mesh edge lit by one (pseudo-)source unfolded into the plane of the edge's
// next triangle; windows cross triangles and split at the opposite vertex. Saddle vertices
// (angle sum >= 2 pi) and boundary vertices become new sources. A window is dropped when a
// known path through one of its edge's end vertices already reaches every point of it
// sooner (sound: only provably longer paths are dropped).
//
// Output-sensitive: events are ordered A*-style by a lower bound of any path through them
// (the event's own shortest distance plus the straight 3D distance to the target), and the
// search stops when that bound reaches the best path to the target found so far, so a short
// edge only lights the triangles around it. The result is the sequence of triangles the
// exact shortest path crosses (a strip, turning around the saddle vertices it passes); the
// caller straightens it with the funnel algorithm, which gives the exact length.
#ifndef boolsurf_ExactGeodesicSearch_h
#define boolsurf_ExactGeodesicSearch_h

#include "Mesh/SurfacePoint.h"
#include "Mesh/ZeroPageArray.h"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace boolsurf
{

class ExactGeodesicSearch
{
public:
  /// `mesh` must outlive the search. Per-vertex angle sums are computed on first use.
  explicit ExactGeodesicSearch(const TriangleMesh& mesh);

  /// Exact shortest distance from `start` to `end` (normalized canonical points whose
  /// triangles are `startTriangles` / `endTriangles`, sharing no triangle), and in `strip` a
  /// chain of edge-adjacent triangles from a start triangle to an end triangle that holds a
  /// shortest path. Returns -1 when no path was found (different components, non-manifold
  /// fan on the way, or the window budget exhausted).
  double FindStrip(const CanonicalPoint& start,
    const std::vector<int>& startTriangles,
    const CanonicalPoint& end,
    const std::vector<int>& endTriangles,
    std::vector<int>& strip);

  /// Windows created by the last search (work measure for benchmarks).
  int GetLastWindowCount() const { return static_cast<int>(this->Windows.size()); }
  /// Vertex events settled by the last search.
  int GetLastVertexCount() const { return this->LastVertexCount; }
  /// Give up (FindStrip returns -1) beyond this many windows (72 bytes each); default 2^20
  /// (~75 MB, about a second): enough for any pair on meshes up to ~30k triangles (kitten's
  /// far pairs need up to 0.8M) and for short paths on any mesh.
  void SetMaximumWindows(int n) { this->MaximumWindows = n; }
  int GetMaximumWindows() const { return this->MaximumWindows; }
  /// The next FindStrip only looks for paths shorter than `length` (a path known to the
  /// caller): windows that cannot lead to one are never made, and it returns -1 when none is
  /// shorter. Applies to one search; 0 or below: no bound.
  void SetUpperBound(double length) { this->UpperBound = length; }
  /// Path searches restart windows at a saddle only into its shadow and trim windows by
  /// their edge's known distances (see ShadowFan, TrimOnEdge); off: the plain filter of Xin
  /// and Wang, for comparison. Same lengths either way; on (default) makes 2 to 3.4 times fewer
  /// windows on scans. The distance field mode always runs plain.
  void SetPruning(bool on) { this->Pruning = on; }
  /// True when the last FindStrip stopped at the window budget.
  bool GetLastBudgetExceeded() const { return this->BudgetExceeded; }
  /// Searching a part of a surface (GeodesicPathSolver::SetPieceReads): `exact(t)` tells
  /// whether the neighbourhood of triangle t (its neighbours, its corners' fans and theirs) is
  /// the surface's there. A window lighting a triangle that is not is not propagated (a wall),
  /// and once one is met the search goes on only while its queue is less than `slack` past
  /// that window: FindStrip then returns -1 and GetLastStoppedAtWall is true. The walls it met
  /// are what the caller must complete, nearest the target first. Null (default): the whole
  /// surface.
  void SetPieceTriangles(std::function<bool(int)> exact, double slack)
  {
    this->PieceExact = std::move(exact);
    this->WallSlack = slack;
  }
  bool GetLastStoppedAtWall() const { return this->StoppedAtWall; }
  /// Appends the triangles the last FindStrip read a window's geometry from, with repeats: on a
  /// part of a surface, the lit and source-side triangles of the windows it propagated and the
  /// walls it met; else those of every window it made. Every vertex the search labelled, walked
  /// around or emitted from is a corner of one of them.
  void AppendLitTriangles(std::vector<int>& out) const;

  ///@{
  /// Distance field mode (geodesic offsets): the exact distance from the nearest of `curves`
  /// (polylines of normalized canonical points whose consecutive points share a triangle, so
  /// each piece is a straight segment of one triangle, or of an edge) to every surface point
  /// closer than `radius`. The same window propagation as FindStrip with every source at
  /// distance 0 and no target, stopped when every event left is at least `radius` away. The
  /// polylines' points are point sources (but where a curve crosses an edge without turning,
  /// which its two pieces cover); each piece is a line source: in its triangle's plane,
  /// the rays normal to it through each edge of the triangle form a window whose source is a
  /// point 1e7 piece lengths behind the piece (at distance -1e7 lengths), so the rays are
  /// parallel to 1e-7 and the distance it gives is the distance to the piece's line to ~1e-8 of
  /// the piece's length. False when the window budget ran out. Afterwards the field can be read
  /// anywhere: a value below `radius` is exact, a value at or above it only says "at least
  /// radius" (infinity where nothing arrived).
  bool ComputeDistanceField(const std::vector<std::vector<CanonicalPoint>>& curves,
    const std::vector<char>& closed,
    double radius);
  /// At mesh vertex v.
  double GetFieldDistanceAtVertex(int v) const;
  /// On mesh edge `edge` at parameter t in [0, 1] from its canonical vertex 0 to vertex 1
  /// (TriangleMesh::GetEdgeVertices): the windows on the edge, the paths through its two
  /// vertices and the sources on it.
  double GetFieldDistanceOnEdge(int edge, double t) const;
  /// At barycentric weights `w` (of its corners in order) inside triangle `face`: the windows
  /// lighting it, the paths through its corners and the sources in it.
  double GetFieldDistanceInTriangle(int face, const std::array<double, 3>& w) const;
  /// Triangles for which `allowed` returns false are never entered (no window lights them, no
  /// path crosses them), in both modes: for a caller that needs the field on one side of its
  /// sources only, or the shortest path within a corridor of triangles (FindStrip then finds
  /// the shortest path inside it, or none). Empty (default): every triangle.
  void SetFieldTriangleFilter(std::function<bool(int)> allowed)
  {
    this->Allowed = std::move(allowed);
  }
  /// Vertices whose distance was set by the last field computation (settled or not).
  const std::vector<int>& GetFieldVertices() const { return this->FieldVertices; }
  ///@}

private:
  enum ParentKind : int
  {
    FromSource = 0,
    FromVertex = 1,
    FromWindow = 2,
  };
  struct Window
  {
    int Edge;      // mesh edge
    int Face;      // triangle the window lights (across Edge from Origin)
    int Origin;    // triangle on the source side
    int Parent;    // window or vertex id (see Kind)
    int Kind;      // ParentKind
    double B0, B1; // lit interval, distances from the edge's canonical vertex 0
    double Sx, Sy; // source in the edge frame: vertex 0 at (0,0), vertex 1 at (L,0),
                   // Face on y > 0, so Sy <= 0
    double Sigma;  // distance from the start to the source
  };
  struct Event
  {
    double Key;
    int Id;   // window id, or -(vertex + 1)
    double D; // vertex events: distance when pushed (stale check); windows: WindowKey
    bool operator<(const Event& o) const { return this->Key > o.Key; }
  };

  void Prepare();
  void ResetMarks();
  void Relax(int v, double d, int kind, int parent, int arrival);
  bool Dominated(const Window& w, const std::array<int, 2>& ev, double length) const;
  static double EdgeSampleAt(double length, int j);
  bool TrimOnEdge(Window& w, const std::array<int, 2>& ev, double length) const;
  void RecordOnEdge(const Window& w, double length);
  void AddWindow(const Window& w);
  void AddWindowOnEdge(Window w,
    const std::array<int, 2>& ev,
    const Vec3& p0,
    const Vec3& p1,
    double length);
  double WindowKey(const Window& w, const Vec3& p0, const Vec3& p1, double length) const;
  Window WholeEdgeWindow(int edge,
    int face,
    int origin,
    const Vec3& point,
    double sigma,
    int kind,
    int parent) const;
  void Propagate(int id);
  bool PieceWindow(const Event& e);
  void EmitFromVertex(int v);
  struct ShadowCorner
  {
    int Corner;      // 3 t + k: v is corner k of triangle t
    double From, To; // angles of the shadow inside the corner, from its side towards k + 1
  };
  void EmitAcrossOpposite(int v, int t, int k, const Vec3& pv, double d, double from, double to);
  bool ShadowFan(int v, std::vector<ShadowCorner>& corners) const;
  bool BackAngle(int v, int t0, int k0, double& angle) const;
  bool Backtrack(std::vector<int>& strip);
  bool FanWalk(int v, int from, int to, std::vector<int>& out) const;
  void OfferTarget(double length, int kind, int id);
  void SeedFromPoint(const CanonicalPoint& source, const std::vector<int>& triangles);
  bool Run(const std::vector<int>& endTriangles);
  void LinkToEdge(int id);
  void PrepareField();
  void AddFaceSource(int face, const Vec3& a, const Vec3& b);
  void AddLineSource(const CanonicalPoint& a, const CanonicalPoint& b);
  bool StraightCrossing(const std::vector<CanonicalPoint>& curve, size_t i, bool closed) const;
  double WindowDistanceAt(const Window& w, double b) const;

  const TriangleMesh& Mesh;
  bool Prepared = false;

public:
  struct PseudoSources; // per vertex: saddle or boundary vertex, decided on first use

private:
  std::shared_ptr<const PseudoSources> PseudoSource; // shared by the searches on one mesh
  int MaximumWindows = 1 << 20;
  bool Pruning = true;
  bool BudgetExceeded = false;
  double UpperBound = 0.0;
  // Queue order of windows. Without a known path, by the lower bound of any path through the
  // window (WindowKey): the target is reached, and the search ends, soonest. With an upper
  // bound the search must visit every window below it anyway; there the looser key, closer
  // to distance order, settles vertices earlier and their labels filter more windows (one of
  // torus.ply's far pairs needs 2^18 windows or more in bound order, fewer in the looser one).
  bool OrderByBound = true;

  // Per-vertex labels, valid where Stamp == CurrentStamp, side by side in one array (zero
  // pages: a search's memory is the part of the mesh it reaches). Five arrays, one per field,
  // put a labelled vertex on five pages and five cache lines: with a region's vertex ids in
  // runs (rows of a scan), a search touched about five times the pages (some 10 MB per solver
  // on ten short legs' worth of a 4.3M-triangle mesh).
  struct VertexLabel
  {
    double Distance;
    int Kind;
    int Parent;
    int Arrival;
    std::uint32_t Stamp;
  };
  ZeroPageArray<VertexLabel> Labels;
  ZeroPageArray<std::uint32_t> EndMark; // == CurrentStamp: triangle holds the end point
  // The shortest distance kept windows gave at EdgeSamples evenly spaced interior points of
  // each edge they lit (see TrimOnEdge), in a pool the next search empties: EdgeSlot is the
  // edge's entry plus one (0: none), so a search touches 4 bytes per edge it reaches.
  static constexpr int EdgeSamples = 7;
  // Trimming costs about a fifth more per window. It pays on scans full of saddles (a search
  // 15-35 % faster on face, kitten and stanford-bunny) but not on the legs of up to 2^15
  // windows that the Bounded method runs (the random SVG benchmark's p90 on igea_1m and
  // 3torus_800k: 10 % slower than without it), so it starts once a search is past that: in
  // the Exact method's searches and the refinements of routed legs.
  static constexpr int TrimAfterWindows = 1 << 15;
  struct EdgeSampleSlot
  {
    int Edge;
    double D[EdgeSamples];
  };
  ZeroPageArray<int> EdgeSlot;
  std::vector<EdgeSampleSlot> SamplePool;
  std::uint32_t CurrentStamp = 0;

  std::vector<Window> Windows;
  std::vector<Event> Heap;
  Vec3 Target;
  CanonicalPoint End;
  int ForcedVertex = -1; // the start, when it is a vertex: a source whatever its angle
  Vec3 StartPoint;       // the start, when it is not a vertex (HasStartPoint)
  bool HasStartPoint = false;
  std::vector<ShadowCorner> ShadowTriangles; // EmitFromVertex's, kept for its memory
  double Best = 0;
  int BestKind = -1, BestId = -1;
  int LastVertexCount = 0;

  // Distance field mode: no target, every window kept per edge for reading the field.
  bool FieldMode = false;
  std::vector<std::uint32_t> ForcedMark;           // == CurrentStamp: a source vertex
  std::vector<int> EdgeHead, WindowNext;           // windows per edge, linked (valid where stamped)
  std::vector<std::uint32_t> EdgeStamp;            //
  std::vector<int> FaceSourceHead, FaceSourceNext; // sources inside or on each triangle
  std::vector<std::uint32_t> FaceStamp;            //
  // The field's sources as segments (a point source is a segment of length 0).
  std::vector<std::array<Vec3, 2>> FieldSources;
  std::vector<int> FieldVertices;
  std::function<bool(int)> Allowed;
  // A part of a surface (SetPieceTriangles): the triangles read, and the walls.
  std::function<bool(int)> PieceExact;
  double WallSlack = 0.0;
  bool StoppedAtWall = false;
  double WallKey = 0.0;
  std::vector<int> PieceRead;
};

} // namespace boolsurf

#endif

#include "Arrangement/Arrangement.h"
#include "Arrangement/ArrangementOfRuns.h"

#include "Arrangement/EditBuffers.h"

#include "Arrangement/SegmentIntersection.h"
#include "Arrangement/TriangleRefinement.h"
#include "Arrangement/TriangleSegments.h"
#include "Mesh/ParallelRange.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>

namespace boolsurf
{
namespace
{

using Clock = std::chrono::steady_clock;

// Triangles per tile of the flood fill: small enough that curves leave most tiles clean (a
// curve crosses about the tile's diameter, ~8 triangles, per tile it enters), large enough
// that clean tiles cost little next to their triangles.
constexpr int TileSize = 64;

double Milliseconds(Clock::time_point from, Clock::time_point to)
{
  return std::chrono::duration<double, std::milli>(to - from).count();
}

} // namespace

//------------------------------------------------------------------------------
struct Arrangement::WorkBuffers
{
  /// The mesh the per-triangle and per-edge buffers below are sized for and clean on (0: none
  /// yet, or a call stopped before it could say).
  std::uint64_t MeshSerial = 0;
  TriangleSegmentMap Map;
  std::vector<LocalArrangement> Local;
  std::vector<std::vector<int>> EdgeSegmentPoints;
  std::vector<int> NewPointBase, SlotOfSegment;
  /// Per segment inside a triangle (map.Segments order): its refined points' global ids, at
  /// ChainPointIds[ChainOffset[g] .. ChainOffset[g + 1]). Written by the pass that numbers a
  /// triangle's points, while they are in cache; reading them from the triangles' own chains
  /// when the curves are assembled was mostly cache misses on large meshes.
  std::vector<int> ChainOffset, ChainPointIds;
  ZeroPageVector<char> State, MeshEdgeHasBlocked;
  /// Triangles and mesh edges whose State / MeshEdgeHasBlocked entries the
  /// last call set: reset at the next call instead of clearing whole-mesh arrays.
  std::vector<int> TouchedTriangles, TouchedEdges;
  std::unordered_set<std::uint64_t> BlockedMeshSubEdges;
  ZeroPageVector<unsigned char> Blocked;
  std::vector<std::array<int, 3>> PieceAcross;
  std::vector<EdgeIndex> CrowdedHalfEdges; ///< per slot, see RefinedSurfaceView
  std::shared_ptr<MeshTiles> Tiles;
  TileFloodBuffers Flood;
  PatchGraphBuffers PatchGraph;
  std::vector<RefinedCurve> RefinedCurves;
};

namespace
{

//------------------------------------------------------------------------------
// Before the stages: the results cleared, keeping their capacity (the next edit needs about as
// much), and the per-triangle and per-edge buffers made clean for this mesh.
void ResetResultsAndBuffers(const TriangleMesh& mesh,
  Arrangement& out,
  Arrangement::WorkBuffers& work)
{
  const int nt = mesh.GetNumberOfTriangles();
  // The work buffers may be shared by several arrangements (a filter that double-buffers its
  // results computes them in turn): whether they belong to this mesh, and whether this result's
  // refined slots index this mesh's triangles (LayoutMeshSerial, below), are two questions.
  const bool sameMesh = work.MeshSerial != 0 && work.MeshSerial == mesh.GetSerial();
  // Results are cleared, keeping their capacity (the next edit needs about as much).
  // RefinedSlot keeps its contents: an edit on the same mesh only rewrites the entries curves
  // crossed before or cross now.
  out.NumberOfCells = 0;
  out.NumberOfRefinedSourceTriangles = 0;
  out.Patches.clear();
  out.CellGraph.clear();
  out.NumberOfPatchGraphVertices = 0;
  out.CurvePoints.clear();
  out.CurveStations.clear();
  out.Times = ArrangementStageTimes();
  if (!sameMesh)
  {
    // Fresh zero pages: an edit writes the entries of the triangles and edges curves touch.
    AssignFreshZeroPages(work.State, nt);
    AssignFreshZeroPages(work.MeshEdgeHasBlocked, mesh.GetNumberOfEdges());
  }
  else
  {
    for (int t : work.TouchedTriangles)
    {
      work.State[t] = 0;
    }
    for (int e : work.TouchedEdges)
    {
      work.MeshEdgeHasBlocked[e] = 0;
    }
  }
  work.TouchedTriangles.clear();
  work.TouchedEdges.clear();
  work.MeshSerial = 0; // until the buffers are known clean again
}
//------------------------------------------------------------------------------
// Stage 2: the crossings of the segments inside each triangle, and the points splitting the
// segments that run along mesh edges.
void IntersectSegments(const TriangleMesh& mesh,
  const std::vector<TracedCurve>& curves,
  Arrangement::WorkBuffers& work,
  tbb::task_arena& arena)
{
  const TriangleSegmentMap& map = work.Map;
  const int slots = static_cast<int>(map.Triangles.size());
  std::vector<LocalArrangement>& local = work.Local;
  local.resize(slots);
  ParallelFor(
    arena, slots, [&](int s) { IntersectTriangleSegments(mesh, map, curves, s, local[s]); });
  std::vector<std::vector<int>>& edgeSegmentPoints = work.EdgeSegmentPoints;
  edgeSegmentPoints.resize(map.EdgeSegments.size());
  ParallelFor(arena,
    static_cast<int>(map.EdgeSegments.size()),
    [&](int i) { SplitEdgeSegment(mesh, map, i, edgeSegmentPoints[i]); });
}
//------------------------------------------------------------------------------
// Stage 3a: each crossed triangle's local triangulation (see TriangleRefinement).
bool RefineTriangles(const TriangleMesh& mesh,
  const std::vector<TracedCurve>& curves,
  Arrangement::WorkBuffers& work,
  tbb::task_arena& arena,
  std::string& error)
{
  const TriangleSegmentMap& map = work.Map;
  const int slots = static_cast<int>(map.Triangles.size());
  std::vector<LocalArrangement>& local = work.Local;
  ParallelFor(arena,
    slots,
    [&](int s)
    {
      if (!RefineTriangle(local[s]))
      {
        // Merging near points bent pieces across each other (SegmentIntersection.h): cut
        // this triangle again exactly, which the refinement always triangulates.
        IntersectTriangleSegments(mesh, map, curves, s, local[s], 0.0);
        RefineTriangle(local[s]);
      }
    });
  for (int s = 0; s < slots; ++s)
  {
    if (!local[s].Error.empty())
    {
      error = "arrangement failed in " + local[s].Error;
      return false;
    }
  }
  return true;
}
//------------------------------------------------------------------------------
// Stage 3b: global ids for the new points (after the mesh vertices: the edge points, then each
// triangle's own), their positions, and each segment's chain of refined point ids.
void NumberRefinedPoints(const TriangleMesh& mesh,
  Arrangement::WorkBuffers& work,
  Arrangement& out,
  tbb::task_arena& arena)
{
  const int nv = mesh.GetNumberOfVertices();
  const TriangleSegmentMap& map = work.Map;
  const int slots = static_cast<int>(map.Triangles.size());
  std::vector<LocalArrangement>& local = work.Local;
  const int edgePoints = static_cast<int>(map.EdgePoints.size());
  std::vector<int>& newPointBase = work.NewPointBase;
  newPointBase.assign(slots + 1, nv + edgePoints);
  for (int s = 0; s < slots; ++s)
  {
    newPointBase[s + 1] = newPointBase[s] + local[s].NumberOfNewPoints;
  }
  const int totalPoints = newPointBase[slots];
  std::vector<int>& chainOffset = work.ChainOffset;
  chainOffset.assign(map.Segments.size() + 1, 0);
  for (int s = 0; s < slots; ++s)
  {
    const std::vector<std::vector<int>>& chains = local[s].Chains;
    for (size_t c = 0; c < chains.size(); ++c)
    {
      chainOffset[map.SegmentOffset[s] + c + 1] = static_cast<int>(chains[c].size());
    }
  }
  for (size_t g = 0; g < map.Segments.size(); ++g)
  {
    chainOffset[g + 1] += chainOffset[g];
  }
  std::vector<int>& chainPointIds = work.ChainPointIds;
  chainPointIds.resize(chainOffset.back());
  // Mesh vertices keep their ids and are not stored: the curves' points follow them.
  ResizeForEdits(out.CurvePositions, totalPoints - nv);
  ResizeForEdits(out.CurvePointOnMesh, totalPoints - nv);
  ResizeForEdits(out.CurvePointSurface, totalPoints - nv);
  out.NumberOfMeshVertices = nv;
  work.MeshSerial = mesh.GetSerial();
  ParallelFor(arena,
    edgePoints,
    [&](int i)
    {
      CanonicalPoint c;
      c.Location = PointLocation::Edge;
      c.Id = map.EdgePoints[i].Edge;
      c.T = map.EdgePoints[i].T;
      out.CurvePositions[i] = PositionOf(mesh, c);
      out.CurvePointOnMesh[i] = c;
      out.CurvePointSurface[i] = ToSurfacePoint(mesh, c);
    });
  ParallelFor(arena,
    slots,
    [&](int s)
    {
      LocalArrangement& a = local[s];
      int next = newPointBase[s];
      for (size_t i = 0; i < a.Points.size(); ++i)
      {
        LocalPoint& p = a.Points[i];
        if (p.Where >= 0 || a.Alias[i] != static_cast<int>(i))
        {
          continue;
        }
        p.Global = next++;
        CanonicalPoint c;
        c.Location = PointLocation::Face;
        c.Id = a.Triangle;
        c.U = p.P.x;
        c.V = p.P.y;
        out.CurvePositions[p.Global - nv] = mesh.Evaluate(a.Triangle, c.U, c.V);
        out.CurvePointOnMesh[p.Global - nv] = c;
        out.CurvePointSurface[p.Global - nv] = { a.Triangle, c.U, c.V };
      }
      for (size_t i = 0; i < a.Points.size(); ++i)
      {
        a.Points[i].Global = a.Points[a.Alias[i]].Global;
      }
      int* ids = chainPointIds.data();
      for (size_t c = 0; c < a.Chains.size(); ++c)
      {
        int k = chainOffset[map.SegmentOffset[s] + c];
        for (int p : a.Chains[c])
        {
          ids[k++] = a.Points[p].Global;
        }
      }
    });
}
//------------------------------------------------------------------------------
// Stage 3c: per source triangle, its state for the flood fill (refined, or next to a closed
// curve running along one of its edges), and the mesh sub-edges closed curves block.
void MarkRefinedAndBlocked(const TriangleMesh& mesh,
  const std::vector<TracedCurve>& curves,
  Arrangement::WorkBuffers& work)
{
  const TriangleSegmentMap& map = work.Map;
  const int slots = static_cast<int>(map.Triangles.size());
  const std::vector<std::vector<int>>& edgeSegmentPoints = work.EdgeSegmentPoints;
  ZeroPageVector<char>& state = work.State;
  for (int s = 0; s < slots; ++s)
  {
    state[map.Triangles[s]] = RefinedSurfaceView::RefinedBit;
    work.TouchedTriangles.push_back(map.Triangles[s]);
  }
  std::unordered_set<std::uint64_t>& blockedMeshSubEdges = work.BlockedMeshSubEdges;
  blockedMeshSubEdges.clear();
  ZeroPageVector<char>& meshEdgeHasBlocked = work.MeshEdgeHasBlocked;
  for (size_t i = 0; i < map.EdgeSegments.size(); ++i)
  {
    const EdgeSegment& es = map.EdgeSegments[i];
    if (!curves[es.Curve].Closed)
    {
      continue;
    }
    meshEdgeHasBlocked[es.Edge] = 1;
    work.TouchedEdges.push_back(es.Edge);
    const int h = mesh.GetEdgeHalfEdge(es.Edge);
    state[h / 3] |= RefinedSurfaceView::BlockedEdgeBit;
    work.TouchedTriangles.push_back(h / 3);
    const int twin = mesh.GetTwin(h);
    if (twin >= 0)
    {
      state[twin / 3] |= RefinedSurfaceView::BlockedEdgeBit;
      work.TouchedTriangles.push_back(twin / 3);
    }
    const std::vector<int>& ids = edgeSegmentPoints[i];
    for (size_t k = 0; k + 1 < ids.size(); ++k)
    {
      blockedMeshSubEdges.insert(UndirectedPointPair(ids[k], ids[k + 1]));
    }
  }
}
//------------------------------------------------------------------------------
// Stage 3d: the refined surface's layout: the pieces of the refined triangles, their sources,
// blocked sides and neighbours.
bool LayOutRefinedPieces(const TriangleMesh& mesh,
  Arrangement::WorkBuffers& work,
  Arrangement& out,
  tbb::task_arena& arena,
  std::string& error)
{
  const int nt = mesh.GetNumberOfTriangles();
  const TriangleSegmentMap& map = work.Map;
  const int slots = static_cast<int>(map.Triangles.size());
  const std::vector<LocalArrangement>& local = work.Local;
  // The refined triangles: the mesh's own, in place (read from the mesh), then the extra pieces
  // of the refined ones. On the mesh of the previous call only the slots it refined are cleared
  // and those this call refines written, so an edit costs what the curves cross, not the
  // mesh's size.
  const bool layoutKept = out.LayoutMeshSerial != 0 && out.LayoutMeshSerial == mesh.GetSerial() &&
    static_cast<int>(out.RefinedSlot.size()) == nt;
  out.LayoutMeshSerial = 0; // until the layout is consistent again
  std::vector<int>& pieceOffset = out.PieceOffset;
  pieceOffset.resize(slots + 1);
  pieceOffset[0] = nt;
  for (int s = 0; s < slots; ++s)
  {
    if (local[s].Triangles.empty())
    {
      error = "internal error: triangle " + std::to_string(local[s].Triangle) +
        " was refined into no triangle";
      return false;
    }
    pieceOffset[s + 1] = pieceOffset[s] + static_cast<int>(local[s].Triangles.size()) - 1;
  }
  const int refinedCount = pieceOffset[slots];
  ResizeForEdits(out.FirstPieces, slots);
  ResizeForEdits(out.AppendedPieces, refinedCount - nt);
  ResizeForEdits(out.AppendedSources, refinedCount - nt);
  ZeroPageVector<int>& refinedSlot = out.RefinedSlot;
  if (!layoutKept)
  {
    AssignFreshZeroPages(refinedSlot, nt); // no triangle refined
    out.NumberOfHoles = 0;
    for (int t = 0; t < nt; ++t)
    {
      out.NumberOfHoles += !mesh.IsUsable(t);
    }
  }
  else
  {
    for (int t : out.RefinedSources)
    {
      refinedSlot[t] = 0;
    }
  }
  out.NumberOfMeshTriangles = nt;
  out.RefinedSources.assign(map.Triangles.begin(), map.Triangles.end());
  for (int s = 0; s < slots; ++s)
  {
    refinedSlot[map.Triangles[s]] = s + 1;
  }
  // Per refined triangle, the sides that closed curves run along inside its source triangle:
  // read only for pieces of refined triangles, so only those are written.
  // And what lies across each piece's edges (RefinedSurfaceView::PieceAcross), found here
  // from the local triangulation, where the points' places on the triangle are known, with
  // the half-edge index of crowded triangles (CrowdedHalfEdges).
  ZeroPageVector<unsigned char>& blocked = work.Blocked;
  ResizeDiscardingForEdits(blocked, refinedCount); // pieces' entries are rewritten below
  std::vector<std::array<int, 3>>& pieceAcross = work.PieceAcross;
  ResizeForEdits(pieceAcross, refinedCount - nt + slots);
  work.CrowdedHalfEdges.resize(slots);
  ParallelFor(arena,
    slots,
    [&](int s)
    {
      const LocalArrangement& a = local[s];
      const int t = a.Triangle;
      const auto piece = [&](int i) { return i == 0 ? t : pieceOffset[s] + i - 1; };
      thread_local std::vector<Triangle> pieces;
      pieces.resize(a.Triangles.size());
      for (size_t i = 0; i < a.Triangles.size(); ++i)
      {
        const int r = piece(static_cast<int>(i));
        for (int j = 0; j < 3; ++j)
        {
          pieces[i][j] = a.Points[a.Triangles[i][j]].Global;
        }
        if (i == 0)
        {
          out.FirstPieces[s] = pieces[0];
        }
        else
        {
          out.AppendedPieces[r - nt] = pieces[i];
          out.AppendedSources[r - nt] = t;
        }
        blocked[r] = a.Blocked[i];
      }
      const auto edgeBits = [&](int i, int j)
      { return a.Points[a.Alias[a.Triangles[i][j]]].Sides(); };
      SetPieceNeighbors(static_cast<int>(a.Triangles.size()),
        piece,
        pieces.data(),
        edgeBits,
        &pieceAcross[pieceOffset[s] - nt + s],
        work.CrowdedHalfEdges[s]);
    });
  out.LayoutMeshSerial = mesh.GetSerial();
  out.NumberOfRefinedSourceTriangles = slots;
  return true;
}
//------------------------------------------------------------------------------
// What the flood fill and the cell graph read of the refined surface (pointers into `out` and
// `work`, valid until either changes).
RefinedSurfaceView ViewOfRefinedSurface(const TriangleMesh& mesh,
  const Arrangement::WorkBuffers& work,
  const Arrangement& out)
{
  RefinedSurfaceView view;
  view.Mesh = &mesh;
  view.SlotOfTriangle = &out.RefinedSlot;
  view.PieceOffset = &out.PieceOffset;
  view.Layout = &out;
  view.Refined = &work.State;
  view.Blocked = &work.Blocked;
  view.BlockedMeshSubEdges = &work.BlockedMeshSubEdges;
  view.MeshEdgeHasBlocked = &work.MeshEdgeHasBlocked;
  view.CrowdedHalfEdges = &work.CrowdedHalfEdges;
  view.PieceAcross = &work.PieceAcross;
  return view;
}

//------------------------------------------------------------------------------
// Stage 4: the cells, by flood fill over the mesh's tiles and the refined triangles.
void FloodFillCells(const TriangleMesh& mesh,
  const RefinedSurfaceView& view,
  const ArrangementOptions& options,
  Arrangement::WorkBuffers& work,
  Arrangement& out,
  tbb::task_arena& arena)
{
  // Tiles of the mesh: built once per mesh (the persistent part of the dual graph); an edit
  // floods clean tiles as single nodes and only the triangles of tiles that curves touch.
  if (!work.Tiles || work.Tiles->MeshSerial != mesh.GetSerial() || mesh.GetSerial() == 0)
  {
    work.Tiles = std::make_shared<MeshTiles>();
    BuildMeshTiles(mesh, TileSize, *work.Tiles);
  }
  out.Tiles = work.Tiles;
  work.Flood.Method = options.FloodFill;
  arena.execute(
    [&]
    {
      out.NumberOfCells = FloodFillCellsByTiles(view,
        *work.Tiles,
        work.TouchedTriangles,
        out.TileCell,
        out.LooseCell,
        &out.CellFirstTriangle,
        work.Flood,
        &out.Contents);
    });
}

//------------------------------------------------------------------------------
// Stage 5a: each curve as a chain of refined points, with its stations (the traced segment and
// the fraction along it of each point).
bool AssembleRefinedCurves(const TriangleMesh& mesh,
  const std::vector<TracedCurve>& curves,
  Arrangement::WorkBuffers& work,
  Arrangement& out,
  tbb::task_arena& arena,
  std::string& error)
{
  const TriangleSegmentMap& map = work.Map;
  const int slots = static_cast<int>(map.Triangles.size());
  const std::vector<std::vector<int>>& edgeSegmentPoints = work.EdgeSegmentPoints;
  const std::vector<int>& chainOffset = work.ChainOffset;
  const std::vector<int>& chainPointIds = work.ChainPointIds;
  std::vector<int>& slotOfSegment = work.SlotOfSegment;
  slotOfSegment.resize(map.Segments.size());
  for (int s = 0; s < slots; ++s)
  {
    for (int g = map.SegmentOffset[s]; g < map.SegmentOffset[s + 1]; ++g)
    {
      slotOfSegment[g] = s;
    }
  }
  // Each curve's refined points and stations, curves in parallel: the pieces' chains were
  // written by other threads in the refinement, so reading them is mostly cache misses
  // (about a millisecond for ten circles on 1M triangles, serially).
  std::vector<RefinedCurve>& refinedCurves = work.RefinedCurves;
  refinedCurves.resize(curves.size());
  out.CurvePoints.resize(curves.size());
  out.CurveStations.resize(curves.size());
  std::vector<std::string> curveErrors(curves.size());
  ParallelFor(arena,
    static_cast<int>(curves.size()),
    [&](int ci)
    {
      RefinedCurve& rc = refinedCurves[ci];
      std::vector<double>& stations = out.CurveStations[ci];
      rc.Points.clear();
      rc.SubEdgeSource.clear();
      stations.clear();
      std::vector<int> ids;
      for (const SegmentLocation& loc : map.CurveSegments[ci])
      {
        int source, traced;
        ids.clear();
        if (loc.AlongEdge)
        {
          ids = edgeSegmentPoints[loc.Index];
          source = -map.EdgeSegments[loc.Index].Edge - 1;
          traced = map.EdgeSegments[loc.Index].Segment;
        }
        else
        {
          ids.assign(chainPointIds.begin() + chainOffset[loc.Index],
            chainPointIds.begin() + chainOffset[loc.Index + 1]);
          source = map.Triangles[slotOfSegment[loc.Index]];
          traced = map.Segments[loc.Index].Segment;
        }
        size_t from = 0;
        if (!rc.Points.empty())
        {
          if (rc.Points.back() != ids.front())
          {
            curveErrors[ci] = "internal error: curve " + std::to_string(ci) + " is not continuous";
            return;
          }
          from = 1;
        }
        // The traced segment is straight on its triangle or edge: the fraction of its length
        // is the fraction of the way between its two traced points.
        const Vec3 first = out.GetPosition(mesh, ids.front());
        const double whole = Distance(first, out.GetPosition(mesh, ids.back()));
        for (size_t k = from; k < ids.size(); ++k)
        {
          rc.Points.push_back(ids[k]);
          const double f = k + 1 == ids.size()
            ? 1.0
            : (whole > 0 ? std::min(1.0, Distance(first, out.GetPosition(mesh, ids[k])) / whole)
                         : 0.0);
          stations.push_back(k == 0 ? traced : traced + f);
        }
        rc.SubEdgeSource.insert(rc.SubEdgeSource.end(), ids.size() - 1, source);
      }
      if (curves[ci].Closed && rc.Points.size() > 1 && rc.Points.front() == rc.Points.back())
      {
        rc.Points.pop_back();
        stations.pop_back();
      }
      out.CurvePoints[ci] = rc.Points;
    });
  for (const std::string& curveError : curveErrors)
  {
    if (!curveError.empty())
    {
      error = curveError;
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
// The stages in order, timed: the segment map, the crossings, the refinement (local
// triangulations, point numbering, blocked edges, piece layout), the flood fill into cells,
// and the curves on the refined surface with the patches and the cell graph.
// `bounding`: the curves as the refinement and the blocked edges read them, whose Closed says
// which bound cells (the curves themselves, or ComputeArrangementOfRuns' copy).
bool ComputeArrangementBoundedBy(const TriangleMesh& mesh,
  const std::vector<TracedCurve>& curves,
  const std::vector<TracedCurve>& bounding,
  const ArrangementOptions& options,
  Arrangement& out,
  std::string& error)
{
  error.clear();
  if (!out.Work)
  {
    out.Work = std::make_shared<Arrangement::WorkBuffers>();
  }
  Arrangement::WorkBuffers& work = *out.Work;
  ResetResultsAndBuffers(mesh, out, work);
  tbb::task_arena arena(options.Threads > 0 ? options.Threads : tbb::task_arena::automatic);
  const Clock::time_point start = Clock::now();

  // --- 1. hash map triangle -> segments
  CurvePointRef failed;
  out.FailedCurve = out.FailedPoint = -1;
  bool mapped = false;
  arena.execute([&] { mapped = BuildTriangleSegmentMap(mesh, curves, work.Map, error, &failed); });
  if (!mapped)
  {
    out.FailedCurve = failed.Curve;
    out.FailedPoint = failed.Point;
    return false;
  }
  const Clock::time_point hashed = Clock::now();

  // --- 2. intersections
  IntersectSegments(mesh, bounding, work, arena);
  const Clock::time_point intersected = Clock::now();

  // --- 3. refinement, then assembly of the refined surface
  if (!RefineTriangles(mesh, bounding, work, arena, error))
  {
    return false;
  }
  NumberRefinedPoints(mesh, work, out, arena);
  MarkRefinedAndBlocked(mesh, bounding, work);
  if (!LayOutRefinedPieces(mesh, work, out, arena, error))
  {
    return false;
  }
  const Clock::time_point refinedTime = Clock::now();

  // --- 4. flood fill
  const RefinedSurfaceView view = ViewOfRefinedSurface(mesh, work, out);
  FloodFillCells(mesh, view, options, work, out, arena);
  const Clock::time_point filled = Clock::now();

  // --- 5. curves on the refined surface, patches, cell graph
  if (!AssembleRefinedCurves(mesh, curves, work, out, arena, error))
  {
    return false;
  }
  out.NumberOfPatchGraphVertices = BuildPatchesAndCellGraph(view,
    curves,
    work.RefinedCurves,
    out.CurvePositions,
    out.CurvePointSurface,
    out.GetCellLookup(),
    out.Patches,
    out.CellGraph,
    &work.PatchGraph);
  const Clock::time_point done = Clock::now();

  out.Times.Hash = Milliseconds(start, hashed);
  out.Times.Intersections = Milliseconds(hashed, intersected);
  out.Times.Refinement = Milliseconds(intersected, refinedTime);
  out.Times.FloodFill = Milliseconds(refinedTime, filled);
  out.Times.CellGraph = Milliseconds(filled, done);
  out.Times.Total = Milliseconds(start, done);
  return true;
}

} // namespace

//------------------------------------------------------------------------------
bool ComputeArrangement(const TriangleMesh& mesh,
  const std::vector<TracedCurve>& curves,
  const ArrangementOptions& options,
  Arrangement& out,
  std::string& error)
{
  return ComputeArrangementBoundedBy(mesh, curves, curves, options, out, error);
}

//------------------------------------------------------------------------------
bool ComputeArrangementOfRuns(const TriangleMesh& mesh,
  const std::vector<TracedCurve>& curves,
  const std::vector<char>& cutFromClosed,
  const ArrangementOptions& options,
  Arrangement& out,
  std::string& error)
{
  std::vector<TracedCurve> bounding = curves;
  for (size_t c = 0; c < bounding.size() && c < cutFromClosed.size(); ++c)
  {
    bounding[c].Closed = bounding[c].Closed || cutFromClosed[c] != 0;
  }
  return ComputeArrangementBoundedBy(mesh, curves, bounding, options, out, error);
}

//------------------------------------------------------------------------------
void UpdateTriangleCells(const Arrangement& arr,
  std::vector<int>& cells,
  WrittenTriangleCells& written,
  int threads)
{
  const int count = arr.GetNumberOfTriangles();
  const MeshTiles* tiles = arr.Tiles.get();
  const int nt = arr.NumberOfMeshTriangles;
  if (!tiles || tiles->MeshSerial == 0 || written.TilesSerial != tiles->MeshSerial ||
    written.TileCell.size() != arr.TileCell.size() || static_cast<int>(cells.size()) < nt)
  {
    WriteTriangleCells(arr, cells, threads);
    written.TilesSerial = tiles ? tiles->MeshSerial : 0;
    written.TileCell = arr.TileCell;
    return;
  }
  written.TilesSerial = 0; // until consistent again
  ResizeForEdits(cells, count);
  const TriangleCellLookup lookup = arr.GetCellLookup();
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  ParallelRange(
    arena,
    tiles->GetNumberOfTiles(),
    [&](int k)
    {
      const int now = arr.TileCell[k];
      if (now >= 0 && written.TileCell[k] == now)
      {
        return; // clean then and now, in the same cell: its entries already hold it
      }
      for (int m = tiles->Offset[k]; m < tiles->Offset[k + 1]; ++m)
      {
        cells[tiles->Members[m]] = lookup(tiles->Members[m]);
      }
      written.TileCell[k] = now;
    },
    256);
  for (int r = nt; r < count; ++r)
  {
    cells[r] = lookup(r);
  }
  written.TilesSerial = tiles->MeshSerial;
}

//------------------------------------------------------------------------------
void WriteTriangleCells(const Arrangement& arr, std::vector<int>& cells, int threads)
{
  const int count = arr.GetNumberOfTriangles();
  ResizeForEdits(cells, count);
  const TriangleCellLookup lookup = arr.GetCellLookup();
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  ParallelRange(arena, count, [&](int r) { cells[r] = lookup(r); });
}

} // namespace boolsurf

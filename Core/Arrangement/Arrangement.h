// The surface arrangement of a set of traced curves (BoolSurf, Riso et al. 2022, §4):
// the mesh refined so that every curve runs along its edges, the partition of the refined
// surface into cells bounded by closed curves, the curves cut into patches at their
// intersections, and the cell graph that the labeling stage walks.
//
// Stages (each in its own file, timed separately):
//  1. TriangleSegments     per-triangle hash map of curve segments, in unit-triangle coordinates
//  2. SegmentIntersection  crossings inside each triangle (exact predicates); edge segments
//                          split by canonical edge parameters
//  3. TriangleRefinement   a triangulation of each crossed triangle embedding its segments
//  4. CellPartition        flood fill over the dual graph of adjacencies
//  5. CellPartition        patches and the oriented cell graph
// Stages 2 and 3 run in parallel over triangles; results are assembled in triangle order, so
// the output does not depend on the number of threads.
#ifndef boolsurf_Arrangement_h
#define boolsurf_Arrangement_h

#include "Arrangement/CellPartition.h"
#include "Arrangement/RefinedTriangles.h"
#include "Geodesic/TracedCurve.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace boolsurf
{

struct ArrangementOptions
{
  int Threads = 0; ///< 0: all hardware threads
  /// Tiles (few tiles touched by curves), whole surface (most touched), or chosen per edit.
  FloodFillMethod FloodFill = FloodFillMethod::Automatic;
};

/// Wall-clock milliseconds per stage.
struct ArrangementStageTimes
{
  double Hash = 0, Intersections = 0, Refinement = 0, FloodFill = 0, CellGraph = 0, Total = 0;
};

/// The refined triangles are the RefinedTriangles base (the pieces of what curves cross; the
/// rest is the mesh's): read them with GetTriangle(mesh, r) and GetSourceTriangle(mesh, r).
struct Arrangement : RefinedTriangles
{
  // --- refined surface. Points: the mesh vertices (same ids), then the curve points on mesh
  // edges, then the new points inside triangles. Only the points past the mesh's vertices are
  // stored (entry p - NumberOfMeshVertices): read any point with GetPosition, GetPointOnMesh
  // and GetPointSurface.
  std::vector<Vec3> CurvePositions;
  /// Canonical surface point of each refined point past the mesh's vertices (a mesh vertex is
  /// its own canonical point, not stored: 32 bytes per vertex, 69 MB on 4.3M triangles).
  std::vector<CanonicalPoint> CurvePointOnMesh;
  /// Each refined point past the mesh's vertices as triangle + barycentric (u, v) (a mesh
  /// vertex's is derived from its corners, not stored: 24 bytes per vertex, 52 MB on 4.3M
  /// triangles).
  std::vector<SurfacePoint> CurvePointSurface;
  int NumberOfMeshVertices = 0; ///< refined points below it are the mesh's vertices
  int GetNumberOfPoints() const
  {
    return this->NumberOfMeshVertices + static_cast<int>(this->CurvePositions.size());
  }
  /// Position of refined point p, on the mesh this arrangement was computed on.
  Vec3 GetPosition(const TriangleMesh& mesh, int p) const
  {
    return p < this->NumberOfMeshVertices ? mesh.GetPosition(p)
                                          : this->CurvePositions[p - this->NumberOfMeshVertices];
  }
  /// Refined point p as triangle + barycentric, on the mesh this arrangement was computed on.
  SurfacePoint GetPointSurface(const TriangleMesh& mesh, int p) const
  {
    return p < this->NumberOfMeshVertices ? VertexSurfacePoint(mesh, p)
                                          : this->CurvePointSurface[p - this->NumberOfMeshVertices];
  }
  /// Canonical surface point of refined point p.
  CanonicalPoint GetPointOnMesh(int p) const
  {
    if (p < this->NumberOfMeshVertices)
    {
      CanonicalPoint c;
      c.Location = PointLocation::Vertex;
      c.Id = p;
      return c;
    }
    return this->CurvePointOnMesh[p - this->NumberOfMeshVertices];
  }
  /// Cells: per clean tile of the mesh (-1 for tiles curves touch), and per refined triangle
  /// for the others; entries of LooseCell for clean tiles' triangles are stale. Read them with
  /// CellOfTriangle(), or all at once with WriteTriangleCells().
  std::vector<int> TileCell;
  ZeroPageVector<int> LooseCell; ///< written only where cells are loose (ZeroPageVector)
  int NumberOfCells = 0;
  /// The lowest refined triangle of each cell (cells are numbered in this order).
  std::vector<int> CellFirstTriangle;
  /// Each cell's clean tiles of the mesh and loose refined triangles: its triangles, listed
  /// without scanning the mesh (see ForEachCellTriangle).
  CellContents Contents;
  /// The tiles of the mesh (built once per mesh, shared with the next edit).
  std::shared_ptr<const MeshTiles> Tiles;
  int NumberOfRefinedSourceTriangles = 0; ///< mesh triangles replaced by a triangulation

  // --- curves
  std::vector<ArrangementPatch> Patches;
  std::vector<CellGraphArc> CellGraph;
  /// Vertices of the patch graph: distinct patch end points (intersection points, the start
  /// of each closed curve that meets no other curve, the ends of open curves).
  int NumberOfPatchGraphVertices = 0;
  /// Each input curve on the refined surface (refined point ids in order).
  std::vector<std::vector<int>> CurvePoints;
  /// Where each point of CurvePoints lies on its traced curve: traced point index i plus the
  /// fraction of the way (by length) to traced point i + 1. Intersection points get fractions
  /// in between; this is how results are given back in the curves' own parameters.
  std::vector<std::vector<double>> CurveStations;

  ArrangementStageTimes Times;
  /// After a refusal: the curve (index into the curves) and traced point it is about, -1 when
  /// not about one, so callers can name the point as their user knows it.
  int FailedCurve = -1, FailedPoint = -1;

  /// The mesh whose triangles RefinedSlot indexes (0: none yet): an edit clears the entries
  /// the previous one refined and writes those it refines, instead of all of them.
  std::uint64_t LayoutMeshSerial = 0;

  /// Cell of refined triangle r (-1 for a hole).
  int CellOfTriangle(int r) const { return this->GetCellLookup()(r); }
  TriangleCellLookup GetCellLookup() const
  {
    TriangleCellLookup lookup;
    lookup.TileOfTriangle = this->Tiles ? this->Tiles->TileOfTriangle.data() : nullptr;
    lookup.TileCell = this->TileCell.data();
    lookup.LooseCell = this->LooseCell.data();
    lookup.NumberOfMeshTriangles = this->NumberOfMeshTriangles;
    return lookup;
  }

  /// Work buffers kept between calls: computing again into the same Arrangement (an edit of
  /// the curves on the same mesh) reuses every allocation. Nothing of the result is in them, so
  /// arrangements computed one after the other may share them (assign one's Work to another).
  struct WorkBuffers;
  std::shared_ptr<WorkBuffers> Work;
};

/// Calls f(r) for every refined triangle r of mesh triangle t (none for an unusable one), t
/// itself first, then its other pieces in order.
template <class F>
void ForEachRefinedTriangle(const TriangleMesh& mesh, const Arrangement& arr, int t, F f)
{
  const int s = arr.GetRefinedSlot(t);
  if (s < 0 && !mesh.IsUsable(t))
  {
    return;
  }
  f(t);
  if (s >= 0)
  {
    for (int r = arr.PieceOffset[s]; r < arr.PieceOffset[s + 1]; ++r)
    {
      f(r);
    }
  }
}

/// Number of refined triangles of mesh triangle t.
inline int CountRefinedTriangles(const TriangleMesh& mesh, const Arrangement& arr, int t)
{
  const int s = arr.GetRefinedSlot(t);
  return s >= 0 ? 1 + arr.PieceOffset[s + 1] - arr.PieceOffset[s] : (mesh.IsUsable(t) ? 1 : 0);
}

/// The cell of every refined triangle (-1 for holes), written in parallel: for outputs that
/// hand all of them over (the Surface Arrangement filter's ArrangementCell array).
void WriteTriangleCells(const Arrangement& arr, std::vector<int>& cells, int threads = 0);

/// What a per-triangle cell array written by UpdateTriangleCells holds for clean tiles.
struct WrittenTriangleCells
{
  std::uint64_t TilesSerial = 0; ///< MeshTiles::MeshSerial of the tiles (0: nothing written)
  std::vector<int> TileCell;     ///< per tile: the cell its triangles hold, -1 when not uniform
};

/// WriteTriangleCells for a `cells` array kept from edit to edit (the stage filter's output):
/// on the same mesh's tiles it rewrites only the triangles of tiles whose cell changed or that
/// curves touch (now or when last written) and the appended pieces; the result equals
/// WriteTriangleCells'.
void UpdateTriangleCells(const Arrangement& arr,
  std::vector<int>& cells,
  WrittenTriangleCells& written,
  int threads = 0);

/// Calls f(first, count) for each run of refined triangle ids first[0 .. count) making up cell
/// c: each clean tile's members (unrefined: refined index = mesh index), then the cell's loose
/// triangles.
template <class F>
void ForEachCellRun(const Arrangement& arr, int c, F f)
{
  const CellContents& in = arr.Contents;
  const MeshTiles& tiles = *arr.Tiles;
  for (int i = in.TileOffset[c]; i < in.TileOffset[c + 1]; ++i)
  {
    const int k = in.Tiles[i];
    f(tiles.Members.data() + tiles.Offset[k], tiles.Offset[k + 1] - tiles.Offset[k]);
  }
  f(in.Triangles.data() + in.TriangleOffset[c], in.TriangleOffset[c + 1] - in.TriangleOffset[c]);
}

/// Calls f(r) for every refined triangle r of cell c (clean tiles first, then loose triangles).
template <class F>
void ForEachCellTriangle(const Arrangement& arr, int c, F f)
{
  ForEachCellRun(arr,
    c,
    [&](const int* first, int count)
    {
      for (int i = 0; i < count; ++i)
      {
        f(first[i]);
      }
    });
}

/// Computes the arrangement into `out`, reusing its buffers (on failure its contents are
/// unspecified). Unusable mesh triangles (see
/// TriangleMesh::IsUsable) are left out of the refined surface. Fails, with a message naming the
/// curve and point, on invalid curve points or consecutive points that share no triangle; the mesh
/// must not be modified while `mesh` is in use (its adjacency is the base of the dual graph).
bool ComputeArrangement(const TriangleMesh& mesh,
  const std::vector<TracedCurve>& curves,
  const ArrangementOptions& options,
  Arrangement& out,
  std::string& error);

} // namespace boolsurf

#endif

// The distributed arrangement (Core/Distributed) on one process: a surface split into P slabs
// (owned triangles plus a ring of ghosts), each piece arranged alone and summarized, the
// summaries merged; against ComputeArrangement on the whole surface. Reports, per split:
//  * whole_ms: the whole-surface arrangement; piece_max_ms / piece_sum_ms: the pieces'
//    arrangements and summaries (the largest is what P processes would wait for);
//    restrict_max_ms: restricting the curves to a piece; merge_ms: the merge of the summaries;
//  * piece_bytes_max: the largest piece as received (positions, ids, triangles, ghost marks);
//    boundary_bytes_max: the largest piece's boundary records (sent to its neighbours);
//    to_merge_bytes_max / _total: what the pieces would send to the merge (cells, crossings,
//    the joins they matched with their neighbours);
//  * boundary_max: the largest piece's boundary sub-segments; same_cells: 1 when the merged
//    cells are as many as the whole surface's (the tests check every triangle's cell).
// Curves: ten plane sections (loops) of the mesh, outside the timed loop. The argument is P.
#include "Arrangement/Arrangement.h"
#include "Distributed/BoundaryJoins.h"
#include "Distributed/MergedArrangement.h"
#include "Distributed/PieceCurves.h"
#include "Distributed/PieceSummary.h"
#include "Mesh/ProceduralMeshes.h"
#include "SharedMeshes.h"
#include "Support/PieceSplits.h"
#include "Support/SyntheticCurves.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

using namespace boolsurf;

namespace
{

using Clock = std::chrono::steady_clock;

double Milliseconds(Clock::time_point from, Clock::time_point to)
{
  return std::chrono::duration<double, std::milli>(to - from).count();
}

std::vector<TracedCurve> TenSections(const TriangleMesh& mesh)
{
  Vec3 lo = mesh.GetPosition(0), hi = lo;
  for (const Vec3& p : mesh.GetPositions())
  {
    lo = { std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z) };
    hi = { std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z) };
  }
  const Vec3 center = 0.5 * (lo + hi);
  std::vector<TracedCurve> curves;
  for (int i = 0; i < 10; ++i)
  {
    const double a = 0.37 + 0.61 * i;
    Vec3 n{ std::cos(a), std::sin(a), 0.4 * std::cos(2.3 * a) };
    n = (1.0 / Length(n)) * n;
    for (TracedCurve& c : PlaneSectionCurves(mesh, n, Dot(n, center), i, 100 * i))
    {
      curves.push_back(std::move(c));
    }
  }
  return curves;
}

void RunPieces(benchmark::State& state, const std::string& name)
{
  const int pieces = static_cast<int>(state.range(0));
  std::unique_ptr<TriangleMesh> mesh;
  if (name == "torus_102k")
  {
    const MeshData d = MakeTorus(1.0, 0.35, 320, 160);
    mesh.reset(new TriangleMesh(d.Positions, d.Triangles));
  }
  else
  {
    std::string error;
    const MeshData* d = benchutil::LoadSharedMesh(name, error);
    if (!d)
    {
      state.SkipWithError(error.c_str());
      return;
    }
    mesh.reset(new TriangleMesh(d->Positions, d->Triangles));
  }
  const std::vector<TracedCurve> curves = TenSections(*mesh);
  Arrangement whole;
  std::string error;
  const auto w0 = Clock::now();
  if (!ComputeArrangement(*mesh, curves, ArrangementOptions(), whole, error))
  {
    state.SkipWithError(error.c_str());
    return;
  }
  const double wholeMs = Milliseconds(w0, Clock::now());
  const std::vector<int> owner = testing::SlabOwners(*mesh, pieces, 0);
  std::vector<PieceInput> inputs(pieces);
  double pieceBytesMax = 0;
  for (int p = 0; p < pieces; ++p)
  {
    inputs[p] = testing::MakePiece(*mesh, owner, p);
    const PieceInput& in = inputs[p];
    pieceBytesMax = std::max(pieceBytesMax,
      static_cast<double>(in.Positions.size() * (sizeof(Vec3) + sizeof(int)) +
        in.Triangles.size() * (sizeof(Triangle) + sizeof(int) + 1)));
  }
  const GlobalEdgeVertices edgeVertices = [&](int e) { return mesh->GetEdgeVertices(e); };
  std::vector<PieceMesh> meshes(pieces);
  for (int p = 0; p < pieces; ++p)
  {
    BuildPieceMesh(inputs[p], meshes[p], error);
  }
  std::vector<Arrangement> arrangements(pieces);
  std::vector<PieceSummary> summaries(pieces);
  MergedArrangement merged;
  double pieceMax = 0, pieceSum = 0, restrictMax = 0, mergeMs = 0;
  for (auto _ : state)
  {
    pieceMax = pieceSum = restrictMax = 0;
    for (int p = 0; p < pieces; ++p)
    {
      const auto t0 = Clock::now();
      PieceCurves local;
      RestrictCurvesToPiece(meshes[p], curves, edgeVertices, local);
      const auto t1 = Clock::now();
      ArrangePiece(meshes[p], local, ArrangementOptions(), arrangements[p], summaries[p], error);
      const auto t2 = Clock::now();
      restrictMax = std::max(restrictMax, Milliseconds(t0, t1));
      pieceMax = std::max(pieceMax, Milliseconds(t0, t2));
      pieceSum += Milliseconds(t0, t2);
    }
    const auto m0 = Clock::now();
    MergePieceSummaries(summaries, merged, error);
    mergeMs = Milliseconds(m0, Clock::now());
  }
  // What each piece would send: its boundary records to its neighbours (the owners of its
  // ghosts), then its cells, crossings and the joins it matched to the merge.
  double boundaryBytesMax = 0, toMergeMax = 0, toMergeTotal = 0, boundaryMax = 0;
  for (int p = 0; p < pieces; ++p)
  {
    std::vector<int> ids{ p };
    for (int g : meshes[p].GlobalTriangle)
    {
      ids.push_back(owner[g]);
    }
    std::sort(ids.begin() + 1, ids.end());
    ids.erase(std::unique(ids.begin() + 1, ids.end()), ids.end());
    ids.erase(std::remove(ids.begin() + 1, ids.end(), p), ids.end());
    std::vector<const PieceSummary*> given;
    for (int q : ids)
    {
      given.push_back(&summaries[q]);
    }
    BoundaryJoins joins;
    JoinPieceBoundaries(ids, given, p, joins, error);
    const PieceSummary& s = summaries[p];
    const double toMerge =
      static_cast<double>(s.GetBytes() - s.GetBoundaryBytes() + joins.GetBytes());
    toMergeMax = std::max(toMergeMax, toMerge);
    toMergeTotal += toMerge;
    boundaryBytesMax = std::max(boundaryBytesMax, static_cast<double>(s.GetBoundaryBytes()));
    boundaryMax = std::max(boundaryMax, static_cast<double>(s.Boundary.size()));
  }
  state.counters["triangles"] = mesh->GetNumberOfTriangles();
  state.counters["curve_points"] = [&]()
  {
    double n = 0;
    for (const TracedCurve& c : curves)
      n += static_cast<double>(c.Points.size());
    return n;
  }();
  state.counters["whole_ms"] = wholeMs;
  state.counters["piece_max_ms"] = pieceMax;
  state.counters["piece_sum_ms"] = pieceSum;
  state.counters["restrict_max_ms"] = restrictMax;
  state.counters["merge_ms"] = mergeMs;
  state.counters["piece_bytes_max"] = pieceBytesMax;
  state.counters["boundary_bytes_max"] = boundaryBytesMax;
  state.counters["to_merge_bytes_max"] = toMergeMax;
  state.counters["to_merge_bytes_total"] = toMergeTotal;
  state.counters["boundary_max"] = boundaryMax;
  state.counters["cells"] = merged.NumberOfCells;
  state.counters["same_cells"] = merged.NumberOfCells == whole.NumberOfCells ? 1 : 0;
}

} // namespace

BENCHMARK_CAPTURE(RunPieces, Torus102k, std::string("torus_102k"))
  ->Arg(1)
  ->Arg(2)
  ->Arg(4)
  ->Arg(8)
  ->Unit(benchmark::kMillisecond)
  ->Iterations(3);
BENCHMARK_CAPTURE(RunPieces, Igea1M, std::string("igea_1m.ply"))
  ->Arg(1)
  ->Arg(4)
  ->Arg(16)
  ->Unit(benchmark::kMillisecond)
  ->Iterations(1);

// The distributed arrangement (Core/Distributed): a surface split into pieces (owned triangles
// plus a ring of ghosts), each arranged alone and summarized, the summaries merged. Checked
// against ComputeArrangement on the whole surface: the same cells with the same numbering for
// every refined triangle, the same areas, the same cell graph and labels, on flat, spherical,
// toroidal and genus-2 surfaces split in slabs and in random regions (with an empty piece, a
// piece no curve touches, vertices shared by three or more pieces, curves along and across
// piece boundaries, a shape inside one piece).
#include "Distributed/BoundaryJoins.h"
#include "Distributed/MergedArrangement.h"
#include "Distributed/MergedLabeling.h"
#include "Distributed/PieceCurves.h"
#include "Distributed/PieceMesh.h"
#include "Distributed/PieceRegionBoundary.h"
#include "Distributed/PieceSelection.h"
#include "Distributed/PieceSummary.h"
#include "Distributed/PieceTileSums.h"

#include "Arrangement/Arrangement.h"
#include "Geodesic/CurveTracer.h"
#include "Labeling/ArrangementLabelingInput.h"
#include "Mesh/MeshTopology.h"
#include "Mesh/PlyReader.h"
#include "Mesh/ProceduralMeshes.h"
#include "Support/PieceRegions.h"
#include "Support/PieceSplits.h"
#include "Support/SourceTree.h"
#include "Support/SyntheticCurves.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <queue>
#include <random>
#include <set>

using namespace boolsurf;
using boolsurf::testing::CellAreas;
using boolsurf::testing::CompareRegionBoundaries;
using boolsurf::testing::CompareRegions;
using boolsurf::testing::MakePiece;
using boolsurf::testing::PieceRegionBySource;
using boolsurf::testing::RandomGeodesicCurves;
using boolsurf::testing::RefinedArea;
using boolsurf::testing::RegionOwners;
using boolsurf::testing::SlabOwners;
using boolsurf::testing::SourceShare;
using boolsurf::testing::SphereWithHoles;
using boolsurf::testing::TestBooleanOptions;
using boolsurf::testing::WholeRegionBySource;

namespace
{

/// The summary's cells read through the clean tiles' figures (PieceTileSums, as an edit on
/// pieces reads them, computed once and kept) are those read triangle by triangle: the same
/// cells and lowest triangles, areas summed in another order.
void ExpectTileSumsGiveTheSameCells(const PieceMesh& piece,
  const PieceCurves& curves,
  const Arrangement& arr,
  const PieceSummary& direct)
{
  PieceTileSums sums;
  for (int pass = 0; pass < 2; ++pass)
  {
    PieceSummary tiled;
    SummarizePiece(piece, curves, arr, tiled, &sums);
    ASSERT_EQ(tiled.Cells.size(), direct.Cells.size());
    for (std::size_t i = 0; i < direct.Cells.size(); ++i)
    {
      const PieceCell &a = tiled.Cells[i], &b = direct.Cells[i];
      EXPECT_EQ(a.LocalCell, b.LocalCell);
      EXPECT_EQ(a.Lowest, b.Lowest) << "cell " << b.LocalCell;
      EXPECT_NEAR(a.Area, b.Area, 1e-12 * std::max(1.0, b.Area)) << "cell " << b.LocalCell;
    }
    EXPECT_EQ(tiled.Boundary.size(), direct.Boundary.size());
    EXPECT_EQ(tiled.Crossings, direct.Crossings);
  }
}

struct DistributedRun
{
  std::vector<PieceMesh> Pieces;
  std::vector<Arrangement> Arrangements;
  std::vector<PieceSummary> Summaries;
  MergedArrangement Merged;
  /// Per piece: the neighbours' boundary records it receives, and what it sends to the merge.
  std::vector<std::size_t> NeighbourBytes, SentBytes;
};

void RunDistributed(const TriangleMesh& mesh,
  const std::vector<TracedCurve>& curves,
  const std::vector<int>& owner,
  int pieces,
  DistributedRun& run)
{
  run.Pieces.resize(pieces);
  run.Arrangements.resize(pieces);
  run.Summaries.resize(pieces);
  const GlobalEdgeVertices edgeVertices = [&](int e) { return mesh.GetEdgeVertices(e); };
  for (int p = 0; p < pieces; ++p)
  {
    std::string error;
    ASSERT_TRUE(BuildPieceMesh(MakePiece(mesh, owner, p), run.Pieces[p], error)) << error;
    PieceCurves local;
    RestrictCurvesToPiece(run.Pieces[p], curves, edgeVertices, local);
    ASSERT_TRUE(ArrangePiece(
      run.Pieces[p], local, ArrangementOptions(), run.Arrangements[p], run.Summaries[p], error))
      << "piece " << p << ": " << error;
    ExpectTileSumsGiveTheSameCells(run.Pieces[p], local, run.Arrangements[p], run.Summaries[p]);
  }
  // As processes would merge: each matches its boundary records with its neighbours' (the
  // owners of its ghosts) and sends on the joins; the merge never sees a boundary record.
  std::vector<PieceSummary> sent = run.Summaries;
  BoundaryJoins joins;
  run.NeighbourBytes.assign(pieces, 0);
  run.SentBytes.assign(pieces, 0);
  for (int p = 0; p < pieces; ++p)
  {
    std::vector<int> ids{ p };
    for (size_t t = 0; t < run.Pieces[p].GlobalTriangle.size(); ++t)
    {
      ids.push_back(owner[run.Pieces[p].GlobalTriangle[t]]);
    }
    std::sort(ids.begin() + 1, ids.end());
    ids.erase(std::unique(ids.begin() + 1, ids.end()), ids.end());
    ids.erase(std::remove(ids.begin() + 1, ids.end(), p), ids.end());
    std::vector<const PieceSummary*> given;
    for (int q : ids)
    {
      given.push_back(&run.Summaries[q]);
      run.NeighbourBytes[p] += q == p ? 0 : run.Summaries[q].GetBoundaryBytes();
    }
    BoundaryJoins mine;
    std::string error;
    ASSERT_TRUE(JoinPieceBoundaries(ids, given, p, mine, error)) << "piece " << p << ": " << error;
    sent[p].Boundary.clear();
    sent[p].BoundarySteps.clear();
    run.SentBytes[p] = sent[p].GetBytes() + mine.GetBytes();
    joins.Joins.insert(joins.Joins.end(), mine.Joins.begin(), mine.Joins.end());
    joins.Crossings.insert(joins.Crossings.end(), mine.Crossings.begin(), mine.Crossings.end());
  }
  std::string error;
  ASSERT_TRUE(MergeCellGraph(sent, joins, run.Merged, error)) << error;
  // The same as matching everything in one place.
  MergedArrangement direct;
  ASSERT_TRUE(MergePieceSummaries(run.Summaries, direct, error)) << error;
  EXPECT_EQ(direct.GlobalCellOfLocal, run.Merged.GlobalCellOfLocal);
  EXPECT_EQ(direct.Crossings, run.Merged.Crossings);
}

// The merged graph's labels are the labeling stage's own (from the whole arrangement's patches
// and boundary plugs): the same plugs, components and zero nodes, the same consistency per
// shape and the same labels. For an inconsistent shape the labels are one search's, equal here
// because the search meets the cells in the same order (MergedLabeling.h says when it may not).
// Returns the stage's labels.
LabelingResult ExpectLabelsOfTheStage(const TriangleMesh& mesh,
  const std::vector<TracedCurve>& curves,
  const Arrangement& whole,
  const MergedArrangement& merged,
  LabelingResult& mine)
{
  const MeshTopology topology = MeshTopology::Compute(mesh);
  const LabelingInput stageInput = MakeLabelingInput(mesh, topology, curves, whole);
  const LabelingResult stage = LabelCells(stageInput);
  const LabelingInput input = MergedLabelingInput(merged, DistinctShapeIds(curves));
  EXPECT_EQ(merged.NumberOfPlugs, static_cast<int>(topology.BoundaryLoops.size()));
  EXPECT_EQ(input.GetNumberOfNodes(), stageInput.GetNumberOfNodes());
  EXPECT_EQ(input.CellComponent, stageInput.CellComponent);
  EXPECT_EQ(input.ZeroCells, stageInput.ZeroCells);
  // Surface Arrangement's BoundaryPlugLinks on pieces: the stage's links, and at most one more
  // pair where curves of one shape cancel along the boundary.
  const std::vector<std::pair<int, int>> links = MergedPlugLinks(merged);
  EXPECT_TRUE(
    std::includes(links.begin(), links.end(), stageInput.Links.begin(), stageInput.Links.end()));
  EXPECT_LE(links.size(), stageInput.Links.size() + 1);
  mine = LabelMergedArrangement(merged, DistinctShapeIds(curves));
  EXPECT_EQ(mine.ShapeIds, stage.ShapeIds);
  EXPECT_EQ(mine.ShapeConsistent, stage.ShapeConsistent);
  if (mine.ShapeIds != stage.ShapeIds || mine.Labels.size() != stage.Labels.size())
  {
    ADD_FAILURE() << "labels of another size";
    return stage;
  }
  int differences = 0;
  for (int s = 0; s < mine.NumberOfShapes; ++s)
  {
    for (int c = 0; c < merged.NumberOfCells; ++c)
    {
      if (mine.GetLabel(c, s) != stage.GetLabel(c, s) && ++differences <= 3)
      {
        ADD_FAILURE() << "shape " << mine.ShapeIdOf(s) << ", cell " << c << ": label "
                      << mine.GetLabel(c, s) << ", the stage's " << stage.GetLabel(c, s);
      }
    }
  }
  return stage;
}

// Each piece's Boolean region (its owned triangles in the selected cells, from the merged
// labels) is its share of the whole surface's region (from the stage's labels), per source
// triangle; together the pieces cover the whole region.
void ExpectRegionsOfTheStage(const TriangleMesh& mesh,
  const Arrangement& whole,
  const LabelingResult& stage,
  const LabelingResult& mine,
  const DistributedRun& run)
{
  for (const BooleanOptions& options : TestBooleanOptions(stage.ShapeIds))
  {
    SCOPED_TRACE("operation " + std::to_string(static_cast<int>(options.Operation)));
    std::vector<char> selected;
    std::string text, error;
    const bool ok = SelectBooleanCells(stage, options, selected, text, error);
    std::map<int, SourceShare> union_;
    std::vector<BoundaryRun> runs; // every piece's, through message 4
    for (size_t p = 0; p < run.Pieces.size(); ++p)
    {
      PieceRegion region;
      std::vector<char> mySelected;
      std::string myText, myError;
      const bool mineOk = SelectPieceBoolean(run.Pieces[p],
        run.Arrangements[p],
        run.Merged.GlobalCellOfLocal[p],
        mine,
        options,
        region,
        mySelected,
        myText,
        myError);
      ASSERT_EQ(mineOk, ok) << myError << " / " << error;
      if (!ok)
      {
        break;
      }
      EXPECT_EQ(myText, text);
      EXPECT_EQ(mySelected, selected);
      for (const auto& share : PieceRegionBySource(run.Pieces[p], run.Arrangements[p], region))
      {
        EXPECT_TRUE(union_.insert(share).second) << "source triangle " << share.first;
      }
      std::vector<BoundaryRun> mine;
      PieceRegionBoundaryRuns(
        run.Pieces[p], run.Arrangements[p], run.Merged.GlobalCellOfLocal[p], mySelected, mine);
      std::vector<long long> message;
      PackBoundaryRuns(mine, message);
      EXPECT_TRUE(UnpackBoundaryRuns(message, runs, myError)) << myError;
    }
    if (ok)
    {
      const std::string difference =
        CompareRegions(union_, WholeRegionBySource(mesh, whole, selected));
      EXPECT_TRUE(difference.empty()) << difference;
      const std::vector<BoundaryRun> loops = ChainBoundaryRuns(runs);
      const std::string boundary = CompareRegionBoundaries(loops, mesh, whole, selected);
      EXPECT_TRUE(boundary.empty()) << boundary;
      // Independent of the split: chaining the runs in another order gives the same loops.
      std::reverse(runs.begin(), runs.end());
      const std::vector<BoundaryRun> again = ChainBoundaryRuns(runs);
      ASSERT_EQ(again.size(), loops.size());
      for (std::size_t l = 0; l < loops.size(); ++l)
      {
        ASSERT_EQ(again[l].Points.size(), loops[l].Points.size());
        for (std::size_t k = 0; k < loops[l].Points.size(); ++k)
        {
          EXPECT_EQ(again[l].Points[k].Key, loops[l].Points[k].Key);
        }
      }
    }
  }
}

// The merged result equals the whole-surface arrangement.
void ExpectSameAsWhole(const TriangleMesh& mesh,
  const std::vector<TracedCurve>& curves,
  const std::vector<int>& owner,
  int pieces)
{
  Arrangement whole;
  std::string error;
  ASSERT_TRUE(ComputeArrangement(mesh, curves, ArrangementOptions(), whole, error)) << error;
  DistributedRun run;
  RunDistributed(mesh, curves, owner, pieces, run);
  if (::testing::Test::HasFatalFailure())
  {
    return;
  }
  const MergedArrangement& merged = run.Merged;
  ASSERT_EQ(merged.NumberOfCells, whole.NumberOfCells);
  EXPECT_GT(whole.NumberOfCells, static_cast<int>(curves.size())); // the curves cut the surface
  // Every owned triangle's refined triangles: as many as on the whole surface, each in the
  // cell of the same number.
  int mismatches = 0;
  for (int p = 0; p < pieces; ++p)
  {
    const PieceMesh& piece = run.Pieces[p];
    const Arrangement& arr = run.Arrangements[p];
    for (int t = 0; t < piece.Mesh.GetNumberOfTriangles(); ++t)
    {
      if (!piece.Owned[t])
      {
        continue;
      }
      const int g = piece.GlobalTriangle[t];
      std::vector<int> mine, theirs;
      std::vector<Vec3> myCorners, theirCorners;
      ForEachRefinedTriangle(piece.Mesh,
        arr,
        t,
        [&](int r)
        {
          mine.push_back(merged.GlobalCellOfLocal[p][arr.CellOfTriangle(r)]);
          for (int q : arr.GetTriangle(piece.Mesh, r))
          {
            myCorners.push_back(arr.GetPosition(piece.Mesh, q));
          }
        });
      ForEachRefinedTriangle(mesh,
        whole,
        g,
        [&](int r)
        {
          for (int q : whole.GetTriangle(mesh, r))
          {
            theirCorners.push_back(whole.GetPosition(mesh, q));
          }
        });
      // Refined the same way, bit for bit.
      const bool sameCorners = myCorners.size() == theirCorners.size() &&
        std::equal(myCorners.begin(),
          myCorners.end(),
          theirCorners.begin(),
          [](const Vec3& a, const Vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; });
      if (!sameCorners && ++mismatches <= 5)
      {
        ADD_FAILURE() << "piece " << p << ", triangle " << g << ": refined differently";
      }
      ForEachRefinedTriangle(
        mesh, whole, g, [&](int r) { theirs.push_back(whole.CellOfTriangle(r)); });
      if (mine != theirs && ++mismatches <= 5)
      {
        ADD_FAILURE() << "piece " << p << ", triangle " << g << ": " << mine.size() << " vs "
                      << theirs.size() << " refined triangles, first cell "
                      << (mine.empty() ? -2 : mine[0]) << " vs "
                      << (theirs.empty() ? -2 : theirs[0]);
      }
    }
  }
  EXPECT_EQ(mismatches, 0);
  const std::vector<double> areas = CellAreas(mesh, whole);
  for (int c = 0; c < whole.NumberOfCells; ++c)
  {
    EXPECT_NEAR(merged.CellArea[c], areas[c], 1e-12 * std::max(1.0, areas[c])) << "cell " << c;
    const int first = whole.CellFirstTriangle[c];
    const int source = whole.GetSourceTriangle(mesh, first);
    int index = 0, found = -1;
    ForEachRefinedTriangle(mesh,
      whole,
      source,
      [&](int r)
      {
        found = r == first ? index : found;
        ++index;
      });
    EXPECT_TRUE((merged.CellLowestTriangle[c] == RefinedTriangleKey{ source, found }))
      << "cell " << c;
  }
  // The same cells meet across curves.
  std::set<std::pair<int, int>> meeting, merging;
  for (const CellGraphArc& a : whole.CellGraph)
  {
    meeting.insert({ std::min(a.RightCell, a.LeftCell), std::max(a.RightCell, a.LeftCell) });
  }
  for (const CellCrossing& c : merged.Crossings)
  {
    merging.insert({ c.FromCell, c.ToCell });
  }
  // On a surface with a boundary, a curve through a boundary vertex has two cells on one side
  // there (the boundary parts them) in one patch, and the whole arrangement's cell graph, one
  // arc per patch, names one of them: the pieces, which report crossings per sub-edge, meet
  // both. The labels are the same (the other cell is linked to the boundary's plug).
  if (MeshTopology::Compute(mesh).BoundaryLoops.empty())
  {
    EXPECT_EQ(merging, meeting);
  }
  else
  {
    EXPECT_TRUE(std::includes(merging.begin(), merging.end(), meeting.begin(), meeting.end()));
  }
  LabelingResult mine;
  const LabelingResult stage = ExpectLabelsOfTheStage(mesh, curves, whole, merged, mine);
  ExpectRegionsOfTheStage(mesh, whole, stage, mine, run);
}

// Vertices whose triangles belong to three pieces or more.
int VerticesOfThreeOrMorePieces(const TriangleMesh& mesh, const std::vector<int>& owner)
{
  int count = 0;
  for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
    std::vector<int> owners;
    for (int c : mesh.GetVertexCorners(v))
    {
      owners.push_back(owner[c / 3]);
    }
    std::sort(owners.begin(), owners.end());
    count += std::unique(owners.begin(), owners.end()) - owners.begin() >= 3;
  }
  return count;
}

// Every split of the test: slabs along each axis and random regions (one of them with an
// empty piece), for 1, 2, 3, 4 and 7 pieces.
void ExpectSameForEverySplit(const TriangleMesh& mesh, const std::vector<TracedCurve>& curves)
{
  for (int pieces : { 1, 2, 3, 4, 7 })
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      SCOPED_TRACE(
        "slabs along axis " + std::to_string(axis) + ", " + std::to_string(pieces) + " pieces");
      ExpectSameAsWhole(mesh, curves, SlabOwners(mesh, pieces, axis), pieces);
    }
    for (unsigned seed = 1; seed <= 3; ++seed)
    {
      SCOPED_TRACE(
        "regions, seed " + std::to_string(seed) + ", " + std::to_string(pieces) + " pieces");
      const int empty = seed == 2 ? pieces : -1;
      const int count = empty >= 0 ? pieces + 1 : pieces;
      const std::vector<int> owner = RegionOwners(mesh, count, seed, empty);
      if (pieces == 7)
      {
        EXPECT_GT(VerticesOfThreeOrMorePieces(mesh, owner), 0);
      }
      ExpectSameAsWhole(mesh, curves, owner, count);
    }
  }
}

TracedCurve FlatCurve(const FlatPolygonTracer& tracer, const std::vector<Vec2>& polygon, int shape)
{
  TracedCurve c;
  EXPECT_TRUE(tracer.Trace(polygon, true, shape, shape, c));
  return c;
}

} // namespace

TEST(PieceArrangement, FlatSquareCurvesAlongAndAcrossPieceBoundaries)
{
  const MeshData data = MakeFlatSquare(20);
  const TriangleMesh mesh(data.Positions, data.Triangles);
  FlatPolygonTracer tracer(mesh);
  std::vector<TracedCurve> curves;
  // Along the line x = 0.5, the boundary of two slabs along x, and through grid vertices.
  curves.push_back(FlatCurve(tracer, { { 0.5, 0.1 }, { 0.5, 0.9 }, { 0.85, 0.5 } }, 0));
  // A zigzag crossing the slab boundaries many times.
  std::vector<Vec2> zigzag;
  for (int i = 0; i <= 12; ++i)
  {
    zigzag.push_back({ 0.08 + 0.07 * i, i % 2 ? 0.6 : 0.3 });
  }
  zigzag.push_back({ 0.9, 0.95 });
  zigzag.push_back({ 0.1, 0.95 });
  curves.push_back(FlatCurve(tracer, zigzag, 1));
  // A small shape inside the first slab, and random polygons.
  curves.push_back(FlatCurve(tracer, { { 0.01, 0.02 }, { 0.04, 0.03 }, { 0.02, 0.06 } }, 2));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coord(0.03, 0.97);
  for (int s = 3; s < 6; ++s)
  {
    curves.push_back(FlatCurve(tracer,
      { { coord(rng), coord(rng) },
        { coord(rng), coord(rng) },
        { coord(rng), coord(rng) },
        { coord(rng), coord(rng) } },
      s));
  }
  ExpectSameForEverySplit(mesh, curves);
  // Two slabs along x meet on x = 0.5, where the first curve runs: its steps there are known
  // to the boundary only, and the small shape lies inside one of seven slabs.
  DistributedRun run;
  RunDistributed(mesh, curves, SlabOwners(mesh, 2, 0), 2, run);
  EXPECT_FALSE(run.Summaries[0].BoundarySteps.empty() && run.Summaries[1].BoundarySteps.empty());
}

TEST(PieceArrangement, ShapeInsideOnePieceAndPiecesNoCurveTouches)
{
  const MeshData data = MakeFlatSquare(20, 1.0, 0.2, 3);
  const TriangleMesh mesh(data.Positions, data.Triangles);
  FlatPolygonTracer tracer(mesh);
  const std::vector<TracedCurve> curves{
    FlatCurve(tracer, { { 0.05, 0.1 }, { 0.2, 0.15 }, { 0.1, 0.8 } }, 0),
    FlatCurve(tracer, { { 0.02, 0.5 }, { 0.22, 0.3 }, { 0.2, 0.6 } }, 1),
  };
  const std::vector<int> owner = SlabOwners(mesh, 4, 0);
  ExpectSameAsWhole(mesh, curves, owner, 4);
  DistributedRun run;
  RunDistributed(mesh, curves, owner, 4, run);
  EXPECT_FALSE(run.Summaries[0].Crossings.empty());
  for (int p = 1; p < 4; ++p)
  {
    // No curve: one local cell, nothing but the boundary to tell.
    EXPECT_EQ(run.Summaries[p].Cells.size(), 1u) << "piece " << p;
    EXPECT_TRUE(run.Summaries[p].Crossings.empty()) << "piece " << p;
    EXPECT_TRUE(run.Summaries[p].BoundarySteps.empty()) << "piece " << p;
  }
}

TEST(PieceArrangement, JitteredSquareRandomPolygons)
{
  const MeshData data = MakeFlatSquare(16, 1.0, 0.3, 5);
  const TriangleMesh mesh(data.Positions, data.Triangles);
  FlatPolygonTracer tracer(mesh);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coord(0.02, 0.98);
  std::vector<TracedCurve> curves;
  for (int s = 0; s < 6; ++s)
  {
    std::vector<Vec2> polygon(5);
    for (Vec2& v : polygon)
    {
      v = { coord(rng), coord(rng) };
    }
    curves.push_back(FlatCurve(tracer, polygon, s % 3));
  }
  ExpectSameForEverySplit(mesh, curves);
}

TEST(PieceArrangement, SphereRandomCurves)
{
  const MeshData data = MakeIcosphere(3);
  const TriangleMesh mesh(data.Positions, data.Triangles);
  const std::vector<TracedCurve> curves = RandomGeodesicCurves(mesh, 3, 4);
  ASSERT_EQ(curves.size(), 4u);
  ExpectSameForEverySplit(mesh, curves);
}

TEST(PieceArrangement, TorusRandomCurves)
{
  const MeshData data = MakeTorus(1.0, 0.4, 32, 16);
  const TriangleMesh mesh(data.Positions, data.Triangles);
  const std::vector<TracedCurve> curves = RandomGeodesicCurves(mesh, 5, 4);
  ASSERT_EQ(curves.size(), 4u);
  ExpectSameForEverySplit(mesh, curves);
}

TEST(PieceArrangement, GenusTwoRandomCurves)
{
  MeshData data;
  std::string error;
  ASSERT_TRUE(
    ReadPly((boolsurf::testing::SourceTree() / "Data" / "eight.ply").string(), data, error))
    << error;
  const TriangleMesh mesh(data.Positions, data.Triangles);
  const std::vector<TracedCurve> curves = RandomGeodesicCurves(mesh, 9, 4);
  ASSERT_EQ(curves.size(), 4u);
  ExpectSameForEverySplit(mesh, curves);
}

TEST(PieceArrangement, PieceWithoutItsGhostsIsNamed)
{
  const MeshData data = MakeFlatSquare(8);
  const TriangleMesh mesh(data.Positions, data.Triangles);
  FlatPolygonTracer tracer(mesh);
  const std::vector<TracedCurve> curves{ FlatCurve(
    tracer, { { 0.1, 0.1 }, { 0.9, 0.2 }, { 0.5, 0.9 } }, 0) };
  const std::vector<int> owner = SlabOwners(mesh, 2, 0);
  std::vector<PieceSummary> summaries(2);
  const GlobalEdgeVertices edgeVertices = [&](int e) { return mesh.GetEdgeVertices(e); };
  for (int p = 0; p < 2; ++p)
  {
    PieceInput in = MakePiece(mesh, owner, p);
    if (p == 1)
    {
      // Drop the ghosts.
      PieceInput owned;
      owned.Positions = in.Positions;
      owned.PointGlobalIds = in.PointGlobalIds;
      for (size_t t = 0; t < in.Triangles.size(); ++t)
      {
        if (!in.Ghost[t])
        {
          owned.Triangles.push_back(in.Triangles[t]);
          owned.TriangleGlobalIds.push_back(in.TriangleGlobalIds[t]);
          owned.Ghost.push_back(0);
        }
      }
      in = owned;
    }
    PieceMesh piece;
    std::string error;
    ASSERT_TRUE(BuildPieceMesh(in, piece, error)) << error;
    PieceCurves local;
    RestrictCurvesToPiece(piece, curves, edgeVertices, local);
    Arrangement arr;
    ASSERT_TRUE(ArrangePiece(piece, local, ArrangementOptions(), arr, summaries[p], error))
      << error;
  }
  MergedArrangement merged;
  std::string error;
  EXPECT_FALSE(MergePieceSummaries(summaries, merged, error));
  EXPECT_NE(error.find("ghost"), std::string::npos) << error;
}

TEST(PieceArrangement, RepeatedGlobalIdIsNamed)
{
  PieceInput in;
  in.Positions = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
  in.PointGlobalIds = { 4, 7, 4 };
  in.Triangles = { { 0, 1, 2 } };
  in.TriangleGlobalIds = { 0 };
  in.Ghost = { 0 };
  PieceMesh piece;
  std::string error;
  EXPECT_FALSE(BuildPieceMesh(in, piece, error));
  EXPECT_NE(error.find("point global id 4"), std::string::npos) << error;
}

// Summary sizes against piece sizes on a 100k-triangle torus split in 4 slabs, with plane
// sections (meridians and parallels) as curves.
TEST(PieceArrangement, SummariesAreSmallNextToPieces)
{
  const MeshData data = MakeTorus(1.0, 0.35, 320, 160);
  const TriangleMesh mesh(data.Positions, data.Triangles);
  std::vector<TracedCurve> curves;
  for (int i = 0; i < 5; ++i)
  {
    const double angle = 0.3 + 0.55 * i;
    for (TracedCurve& c :
      PlaneSectionCurves(mesh, Vec3{ std::cos(angle), std::sin(angle), 0.0 }, 0.0, i, 10 * i))
    {
      curves.push_back(std::move(c));
    }
  }
  for (TracedCurve& c : PlaneSectionCurves(mesh, Vec3{ 0.0, 0.0, 1.0 }, 0.11, 9, 100))
  {
    curves.push_back(std::move(c));
  }
  const int pieces = 4;
  const std::vector<int> owner = SlabOwners(mesh, pieces, 0);
  ExpectSameAsWhole(mesh, curves, owner, pieces);
  DistributedRun run;
  RunDistributed(mesh, curves, owner, pieces, run);
  for (int p = 0; p < pieces; ++p)
  {
    const PieceSummary& s = run.Summaries[p];
    const std::size_t meshBytes =
      run.Pieces[p].Mesh.GetNumberOfTriangles() * (sizeof(Triangle) + sizeof(int)) +
      run.Pieces[p].Mesh.GetNumberOfVertices() * (sizeof(Vec3) + sizeof(int));
    std::printf("piece %d: %d owned + %d ghost triangles (%zu bytes); boundary records %zu "
                "bytes (%zu sub-segments, %zu curve steps), from neighbours %zu bytes; sent "
                "to the merge %zu bytes (%zu cells, %zu crossings)\n",
      p,
      run.Pieces[p].NumberOfOwnedTriangles,
      run.Pieces[p].Mesh.GetNumberOfTriangles() - run.Pieces[p].NumberOfOwnedTriangles,
      meshBytes,
      s.GetBoundaryBytes(),
      s.Boundary.size(),
      s.BoundarySteps.size(),
      run.NeighbourBytes[p],
      run.SentBytes[p],
      s.Cells.size(),
      s.Crossings.size());
    EXPECT_LT(run.SentBytes[p] * 100, meshBytes);
    EXPECT_LT(s.GetBytes() * 20, meshBytes);
  }
}

// Many random drawings: geodesic polygons on a sphere and a torus split in random regions,
// and grid-aligned polygons on a flat square (curves along mesh edges and through vertices,
// shared by several shapes) split in slabs and regions.
TEST(PieceArrangement, ManyRandomDrawings)
{
  for (unsigned seed = 20; seed < 32; ++seed)
  {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const MeshData data = seed % 2 ? MakeTorus(1.0, 0.4, 24, 12) : MakeIcosphere(2);
    const TriangleMesh mesh(data.Positions, data.Triangles);
    const std::vector<TracedCurve> curves = RandomGeodesicCurves(mesh, seed, 7);
    for (int pieces : { 2, 5, 9 })
    {
      for (unsigned s = 1; s <= 3; ++s)
      {
        ExpectSameAsWhole(mesh, curves, RegionOwners(mesh, pieces, seed * 7 + s, -1), pieces);
      }
    }
    const MeshData flat = MakeFlatSquare(12, 1.0, seed % 3 ? 0.0 : 0.3, seed);
    const TriangleMesh square(flat.Positions, flat.Triangles);
    FlatPolygonTracer tracer(square);
    std::mt19937 rng(seed);
    // Grid-aligned coordinates: curves along edges and through vertices, shared between shapes.
    std::uniform_int_distribution<int> grid(1, 11);
    std::vector<TracedCurve> flatCurves;
    for (int c = 0; c < 6; ++c)
    {
      std::vector<Vec2> polygon(4);
      for (Vec2& v : polygon)
      {
        v = { grid(rng) / 12.0, grid(rng) / 12.0 };
      }
      TracedCurve curve;
      if (tracer.Trace(polygon, true, c % 3, c, curve) && curve.Points.size() >= 3)
      {
        flatCurves.push_back(curve);
      }
    }
    Arrangement probe;
    std::string error;
    if (!ComputeArrangement(square, flatCurves, ArrangementOptions(), probe, error))
    {
      continue;
    }
    for (int pieces : { 2, 3, 6 })
    {
      for (int axis = 0; axis < 2; ++axis)
      {
        ExpectSameAsWhole(square, flatCurves, SlabOwners(square, pieces, axis), pieces);
      }
      ExpectSameAsWhole(square, flatCurves, RegionOwners(square, pieces, seed, -1), pieces);
    }
  }
}

// A sphere with four holes of different sizes: every boundary loop has a plug, the largest is
// the zero node, and the labels are the stage's exactly whatever the split.
TEST(PieceArrangement, OpenSphereWithHolesRandomCurves)
{
  const MeshData data = SphereWithHoles();
  const TriangleMesh mesh(data.Positions, data.Triangles);
  const MeshTopology topology = MeshTopology::Compute(mesh);
  ASSERT_EQ(topology.BoundaryLoops.size(), 4u);
  ASSERT_TRUE(topology.NonManifoldVertices.empty());
  for (unsigned seed : { 3u, 8u })
  {
    SCOPED_TRACE("curves of seed " + std::to_string(seed));
    const std::vector<TracedCurve> curves = RandomGeodesicCurves(mesh, seed, 5);
    ASSERT_GE(curves.size(), 3u);
    ExpectSameForEverySplit(mesh, curves);
  }
}

// Curves along the square's boundary: along one side, around a corner, around the whole loop
// (no stretch of it left free) and reversed, so that the plug meets cells through crossings as
// well as links, on every split.
TEST(PieceArrangement, FlatSquareCurvesAlongItsBoundary)
{
  const MeshData data = MakeFlatSquare(12);
  const TriangleMesh mesh(data.Positions, data.Triangles);
  FlatPolygonTracer tracer(mesh);
  const std::vector<std::vector<Vec2>> polygons{
    { { 0, 0 }, { 0.5, 0 }, { 0.5, 0.5 }, { 0, 0.5 } },
    { { 1, 1 }, { 0.25, 1 }, { 0.25, 0.75 }, { 1, 0.25 } },
    { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } },
    { { 0.75, 0 }, { 0.75, 0.5 }, { 1, 0.5 }, { 1, 0 } },
    { { 0.3, 0.3 }, { 0.7, 0.4 }, { 0.4, 0.8 } },
    { { 0.45, 0.5 }, { 0.9, 0.6 }, { 0.6, 0.9 } },
  };
  std::vector<TracedCurve> curves;
  for (size_t s = 0; s < polygons.size(); ++s)
  {
    curves.push_back(FlatCurve(tracer, polygons[s], static_cast<int>(s)));
  }
  ExpectSameForEverySplit(mesh, curves);
  DistributedRun run;
  RunDistributed(mesh, curves, RegionOwners(mesh, 4, 2, -1), 4, run);
  EXPECT_EQ(run.Merged.NumberOfPlugs, 1);
  EXPECT_TRUE(std::any_of(run.Merged.PlugCrossings.begin(),
    run.Merged.PlugCrossings.end(),
    [](const CellCrossing& c) { return !c.Delta.empty(); }));
  // Each boundary shape with the inner ones only: the loop covered whole is then its plug's
  // only way in.
  for (size_t s = 0; s + 2 < curves.size(); ++s)
  {
    SCOPED_TRACE("shape " + std::to_string(s) + " with the inner ones");
    ExpectSameAsWhole(mesh, { curves[s], curves[4], curves[5] }, RegionOwners(mesh, 3, 5, -1), 3);
  }
}

// A scan with eleven holes (beetle.ply, 38,656 triangles) from the shared mesh collection.
TEST(PieceArrangement, ScanWithHolesRandomCurves)
{
  const char* shared = std::getenv("BOOLSURF_SHARED_DATA");
  const std::string path =
    shared && *shared ? std::string(shared) + "/meshes/beetle.ply" : std::string();
  MeshData data;
  std::string error;
  if (path.empty() || !ReadPly(path, data, error))
  {
    GTEST_SKIP() << "BOOLSURF_SHARED_DATA is not set or has no meshes/beetle.ply";
  }
  const TriangleMesh mesh(data.Positions, data.Triangles);
  const MeshTopology topology = MeshTopology::Compute(mesh);
  ASSERT_GE(topology.BoundaryLoops.size(), 2u);
  const std::vector<TracedCurve> curves = RandomGeodesicCurves(mesh, 4, 5);
  ASSERT_GE(curves.size(), 3u);
  for (int pieces : { 2, 4, 7 })
  {
    SCOPED_TRACE(std::to_string(pieces) + " pieces");
    ExpectSameAsWhole(mesh, curves, SlabOwners(mesh, pieces, 0), pieces);
    ExpectSameAsWhole(mesh, curves, RegionOwners(mesh, pieces, 13, -1), pieces);
  }
}

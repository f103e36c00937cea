// The distributed arrangement's messages (Core/Distributed/PieceWire.h): pieces that talk only
// through packed buffers -- the traced curves from the tracer (restricted to each piece as the
// curves themselves are), boundary records to their neighbours, their cells, crossings and
// joins to the merge, the merged cells back -- end with what merging every summary in one place
// gives (MergePieceSummaries), and a short or corrupt buffer is an error, not a crash. Prints
// the words each piece sends per message, as a run on processes would send them.
#include "Distributed/BoundaryJoins.h"
#include "Distributed/MergedArrangement.h"
#include "Distributed/PieceCurves.h"
#include "Distributed/PieceMesh.h"
#include "Distributed/PieceSummary.h"
#include "Distributed/PieceWire.h"

#include "Mesh/ProceduralMeshes.h"
#include "Support/PieceSplits.h"
#include "Support/SyntheticCurves.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>

using namespace boolsurf;
using boolsurf::testing::MakePiece;
using boolsurf::testing::RandomGeodesicCurves;
using boolsurf::testing::RegionOwners;
using boolsurf::testing::SlabOwners;

namespace
{

/// The owners of piece p's ghosts: the pieces it exchanges boundary records with.
std::vector<int> NeighboursOf(const PieceMesh& piece, const std::vector<int>& owner, int p)
{
  std::vector<int> ids;
  for (int g : piece.GlobalTriangle)
  {
    if (owner[g] != p)
    {
      ids.push_back(owner[g]);
    }
  }
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

// One distributed run through buffers only, compared with the merge of every summary in one
// place.
void ExpectWireRunEqualsMerge(const TriangleMesh& mesh,
  const std::vector<TracedCurve>& curves,
  const std::vector<int>& owner,
  int pieces)
{
  const GlobalEdgeVertices edgeVertices = [&](int e) { return mesh.GetEdgeVertices(e); };
  // The curves as the pieces receive them: edges named by their global vertices.
  WireBuffer curvesMessage;
  PackTracedCurves(curves, mesh, {}, {}, curvesMessage);
  std::vector<TracedCurve> received;
  std::vector<std::array<int, 2>> edgeTable;
  std::string curvesError;
  ASSERT_TRUE(UnpackTracedCurves(curvesMessage, received, edgeTable, curvesError)) << curvesError;
  const GlobalEdgeVertices receivedEdges = [&](int e) { return edgeTable[e]; };
  std::vector<PieceMesh> meshes(pieces);
  std::vector<PieceSummary> summaries(pieces);
  std::vector<WireBuffer> boundary(pieces);
  for (int p = 0; p < pieces; ++p)
  {
    std::string error;
    ASSERT_TRUE(BuildPieceMesh(MakePiece(mesh, owner, p), meshes[p], error)) << error;
    PieceCurves local, fromMessage;
    RestrictCurvesToPiece(meshes[p], curves, edgeVertices, local);
    RestrictCurvesToPiece(meshes[p], received, receivedEdges, fromMessage);
    ASSERT_EQ(fromMessage.Curves.size(), local.Curves.size());
    for (std::size_t c = 0; c < local.Curves.size(); ++c)
    {
      EXPECT_TRUE(fromMessage.Curves[c].Points == local.Curves[c].Points) << "curve " << c;
      EXPECT_EQ(fromMessage.Curves[c].Closed, local.Curves[c].Closed);
      EXPECT_EQ(fromMessage.Curves[c].ShapeId, local.Curves[c].ShapeId);
    }
    EXPECT_EQ(fromMessage.SourceCurve, local.SourceCurve);
    EXPECT_EQ(fromMessage.FirstPoint, local.FirstPoint);
    EXPECT_EQ(fromMessage.CutFromClosed, local.CutFromClosed);
    Arrangement arr;
    ASSERT_TRUE(ArrangePiece(meshes[p], local, ArrangementOptions(), arr, summaries[p], error))
      << error;
    PackBoundaryRecords(summaries[p], boundary[p]);
  }
  // Each piece: its neighbours' boundary records from their buffers, matched with its own; its
  // merge input packed.
  std::vector<WireBuffer> toMerge(pieces);
  for (int p = 0; p < pieces; ++p)
  {
    std::vector<int> ids{ p };
    std::vector<PieceSummary> received;
    std::size_t receivedWords = 0;
    for (int q : NeighboursOf(meshes[p], owner, p))
    {
      PieceSummary records;
      std::string error;
      ASSERT_TRUE(UnpackBoundaryRecords(boundary[q], records, error)) << error;
      ids.push_back(q);
      received.push_back(std::move(records));
      receivedWords += boundary[q].size();
    }
    std::vector<const PieceSummary*> given{ &summaries[p] };
    for (const PieceSummary& r : received)
    {
      given.push_back(&r);
    }
    BoundaryJoins joins;
    std::string error;
    ASSERT_TRUE(JoinPieceBoundaries(ids, given, p, joins, error)) << error;
    PackMergeInput(summaries[p], joins, toMerge[p]);
    std::printf("%d pieces, piece %d: boundary records sent %zu B, received %zu B; to the "
                "merge %zu B\n",
      pieces,
      p,
      boundary[p].size() * sizeof(long long),
      receivedWords * sizeof(long long),
      toMerge[p].size() * sizeof(long long));
  }
  // The merge, from the buffers only.
  std::vector<PieceSummary> merging(pieces);
  BoundaryJoins joins;
  for (int p = 0; p < pieces; ++p)
  {
    std::string error;
    ASSERT_TRUE(UnpackMergeInput(toMerge[p], merging[p], joins, error)) << error;
  }
  MergedArrangement merged;
  std::string error;
  ASSERT_TRUE(MergeCellGraph(merging, joins, merged, error)) << error;
  MergedArrangement direct;
  ASSERT_TRUE(MergePieceSummaries(summaries, direct, error)) << error;
  EXPECT_EQ(merged.NumberOfCells, direct.NumberOfCells);
  EXPECT_EQ(merged.GlobalCellOfLocal, direct.GlobalCellOfLocal);
  EXPECT_EQ(merged.CellArea, direct.CellArea);
  EXPECT_EQ(merged.Crossings, direct.Crossings);
  EXPECT_EQ(merged.NumberOfPlugs, direct.NumberOfPlugs);
  EXPECT_EQ(merged.PlugCrossings, direct.PlugCrossings);
  EXPECT_EQ(merged.NodeComponent, direct.NodeComponent);
  EXPECT_EQ(merged.ZeroNodes, direct.ZeroNodes);
  // Back to each piece.
  for (int p = 0; p < pieces; ++p)
  {
    WireBuffer back;
    PackMergedForPiece(merged, p, back);
    MergedArrangement mine;
    ASSERT_TRUE(UnpackMergedForPiece(back, mine, error)) << error;
    EXPECT_EQ(mine.NumberOfCells, direct.NumberOfCells);
    EXPECT_EQ(mine.GlobalCellOfLocal[0], direct.GlobalCellOfLocal[p]);
    EXPECT_EQ(mine.CellArea, direct.CellArea);
    EXPECT_EQ(mine.Crossings, direct.Crossings);
    EXPECT_EQ(mine.NumberOfPlugs, direct.NumberOfPlugs);
    EXPECT_EQ(mine.PlugCrossings, direct.PlugCrossings);
    EXPECT_EQ(mine.NodeComponent, direct.NodeComponent);
    EXPECT_EQ(mine.ZeroNodes, direct.ZeroNodes);
    std::printf(
      "%d pieces, piece %d: from the merge %zu B\n", pieces, p, back.size() * sizeof(long long));
  }
}

std::vector<TracedCurve> TorusSections(const TriangleMesh& mesh)
{
  std::vector<TracedCurve> curves;
  const Vec3 normals[] = { { 1, 0, 0 }, { 0, 1, 0.3 }, { 0.2, -1, 0.5 } };
  for (int s = 0; s < 3; ++s)
  {
    for (const TracedCurve& c : PlaneSectionCurves(mesh, normals[s], 0.1 * s + 0.05, s))
    {
      curves.push_back(c);
    }
  }
  return curves;
}

} // namespace

TEST(PieceWire, MessagesCarryTheMergeOfATorusInSlabsAndRegions)
{
  const MeshData data = MakeTorus(1.0, 0.4, 40, 20);
  const TriangleMesh mesh(data.Positions, data.Triangles);
  const std::vector<TracedCurve> curves = TorusSections(mesh);
  ASSERT_FALSE(curves.empty());
  for (int pieces : { 1, 2, 3, 4 })
  {
    SCOPED_TRACE(std::to_string(pieces) + " pieces");
    ExpectWireRunEqualsMerge(mesh, curves, SlabOwners(mesh, pieces, 0), pieces);
    ExpectWireRunEqualsMerge(mesh, curves, RegionOwners(mesh, pieces + 1, 7, pieces), pieces + 1);
  }
}

// An open cylinder: its two boundary loops cut by the piece borders, their fragments and plugs
// through messages 2 and 3.
TEST(PieceWire, MessagesCarryTheBoundaryLoopsOfAnOpenCylinder)
{
  const MeshData data = MakeOpenCylinder(0.5, 1.0, 32, 12);
  const TriangleMesh mesh(data.Positions, data.Triangles);
  std::vector<TracedCurve> curves = PlaneSectionCurves(mesh, Vec3{ 0.0, 0.0, 1.0 }, 0.4, 0);
  for (TracedCurve& c : RandomGeodesicCurves(mesh, 6, 3))
  {
    c.ShapeId += 1;
    curves.push_back(std::move(c));
  }
  ASSERT_GE(curves.size(), 2u);
  for (int pieces : { 1, 2, 3, 4 })
  {
    SCOPED_TRACE(std::to_string(pieces) + " pieces");
    ExpectWireRunEqualsMerge(mesh, curves, SlabOwners(mesh, pieces, 0), pieces);
    ExpectWireRunEqualsMerge(mesh, curves, RegionOwners(mesh, pieces, 9, -1), pieces);
  }
}

TEST(PieceWire, ShortOrCorruptMessagesAreErrors)
{
  PieceSummary summary;
  summary.NumberOfLocalCells = 2;
  summary.Cells.push_back({ 0, { 3, 0 }, 0.25 });
  summary.Boundary.push_back({ 42, 0, 1, 0, true, false });
  summary.BoundarySteps.push_back({ 42, 0, 1, true });
  summary.Crossings.push_back({ 0, 1, { { 1, 1 } } });
  BoundaryJoins joins;
  joins.Joins.push_back({ { 0, 0 }, { 1, 0 } });
  joins.Crossings.push_back({ { 0, 1 }, { 1, 0 }, { { 1, -1 } } });

  WireBuffer records, merge;
  PackBoundaryRecords(summary, records);
  PackMergeInput(summary, joins, merge);
  PieceSummary back;
  BoundaryJoins backJoins;
  std::string error;
  ASSERT_TRUE(UnpackBoundaryRecords(records, back, error)) << error;
  EXPECT_EQ(back.Boundary.size(), 1u);
  EXPECT_EQ(back.BoundarySteps.size(), 1u);
  ASSERT_TRUE(UnpackMergeInput(merge, back, backJoins, error)) << error;
  EXPECT_EQ(back.Cells.size(), 1u);
  EXPECT_EQ(back.Cells[0].Area, 0.25);
  EXPECT_EQ(back.Crossings, summary.Crossings);
  EXPECT_EQ(backJoins.Joins, joins.Joins);
  ASSERT_EQ(backJoins.Crossings.size(), 1u);
  EXPECT_EQ(backJoins.Crossings[0].Delta, joins.Crossings[0].Delta);

  records.pop_back();
  EXPECT_FALSE(UnpackBoundaryRecords(records, back, error));
  EXPECT_NE(error.find("boundary records"), std::string::npos) << error;
  merge[1] = 1000000; // a count the buffer cannot hold
  EXPECT_FALSE(UnpackMergeInput(merge, back, backJoins, error));
  EXPECT_NE(error.find("merge input"), std::string::npos) << error;
  MergedArrangement merged;
  EXPECT_FALSE(UnpackMergedForPiece({ 3, -1 }, merged, error));
  EXPECT_NE(error.find("merged arrangement"), std::string::npos) << error;
  std::vector<TracedCurve> curves;
  std::vector<std::array<int, 2>> edges;
  // One curve of one edge point naming edge 5 of an empty edge table.
  EXPECT_FALSE(UnpackTracedCurves({ 1, 1, 0, 0, 1, 1, 5, 0, 0, 0, 0 }, curves, edges, error));
  EXPECT_NE(error.find("edge 5"), std::string::npos) << error;
}

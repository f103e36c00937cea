// ComputeArrangementOfRuns: an open curve flagged as a run of a closed curve separates cells
// like a closed one, and is still open (no arc of the cell graph, ends not joined).
#include "Arrangement/ArrangementOfRuns.h"

#include "Mesh/ProceduralMeshes.h"
#include "Support/SyntheticCurves.h"

#include <gtest/gtest.h>

using namespace boolsurf;

TEST(ArrangementOfRuns, FlaggedOpenChordSplitsTheSquare)
{
  const MeshData data = MakeFlatSquare(10, 1.0, 0.2, 4);
  const TriangleMesh mesh(data.Positions, data.Triangles);
  FlatPolygonTracer tracer(mesh);
  std::vector<TracedCurve> curves(1);
  ASSERT_TRUE(
    tracer.Trace({ { 0.0, 0.37 }, { 0.52, 0.45 }, { 1.0, 0.41 } }, false, 0, 0, curves[0]));
  std::string error;
  Arrangement open, run;
  ASSERT_TRUE(ComputeArrangement(mesh, curves, ArrangementOptions(), open, error)) << error;
  EXPECT_EQ(open.NumberOfCells, 1);
  ASSERT_TRUE(ComputeArrangementOfRuns(mesh, curves, { 1 }, ArrangementOptions(), run, error))
    << error;
  EXPECT_EQ(run.NumberOfCells, 2);
  EXPECT_TRUE(run.CellGraph.empty());
  // Unflagged, the same as ComputeArrangement.
  Arrangement unflagged;
  ASSERT_TRUE(ComputeArrangementOfRuns(mesh, curves, { 0 }, ArrangementOptions(), unflagged, error))
    << error;
  EXPECT_EQ(unflagged.NumberOfCells, 1);
}

// Degenerate configurations of the arrangement, on an exact grid (MakeFlatSquare(4, 4.0): the
// vertices are at integer coordinates, diagonals run from (i, j) to (i+1, j+1)), so that
// curves can cross exactly on mesh edges and vertices, run along edges, overlap and touch.
#include "ArrangementTestUtils.h"

#include <algorithm>

using namespace boolsurf;
using namespace boolsurf::testing;

namespace
{

struct GridFixture
{
  TriangleMesh Mesh = MeshOf(MakeFlatSquare(4, 4.0));
  FlatPolygonTracer Tracer{ Mesh };

  std::vector<TracedCurve> Trace(const std::vector<std::vector<Vec2>>& polygons)
  {
    std::vector<TracedCurve> curves;
    for (size_t i = 0; i < polygons.size(); ++i)
      curves.push_back(
        TraceOrDie(this->Tracer, polygons[i], true, static_cast<int>(i), static_cast<int>(i)));
    return curves;
  }
};

int VertexId(int i, int j)
{
  return j * 5 + i;
}

bool CurveVisits(const Arrangement& arr, int curve, int point)
{
  const std::vector<int>& p = arr.CurvePoints[curve];
  return std::find(p.begin(), p.end(), point) != p.end();
}

std::vector<double> SortedCellAreas(const TriangleMesh& mesh, const Arrangement& arr)
{
  std::vector<double> a = CellAreas(mesh, arr);
  std::sort(a.begin(), a.end());
  return a;
}

void ExpectSortedAreas(const TriangleMesh& mesh,
  const Arrangement& arr,
  std::vector<double> expected)
{
  std::sort(expected.begin(), expected.end());
  const std::vector<double> areas = SortedCellAreas(mesh, arr);
  ASSERT_EQ(areas.size(), expected.size());
  for (size_t i = 0; i < areas.size(); ++i)
    EXPECT_NEAR(areas[i], expected[i], 1e-12) << "cell " << i;
}

// Area of the cell on the left of curve c's first patch.
double LeftArea(const TriangleMesh& mesh, const Arrangement& arr, int curve)
{
  for (const ArrangementPatch& p : arr.Patches)
    if (p.Curve == curve)
      return CellAreas(mesh, arr)[p.LeftCell];
  return -1;
}

void ExpectValid(const TriangleMesh& mesh, const Arrangement& arr, int components)
{
  ExpectAreasConserved(mesh, arr);
  ExpectConforming(mesh, arr);
  EXPECT_EQ(PatchGraphEuler(arr), 1 + components);
}

} // namespace

TEST(ArrangementDegenerate, CrossingExactlyOnMeshEdge)
{
  GridFixture g;
  const std::vector<std::vector<Vec2>> polygons{
    { { 0.5, 0.25 }, { 2.5, 0.25 }, { 2.5, 2.25 }, { 0.5, 2.25 } },
    { { 0.25, 0.5 }, { 0.75, 1.5 }, { 0.1, 1.4 } }, // its first side crosses x = 0.5 at y = 1
  };
  const Arrangement arr = ArrangeOrDie(g.Mesh, g.Trace(polygons));
  EXPECT_EQ(arr.NumberOfCells, CountPlanarArrangement(polygons).Faces());
  ExpectValid(g.Mesh, arr, 1);
  // The crossing is one refined point on the horizontal edge y = 1, shared by both curves.
  int shared = -1;
  for (size_t p = 0; p < static_cast<size_t>(arr.GetNumberOfPoints()); ++p)
    if (Distance(arr.GetPosition(g.Mesh, p), { 0.5, 1.0, 0.0 }) < 1e-15)
      shared = static_cast<int>(p);
  ASSERT_GE(shared, 0);
  EXPECT_EQ(arr.GetPointOnMesh(shared).Location, PointLocation::Edge);
  EXPECT_TRUE(CurveVisits(arr, 0, shared));
  EXPECT_TRUE(CurveVisits(arr, 1, shared));
}

TEST(ArrangementDegenerate, CrossingExactlyAtMeshVertex)
{
  GridFixture g;
  const std::vector<std::vector<Vec2>> polygons{
    { { 0.75, 0.5 }, { 1.25, 1.5 }, { 0.3, 1.2 } }, // slope 2 through (1, 1)
    { { 1.25, 0.5 }, { 1.8, 1.4 }, { 0.75, 1.5 } }, // slope -2 through (1, 1)
  };
  const Arrangement arr = ArrangeOrDie(g.Mesh, g.Trace(polygons));
  EXPECT_EQ(arr.NumberOfCells, CountPlanarArrangement(polygons).Faces());
  ExpectValid(g.Mesh, arr, 1);
  EXPECT_TRUE(CurveVisits(arr, 0, VertexId(1, 1)));
  EXPECT_TRUE(CurveVisits(arr, 1, VertexId(1, 1)));
}

TEST(ArrangementDegenerate, CurveAlongMeshEdges)
{
  GridFixture g;
  // Every side along mesh edges: nothing needs refining, the edges themselves separate.
  const Arrangement square =
    ArrangeOrDie(g.Mesh, g.Trace({ { { 1, 1 }, { 3, 1 }, { 3, 3 }, { 1, 3 } } }));
  EXPECT_EQ(square.NumberOfCells, 2);
  EXPECT_EQ(square.NumberOfRefinedSourceTriangles, 0);
  EXPECT_NEAR(LeftArea(g.Mesh, square, 0), 4.0, 1e-12);
  ExpectValid(g.Mesh, square, 1);
  // Along the diagonals and through vertices.
  const Arrangement diagonal = ArrangeOrDie(g.Mesh, g.Trace({ { { 1, 1 }, { 3, 3 }, { 1, 3 } } }));
  EXPECT_EQ(diagonal.NumberOfCells, 2);
  EXPECT_NEAR(LeftArea(g.Mesh, diagonal, 0), 2.0, 1e-12);
  ExpectValid(g.Mesh, diagonal, 1);
  // Partly along an edge (from a vertex to an edge point), partly across triangles.
  const Arrangement mixed =
    ArrangeOrDie(g.Mesh, g.Trace({ { { 1, 1 }, { 2.5, 1 }, { 2.2, 2.7 } } }));
  EXPECT_EQ(mixed.NumberOfCells, 2);
  EXPECT_NEAR(LeftArea(g.Mesh, mixed, 0), 0.5 * 1.5 * 1.7, 1e-12);
  ExpectValid(g.Mesh, mixed, 1);
}

TEST(ArrangementDegenerate, CollinearOverlapInsideTriangles)
{
  GridFixture g;
  const Arrangement arr = ArrangeOrDie(g.Mesh,
    g.Trace({ { { 0.5, 0.5 }, { 2.5, 0.5 }, { 2.5, 2.5 }, { 0.5, 2.5 } },
      { { 1.5, 0.5 }, { 3.5, 0.5 }, { 3.5, 2.5 }, { 1.5, 2.5 } } }));
  EXPECT_EQ(arr.NumberOfCells, 4);
  ExpectSortedAreas(g.Mesh, arr, { 2.0, 2.0, 2.0, 10.0 });
  ExpectAreasConserved(g.Mesh, arr);
  ExpectConforming(g.Mesh, arr);
}

TEST(ArrangementDegenerate, CollinearOverlapAlongMeshEdge)
{
  GridFixture g;
  const Arrangement arr = ArrangeOrDie(g.Mesh,
    g.Trace({ { { 1, 1 }, { 3, 1 }, { 3, 3 }, { 1, 3 } },
      { { 2, 1 }, { 3.5, 1 }, { 3.5, 2 }, { 2, 2 } } }));
  EXPECT_EQ(arr.NumberOfCells, 4);
  ExpectSortedAreas(g.Mesh, arr, { 1.0, 3.0, 0.5, 11.5 });
  ExpectAreasConserved(g.Mesh, arr);
  ExpectConforming(g.Mesh, arr);
}

TEST(ArrangementDegenerate, TangencyOnMeshEdge)
{
  GridFixture g;
  // The diamond's left corner touches the square's right side at (1.5, 1), on edge y = 1.
  const Arrangement arr = ArrangeOrDie(g.Mesh,
    g.Trace({ { { 0.5, 0.5 }, { 1.5, 0.5 }, { 1.5, 1.5 }, { 0.5, 1.5 } },
      { { 1.5, 1.0 }, { 2.0, 0.6 }, { 2.5, 1.0 }, { 2.0, 1.4 } } }));
  EXPECT_EQ(arr.NumberOfCells, 3);
  ExpectSortedAreas(g.Mesh, arr, { 1.0, 0.4, 16.0 - 1.4 });
  EXPECT_EQ(arr.NumberOfPatchGraphVertices, 1);
  EXPECT_EQ(arr.Patches.size(), 2u);
  ExpectValid(g.Mesh, arr, 1);
}

TEST(ArrangementDegenerate, TangencyInsideTriangle)
{
  GridFixture g;
  // The diamond's corner (1.5, 0.9) lies inside a triangle, exactly on the square's side.
  const Arrangement arr = ArrangeOrDie(g.Mesh,
    g.Trace({ { { 0.5, 0.5 }, { 1.5, 0.5 }, { 1.5, 1.5 }, { 0.5, 1.5 } },
      { { 1.5, 0.9 }, { 2.0, 0.5 }, { 2.5, 0.9 }, { 2.0, 1.3 } } }));
  EXPECT_EQ(arr.NumberOfCells, 3);
  ExpectSortedAreas(g.Mesh, arr, { 1.0, 0.4, 16.0 - 1.4 });
  EXPECT_EQ(arr.NumberOfPatchGraphVertices, 1);
  ExpectValid(g.Mesh, arr, 1);
}

TEST(ArrangementDegenerate, CurveMeetsItselfAtVertex)
{
  GridFixture g;
  // Figure eight through vertex (2, 2), touching itself there: both lobes counter-clockwise.
  const Arrangement touching = ArrangeOrDie(
    g.Mesh, g.Trace({ { { 2, 2 }, { 3, 1.5 }, { 3, 2.5 }, { 2, 2 }, { 1, 2.5 }, { 1, 1.5 } } }));
  EXPECT_EQ(touching.NumberOfCells, 3);
  ExpectSortedAreas(g.Mesh, touching, { 0.5, 0.5, 15.0 });
  EXPECT_EQ(touching.NumberOfPatchGraphVertices, 1);
  ASSERT_EQ(touching.Patches.size(), 2u);
  const std::vector<double> areas = CellAreas(g.Mesh, touching);
  for (const ArrangementPatch& p : touching.Patches)
    EXPECT_NEAR(areas[p.LeftCell], 0.5, 1e-12); // both lobes are on the left
  ExpectValid(g.Mesh, touching, 1);

  // Crossing itself there: the second lobe turns clockwise, so it is on the right.
  const Arrangement crossing = ArrangeOrDie(
    g.Mesh, g.Trace({ { { 2, 2 }, { 3, 1.5 }, { 3, 2.5 }, { 2, 2 }, { 1, 1.5 }, { 1, 2.5 } } }));
  EXPECT_EQ(crossing.NumberOfCells, 3);
  ASSERT_EQ(crossing.Patches.size(), 2u);
  const std::vector<double> a2 = CellAreas(g.Mesh, crossing);
  int leftLobes = 0, rightLobes = 0;
  for (const ArrangementPatch& p : crossing.Patches)
  {
    leftLobes += std::abs(a2[p.LeftCell] - 0.5) < 1e-12;
    rightLobes += std::abs(a2[p.RightCell] - 0.5) < 1e-12;
  }
  EXPECT_EQ(leftLobes, 1);
  EXPECT_EQ(rightLobes, 1);
  ExpectValid(g.Mesh, crossing, 1);
}

TEST(ArrangementDegenerate, ThreeCurvesThroughOnePoint)
{
  GridFixture g;
  // A horizontal, a vertical and a steep line all through (1.25, 1.75), inside a triangle.
  const Arrangement arr = ArrangeOrDie(g.Mesh,
    g.Trace({ { { 0.5, 1.75 }, { 2.5, 1.75 }, { 1.5, 3.0 } },
      { { 1.25, 0.5 }, { 1.25, 3.2 }, { 0.3, 2.0 } },
      { { 1.0, 1.0 }, { 1.5, 2.5 }, { 2.5, 0.6 } } }));
  ExpectValid(g.Mesh, arr, 1);
  EXPECT_GE(arr.NumberOfCells, 7);
}

TEST(ArrangementDegenerate, RepeatedPointsAndMeshBoundary)
{
  GridFixture g;
  // Zero-length segments (repeated points) are skipped.
  TracedCurve c = TraceOrDie(g.Tracer, { { 0.5, 0.5 }, { 1.5, 0.5 }, { 1.5, 1.5 } });
  c.Points.insert(c.Points.begin() + 2, c.Points[2]);
  c.Points.push_back(c.Points.back());
  const Arrangement arr = ArrangeOrDie(g.Mesh, { c });
  EXPECT_EQ(arr.NumberOfCells, 2);
  // A curve along the mesh boundary separates nothing; its outer side is no cell.
  const Arrangement boundary =
    ArrangeOrDie(g.Mesh, g.Trace({ { { 0, 0 }, { 4, 0 }, { 4, 4 }, { 0, 4 } } }));
  EXPECT_EQ(boundary.NumberOfCells, 1);
  ASSERT_EQ(boundary.Patches.size(), 1u);
  EXPECT_EQ(boundary.Patches[0].LeftCell, 0);
  EXPECT_EQ(boundary.Patches[0].RightCell, -1);
  EXPECT_TRUE(boundary.CellGraph.empty());
}

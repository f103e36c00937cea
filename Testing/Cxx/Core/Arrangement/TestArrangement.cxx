// Arrangement on flat, spherical and toroidal meshes: cell counts against independent
// computations, area conservation, conformity, orientation of the cell graph, determinism.
#include "ArrangementTestUtils.h"

#include <algorithm>

using namespace boolsurf;
using namespace boolsurf::testing;

namespace
{

// Cell on the left of the first patch of curve `curve`.
int LeftCellOfCurve(const Arrangement& arr, int curve)
{
  for (const ArrangementPatch& p : arr.Patches)
    if (p.Curve == curve)
      return p.LeftCell;
  return -1;
}

// Two arrangements of the same curves on the same mesh are identical, bit for bit.
void ExpectSameArrangement(const TriangleMesh& mesh, const Arrangement& a, const Arrangement& b)
{
  EXPECT_EQ(a.NumberOfCells, b.NumberOfCells);
  std::vector<int> cellsA, cellsB;
  WriteTriangleCells(a, cellsA);
  WriteTriangleCells(b, cellsB);
  EXPECT_EQ(cellsA, cellsB);
  EXPECT_EQ(a.CellFirstTriangle, b.CellFirstTriangle);
  EXPECT_EQ(a.RefinedSlot, b.RefinedSlot);
  EXPECT_EQ(a.PieceOffset, b.PieceOffset);
  EXPECT_EQ(a.FirstPieces, b.FirstPieces);
  EXPECT_EQ(a.AppendedPieces, b.AppendedPieces);
  EXPECT_EQ(a.AppendedSources, b.AppendedSources);
  const RefinedSurfaceArrays wholeA = RefinedSurfaceArrays::Of(mesh, a);
  const RefinedSurfaceArrays wholeB = RefinedSurfaceArrays::Of(mesh, b);
  EXPECT_EQ(wholeA.Triangles, wholeB.Triangles);
  EXPECT_EQ(wholeA.SourceTriangle, wholeB.SourceTriangle);
  ASSERT_EQ(wholeA.Positions.size(), wholeB.Positions.size());
  for (size_t i = 0; i < wholeB.Positions.size(); ++i)
  {
    ASSERT_EQ(Distance(wholeA.Positions[i], wholeB.Positions[i]), 0.0) << "point " << i;
  }
  ASSERT_EQ(a.CurvePointSurface.size(), b.CurvePointSurface.size());
  for (size_t i = 0; i < b.CurvePointSurface.size(); ++i)
  {
    ASSERT_EQ(a.CurvePointSurface[i].Triangle, b.CurvePointSurface[i].Triangle);
    ASSERT_EQ(a.CurvePointSurface[i].U, b.CurvePointSurface[i].U);
    ASSERT_EQ(a.CurvePointSurface[i].V, b.CurvePointSurface[i].V);
  }
  ASSERT_EQ(a.NumberOfMeshVertices, b.NumberOfMeshVertices);
  ASSERT_EQ(a.CurvePointOnMesh.size(), b.CurvePointOnMesh.size());
  for (size_t i = 0; i < b.CurvePointOnMesh.size(); ++i)
  {
    ASSERT_TRUE(a.CurvePointOnMesh[i] == b.CurvePointOnMesh[i]) << "curve point " << i;
  }
  ASSERT_EQ(a.Patches.size(), b.Patches.size());
  for (size_t i = 0; i < b.Patches.size(); ++i)
  {
    EXPECT_EQ(a.Patches[i].Points, b.Patches[i].Points);
    EXPECT_EQ(a.Patches[i].LeftCell, b.Patches[i].LeftCell);
    EXPECT_EQ(a.Patches[i].RightCell, b.Patches[i].RightCell);
  }
  ASSERT_EQ(a.CellGraph.size(), b.CellGraph.size());
  for (size_t i = 0; i < b.CellGraph.size(); ++i)
  {
    EXPECT_EQ(a.CellGraph[i].LeftCell, b.CellGraph[i].LeftCell);
    EXPECT_EQ(a.CellGraph[i].RightCell, b.CellGraph[i].RightCell);
  }
}

} // namespace

TEST(Arrangement, SingleSquareOnJitteredMesh)
{
  const TriangleMesh mesh = MeshOf(MakeFlatSquare(12, 1.0, 0.3, 7));
  FlatPolygonTracer tracer(mesh);
  const std::vector<Vec2> square{ { 0.2, 0.2 }, { 0.7, 0.25 }, { 0.75, 0.8 }, { 0.25, 0.7 } };
  const Arrangement arr = ArrangeOrDie(mesh, { TraceOrDie(tracer, square) });
  ASSERT_EQ(arr.NumberOfCells, 2);
  ExpectAreasConserved(mesh, arr);
  ExpectConforming(mesh, arr);
  // A counter-clockwise curve on a +z mesh has its interior on the left.
  ASSERT_EQ(arr.Patches.size(), 1u);
  ASSERT_EQ(arr.CellGraph.size(), 1u);
  const int inside = arr.CellGraph[0].LeftCell;
  EXPECT_EQ(arr.CellGraph[0].RightCell, 1 - inside);
  double expected = 0.0;
  for (int i = 0; i < 4; ++i)
    expected += 0.5 * Cross(square[i], square[(i + 1) % 4]);
  EXPECT_NEAR(CellAreas(mesh, arr)[inside], expected, 1e-12);
  EXPECT_EQ(arr.Patches[0].Points.front(), arr.Patches[0].Points.back()); // a loop
  EXPECT_NEAR(arr.Patches[0].Length,
    Length(square[1] - square[0]) + Length(square[2] - square[1]) + Length(square[3] - square[2]) +
      Length(square[0] - square[3]),
    1e-12);
  const RefinedSurfaceArrays whole = RefinedSurfaceArrays::Of(mesh, arr);
  for (size_t r = 0; r < whole.Triangles.size(); ++r)
  {
    const auto& t = whole.Triangles[r];
    EXPECT_GT(
      SignedPlanarArea(whole.Positions[t[0]], whole.Positions[t[1]], whole.Positions[t[2]]), 0)
      << "refined triangle " << r << " is flipped";
  }
  // Every refined point's surface form evaluates to its position.
  for (size_t p = 0; p < whole.Positions.size(); ++p)
  {
    const SurfacePoint s = arr.GetPointSurface(mesh, static_cast<int>(p));
    const Vec3 q = mesh.Evaluate(s.Triangle, s.U, s.V);
    if (static_cast<int>(p) < arr.NumberOfMeshVertices)
    {
      // A vertex's form is derived, and must be what ToSurfacePoint writes, bit for bit.
      const SurfacePoint written = ToSurfacePoint(mesh, arr.GetPointOnMesh(static_cast<int>(p)));
      EXPECT_EQ(s.Triangle, written.Triangle) << "vertex " << p;
      EXPECT_EQ(s.U, written.U) << "vertex " << p;
      EXPECT_EQ(s.V, written.V) << "vertex " << p;
    }
    EXPECT_LT(Distance(q, whole.Positions[p]), 1e-12);
    // and its canonical form too (mesh vertices are not stored but derived from their id)
    EXPECT_LT(
      Distance(PositionOf(mesh, arr.GetPointOnMesh(static_cast<int>(p))), whole.Positions[p]),
      1e-12);
  }
}

TEST(Arrangement, TwoOverlappingSquaresAreas)
{
  const TriangleMesh mesh = MeshOf(MakeFlatSquare(16, 1.0, 0.25, 3));
  FlatPolygonTracer tracer(mesh);
  std::vector<TracedCurve> curves{
    TraceOrDie(tracer, { { 0.1, 0.1 }, { 0.6, 0.1 }, { 0.6, 0.6 }, { 0.1, 0.6 } }, true, 0, 0),
    TraceOrDie(tracer, { { 0.3, 0.3 }, { 0.9, 0.3 }, { 0.9, 0.9 }, { 0.3, 0.9 } }, true, 1, 1)
  };
  const Arrangement arr = ArrangeOrDie(mesh, curves);
  ASSERT_EQ(arr.NumberOfCells, 4);
  ExpectAreasConserved(mesh, arr);
  ExpectConforming(mesh, arr);
  std::vector<double> areas = CellAreas(mesh, arr);
  std::sort(areas.begin(), areas.end());
  EXPECT_NEAR(areas[0], 0.09, 1e-12); // A and B
  EXPECT_NEAR(areas[1], 0.16, 1e-12); // A only
  EXPECT_NEAR(areas[2], 0.27, 1e-12); // B only
  EXPECT_NEAR(areas[3], 0.48, 1e-12); // outside
  EXPECT_EQ(arr.Patches.size(), 4u);  // two crossings cut each square in two
  EXPECT_EQ(arr.NumberOfPatchGraphVertices, 2);
  for (const CellGraphArc& a : arr.CellGraph)
    EXPECT_NE(a.LeftCell, a.RightCell);
}

TEST(Arrangement, RandomSelfIntersectingPolygonsMatchPlanarCount)
{
  for (std::uint32_t seed = 1; seed <= 12; ++seed)
  {
    const TriangleMesh mesh = MeshOf(MakeFlatSquare(20, 1.0, 0.3, seed));
    FlatPolygonTracer tracer(mesh);
    std::mt19937 rng(seed * 7919u);
    std::vector<std::vector<Vec2>> polygons;
    std::vector<TracedCurve> curves;
    const int count = 1 + seed % 4;
    for (int c = 0; c < count; ++c)
    {
      polygons.push_back(RandomPolygon(rng, 4 + (seed + c) % 5, 0.05, 0.95));
      curves.push_back(TraceOrDie(tracer, polygons.back(), true, c, c));
    }
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Arrangement arr = ArrangeOrDie(mesh, curves);
    const PlanarCount expected = CountPlanarArrangement(polygons);
    EXPECT_EQ(arr.NumberOfCells, expected.Faces());
    // Patch-graph vertices: the crossings, plus one per curve that meets nothing (a loop).
    std::vector<int> patchesPerCurve(curves.size(), 0);
    for (const ArrangementPatch& p : arr.Patches)
      ++patchesPerCurve[p.Curve];
    const int loops = static_cast<int>(
      std::count_if(patchesPerCurve.begin(), patchesPerCurve.end(), [](int n) { return n == 1; }));
    EXPECT_EQ(arr.NumberOfPatchGraphVertices, expected.Crossings + loops);
    ExpectAreasConserved(mesh, arr);
    ExpectConforming(mesh, arr);
    // In a disc, V - E + F = 1 + (connected components of the union of the curves).
    EXPECT_EQ(PatchGraphEuler(arr), 1 + expected.Components);
  }
}

TEST(Arrangement, SameResultWithOneAndTwoThreads)
{
  const TriangleMesh mesh = MeshOf(MakeFlatSquare(40, 1.0, 0.3, 11));
  FlatPolygonTracer tracer(mesh);
  std::mt19937 rng(5);
  std::vector<TracedCurve> curves;
  for (int c = 0; c < 6; ++c)
    curves.push_back(TraceOrDie(tracer, RandomPolygon(rng, 7, 0.02, 0.98), true, c % 3, c));
  const Arrangement one = ArrangeOrDie(mesh, curves, 1);
  const Arrangement two = ArrangeOrDie(mesh, curves, 2);
  ExpectSameArrangement(mesh, one, two);
}

TEST(Arrangement, SphereGreatCirclesEuler)
{
  const TriangleMesh mesh = MeshOf(MakeIcosphere(4));
  std::mt19937 rng(3);
  std::normal_distribution<double> g;
  std::vector<TracedCurve> curves;
  for (int c = 0; c < 4; ++c)
  {
    const Vec3 n{ g(rng), g(rng), g(rng) };
    for (TracedCurve& curve : PlaneSectionCurves(mesh, n, 0.0, c, c))
      curves.push_back(curve);
  }
  ASSERT_EQ(curves.size(), 4u);
  const Arrangement arr = ArrangeOrDie(mesh, curves);
  // Four great circles in general position: each pair meets twice, V = 12, E = 24, F = 14.
  EXPECT_EQ(arr.NumberOfPatchGraphVertices, 12);
  EXPECT_EQ(arr.Patches.size(), 24u);
  EXPECT_EQ(arr.NumberOfCells, 14);
  EXPECT_EQ(PatchGraphEuler(arr), 2);
  ExpectAreasConserved(mesh, arr);
  ExpectConforming(mesh, arr);
}

TEST(Arrangement, SphereSmallCirclesEuler)
{
  const TriangleMesh mesh = MeshOf(MakeIcosphere(3));
  std::mt19937 rng(9);
  std::normal_distribution<double> g;
  std::vector<TracedCurve> curves;
  // Small circles (offset planes) chained so that their union is connected.
  const Vec3 normals[3] = { { 1, 0.1, 0.2 }, { 0.8, 0.6, -0.1 }, { 0.3, 0.9, 0.25 } };
  for (int c = 0; c < 3; ++c)
  {
    const Vec3 n = (1.0 / Length(normals[c])) * normals[c];
    for (TracedCurve& curve : PlaneSectionCurves(mesh, n, 0.5, c, c))
      curves.push_back(curve);
  }
  ASSERT_EQ(curves.size(), 3u);
  const Arrangement arr = ArrangeOrDie(mesh, curves);
  EXPECT_EQ(PatchGraphEuler(arr), 2);
  ExpectAreasConserved(mesh, arr);
  ExpectConforming(mesh, arr);
}

TEST(Arrangement, TorusCutIntoDiscsEuler)
{
  const double R = 2.0, r = 0.7;
  const TriangleMesh mesh = MeshOf(MakeTorus(R, r, 48, 24));
  std::vector<TracedCurve> curves;
  // Plane y = 0.01 through (almost) the axis: two meridians. Plane z = 0.3 r: two parallels.
  for (TracedCurve& c : PlaneSectionCurves(mesh, { 0.0, 1.0, 0.0 }, 0.01, 0, 0))
    curves.push_back(c);
  for (TracedCurve& c : PlaneSectionCurves(mesh, { 0.0, 0.0, 1.0 }, 0.3 * r, 1, 2))
    curves.push_back(c);
  ASSERT_EQ(curves.size(), 4u);
  const Arrangement arr = ArrangeOrDie(mesh, curves);
  EXPECT_EQ(arr.NumberOfPatchGraphVertices, 4);
  EXPECT_EQ(arr.Patches.size(), 8u);
  EXPECT_EQ(arr.NumberOfCells, 4);
  EXPECT_EQ(PatchGraphEuler(arr), 0); // torus
  ExpectAreasConserved(mesh, arr);
  ExpectConforming(mesh, arr);
}

TEST(Arrangement, TorusNonSeparatingLoopGivesSelfArc)
{
  const TriangleMesh mesh = MeshOf(MakeTorus(2.0, 0.7, 32, 16));
  // One meridian alone does not separate the torus: one cell, an arc from it to itself.
  std::vector<TracedCurve> meridians = PlaneSectionCurves(mesh, { 0.0, 1.0, 0.0 }, 0.01, 0, 0);
  ASSERT_EQ(meridians.size(), 2u);
  const Arrangement arr = ArrangeOrDie(mesh, { meridians[0] });
  EXPECT_EQ(arr.NumberOfCells, 1);
  ASSERT_EQ(arr.CellGraph.size(), 1u);
  EXPECT_EQ(arr.CellGraph[0].LeftCell, arr.CellGraph[0].RightCell);
  const Arrangement both = ArrangeOrDie(mesh, meridians);
  EXPECT_EQ(both.NumberOfCells, 2);
}

TEST(Arrangement, OpenCurvesAreRefinedButDoNotSeparate)
{
  const TriangleMesh mesh = MeshOf(MakeFlatSquare(10, 1.0, 0.2, 4));
  FlatPolygonTracer tracer(mesh);
  std::vector<TracedCurve> curves{
    TraceOrDie(tracer, { { 0.3, 0.3 }, { 0.7, 0.3 }, { 0.7, 0.7 }, { 0.3, 0.7 } }, true, 0, 0),
    // Open: from inside the square to outside it, crossing its side once... and back in.
    TraceOrDie(tracer, { { 0.05, 0.5 }, { 0.5, 0.52 }, { 0.95, 0.45 } }, false, 1, 1)
  };
  const Arrangement arr = ArrangeOrDie(mesh, curves);
  EXPECT_EQ(arr.NumberOfCells, 2);
  ExpectAreasConserved(mesh, arr);
  ExpectConforming(mesh, arr);
  int openPatches = 0;
  for (const ArrangementPatch& p : arr.Patches)
  {
    if (p.Curve == 1)
    {
      ++openPatches;
      EXPECT_FALSE(p.Closed);
      EXPECT_EQ(p.LeftCell, p.RightCell); // nothing separates its sides
    }
  }
  EXPECT_EQ(openPatches, 3); // cut twice by the square
  for (const CellGraphArc& a : arr.CellGraph)
    EXPECT_EQ(a.Shape, 0);
  // The open curve runs along refined edges.
  std::set<std::pair<int, int>> edges;
  for (const auto& t : RefinedSurfaceArrays::Of(mesh, arr).Triangles)
    for (int j = 0; j < 3; ++j)
      edges.insert({ std::min(t[j], t[(j + 1) % 3]), std::max(t[j], t[(j + 1) % 3]) });
  const std::vector<int>& path = arr.CurvePoints[1];
  ASSERT_GT(path.size(), 2u);
  for (size_t i = 0; i + 1 < path.size(); ++i)
    EXPECT_TRUE(edges.count({ std::min(path[i], path[i + 1]), std::max(path[i], path[i + 1]) }));

  // The open curve alone, from boundary to boundary, still leaves one cell.
  const Arrangement alone =
    ArrangeOrDie(mesh, { TraceOrDie(tracer, { { 0.0, 0.37 }, { 1.0, 0.61 } }, false, 0, 0) });
  EXPECT_EQ(alone.NumberOfCells, 1);
  EXPECT_GT(alone.NumberOfRefinedSourceTriangles, 0);
}

TEST(Arrangement, ErrorsNameCurveAndPoint)
{
  const TriangleMesh mesh = MeshOf(MakeFlatSquare(4, 4.0));
  Arrangement arr;
  std::string error;
  TracedCurve c;
  c.Closed = false;
  c.CurveId = 12;
  CanonicalPoint a, b;
  a.Location = PointLocation::Vertex;
  a.Id = 0;
  b.Location = PointLocation::Vertex;
  b.Id = 24; // the far corner: no common triangle
  c.Points = { a, b };
  EXPECT_FALSE(ComputeArrangement(mesh, { c }, {}, arr, error));
  EXPECT_NE(error.find("curve 0"), std::string::npos) << error;
  EXPECT_NE(error.find("share no triangle"), std::string::npos) << error;

  b.Id = 999;
  c.Points = { a, b };
  EXPECT_FALSE(ComputeArrangement(mesh, { c }, {}, arr, error));
  EXPECT_NE(error.find("point 1"), std::string::npos) << error;
  EXPECT_NE(error.find("out of range"), std::string::npos) << error;

  b.Location = PointLocation::Face;
  b.Id = -3;
  c.Points = { a, b };
  EXPECT_FALSE(ComputeArrangement(mesh, { c }, {}, arr, error));
  EXPECT_NE(error.find("triangle id -3"), std::string::npos) << error;

  c.Points = { a };
  EXPECT_FALSE(ComputeArrangement(mesh, { c }, {}, arr, error));

  // No curves at all: one cell per connected component, nothing refined.
  EXPECT_TRUE(ComputeArrangement(mesh, {}, {}, arr, error)) << error;
  EXPECT_EQ(arr.NumberOfCells, 1);
  EXPECT_EQ(arr.GetNumberOfTriangles(), mesh.GetNumberOfTriangles());
}

// The segment map is built per curve in parallel: among many curves, several of them bad, the
// error must still name the first bad one in curve order, and a bad point (checked first) must
// be named before a later step's failure (two points sharing no triangle) of an earlier curve.
TEST(Arrangement, ErrorsNameTheFirstBadCurveInOrder)
{
  const TriangleMesh mesh = MeshOf(MakeFlatSquare(4, 4.0));
  const auto vertex = [](int id)
  {
    CanonicalPoint p;
    p.Location = PointLocation::Vertex;
    p.Id = id;
    return p;
  };
  TracedCurve good;
  good.Closed = false;
  good.Points = { vertex(0), vertex(1) }; // along one mesh edge
  TracedCurve farApart = good;
  farApart.Points = { vertex(0), vertex(24) }; // opposite corners: no common triangle
  TracedCurve outOfRange = good;
  outOfRange.Points = { vertex(0), vertex(1), vertex(999) };

  std::vector<TracedCurve> curves(64, good);
  curves[23] = farApart;
  curves[41] = farApart;
  curves[57] = farApart;
  Arrangement arr;
  std::string error;
  EXPECT_FALSE(ComputeArrangement(mesh, curves, {}, arr, error));
  EXPECT_NE(error.find("curve 23 "), std::string::npos) << error;
  EXPECT_NE(error.find("share no triangle"), std::string::npos) << error;
  EXPECT_EQ(arr.FailedCurve, 23);
  EXPECT_EQ(arr.FailedPoint, 0);

  curves[50] = outOfRange;
  EXPECT_FALSE(ComputeArrangement(mesh, curves, {}, arr, error));
  EXPECT_NE(error.find("curve 50 "), std::string::npos) << error;
  EXPECT_NE(error.find("point 2"), std::string::npos) << error;
  EXPECT_EQ(arr.FailedCurve, 50);
  EXPECT_EQ(arr.FailedPoint, 2);

  curves[23] = curves[41] = curves[57] = good;
  curves[50] = good;
  EXPECT_TRUE(ComputeArrangement(mesh, curves, {}, arr, error)) << error;
}

// An edit computes into the Arrangement of the previous one (its buffers, its per-triangle
// states reset where the last curves set them, its mesh-vertex points kept): every result must
// equal that of a fresh Arrangement, whatever came before.
TEST(Arrangement, EditsIntoTheSameArrangementEqualFreshOnes)
{
  const TriangleMesh mesh = MeshOf(MakeFlatSquare(40, 1.0, 0.3, 3));
  FlatPolygonTracer tracer(mesh);
  Arrangement reused;
  // The whole refined surface, updated edit after edit as the Surface Arrangement filter does
  // (only the entries curves crossed then or cross now are rewritten): always the fresh arrays.
  RefinedSurfaceArrays updated;
  const auto expectUpdatedArrays = [&](const TriangleMesh& m)
  {
    updated.Update(m, reused);
    const RefinedSurfaceArrays fresh = RefinedSurfaceArrays::Of(m, reused);
    EXPECT_EQ(updated.Triangles, fresh.Triangles);
    EXPECT_EQ(updated.SourceTriangle, fresh.SourceTriangle);
    ASSERT_EQ(updated.Positions.size(), fresh.Positions.size());
    for (std::size_t p = 0; p < fresh.Positions.size(); ++p)
      ASSERT_EQ(Distance(updated.Positions[p], fresh.Positions[p]), 0.0) << "point " << p;
  };
  std::string error;
  for (std::uint32_t edit = 0; edit < 8; ++edit)
  {
    std::mt19937 rng(100 + edit);
    std::vector<TracedCurve> curves;
    const int count = 1 + static_cast<int>(edit % 4) * 2;
    for (int c = 0; c < count; ++c)
      curves.push_back(TraceOrDie(tracer, RandomPolygon(rng, 5 + c % 3, 0.02, 0.98), true, c, c));
    SCOPED_TRACE("edit " + std::to_string(edit));
    ASSERT_TRUE(ComputeArrangement(mesh, curves, ArrangementOptions(), reused, error)) << error;
    ExpectCellsAreFloodFill(mesh, reused);
    ExpectSameArrangement(mesh, reused, ArrangeOrDie(mesh, curves));
    expectUpdatedArrays(mesh);
  }
  // Another mesh into the same Arrangement: nothing of the first mesh may survive.
  const TriangleMesh other = MeshOf(MakeFlatSquare(17, 1.0, 0.2, 9));
  FlatPolygonTracer otherTracer(other);
  std::mt19937 rng(7);
  const std::vector<TracedCurve> curves{ TraceOrDie(
    otherTracer, RandomPolygon(rng, 6, 0.05, 0.95), true, 0, 0) };
  ASSERT_TRUE(ComputeArrangement(other, curves, ArrangementOptions(), reused, error)) << error;
  ExpectCellsAreFloodFill(other, reused);
  ExpectSameArrangement(other, reused, ArrangeOrDie(other, curves));
  expectUpdatedArrays(other);
}

// Edits whose small curves move from place to place on a mesh of several tile blocks (about
// 1,100 tiles, 35 groups, 2 blocks): each edit's flood fill starts from the blocks' and
// groups' precomputed components where no curve passes and from single tiles where one does,
// so the blocks touched before and now must be restored; every result equals a fresh one.
TEST(Arrangement, EditsAcrossTileBlocksEqualFreshOnes)
{
  const TriangleMesh mesh = MeshOf(MakeFlatSquare(190, 1.0, 0.3, 5));
  FlatPolygonTracer tracer(mesh);
  Arrangement reused;
  std::string error;
  for (std::uint32_t edit = 0; edit < 6; ++edit)
  {
    std::mt19937 rng(300 + edit);
    std::uniform_real_distribution<double> corner(0.05, 0.75);
    std::vector<TracedCurve> curves;
    const int count = 1 + static_cast<int>(edit % 3);
    for (int c = 0; c < count; ++c)
    {
      const double x = corner(rng), y = corner(rng);
      curves.push_back(TraceOrDie(tracer,
        { { x, y }, { x + 0.2, y + 0.03 }, { x + 0.12, y + 0.2 }, { x + 0.02, y + 0.1 } },
        true,
        c,
        c));
    }
    SCOPED_TRACE("edit " + std::to_string(edit));
    ASSERT_TRUE(ComputeArrangement(mesh, curves, ArrangementOptions(), reused, error)) << error;
    ASSERT_GT(reused.Tiles->GetNumberOfBlocks(), 1);
    ExpectCellsAreFloodFill(mesh, reused);
    ExpectSameArrangement(mesh, reused, ArrangeOrDie(mesh, curves));
  }
}

// A per-triangle cell array kept from edit to edit and updated only where tiles changed (the
// Surface Arrangement filter's output) always equals one written whole, also across a change
// of mesh and when an edit adds or removes cells (which renumbers them).
TEST(Arrangement, UpdatedTriangleCellsEqualWrittenOnes)
{
  const TriangleMesh mesh = MeshOf(MakeFlatSquare(40, 1.0, 0.3, 11));
  const TriangleMesh other = MeshOf(MakeFlatSquare(25, 1.0, 0.3, 12));
  Arrangement arr;
  std::vector<int> kept, whole;
  WrittenTriangleCells written;
  std::string error;
  int step = 0;
  for (const TriangleMesh* m : { &mesh, &mesh, &mesh, &mesh, &other, &other, &mesh, &mesh })
  {
    FlatPolygonTracer tracer(*m);
    std::mt19937 rng(900 + step);
    std::vector<TracedCurve> curves;
    const int count = 1 + step % 3; // cells come and go
    for (int c = 0; c < count; ++c)
      curves.push_back(TraceOrDie(tracer, RandomPolygon(rng, 5, 0.1, 0.9), true, c, c));
    SCOPED_TRACE("step " + std::to_string(step++));
    ASSERT_TRUE(ComputeArrangement(*m, curves, ArrangementOptions(), arr, error)) << error;
    UpdateTriangleCells(arr, kept, written);
    WriteTriangleCells(arr, whole);
    ASSERT_EQ(kept, whole);
  }
}

// A refused edit leaves the refined triangles as the last good edit wrote them, and the next
// edit restores only what that one refined: every later result still equals a fresh one.
TEST(Arrangement, EditsAfterARefusedEditEqualFreshOnes)
{
  const TriangleMesh mesh = MeshOf(MakeFlatSquare(30, 1.0, 0.3, 5));
  FlatPolygonTracer tracer(mesh);
  Arrangement reused;
  std::string error;
  TracedCurve broken;
  broken.Closed = false;
  CanonicalPoint a, b;
  a.Location = b.Location = PointLocation::Vertex;
  a.Id = 0;
  b.Id = mesh.GetNumberOfVertices() - 1; // far corner: no common triangle
  broken.Points = { a, b };
  for (std::uint32_t edit = 0; edit < 6; ++edit)
  {
    std::mt19937 rng(500 + edit);
    std::vector<TracedCurve> curves{ TraceOrDie(tracer, RandomPolygon(rng, 6, 0.05, 0.95)),
      TraceOrDie(tracer, RandomPolygon(rng, 4, 0.2, 0.8), true, 1, 1) };
    SCOPED_TRACE("edit " + std::to_string(edit));
    ASSERT_TRUE(ComputeArrangement(mesh, curves, ArrangementOptions(), reused, error)) << error;
    ExpectCellsAreFloodFill(mesh, reused);
    ExpectSameArrangement(mesh, reused, ArrangeOrDie(mesh, curves));
    curves.push_back(broken);
    EXPECT_FALSE(ComputeArrangement(mesh, curves, ArrangementOptions(), reused, error));
  }
}

// Unusable mesh triangles (repeated or out-of-range corners) keep their index as holes: no
// points, no source, no cell; the usable ones are arranged as without them.
TEST(Arrangement, UnusableTrianglesAreHoles)
{
  MeshData square = MakeFlatSquare(12, 1.0, 0.2, 4);
  MeshData holed = square;
  const int at = static_cast<int>(holed.Triangles.size()) / 2;
  holed.Triangles.insert(holed.Triangles.begin() + at, { 3, 3, 4 });
  holed.Triangles.push_back({ 0, 1, 100000 });
  const TriangleMesh plain = MeshOf(square), mesh = MeshOf(holed);
  ASSERT_FALSE(mesh.IsUsable(at));
  FlatPolygonTracer plainTracer(plain), tracer(mesh);
  Arrangement reused;
  std::string error;
  for (std::uint32_t edit = 0; edit < 4; ++edit)
  {
    std::mt19937 rng(700 + edit), sameRng(700 + edit);
    const std::vector<TracedCurve> curves{ TraceOrDie(tracer, RandomPolygon(rng, 6, 0.05, 0.95)) };
    const std::vector<TracedCurve> plainCurves{ TraceOrDie(
      plainTracer, RandomPolygon(sameRng, 6, 0.05, 0.95)) };
    ASSERT_TRUE(ComputeArrangement(mesh, curves, ArrangementOptions(), reused, error)) << error;
    const Arrangement expected = ArrangeOrDie(plain, plainCurves);
    EXPECT_EQ(reused.NumberOfHoles, 2);
    EXPECT_EQ(reused.NumberOfCells, expected.NumberOfCells);
    for (int t : { at, mesh.GetNumberOfTriangles() - 1 })
    {
      EXPECT_EQ(reused.GetSourceTriangle(mesh, t), -1);
      EXPECT_EQ(reused.GetTriangle(mesh, t)[0], -1);
      EXPECT_EQ(reused.CellOfTriangle(t), -1);
      EXPECT_EQ(CountRefinedTriangles(mesh, reused, t), 0);
    }
    const RefinedSurfaceArrays whole = RefinedSurfaceArrays::Of(mesh, reused);
    std::vector<double> areas(reused.NumberOfCells, 0.0);
    for (std::size_t r = 0; r < whole.Triangles.size(); ++r)
    {
      if (whole.SourceTriangle[r] < 0)
        continue;
      const auto& t = whole.Triangles[r];
      areas[reused.CellOfTriangle(static_cast<int>(r))] +=
        TriangleArea(whole.Positions[t[0]], whole.Positions[t[1]], whole.Positions[t[2]]);
    }
    std::vector<double> want = CellAreas(plain, expected);
    std::sort(areas.begin(), areas.end());
    std::sort(want.begin(), want.end());
    ASSERT_EQ(areas.size(), want.size());
    for (std::size_t c = 0; c < want.size(); ++c)
      EXPECT_NEAR(areas[c], want[c], 1e-12);
  }
}

// An edit that adds a few points and triangles (a curve moved or added over a few triangles)
// computes in place: the buffers of the refined surface are not reallocated, since the first
// edit that grew one by a single entry used to double it (a copy and fresh pages: ~30 ms on a
// million triangles, in the middle of a drag).
TEST(Arrangement, AnEditAddingAFewPointsKeepsItsBuffers)
{
  const TriangleMesh mesh = MeshOf(MakeFlatSquare(40, 1.0, 0.3, 5));
  FlatPolygonTracer tracer(mesh);
  std::mt19937 rng(41);
  std::vector<TracedCurve> curves{ TraceOrDie(
    tracer, RandomPolygon(rng, 6, 0.1, 0.9), true, 0, 0) };
  Arrangement arr;
  std::string error;
  ASSERT_TRUE(ComputeArrangement(mesh, curves, ArrangementOptions(), arr, error)) << error;
  const int points = arr.GetNumberOfPoints(), triangles = arr.GetNumberOfTriangles();
  const Vec3* positions = arr.CurvePositions.data();
  const std::array<int, 3>* refined = arr.AppendedPieces.data();
  const int* cells = arr.LooseCell.data();
  // A small second curve over a few triangles.
  curves.push_back(TraceOrDie(tracer, RandomPolygon(rng, 4, 0.47, 0.53), true, 1, 1));
  ASSERT_TRUE(ComputeArrangement(mesh, curves, ArrangementOptions(), arr, error)) << error;
  ASSERT_GT(arr.GetNumberOfPoints(), points);
  ASSERT_GT(arr.GetNumberOfTriangles(), triangles);
  EXPECT_EQ(arr.CurvePositions.data(), positions);
  EXPECT_EQ(arr.AppendedPieces.data(), refined);
  EXPECT_EQ(arr.LooseCell.data(), cells);
  ExpectSameArrangement(mesh, arr, ArrangeOrDie(mesh, curves));
}

// Two arrangements sharing their work buffers (as a filter that double-buffers its results
// does), computed in turn, across a change to another mesh with as many vertices: each result
// equals a fresh one, so neither keeps the other mesh's vertices.
TEST(Arrangement, ArrangementsSharingWorkBuffersEqualFreshOnes)
{
  const TriangleMesh first = MeshOf(MakeFlatSquare(20, 1.0, 0.3, 1));
  const TriangleMesh second = MeshOf(MakeFlatSquare(20, 1.0, 0.3, 2));
  ASSERT_EQ(first.GetNumberOfVertices(), second.GetNumberOfVertices());
  Arrangement a, b;
  std::string error;
  int step = 0;
  for (const TriangleMesh* mesh : { &first, &first, &second, &second, &first })
  {
    FlatPolygonTracer tracer(*mesh);
    for (Arrangement* out : { &a, &b })
    {
      std::mt19937 rng(300 + step++);
      const std::vector<TracedCurve> curves{
        TraceOrDie(tracer, RandomPolygon(rng, 6, 0.05, 0.95), true, 0, 0),
        TraceOrDie(tracer, RandomPolygon(rng, 5, 0.05, 0.95), true, 1, 1)
      };
      if (out == &b && a.Work)
      {
        b.Work = a.Work;
      }
      SCOPED_TRACE("step " + std::to_string(step));
      ASSERT_TRUE(ComputeArrangement(*mesh, curves, ArrangementOptions(), *out, error)) << error;
      ExpectSameArrangement(*mesh, *out, ArrangeOrDie(*mesh, curves));
    }
  }
  EXPECT_EQ(a.Work, b.Work);
}

// Tiles partition the usable triangles into connected groups of at most the requested size,
// each led by its lowest member, in increasing order of that member.
TEST(Arrangement, MeshTilesAreConnectedAndOrdered)
{
  const TriangleMesh mesh = MeshOf(MakeFlatSquare(30, 1.0, 0.3, 5));
  MeshTiles tiles;
  BuildMeshTiles(mesh, 64, tiles);
  const int nt = mesh.GetNumberOfTriangles();
  ASSERT_GT(tiles.GetNumberOfTiles(), 10);
  std::vector<int> seen(nt, 0);
  int previousFirst = -1;
  for (int k = 0; k < tiles.GetNumberOfTiles(); ++k)
  {
    const int begin = tiles.Offset[k], end = tiles.Offset[k + 1];
    ASSERT_GT(end, begin);
    ASSERT_LE(end - begin, 64);
    EXPECT_GT(tiles.Members[begin], previousFirst);
    previousFirst = tiles.Members[begin];
    EXPECT_TRUE(std::is_sorted(tiles.Members.begin() + begin, tiles.Members.begin() + end));
    // Connected: a search from the first member through neighbours in the tile reaches all.
    std::vector<int> queue{ tiles.Members[begin] };
    std::vector<char> reached(nt, 0);
    reached[queue[0]] = 1;
    for (size_t head = 0; head < queue.size(); ++head)
      for (int j = 0; j < 3; ++j)
      {
        const int n = mesh.GetNeighbor(queue[head], j);
        if (n >= 0 && !reached[n] && tiles.TileOfTriangle[n] == k)
        {
          reached[n] = 1;
          queue.push_back(n);
        }
      }
    EXPECT_EQ(static_cast<int>(queue.size()), end - begin) << "tile " << k << " is not connected";
    for (int i = begin; i < end; ++i)
    {
      ++seen[tiles.Members[i]];
      EXPECT_EQ(tiles.TileOfTriangle[tiles.Members[i]], k);
    }
  }
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
}

// Tile groups partition the tiles into groups connected over tile adjacency; the arcs inside
// groups and between them are exactly the tile pairs sharing an edge, and each group's
// precomputed root of a tile is the lowest tile of its component inside the group.
TEST(Arrangement, TileGroupsPartitionTheTileGraph)
{
  const TriangleMesh mesh = MeshOf(MakeFlatSquare(60, 1.0, 0.3, 8));
  for (int groupSize : { 1, 4, 32 })
  {
    SCOPED_TRACE("group size " + std::to_string(groupSize));
    MeshTiles tiles;
    BuildMeshTiles(mesh, 16, tiles, groupSize);
    const int count = tiles.GetNumberOfTiles();
    ASSERT_GT(tiles.GetNumberOfGroups(), 3);
    // The tile graph, from the triangles.
    std::set<std::pair<int, int>> adjacent;
    for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
      for (int j = 0; j < 3; ++j)
      {
        const int n = mesh.GetNeighbor(t, j);
        const int a = tiles.TileOfTriangle[t], b = n >= 0 ? tiles.TileOfTriangle[n] : -1;
        if (b >= 0 && a != b)
          adjacent.emplace(std::min(a, b), std::max(a, b));
      }
    std::set<std::pair<int, int>> listed;
    for (int g = 0; g < tiles.GetNumberOfGroups(); ++g)
      for (int i = tiles.GroupArcOffset[g]; i < tiles.GroupArcOffset[g + 1]; ++i)
      {
        const std::pair<int, int>& ab = tiles.GroupArcs[i];
        EXPECT_EQ(tiles.GroupOf[ab.first], g);
        EXPECT_EQ(tiles.GroupOf[ab.second], g);
        EXPECT_TRUE(listed.insert(ab).second);
      }
    const auto blockOf = [&](int k) { return tiles.BlockOf[tiles.GroupOf[k]]; };
    for (int b = 0; b < tiles.GetNumberOfBlocks(); ++b)
      for (int i = tiles.BlockArcOffset[b]; i < tiles.BlockArcOffset[b + 1]; ++i)
      {
        const std::pair<int, int>& ab = tiles.BlockArcs[i];
        EXPECT_NE(tiles.GroupOf[ab.first], tiles.GroupOf[ab.second]);
        EXPECT_EQ(blockOf(ab.first), b);
        EXPECT_EQ(blockOf(ab.second), b);
        EXPECT_TRUE(listed.insert(ab).second);
      }
    for (const std::pair<int, int>& ab : tiles.CrossBlockArcs)
    {
      EXPECT_NE(blockOf(ab.first), blockOf(ab.second));
      EXPECT_TRUE(listed.insert(ab).second);
    }
    EXPECT_EQ(listed, adjacent);
    // The tiles a search from tile k reaches without leaving the tiles where inside(tile).
    const auto reachedWithin = [&](int k, const auto& inside)
    {
      std::vector<int> queue{ k };
      std::set<int> reached{ k };
      for (size_t head = 0; head < queue.size(); ++head)
        for (const std::pair<int, int>& ab : adjacent)
        {
          const int other =
            ab.first == queue[head] ? ab.second : (ab.second == queue[head] ? ab.first : -1);
          if (other >= 0 && inside(other) && reached.insert(other).second)
            queue.push_back(other);
        }
      return reached;
    };
    // Groups: a partition, at most groupSize tiles, each connected; the root of a tile is the
    // lowest tile a search inside its group reaches from it.
    std::vector<int> seen(count, 0);
    for (int g = 0; g < tiles.GetNumberOfGroups(); ++g)
    {
      const int begin = tiles.GroupOffset[g], end = tiles.GroupOffset[g + 1];
      ASSERT_GT(end, begin);
      ASSERT_LE(end - begin, groupSize);
      for (int i = begin; i < end; ++i)
      {
        const int k = tiles.GroupTiles[i];
        ++seen[k];
        EXPECT_EQ(tiles.GroupOf[k], g);
        const std::set<int> reached =
          reachedWithin(k, [&](int other) { return tiles.GroupOf[other] == g; });
        EXPECT_EQ(static_cast<int>(reached.size()), end - begin) << "group " << g;
        EXPECT_EQ(tiles.GroupRoot[k], *reached.begin()) << "tile " << k;
      }
    }
    EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
    // Blocks: a partition of the groups, at most groupSize groups, each connected over the
    // tile graph; the block root of a tile is the lowest tile a search inside its block reaches.
    ASSERT_GT(tiles.GetNumberOfBlocks(), 0);
    if (groupSize > 1)
    {
      EXPECT_LT(tiles.GetNumberOfBlocks(), tiles.GetNumberOfGroups());
    }
    std::vector<int> groupSeen(tiles.GetNumberOfGroups(), 0);
    for (int b = 0; b < tiles.GetNumberOfBlocks(); ++b)
    {
      ASSERT_GT(tiles.BlockOffset[b + 1], tiles.BlockOffset[b]);
      ASSERT_LE(tiles.BlockOffset[b + 1] - tiles.BlockOffset[b], groupSize);
      int blockTiles = 0;
      for (int i = tiles.BlockOffset[b]; i < tiles.BlockOffset[b + 1]; ++i)
      {
        const int g = tiles.BlockGroups[i];
        ++groupSeen[g];
        EXPECT_EQ(tiles.BlockOf[g], b);
        blockTiles += tiles.GroupOffset[g + 1] - tiles.GroupOffset[g];
      }
      const int k = tiles.GroupTiles[tiles.GroupOffset[tiles.BlockGroups[tiles.BlockOffset[b]]]];
      const std::set<int> reached =
        reachedWithin(k, [&](int other) { return blockOf(other) == b; });
      EXPECT_EQ(static_cast<int>(reached.size()), blockTiles) << "block " << b;
      for (int other : reached)
      {
        EXPECT_EQ(tiles.BlockRoot[other], *reached.begin()) << "tile " << other;
      }
    }
    EXPECT_TRUE(std::all_of(groupSeen.begin(), groupSeen.end(), [](int n) { return n == 1; }));
  }
}

// The tiled flood fill (few tiles touched) and the whole-surface one (most touched) give the
// same cells, numbering and cell contents, with one thread and two.
TEST(Arrangement, TiledAndWholeSurfaceFloodFillsAgree)
{
  // 72 tiles in 3 groups, 700 tiles in 22 groups (most of them untouched by one curve), then
  // 2,800 tiles in about 90 groups and 3 blocks.
  for (int n : { 48, 150, 300 })
  {
    const TriangleMesh mesh = MeshOf(MakeFlatSquare(n, 1.0, 0.3, 6));
    FlatPolygonTracer tracer(mesh);
    for (int curvesCount : { 1, 12 }) // a few tiles touched, then most of them
    {
      std::mt19937 rng(31 + curvesCount);
      std::vector<TracedCurve> curves;
      for (int c = 0; c < curvesCount; ++c)
        curves.push_back(TraceOrDie(tracer, RandomPolygon(rng, 6, 0.05, 0.95), true, c, c));
      SCOPED_TRACE(std::to_string(curvesCount) + " curves");
      std::vector<Arrangement> results;
      for (FloodFillMethod method : { FloodFillMethod::Tiles, FloodFillMethod::Triangles })
        for (int threads : { 1, 2 })
        {
          ArrangementOptions options;
          options.Threads = threads;
          options.FloodFill = method;
          Arrangement arr;
          std::string error;
          ASSERT_TRUE(ComputeArrangement(mesh, curves, options, arr, error)) << error;
          ExpectCellsAreFloodFill(mesh, arr);
          results.push_back(std::move(arr));
        }
      for (size_t i = 1; i < results.size(); ++i)
      {
        SCOPED_TRACE("variant " + std::to_string(i));
        ExpectSameArrangement(mesh, results[i], results[0]);
      }
    }
  }
}

// Closed curves along a surface's open boundary (Labeling/BoundaryPlugs.h): polygons along one
// side, around corners, from side to side, along several stretches, around and along the loop
// of a hole, on aligned and irregular flat meshes, in both orientations and from every starting
// point; each against the planar winding numbers, the exact sweep and Clipper
// (LatticeDrawingChecks.h). On scanned meshes with holes (shared collection), curves along
// stretches of every boundary loop against a flood fill of the mesh's own triangles.
#include "../Degenerate/LatticeDrawingChecks.h"

#include "Labeling/BoundaryPlugs.h"
#include "Mesh/PlyReader.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <deque>
#include <random>
#include <set>

using namespace boolsurf;
using namespace boolsurf::testing;

namespace
{

using Points = std::vector<std::array<long long, 2>>;

double ShoelaceArea(const Points& p)
{
  double a = 0;
  for (size_t i = 0; i < p.size(); ++i)
  {
    const auto &u = p[i], &v = p[(i + 1) % p.size()];
    a += double(u[0]) * double(v[1]) - double(v[0]) * double(u[1]);
  }
  return 0.5 * a;
}

/// The polygon started at point `start`, walked forwards or backwards.
Points Rotated(const Points& p, size_t start, bool reversed)
{
  Points out;
  for (size_t i = 0; i < p.size(); ++i)
  {
    const size_t k = reversed ? (start + p.size() - i) % p.size() : (start + i) % p.size();
    out.push_back(p[k]);
  }
  return out;
}

/// Every start and orientation of `polygon` on `mesh`: the full checks, and the area of the
/// cells whose label is the polygon's orientation (+1 counter-clockwise, -1 clockwise) equal to
/// its exact shoelace area.
void CheckEveryStartAndOrientation(const TriangleMesh& mesh,
  const Points& polygon,
  const std::string& meshName,
  const FlatHole& hole = FlatHole())
{
  ClipperTally tally;
  int failures = 0;
  for (int reversed = 0; reversed < 2; ++reversed)
  {
    for (size_t start = 0; start < polygon.size(); ++start)
    {
      const Points p = Rotated(polygon, start, reversed != 0);
      const std::vector<LatticePolygon> drawing{ { 0, p } };
      SCOPED_TRACE(meshName + ": " + DescribeDrawing(drawing));
      CheckDrawing(mesh, drawing, meshName, failures, tally, hole);
      const FlatDrawingAnswer a = AnswerDrawing(mesh, drawing);
      ASSERT_TRUE(a.Ok) << a.Error;
      const double signedArea = ShoelaceArea(p);
      const int orientation = signedArea > 0 ? 1 : -1;
      const double inside =
        SelectedArea(a, [&](const std::vector<int>& l) { return l[0] == orientation; });
      EXPECT_NEAR(inside,
        std::abs(signedArea) - (WindingNumber(drawing, 0, hole.Center()) != 0 ? hole.Area() : 0.0),
        1e-9 * std::abs(signedArea));
    }
  }
  EXPECT_EQ(failures, 0);
}

// The polygons on the unit square's 100 x 100 grid, scaled by 100 (exact integers):
// A with its first side on the boundary, B from side to side cutting the outside in two, C at
// a corner over the edge the automatic zero cell used to be taken at; and more: the whole
// boundary, a strip over two corners, three sides, an L around a corner, a comb of three
// stretches on one side.
const std::vector<std::pair<const char*, Points>>& SquarePolygons()
{
  static const std::vector<std::pair<const char*, Points>> polygons{
    { "A", { { 40, 0 }, { 60, 0 }, { 60, 20 }, { 40, 20 } } },
    { "B", { { 0, 60 }, { 100, 60 }, { 100, 40 }, { 0, 40 } } },
    { "C", { { 20, 0 }, { 20, 20 }, { 0, 20 }, { 0, 0 } } },
    { "whole boundary", { { 0, 0 }, { 100, 0 }, { 100, 100 }, { 0, 100 } } },
    { "strip over two corners", { { 0, 0 }, { 100, 0 }, { 100, 10 }, { 0, 10 } } },
    { "three sides",
      { { 0, 0 },
        { 100, 0 },
        { 100, 100 },
        { 70, 100 },
        { 70, 30 },
        { 30, 30 },
        { 30, 100 },
        { 0, 100 } } },
    { "L around a corner",
      { { 70, 0 }, { 100, 0 }, { 100, 30 }, { 90, 30 }, { 90, 10 }, { 70, 10 } } },
    { "comb",
      { { 10, 0 },
        { 20, 0 },
        { 20, 10 },
        { 40, 10 },
        { 40, 0 },
        { 50, 0 },
        { 50, 10 },
        { 70, 10 },
        { 70, 0 },
        { 80, 0 },
        { 80, 30 },
        { 10, 30 } } },
  };
  return polygons;
}

} // namespace

TEST(BoundaryPlugs, SquarePolygonsOnTheRegularGrid)
{
  const TriangleMesh mesh = FlatMeshFor(0, 100, 100, true, 0);
  for (const auto& [name, polygon] : SquarePolygons())
  {
    SCOPED_TRACE(name);
    CheckEveryStartAndOrientation(mesh, polygon, "regular grid");
  }
}

TEST(BoundaryPlugs, SquarePolygonsOnAnIrregularMesh)
{
  // 73 cells: the polygons' corners on the boundary fall between the boundary's vertices.
  for (int cells : { 100, 73 })
  {
    const TriangleMesh mesh = FlatMeshFor(0, 100, cells, false, 11 + cells);
    for (const auto& [name, polygon] : SquarePolygons())
    {
      SCOPED_TRACE(name);
      CheckEveryStartAndOrientation(mesh, polygon, "irregular mesh, " + std::to_string(cells));
    }
  }
}

// The lone closed curve of case A is one patch unless it is cut where it leaves the boundary:
// every patch lies on the boundary or off it, and the boundary ones have no cell outside.
TEST(BoundaryPlugs, PatchesEndWhereCurvesLeaveTheBoundary)
{
  const TriangleMesh mesh = FlatMeshFor(0, 10, 10, true, 0);
  const FlatDrawingAnswer a =
    AnswerDrawing(mesh, { { 0, { { 4, 0 }, { 6, 0 }, { 6, 2 }, { 4, 2 } } } });
  ASSERT_TRUE(a.Ok) << a.Error;
  ASSERT_EQ(a.Arr.Patches.size(), 2u);
  int onBoundary = 0;
  for (const ArrangementPatch& p : a.Arr.Patches)
  {
    if (p.BoundaryHalfEdge >= 0)
    {
      ++onBoundary;
      EXPECT_EQ(p.RightCell, -1);
      EXPECT_GE(p.LeftCell, 0);
      ASSERT_EQ(p.Points.size(), 3u); // (4,0) (5,0) (6,0)
    }
    else
    {
      EXPECT_GE(p.RightCell, 0);
      EXPECT_GE(p.LeftCell, 0);
    }
  }
  EXPECT_EQ(onBoundary, 1);
  // One plug (the square's only loop), its arc from the boundary patch, and links from both
  // cells (the inside meets the boundary only along the curve: just the outside).
  const MeshTopology topo = MeshTopology::Compute(mesh);
  const BoundaryPlugs plugs = FindBoundaryPlugs(mesh, topo, a.Arr);
  EXPECT_EQ(plugs.NumberOfPlugs, 1);
  ASSERT_EQ(plugs.Arcs.size(), 1u);
  EXPECT_EQ(plugs.Arcs[0].RightCell, plugs.PlugOf(0));
  ASSERT_EQ(plugs.Links.size(), 1u);
  EXPECT_NE(plugs.Links[0].first, plugs.Arcs[0].LeftCell);
  EXPECT_EQ(plugs.ZeroNodes, std::vector<int>{ plugs.PlugOf(0) });
  EXPECT_NEAR(SelectedArea(a, [](const std::vector<int>& l) { return l[0] == 1; }), 4.0, 1e-12);
}

// Random lattice drawings on meshes that are exactly the lattice's square: corners on the
// boundary, sides along it, stretches of several polygons and shapes overlapping there.
TEST(BoundaryPlugs, RandomDrawingsOnTheLatticeSquare)
{
  ClipperTally tally;
  int failures = 0, alongBoundary = 0;
  std::mt19937 rng(55);
  for (int lattice : { 3, 5 })
  {
    for (int k = 0; k < 500 && failures < 5; ++k)
    {
      const std::vector<LatticePolygon> drawing = RandomLatticeDrawing(rng, lattice);
      for (const auto& poly : drawing)
      {
        for (size_t i = 0; i < poly.Points.size(); ++i)
        {
          const auto &p = poly.Points[i], &q = poly.Points[(i + 1) % poly.Points.size()];
          alongBoundary += p != q &&
            ((p[0] == q[0] && (p[0] == 0 || p[0] == lattice)) ||
              (p[1] == q[1] && (p[1] == 0 || p[1] == lattice)));
        }
      }
      const int cells = lattice + 1 + static_cast<int>(rng() % 4);
      const std::uint32_t seed = rng();
      CheckDrawing(FlatMeshFor(0, lattice, cells, false, seed),
        drawing,
        "irregular mesh (" + std::to_string(cells) + " cells, seed " + std::to_string(seed) + ")",
        failures,
        tally);
      CheckDrawing(
        FlatMeshFor(0, lattice, lattice, true, 0), drawing, "aligned mesh", failures, tally);
    }
  }
  EXPECT_EQ(failures, 0);
  EXPECT_GT(alongBoundary, 200); // the drawings do run along the boundary
  EXPECT_LT(tally.Disagreements * 20, tally.Comparisons);
}

// A square hole: polygons around it, along its loop, enclosing it, and random drawings that
// keep out of it. The plane's winding numbers inside the hole are constant: the hole's plug.
TEST(BoundaryPlugs, PolygonsAlongTheLoopOfAHole)
{
  const FlatHole hole{ 2, 2, 4, 3 };
  const TriangleMesh mesh = FlatMeshWithHole(0, 6, hole);
  const std::vector<std::pair<const char*, Points>> polygons{
    { "the hole's loop", { { 2, 2 }, { 4, 2 }, { 4, 3 }, { 2, 3 } } },
    { "around the hole", { { 1, 1 }, { 5, 1 }, { 5, 4 }, { 1, 4 } } },
    { "below the hole, sharing its side", { { 2, 1 }, { 4, 1 }, { 4, 2 }, { 2, 2 } } },
    { "along two sides of the hole",
      { { 1, 1 }, { 4, 1 }, { 4, 2 }, { 2, 2 }, { 2, 3 }, { 1, 3 } } },
    { "from the outer loop to the hole", { { 0, 2 }, { 2, 2 }, { 2, 3 }, { 0, 3 } } },
    { "around the hole and along the outer loop",
      { { 0, 0 },
        { 6, 0 },
        { 6, 6 },
        { 0, 6 },
        { 0, 4 },
        { 5, 4 },
        { 5, 1 },
        { 1, 1 },
        { 1, 4 },
        { 0, 4 } } },
  };
  for (const auto& [name, polygon] : polygons)
  {
    SCOPED_TRACE(name);
    ASSERT_TRUE(hole.Avoids({ { 0, polygon } }));
    CheckEveryStartAndOrientation(mesh, polygon, "mesh with a hole", hole);
  }

  // Random drawings around a unit hole near a corner (most drawings keep out of a small one).
  const FlatHole small{ 1, 1, 2, 2 };
  const TriangleMesh smallHoleMesh = FlatMeshWithHole(0, 5, small);
  ClipperTally tally;
  int failures = 0, accepted = 0;
  std::mt19937 rng(56);
  for (int k = 0; k < 20000 && accepted < 300 && failures < 5; ++k)
  {
    const std::vector<LatticePolygon> drawing = RandomLatticeDrawing(rng, 5);
    if (!small.Avoids(drawing))
    {
      continue;
    }
    ++accepted;
    CheckDrawing(smallHoleMesh, drawing, "mesh with a hole", failures, tally, small);
  }
  EXPECT_EQ(failures, 0);
  EXPECT_EQ(accepted, 300);
  EXPECT_LT(tally.Disagreements * 20, tally.Comparisons);
}

namespace
{

double TriangleArea(const TriangleMesh& mesh, int t)
{
  const Triangle& v = mesh.GetTriangle(t);
  const Vec3 a = mesh.GetPosition(v[0]), b = mesh.GetPosition(v[1]), c = mesh.GetPosition(v[2]);
  return 0.5 * Length(Cross(b - a, c - a));
}

/// The vertices of a path from `from` to `to` along mesh edges through interior vertices only
/// (breadth first), `from` first; empty when there is none.
std::vector<int> InteriorPath(const TriangleMesh& mesh,
  const MeshTopology& topo,
  const std::vector<std::vector<int>>& adjacent,
  int from,
  int to)
{
  std::vector<int> parent(mesh.GetNumberOfVertices(), -2);
  std::deque<int> queue{ from };
  parent[from] = -1;
  while (!queue.empty())
  {
    const int v = queue.front();
    queue.pop_front();
    for (int w : adjacent[v])
    {
      if (parent[w] != -2 || (w != to && topo.GetVertexBoundaryLoop(w) >= 0))
      {
        continue;
      }
      // No boundary edge as a first step: the path must leave the boundary.
      if (v == from && w == to)
      {
        continue;
      }
      parent[w] = v;
      if (w == to)
      {
        std::vector<int> path;
        for (int x = to; x >= 0; x = parent[x])
        {
          path.push_back(x);
        }
        std::reverse(path.begin(), path.end());
        return path;
      }
      queue.push_back(w);
    }
  }
  return {};
}

} // namespace

// Scanned surfaces with holes: a curve along a stretch of a boundary loop (the loop's own
// direction, the surface on its left) and back along mesh edges through the interior bounds
// the triangles a flood fill finds on its left (or, when that side holds the free part of the
// longest loop, the zero plug's side, the triangles on its right). Every curve lies on mesh
// edges, so the oracle is exact on the mesh's own triangles. Both orientations, and starts on
// the boundary stretch and on the way back.
TEST(BoundaryPlugs, ScanCurvesAlongBoundaryLoops)
{
  const char* root = std::getenv("BOOLSURF_SHARED_DATA");
  if (!root)
  {
    GTEST_SKIP() << "shared mesh collection not found (set BOOLSURF_SHARED_DATA); skipping "
                    "curves along the holes of scanned meshes";
  }
  std::mt19937 rng(57);
  int checked = 0;
  for (const char* file : { "stanford-bunny.ply", "beetle.ply", "camelhead.ply" })
  {
    SCOPED_TRACE(file);
    MeshData data;
    std::string error;
    if (!ReadPly(std::string(root) + "/meshes/" + file, data, error))
    {
      GTEST_SKIP() << "cannot read " << file << ": " << error;
    }
    const TriangleMesh mesh(data.Positions, data.Triangles);
    const MeshTopology topo = MeshTopology::Compute(mesh);
    ASSERT_FALSE(topo.BoundaryLoops.empty());
    std::vector<std::vector<int>> adjacent(mesh.GetNumberOfVertices());
    for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
    {
      for (int k = 0; mesh.IsUsable(t) && k < 3; ++k)
      {
        adjacent[mesh.GetTriangle(t)[k]].push_back(mesh.GetTriangle(t)[(k + 1) % 3]);
        adjacent[mesh.GetTriangle(t)[(k + 1) % 3]].push_back(mesh.GetTriangle(t)[k]);
      }
    }
    int longest = 0;
    for (int l = 0; l < static_cast<int>(topo.BoundaryLoops.size()); ++l)
    {
      if (topo.BoundaryLoops[l].Length > topo.BoundaryLoops[longest].Length)
        longest = l;
    }
    for (int l = 0; l < static_cast<int>(topo.BoundaryLoops.size()); ++l)
    {
      const BoundaryLoop& loop = topo.BoundaryLoops[l];
      const int n = static_cast<int>(loop.Vertices.size());
      for (int trial = 0; trial < 2 && n >= 4; ++trial)
      {
        const int first = static_cast<int>(rng() % n);
        const int stretch = 1 + static_cast<int>(rng() % std::min(n / 2, 12));
        std::vector<int> curve; // vertices: the stretch, then the way back
        for (int i = 0; i <= stretch; ++i)
          curve.push_back(loop.Vertices[(first + i) % n]);
        const std::vector<int> back =
          InteriorPath(mesh, topo, adjacent, curve.back(), curve.front());
        if (back.size() < 3)
          continue;
        curve.insert(curve.end(), back.begin() + 1, back.end() - 1);
        // The curve's edges, and the flood fill of the triangles on its left.
        std::set<std::pair<int, int>> directed;
        for (size_t i = 0; i < curve.size(); ++i)
          directed.insert({ curve[i], curve[(i + 1) % curve.size()] });
        std::vector<char> left(mesh.GetNumberOfTriangles(), 0);
        std::vector<int> stack;
        for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
        {
          for (int k = 0; mesh.IsUsable(t) && k < 3; ++k)
          {
            if (directed.count({ mesh.GetTriangle(t)[k], mesh.GetTriangle(t)[(k + 1) % 3] }) &&
              !left[t])
            {
              left[t] = 1;
              stack.push_back(t);
            }
          }
        }
        bool leftHoldsFreeLongestLoop = false;
        double leftArea = 0, total = 0;
        while (!stack.empty())
        {
          const int t = stack.back();
          stack.pop_back();
          for (int k = 0; k < 3; ++k)
          {
            const int a = mesh.GetTriangle(t)[k], b = mesh.GetTriangle(t)[(k + 1) % 3];
            const bool onCurve = directed.count({ a, b }) || directed.count({ b, a });
            const int nb = mesh.GetNeighbor(t, k);
            if (nb < 0 && !onCurve && topo.GetVertexBoundaryLoop(a) == longest &&
              topo.GetVertexBoundaryLoop(b) == longest)
              leftHoldsFreeLongestLoop = true;
            if (nb >= 0 && !onCurve && !left[nb])
            {
              left[nb] = 1;
              stack.push_back(nb);
            }
          }
        }
        for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
        {
          if (!mesh.IsUsable(t))
            continue;
          const double area = TriangleArea(mesh, t);
          total += area;
          leftArea += left[t] ? area : 0.0;
        }
        for (int reversed = 0; reversed < 2; ++reversed)
        {
          for (size_t start : { size_t(0), curve.size() / 2, curve.size() - 1 })
          {
            TracedCurve traced;
            traced.ShapeId = 0;
            for (size_t i = 0; i < curve.size(); ++i)
            {
              const size_t k =
                reversed ? (start + curve.size() - i) % curve.size() : (start + i) % curve.size();
              CanonicalPoint p;
              p.Location = PointLocation::Vertex;
              p.Id = curve[k];
              traced.Points.push_back(p);
            }
            Arrangement arr;
            ASSERT_TRUE(ComputeArrangement(mesh, { traced }, ArrangementOptions(), arr, error))
              << error;
            const LabelingResult labels =
              LabelCells(MakeLabelingInput(mesh, topo, { traced }, arr));
            ASSERT_TRUE(labels.ShapeConsistent[0]);
            // Walking the loop's way, the left side is +1 above the right; the side with the
            // free part of the longest loop is 0.
            const int sign = reversed ? -1 : 1;
            const int leftLabel = leftHoldsFreeLongestLoop ? 0 : sign;
            const int rightLabel = leftHoldsFreeLongestLoop ? -sign : 0;
            double inside = 0;
            int wrong = 0;
            for (int r = 0; r < arr.GetNumberOfTriangles(); ++r)
            {
              const int cell = arr.CellOfTriangle(r);
              if (cell < 0)
                continue;
              const int source = arr.GetSourceTriangle(mesh, r);
              const int expected = left[source] ? leftLabel : rightLabel;
              wrong += labels.GetLabel(cell, 0) != expected;
              inside += labels.GetLabel(cell, 0) != 0 ? TriangleArea(mesh, source) : 0.0;
            }
            EXPECT_EQ(wrong, 0) << "loop " << l << " from " << first << ", " << stretch
                                << " edges, reversed " << reversed << ", start " << start;
            EXPECT_NEAR(
              inside, leftHoldsFreeLongestLoop ? total - leftArea : leftArea, 1e-9 * total);
            ++checked;
          }
        }
      }
    }
  }
  EXPECT_GT(checked, 60);
}

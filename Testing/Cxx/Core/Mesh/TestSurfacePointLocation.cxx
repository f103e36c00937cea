// One meaning for a point on the surface: LocateSurfacePoint decides, with the one tolerance
// SurfacePointSnap, whether a given point lies in a triangle, on an edge or on a vertex, whatever
// triangle it is written in; WriteSurfacePoint writes canonical points so that they read back
// as themselves.
#include "Mesh/ProceduralMeshes.h"
#include "Mesh/SurfacePoint.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <random>

using namespace boolsurf;

namespace
{
TriangleMesh Torus()
{
  MeshData d = MakeTorus(1.0, 0.4, 16, 9);
  return TriangleMesh(d.Positions, d.Triangles);
}
} // namespace

// Points a rounding error (1e-16 .. 1e-12) off an edge or a vertex, written in either triangle of
// the edge (or any triangle of the vertex), inside or outside it, are located on it; 1e-9 off is
// a point inside the triangle.
TEST(SurfacePointLocation, RoundingOffEdgesAndVerticesIsOnThem)
{
  const TriangleMesh mesh = Torus();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> anyEdge(0, mesh.GetNumberOfEdges() - 1);
  std::uniform_int_distribution<int> anyVertex(0, mesh.GetNumberOfVertices() - 1);
  std::vector<int> triangles;
  for (int trial = 0; trial < 500; ++trial)
  {
    const double off = std::pow(10.0, -12 - 4 * unit(rng)) * (unit(rng) < 0.5 ? 1 : -1);
    CanonicalPoint edge;
    edge.Location = PointLocation::Edge;
    edge.Id = anyEdge(rng);
    edge.T = 0.05 + 0.9 * unit(rng);
    TrianglesOf(mesh, edge, triangles);
    for (const int t : triangles)
    {
      std::array<double, 3> w = WeightsInTriangle(mesh, edge, t);
      for (double& x : w)
      {
        x = x == 0.0 ? off : x - off / 2;
      }
      const CanonicalPoint located = LocateSurfacePoint(mesh, SurfacePoint{ t, w[1], w[2] });
      ASSERT_EQ(located.Location, PointLocation::Edge) << Describe(edge) << " in triangle " << t;
      EXPECT_EQ(located.Id, edge.Id);
      EXPECT_NEAR(located.T, edge.T, 4e-12); // moved onto the edge by at most the offset
      // Farther off than the snap: inside the triangle (or clamped onto the edge from outside).
      std::array<double, 3> inside = WeightsInTriangle(mesh, edge, t);
      for (double& x : inside)
      {
        x = x == 0.0 ? 1e-9 : x - 0.5e-9;
      }
      EXPECT_EQ(LocateSurfacePoint(mesh, SurfacePoint{ t, inside[1], inside[2] }).Location,
        PointLocation::Face);
    }
    CanonicalPoint vertex;
    vertex.Location = PointLocation::Vertex;
    vertex.Id = anyVertex(rng);
    TrianglesOf(mesh, vertex, triangles);
    for (const int t : triangles)
    {
      std::array<double, 3> w = WeightsInTriangle(mesh, vertex, t);
      for (double& x : w)
      {
        x = x == 0.0 ? std::abs(off) : x - 2 * std::abs(off);
      }
      const CanonicalPoint located = LocateSurfacePoint(mesh, SurfacePoint{ t, w[1], w[2] });
      EXPECT_EQ(located, vertex) << Describe(vertex) << " in triangle " << t;
    }
  }
}

// Written canonical points read back bit for bit: faces always, vertices always, edge points in
// some triangle of theirs whenever one has the edge's second vertex at an explicit corner, and
// otherwise in the one deterministic form every curve through the point shares.
TEST(SurfacePointLocation, WrittenPointsReadBackAsThemselves)
{
  const TriangleMesh mesh = Torus();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> anyTriangle(0, mesh.GetNumberOfTriangles() - 1);
  std::vector<int> triangles;
  int exact = 0, edges = 0;
  for (int trial = 0; trial < 2000; ++trial)
  {
    const int t = anyTriangle(rng);
    const int corner = trial % 3;
    CanonicalPoint c;
    switch (trial % 3)
    {
      case 0:
        c.Location = PointLocation::Face;
        c.Id = t;
        c.U = 0.01 + 0.5 * unit(rng);
        c.V = 0.01 + 0.45 * unit(rng);
        break;
      case 1:
        c.Location = PointLocation::Edge;
        c.Id = mesh.GetEdgeId(t, corner);
        c.T = unit(rng);
        if (!(c.T > 1e-3 && c.T < 1 - 1e-3))
        {
          c.T = 0.3;
        }
        break;
      default:
        c.Location = PointLocation::Vertex;
        c.Id = mesh.GetTriangle(t)[corner];
        break;
    }
    TrianglesOf(mesh, c, triangles);
    const SurfacePoint first = WriteSurfacePoint(mesh, c, triangles.front());
    for (const int preferred : triangles)
    {
      const SurfacePoint sp = WriteSurfacePoint(mesh, c, preferred);
      const CanonicalPoint back = LocateSurfacePoint(mesh, sp);
      ASSERT_EQ(back.Location, c.Location) << Describe(c);
      ASSERT_EQ(back.Id, c.Id) << Describe(c);
      if (c.Location != PointLocation::Edge)
      {
        EXPECT_EQ(back, c) << Describe(c);
        continue;
      }
      ++edges;
      exact += back == c;
      // Inexact only in the shared fallback form: every writer of c writes the same numbers.
      if (!(back == c))
      {
        EXPECT_NEAR(back.T, c.T, 1e-15);
        EXPECT_EQ(sp.Triangle, first.Triangle);
        EXPECT_EQ(sp.U, first.U);
        EXPECT_EQ(sp.V, first.V);
      }
    }
    // Writing in a triangle that does not hold c falls back to one that does.
    const SurfacePoint elsewhere =
      WriteSurfacePoint(mesh, c, (t + 7) % mesh.GetNumberOfTriangles());
    EXPECT_TRUE(TriangleContains(mesh, LocateSurfacePoint(mesh, elsewhere), elsewhere.Triangle));
  }
  // Most edge points have an exact form (an explicit corner at the edge's second vertex).
  EXPECT_GT(exact, edges * 3 / 4) << exact << " of " << edges;
}

// WriteSurfacePoint takes an edge point's form without reading it back when the edge's second
// vertex is an explicit corner; that shortcut gives exactly what reading every candidate back
// gives, also for parameters next to the snap and for every orientation of the edge.
TEST(SurfacePointLocation, EdgeShortcutWritesWhatReadingBackWrites)
{
  const TriangleMesh mesh = Torus();
  // The written form as found by reading each candidate back (WriteSurfacePoint's definition).
  const auto byReadingBack = [&mesh](const CanonicalPoint& c, int preferred)
  {
    const auto formIn = [&](int t)
    {
      const std::array<double, 3> w = WeightsInTriangle(mesh, c, t);
      return SurfacePoint{ t, w[1], w[2] };
    };
    std::vector<int> candidates;
    if (preferred >= 0 && TriangleContains(mesh, c, preferred))
    {
      candidates.push_back(preferred);
    }
    std::vector<int> triangles;
    TrianglesOf(mesh, c, triangles);
    candidates.insert(candidates.end(), triangles.begin(), triangles.end());
    for (const int t : candidates)
    {
      const SurfacePoint sp = formIn(t);
      if (LocateSurfacePoint(mesh, sp) == c)
      {
        return sp;
      }
    }
    return ToSurfacePoint(mesh, c);
  };
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<int> triangles;
  int shortcuts = 0;
  for (int e = 0; e < mesh.GetNumberOfEdges(); ++e)
  {
    const double eps = std::numeric_limits<double>::epsilon();
    for (const double t :
      { unit(rng), 0.5, 3e-11, 2e-11 + eps, 1e-11, 1 - 2e-11, 1 - 3e-11, eps, 1 - eps })
    {
      CanonicalPoint c;
      c.Location = PointLocation::Edge;
      c.Id = e;
      c.T = t;
      TrianglesOf(mesh, c, triangles);
      triangles.push_back(-1);                                    // no preference
      triangles.push_back((7 * e) % mesh.GetNumberOfTriangles()); // most often not on the edge
      for (const int preferred : triangles)
      {
        const SurfacePoint written = WriteSurfacePoint(mesh, c, preferred);
        const SurfacePoint reference = byReadingBack(c, preferred);
        ASSERT_EQ(written.Triangle, reference.Triangle) << Describe(c);
        ASSERT_EQ(written.U, reference.U) << Describe(c);
        ASSERT_EQ(written.V, reference.V) << Describe(c);
        shortcuts += preferred >= 0 && TriangleContains(mesh, c, preferred) &&
          mesh.GetTriangle(preferred)[0] != mesh.GetEdgeVertices(e)[1];
      }
    }
  }
  EXPECT_GT(shortcuts, mesh.GetNumberOfEdges()); // the shortcut was taken, on many edges
}

// SnapWeights writes, in the point's own triangle, exactly what LocateSurfacePoint reads.
TEST(SurfacePointLocation, SnappedWeightsAreTheLocatedPoint)
{
  const TriangleMesh mesh = Torus();
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> anyTriangle(0, mesh.GetNumberOfTriangles() - 1);
  for (int trial = 0; trial < 3000; ++trial)
  {
    const int t = anyTriangle(rng);
    std::array<double, 3> w{ unit(rng), unit(rng), unit(rng) };
    const double sum = w[0] + w[1] + w[2];
    for (double& x : w)
    {
      x /= sum;
    }
    // One or two weights pushed to rounding level.
    const int k = trial % 3;
    const double tiny = std::pow(10.0, -12 - 4 * unit(rng));
    if (trial % 2)
    {
      w[k] = tiny;
      w[(k + 1) % 3] = std::pow(10.0, -12 - 4 * unit(rng));
      w[(k + 2) % 3] = 1 - w[k] - w[(k + 1) % 3];
    }
    else
    {
      const double rest = w[(k + 1) % 3] + w[(k + 2) % 3];
      w[k] = tiny;
      w[(k + 1) % 3] *= (1 - tiny) / rest;
      w[(k + 2) % 3] = 1 - w[k] - w[(k + 1) % 3];
    }
    const SurfacePoint given{ t, w[1], w[2] };
    const SurfacePoint snapped = SnapWeights(given);
    const CanonicalPoint located = LocateSurfacePoint(mesh, given);
    EXPECT_EQ(Canonicalize(mesh, snapped, 0.0).Location, located.Location);
    EXPECT_EQ(Canonicalize(mesh, snapped, 0.0).Id, located.Id);
    // A zero weight is exactly zero (corner 0's is implicit: within the 4 ulps read as zero).
    EXPECT_TRUE(snapped.U == 0.0 || snapped.V == 0.0 ||
      std::abs(1.0 - snapped.U - snapped.V) <= 4 * std::numeric_limits<double>::epsilon());
  }
}

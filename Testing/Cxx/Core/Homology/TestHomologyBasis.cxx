// Homology generators (tree-cotree): 2g per component, cutting along them leaves one disc per
// component (Euler characteristic of the complement), their intersection matrix is unimodular,
// each generator's class is its own unit vector; on a parametrized torus the class of a traced
// curve is its pair of analytic winding numbers up to one fixed unimodular change of basis.
#include "Homology/GeneratorShortening.h"
#include "Homology/HomologyBasis.h"

#include "Geodesic/CurveTracer.h"
#include "Mesh/PlyReader.h"
#include "Mesh/ProceduralMeshes.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <functional>
#include <numeric>
#include <random>

using namespace boolsurf;

namespace
{
/// The message of the last failed trace or path (a test reads it only after a failure).
std::string traceError;
}

namespace
{

struct Surface
{
  TriangleMesh Mesh;
  MeshTopology Topology;
  HomologyBasis Basis;
};

void Build(const MeshData& d, Surface& s)
{
  s.Mesh = TriangleMesh(d.Positions, d.Triangles);
  s.Topology = MeshTopology::Compute(s.Mesh);
  std::string error;
  ASSERT_TRUE(s.Basis.Compute(s.Mesh, s.Topology, HomologyOptions(), error)) << error;
}

// Determinant of a small integer matrix (fraction-free Gaussian elimination, Bareiss).
long long Determinant(std::vector<std::vector<long long>> m)
{
  const int n = static_cast<int>(m.size());
  long long sign = 1, previous = 1;
  for (int k = 0; k < n - 1; ++k)
  {
    if (m[k][k] == 0)
    {
      int swap = k + 1;
      while (swap < n && m[swap][k] == 0)
      {
        ++swap;
      }
      if (swap == n)
      {
        return 0;
      }
      std::swap(m[k], m[swap]);
      sign = -sign;
    }
    for (int i = k + 1; i < n; ++i)
    {
      for (int j = k + 1; j < n; ++j)
      {
        m[i][j] = (m[i][j] * m[k][k] - m[i][k] * m[k][j]) / previous;
      }
    }
    previous = m[k][k];
  }
  return n == 0 ? 1 : sign * m[n - 1][n - 1];
}

// Euler characteristic and connected pieces of the surface (boundary loops capped) minus the
// cut graph: the complement retracts onto the vertices, the edges the cut graph does not cross
// and the faces it does not enter (the caps included).
void CheckCutLeavesDiscs(const Surface& s)
{
  const TriangleMesh& mesh = s.Mesh;
  const std::vector<int> cut = s.Basis.CutGraphEdges();
  std::vector<char> edgeCut(mesh.GetNumberOfEdges(), 0),
    triangleCut(mesh.GetNumberOfTriangles(), 0);
  for (int e : cut)
  {
    edgeCut[e] = 1;
    const int h = mesh.GetEdgeHalfEdge(e);
    triangleCut[h / 3] = 1;
    triangleCut[mesh.GetTwin(h) / 3] = 1;
  }
  for (int b : s.Basis.GetBaseTriangles())
  {
    triangleCut[b] = 1; // a genus-0 component has no cut graph: cut out its base point
  }
  std::vector<char> usedVertex(mesh.GetNumberOfVertices(), 0);
  long long faces = static_cast<long long>(s.Topology.BoundaryLoops.size());
  for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    if (!mesh.IsUsable(t))
    {
      continue;
    }
    faces += triangleCut[t] ? 0 : 1;
    for (int v : mesh.GetTriangle(t))
    {
      usedVertex[v] = 1;
    }
  }
  std::vector<int> parent(mesh.GetNumberOfVertices());
  std::iota(parent.begin(), parent.end(), 0);
  std::function<int(int)> find = [&](int a)
  { return parent[a] == a ? a : parent[a] = find(parent[a]); };
  long long vertices = 0, edges = 0;
  for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
    vertices += usedVertex[v];
  }
  int pieces = static_cast<int>(vertices);
  for (int e = 0; e < mesh.GetNumberOfEdges(); ++e)
  {
    if (edgeCut[e])
    {
      continue;
    }
    ++edges;
    const auto ends = mesh.GetEdgeVertices(e);
    const int a = find(ends[0]), b = find(ends[1]);
    if (a != b)
    {
      parent[a] = b;
      --pieces;
    }
  }
  const int components = s.Topology.GetNumberOfComponents();
  EXPECT_EQ(pieces, components) << "the complement of the cut graph is not one piece per component";
  EXPECT_EQ(vertices - edges + faces, components) << "the complement is not a disc per component";
}

void CheckGenerators(const Surface& s, int expectedPerComponent)
{
  const HomologyBasis& basis = s.Basis;
  const int n = basis.GetNumberOfGenerators();
  ASSERT_EQ(n, expectedPerComponent * s.Topology.GetNumberOfComponents());
  for (int c = 0; c < s.Topology.GetNumberOfComponents(); ++c)
  {
    EXPECT_EQ(2 * s.Topology.Components[c].Genus, expectedPerComponent);
  }
  CheckCutLeavesDiscs(s);

  // Each generator's class (as a traced curve through its edge points) is its unit vector.
  for (int g = 0; g < n; ++g)
  {
    TracedCurve curve;
    curve.Points = basis.GetGenerator(g).Points;
    std::vector<int> h;
    std::string error;
    ASSERT_TRUE(basis.ClassOf(curve, h, error)) << error;
    std::vector<int> unit(n, 0);
    unit[g] = 1;
    EXPECT_EQ(h, unit) << "generator " << g;
    // Never through a vertex: every point is strictly inside an edge.
    for (const CanonicalPoint& p : curve.Points)
    {
      EXPECT_EQ(p.Location, PointLocation::Edge);
      EXPECT_GT(p.T, 0.0);
      EXPECT_LT(p.T, 1.0);
    }
  }
  // Intersection matrix: antisymmetric and unimodular.
  std::vector<std::vector<long long>> m(n, std::vector<long long>(n, 0));
  for (int a = 0; a < n; ++a)
  {
    for (int b = 0; b < n; ++b)
    {
      m[a][b] = basis.Intersection(a, b);
    }
  }
  for (int a = 0; a < n; ++a)
  {
    for (int b = 0; b < n; ++b)
    {
      EXPECT_EQ(m[a][b], -m[b][a]) << a << "," << b;
    }
  }
  const long long det = Determinant(m);
  EXPECT_TRUE(det == 1 || det == -1) << "intersection matrix determinant " << det;
}

} // namespace

TEST(HomologyBasis, ProceduralTorusHasTwoGeneratorsCuttingToADisc)
{
  Surface s;
  Build(MakeTorus(3.0, 1.0, 40, 20), s);
  CheckGenerators(s, 2);
}

TEST(HomologyBasis, GenusZeroHasNoGenerators)
{
  for (const MeshData& d :
    { MakeIcosphere(2), MakeOpenCylinder(1.0, 2.0, 24, 6), MakeFlatSquare(6) })
  {
    Surface s;
    Build(d, s);
    EXPECT_EQ(s.Basis.GetNumberOfGenerators(), 0);
    CheckCutLeavesDiscs(s);
    // A curve around the cylinder is homologous to a boundary loop: class zero (empty vector).
    TracedCurve around;
    std::vector<int> h;
    std::string error;
    EXPECT_TRUE(s.Basis.ClassOf(around, h, error));
    EXPECT_TRUE(h.empty());
  }
}

TEST(HomologyBasis, TwoTorusComponentsHaveTwoGeneratorsEach)
{
  MeshData a = MakeTorus(3.0, 1.0, 24, 12), b = MakeTorus(2.0, 0.5, 20, 10);
  const int offset = static_cast<int>(a.Positions.size());
  for (auto p : b.Positions)
  {
    a.Positions.push_back({ p[0] + 10, p[1], p[2] });
  }
  for (auto t : b.Triangles)
  {
    a.Triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
  }
  Surface s;
  Build(a, s);
  CheckGenerators(s, 2);
  EXPECT_EQ(s.Basis.GetGenerator(0).Component, 0);
  EXPECT_EQ(s.Basis.GetGenerator(3).Component, 1);
  EXPECT_EQ(s.Basis.Intersection(0, 2), 0); // different components never meet
}

TEST(HomologyBasis, BaseTriangleIsSettableAndChecked)
{
  const MeshData d = MakeTorus(3.0, 1.0, 24, 12);
  TriangleMesh mesh(d.Positions, d.Triangles);
  MeshTopology topo = MeshTopology::Compute(mesh);
  HomologyBasis basis;
  HomologyOptions options;
  options.BaseTriangles = { 100 };
  std::string error;
  ASSERT_TRUE(basis.Compute(mesh, topo, options, error)) << error;
  EXPECT_EQ(basis.GetBaseTriangles()[0], 100);
  EXPECT_EQ(basis.GetNumberOfGenerators(), 2);
  options.BaseTriangles = { mesh.GetNumberOfTriangles() };
  EXPECT_FALSE(basis.Compute(mesh, topo, options, error));
  EXPECT_NE(error.find("out of range"), std::string::npos) << error;
}

// Closed geodesic polygons through grid vertices of the parametrized torus, winding p times
// around the axis and q times around the tube: their classes are M (p, q) for one unimodular M.
TEST(HomologyBasis, TorusClassesAreWindingNumbers)
{
  const int nu = 48, nv = 24;
  const MeshData d = MakeTorus(3.0, 1.0, nu, nv);
  Surface s;
  Build(d, s);
  ASSERT_EQ(s.Basis.GetNumberOfGenerators(), 2);
  CurveTracer tracer(s.Mesh);
  std::mt19937 rng(7);
  auto vertexPoint = [&](int i, int j)
  {
    CanonicalPoint p;
    p.Location = PointLocation::Vertex;
    p.Id = ((i % nu + nu) % nu) * nv + ((j % nv + nv) % nv);
    return p;
  };
  // Class of a closed polygon through grid points (i_k, j_k) given as unwrapped steps.
  auto classOf = [&](int p, int q, bool jitter)
  {
    std::uniform_int_distribution<int> noise(-1, 1);
    const int steps = 24 * std::max(1, std::max(std::abs(p), std::abs(q)));
    std::vector<CanonicalPoint> points;
    for (int k = 0; k < steps; ++k)
    {
      const int i =
        static_cast<int>(std::lround(double(p) * nu * k / steps)) + (jitter ? noise(rng) : 0);
      const int j =
        static_cast<int>(std::lround(double(q) * nv * k / steps)) + (jitter ? noise(rng) : 0);
      points.push_back(vertexPoint(i, j));
    }
    CurveTrace trace;
    const bool traced = tracer.TraceGeodesicPolygon(points, true, trace, traceError);
    EXPECT_TRUE(traced) << traceError;
    std::vector<int> h;
    std::string error;
    EXPECT_TRUE(s.Basis.ClassOf(trace.Curve, h, error)) << error;
    return h;
  };
  const std::vector<int> c1 = classOf(1, 0, false), c2 = classOf(0, 1, false);
  const long long det =
    static_cast<long long>(c1[0]) * c2[1] - static_cast<long long>(c1[1]) * c2[0];
  ASSERT_TRUE(det == 1 || det == -1)
    << "basis change (" << c1[0] << "," << c1[1] << "), (" << c2[0] << "," << c2[1] << ")";
  std::uniform_int_distribution<int> winding(-2, 2);
  for (int trial = 0; trial < 20; ++trial)
  {
    const int p = winding(rng), q = winding(rng);
    const std::vector<int> h = classOf(p, q, true);
    EXPECT_EQ(h[0], p * c1[0] + q * c2[0]) << "winding (" << p << ", " << q << ")";
    EXPECT_EQ(h[1], p * c1[1] + q * c2[1]) << "winding (" << p << ", " << q << ")";
  }
}

// The meshes of the shared collection with known genus.
TEST(HomologyBasis, SharedMeshesHaveTwoGPerComponentAndCutToDiscs)
{
  const char* root = std::getenv("BOOLSURF_SHARED_DATA");
  if (!root)
  {
    GTEST_SKIP() << "shared mesh collection not found (set BOOLSURF_SHARED_DATA); skipping "
                    "torus/eight/3torus/fertility generators";
  }
  const std::vector<std::pair<std::string, int>> meshes = {
    { "torus.ply", 1 }, { "eight.ply", 2 }, { "3torus_200k.ply", 3 }, { "fertility.ply", 4 }
  };
  for (const auto& [file, genus] : meshes)
  {
    SCOPED_TRACE(file);
    MeshData data;
    std::string error;
    if (!ReadPly(std::string(root) + "/meshes/" + file, data, error))
    {
      GTEST_SKIP() << "cannot read " << file << ": " << error;
    }
    Surface s;
    Build(data, s);
    CheckGenerators(s, 2 * genus);
    // Shortened loops: fewer when a loop cannot be shortened within its class.
    CurveTracer tracer(s.Mesh);
    int shortened = 0;
    double before = 0, after = 0;
    for (int g = 0; g < s.Basis.GetNumberOfGenerators(); ++g)
    {
      TracedCurve loop, original;
      original.Points = s.Basis.GetGenerator(g).Points;
      if (ShortenGenerator(s.Mesh, s.Basis, g, tracer, loop))
      {
        ++shortened;
        before += TracedLength(s.Mesh, original);
        after += TracedLength(s.Mesh, loop);
      }
    }
    std::printf("%s: %d of %d generators shortened, length %.3g -> %.3g\n",
      file.c_str(),
      shortened,
      s.Basis.GetNumberOfGenerators(),
      before,
      after);
    EXPECT_GT(shortened, 0);
    EXPECT_LE(after, before);
  }
}

// Shortened generators keep their class and are no longer than the tree-cotree loops.
TEST(HomologyBasis, ShortenedGeneratorsKeepTheirClassAndShrink)
{
  Surface s;
  Build(MakeTorus(3.0, 1.0, 48, 24), s);
  CurveTracer tracer(s.Mesh);
  int shortened = 0;
  for (int g = 0; g < s.Basis.GetNumberOfGenerators(); ++g)
  {
    TracedCurve loop;
    if (!ShortenGenerator(s.Mesh, s.Basis, g, tracer, loop))
    {
      continue;
    }
    ++shortened;
    std::vector<int> h;
    std::string error;
    ASSERT_TRUE(s.Basis.ClassOf(loop, h, error)) << error;
    std::vector<int> unit(2, 0);
    unit[g] = 1;
    EXPECT_EQ(h, unit);
    TracedCurve original;
    original.Points = s.Basis.GetGenerator(g).Points;
    EXPECT_LE(TracedLength(s.Mesh, loop), TracedLength(s.Mesh, original) + 1e-9);
  }
  EXPECT_EQ(shortened, 2);
}

// A torus with a hole: still 2 generators (the boundary loop is capped, the virtual shape A0);
// a loop around the hole has class zero, a loop around the tube does not.
TEST(HomologyBasis, BoundaryLoopsAreCappedOnATorusWithAHole)
{
  const int nu = 24, nv = 12;
  MeshData d = MakeTorus(3.0, 1.0, nu, nv);
  auto quad = [&](int i, int j) { return 2 * (i * nv + j); }; // first triangle of quad (i, j)
  d.Triangles.erase(d.Triangles.begin() + quad(5, 5), d.Triangles.begin() + quad(5, 5) + 2);
  auto shifted = [&](int t) { return t > quad(5, 5) ? t - 2 : t; }; // ids after the erase
  Surface s;
  Build(d, s);
  ASSERT_EQ(s.Topology.BoundaryLoops.size(), 1u);
  ASSERT_EQ(s.Topology.Components[0].Genus, 1);
  CheckGenerators(s, 2);
  CurveTracer tracer(s.Mesh);
  auto classOf = [&](const std::vector<std::pair<int, int>>& quads)
  {
    std::vector<SurfacePoint> control;
    for (const auto& [i, j] : quads)
    {
      control.push_back({ shifted(quad(i, j)), 0.3, 0.3 });
    }
    CurveTrace trace;
    EXPECT_TRUE(tracer.Trace(control, CurveType::GeodesicPolygon, true, trace, traceError));
    std::vector<int> h;
    std::string error;
    EXPECT_TRUE(s.Basis.ClassOf(trace.Curve, h, error)) << error;
    return h;
  };
  EXPECT_EQ(
    classOf({ { 4, 4 }, { 5, 4 }, { 6, 4 }, { 6, 5 }, { 6, 6 }, { 5, 6 }, { 4, 6 }, { 4, 5 } }),
    std::vector<int>(2, 0));
  std::vector<std::pair<int, int>> tube;
  for (int j = 0; j < nv; j += 2)
  {
    tube.push_back({ 12, j });
  }
  EXPECT_NE(classOf(tube), std::vector<int>(2, 0));
}

// The exact window search on flat regular grids, where the geodesic distance is the Euclidean
// one (to a point, or to a segment) and so an exact oracle. Regular grids are the hard case for
// window propagation: straight paths run exactly through vertices (every lattice direction
// meets them) and along edges, and every inner vertex is exactly flat, so such a vertex is no
// pseudo-source and the rays through it must carry on by the windows on both its sides. Both
// modes are checked: the distance field (point and line sources, read at vertices, edge
// midpoints and triangle centroids) and the point-to-point search of the Exact method.
#include "Geodesic/ExactGeodesicSearch.h"
#include "Geodesic/GeodesicPath.h"
#include "Mesh/ProceduralMeshes.h"
#include "Support/CanonicalPoints.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

using namespace boolsurf;
using boolsurf::testing::EdgePoint;
using boolsurf::testing::FacePoint;
using boolsurf::testing::VertexPoint;

namespace
{
/// The message of the last failed trace or path (a test reads it only after a failure).
std::string traceError;
}

namespace
{
constexpr double Pi = 3.14159265358979323846;

/// How the grid's cells are split: all by the diagonal rising to the right (MakeFlatSquare),
/// all by the falling one, or alternating like a chessboard (vertices of 4 and 8 triangles).
enum class Diagonals
{
  Rising,
  Falling,
  Alternating
};

const char* NameOf(Diagonals d)
{
  return d == Diagonals::Rising ? "rising" : (d == Diagonals::Falling ? "falling" : "alternating");
}

/// The unit square in n x n cells, vertex (i, j) at (i / n, j / n) with id j (n + 1) + i.
TriangleMesh Grid(int n, Diagonals diagonals)
{
  MeshData data = MakeFlatSquare(n, 1.0, 0.0, 0);
  if (diagonals != Diagonals::Rising)
  {
    data.Triangles.clear();
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
        if (diagonals == Diagonals::Falling || (i + j) % 2 == 1)
        {
          data.Triangles.push_back({ a, b, d });
          data.Triangles.push_back({ b, c, d });
        }
        else
        {
          data.Triangles.push_back({ a, b, c });
          data.Triangles.push_back({ a, c, d });
        }
      }
    }
  }
  return TriangleMesh(data.Positions, data.Triangles);
}

double Cross2(const Vec3& a, const Vec3& b)
{
  return a.x * b.y - a.y * b.x;
}

/// The straight segment a -> b of the flat mesh as a curve of canonical points: its ends, the
/// vertices it passes and its crossings with edges, in order (consecutive points share a
/// triangle). Brute force over the mesh's edges and vertices: fine for test grids.
std::vector<CanonicalPoint> StraightCurve(const TriangleMesh& mesh, const Vec3& a, const Vec3& b)
{
  struct Stop
  {
    double S;
    CanonicalPoint Point;
  };
  std::vector<Stop> stops;
  const Vec3 ab = b - a;
  const double ab2 = Dot(ab, ab);
  const double snap = 1e-12;
  for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
    const Vec3 av = mesh.GetPosition(v) - a;
    const double s = Dot(av, ab) / ab2;
    if (std::abs(Cross2(ab, av)) <= snap * std::sqrt(ab2) && s >= -snap && s <= 1.0 + snap)
    {
      stops.push_back({ s, VertexPoint(v) });
    }
  }
  for (int e = 0; e < mesh.GetNumberOfEdges(); ++e)
  {
    const std::array<int, 2> ev = mesh.GetEdgeVertices(e);
    const Vec3 p = mesh.GetPosition(ev[0]), pq = mesh.GetPosition(ev[1]) - p;
    const double den = Cross2(ab, pq);
    if (std::abs(den) <= 1e-9 * std::sqrt(ab2 * Dot(pq, pq)))
    {
      continue; // parallel: its vertices on the segment are stops already
    }
    const double s = Cross2(p - a, pq) / den, t = Cross2(p - a, ab) / den;
    if (s >= 0.0 && s <= 1.0 && t > snap && t < 1.0 - snap)
    {
      stops.push_back({ s, EdgePoint(e, t) });
    }
  }
  // The ends, unless a vertex or an edge crossing is there already.
  for (const auto& [s, x] : { std::pair<double, Vec3>{ 0.0, a }, { 1.0, b } })
  {
    const bool known = std::any_of(stops.begin(),
      stops.end(),
      [s = s, snap](const Stop& stop) { return std::abs(stop.S - s) <= snap; });
    for (int t = 0; t < mesh.GetNumberOfTriangles() && !known; ++t)
    {
      const Triangle& tri = mesh.GetTriangle(t);
      const std::array<double, 3> w = TrianglePlaneWeights(
        mesh.GetPosition(tri[0]), mesh.GetPosition(tri[1]), mesh.GetPosition(tri[2]))(x);
      if (w[0] > 0.0 && w[1] > 0.0 && w[2] > 0.0)
      {
        stops.push_back({ s, FacePoint(t, w[1], w[2]) });
        break;
      }
    }
  }
  std::sort(stops.begin(), stops.end(), [](const Stop& x, const Stop& y) { return x.S < y.S; });
  std::vector<CanonicalPoint> curve;
  for (size_t i = 0; i < stops.size(); ++i)
  {
    if (i > 0 && stops[i].S - stops[i - 1].S <= snap)
    {
      continue; // a vertex found twice
    }
    curve.push_back(stops[i].Point);
  }
  return curve;
}

/// The worst error of the field of `curve` (a point, or a straight open curve) over the mesh's
/// vertices, edge midpoints and triangle centroids nearer to it than `radius`, in units of the
/// error allowed there: `relative` of the exact distance (to the segment from the curve's first
/// to its last point) plus `absolute`. `where` names the worst place, `count` the places.
double WorstFieldError(const TriangleMesh& mesh,
  const std::vector<CanonicalPoint>& curve,
  double radius,
  double relative,
  double absolute,
  std::string& where,
  int& count)
{
  ExactGeodesicSearch search(mesh);
  EXPECT_TRUE(search.ComputeDistanceField({ curve }, { 0 }, radius));
  const Vec3 a = PositionOf(mesh, curve.front()), b = PositionOf(mesh, curve.back());
  double worst = 0.0;
  count = 0;
  auto check = [&](const Vec3& x, double field, const std::string& place)
  {
    const double exact = SegmentPointDistance(a, b, x);
    if (!(exact < (1.0 - 1e-9) * radius))
    {
      return; // the field is exact below the radius only
    }
    ++count;
    const double error = std::abs(field - exact) / (relative * exact + absolute);
    if (!(error <= worst))
    {
      worst = error;
      std::ostringstream text;
      text.precision(17);
      text << place << " at (" << x.x << ", " << x.y << "): field " << field << ", exact " << exact;
      where = text.str();
    }
  };
  for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
    check(mesh.GetPosition(v), search.GetFieldDistanceAtVertex(v), "vertex " + std::to_string(v));
  }
  for (int e = 0; e < mesh.GetNumberOfEdges(); ++e)
  {
    const std::array<int, 2> ev = mesh.GetEdgeVertices(e);
    check(0.5 * (mesh.GetPosition(ev[0]) + mesh.GetPosition(ev[1])),
      search.GetFieldDistanceOnEdge(e, 0.5),
      "edge " + std::to_string(e));
  }
  for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    const Triangle& tri = mesh.GetTriangle(t);
    const double third = 1.0 / 3.0;
    check(third * (mesh.GetPosition(tri[0]) + mesh.GetPosition(tri[1]) + mesh.GetPosition(tri[2])),
      search.GetFieldDistanceInTriangle(t, { third, third, third }),
      "triangle " + std::to_string(t));
  }
  return worst;
}

/// The canonical point at x (snapped to a vertex or an edge as every reader does).
CanonicalPoint PointAt(const TriangleMesh& mesh, const Vec3& x)
{
  for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    const Triangle& tri = mesh.GetTriangle(t);
    const std::array<double, 3> w = TrianglePlaneWeights(
      mesh.GetPosition(tri[0]), mesh.GetPosition(tri[1]), mesh.GetPosition(tri[2]))(x);
    if (w[0] >= -1e-12 && w[1] >= -1e-12 && w[2] >= -1e-12)
    {
      return LocateSurfacePoint(mesh, SurfacePoint{ t, w[1], w[2] });
    }
  }
  return CanonicalPoint();
}

const Diagonals AllDiagonals[] = { Diagonals::Rising, Diagonals::Falling, Diagonals::Alternating };
} // namespace

TEST(ExactFlatGrid, PointSourceFieldIsTheEuclideanDistance)
{
  // The colleague's case first (vertex (0.3, 0.3), read at (0.27, 0.33): 0.046056 for
  // 0.042426), then a vertex, points on edges of the three directions and inside triangles.
  const Vec3 sources[] = { { 0.3, 0.3, 0.0 },
    { 0.52, 0.47, 0.0 },
    { 0.3, 0.3023, 0.0 },
    { 0.3037, 0.3, 0.0 },
    { 0.305, 0.305, 0.0 },
    { 0.3037, 0.3011, 0.0 },
    { 0.3011, 0.3037, 0.0 },
    { 0.305, 0.3025, 0.0 } };
  for (const Diagonals diagonals : AllDiagonals)
  {
    const TriangleMesh mesh = Grid(100, diagonals);
    for (const Vec3& x : sources)
    {
      const CanonicalPoint source = PointAt(mesh, x);
      std::string where;
      int count = 0;
      const double error = WorstFieldError(mesh, { source }, 0.05, 1e-12, 1e-15, where, count);
      EXPECT_LE(error, 1.0) << NameOf(diagonals) << " grid, source " << Describe(source) << " at ("
                            << x.x << ", " << x.y << "): worst " << where;
      EXPECT_GT(count, 300);
    }
  }
}

TEST(ExactFlatGrid, LineSourceFieldIsTheDistanceToTheSegment)
{
  // Segments from a vertex, from a point on an edge and from a point inside a triangle, at the
  // grid's directions (along its edges, its diagonals, through its vertices) and off them.
  const Vec3 starts[] = { { 0.3, 0.3, 0.0 }, { 0.3, 0.3023, 0.0 }, { 0.3037, 0.3011, 0.0 } };
  const double angles[] = { 0.0,
    Pi / 4.0,
    Pi / 2.0,
    3.0 * Pi / 4.0,
    std::atan(0.5),
    std::atan(2.0),
    Pi - std::atan(0.5),
    std::atan(1.0 / 3.0),
    0.3 };
  for (const Diagonals diagonals : AllDiagonals)
  {
    const TriangleMesh mesh = Grid(100, diagonals);
    for (const Vec3& start : starts)
    {
      for (const double angle : angles)
      {
        const Vec3 end = start + 0.3 * Vec3{ std::cos(angle), std::sin(angle), 0.0 };
        const std::vector<CanonicalPoint> curve = StraightCurve(mesh, start, end);
        std::string where;
        int count = 0;
        // Line sources are windows from a point 1e7 piece lengths behind the piece (see
        // ComputeDistanceField): exact to ~1e-8 of a piece (at most the cells' diagonal;
        // measured up to 1.9e-10 here).
        const double error =
          WorstFieldError(mesh, curve, 0.05, 1e-12, 5e-8 * std::sqrt(2.0) / 100, where, count);
        EXPECT_LE(error, 1.0) << NameOf(diagonals) << " grid, segment from (" << start.x << ", "
                              << start.y << ") at angle " << angle << ": worst " << where;
        EXPECT_GT(count, 2000);
      }
    }
  }
}

TEST(ExactFlatGrid, ShortestPathsAlongLatticeDirectionsAreStraight)
{
  // From vertex (0.5, 0.5) along lattice directions: the straight path runs through vertices
  // at every step (and along edges for the axes and the cells' diagonals).
  const int directions[][2] = { { 1, 0 },
    { 0, 1 },
    { 1, 1 },
    { -1, 1 },
    { 2, 1 },
    { 1, 2 },
    { -2, 1 },
    { -1, 2 },
    { 3, 1 },
    { -3, 1 },
    { 3, 2 },
    { -2, -3 } };
  const int n = 40;
  for (const Diagonals diagonals : AllDiagonals)
  {
    const TriangleMesh mesh = Grid(n, diagonals);
    ExactGeodesicSearch search(mesh);
    GeodesicPathSolver solver(mesh);
    GeodesicPathOptions options;
    options.Method = GeodesicMethod::Exact;
    solver.SetOptions(options);
    const int center = (n / 2) * (n + 1) + n / 2;
    std::vector<int> startTriangles, endTriangles, strip;
    GeodesicPath path;
    for (const auto& d : directions)
    {
      for (int k = 1; std::abs(k * d[0]) <= 12 && std::abs(k * d[1]) <= 12; ++k)
      {
        const CanonicalPoint a = VertexPoint(center);
        const CanonicalPoint b = VertexPoint(center + k * d[1] * (n + 1) + k * d[0]);
        if (SharedTriangle(mesh, a, b) >= 0)
        {
          continue;
        }
        const double exact = Distance(PositionOf(mesh, a), PositionOf(mesh, b));
        TrianglesOf(mesh, a, startTriangles);
        TrianglesOf(mesh, b, endTriangles);
        const std::string pair = std::string(NameOf(diagonals)) + " grid, " + std::to_string(k) +
          " x (" + std::to_string(d[0]) + ", " + std::to_string(d[1]) + ")";
        EXPECT_NEAR(
          search.FindStrip(a, startTriangles, b, endTriangles, strip), exact, 1e-12 * exact)
          << pair;
        ASSERT_TRUE(solver.Compute(a, b, path, traceError)) << pair;
        EXPECT_TRUE(solver.GetLastStatistics().Exact) << pair;
        EXPECT_NEAR(path.Length, exact, 1e-12 * exact) << pair;
      }
    }
  }
}

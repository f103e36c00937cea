// Tracing on pieces (Core/Distributed/PieceTracing): a surface split into 2 to 7 pieces, each
// piece tracing random polygons and Bezier splines from its own triangles and ring, fetching
// what the legs read from a view of the whole surface (what an MPI layer would ask the owners
// for). Every traced curve must equal, bit for bit, the curve traced on the whole surface, with
// the Exact and Bounded methods, on a sphere, a torus, eight.ply (genus 2) and a jittered flat
// square; a piece must hold far fewer triangles than the surface when the curves are short.
#include "Distributed/PieceTracing.h"

#include "Mesh/PlyReader.h"
#include "Mesh/ProceduralMeshes.h"
#include "Support/PieceSplits.h"
#include "Support/SourceTree.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>

using namespace boolsurf;
using boolsurf::testing::MakePiece;
using boolsurf::testing::RegionOwners;
using boolsurf::testing::SlabOwners;

namespace
{

/// The owners' side in one process: every triangle within the rings asked for, from the
/// whole surface.
class WholeSurfaceFetcher : public TriangleFetcher
{
public:
  explicit WholeSurfaceFetcher(const TriangleMesh& mesh)
    : Mesh(mesh)
  {
  }

  bool Fetch(const std::vector<int>& vertices,
    const std::vector<int>& triangles,
    int rings,
    FetchedTriangles& out,
    std::string& error) override
  {
    const TriangleMesh& mesh = this->Mesh;
    std::vector<char> sent(mesh.GetNumberOfTriangles(), 0), seen(mesh.GetNumberOfVertices(), 0);
    std::vector<int> frontier;
    auto reach = [&](int v)
    {
      if (!seen[v])
      {
        seen[v] = 1;
        frontier.push_back(v);
      }
    };
    for (int v : vertices)
    {
      if (v < 0 || v >= mesh.GetNumberOfVertices())
      {
        error = "no vertex " + std::to_string(v);
        return false;
      }
      reach(v);
    }
    for (int t : triangles)
    {
      if (t < 0 || t >= mesh.GetNumberOfTriangles())
      {
        error = "no piece holds triangle " + std::to_string(t);
        return false;
      }
      for (int v : mesh.GetTriangle(t))
      {
        reach(v);
      }
    }
    for (int ring = 0; ring < rings; ++ring)
    {
      const std::vector<int> current = std::move(frontier);
      frontier.clear();
      for (int v : current)
      {
        out.WholeVertices.push_back(v);
        for (int corner : mesh.GetVertexCorners(v))
        {
          const int t = corner / 3;
          if (sent[t])
          {
            continue;
          }
          sent[t] = 1;
          out.TriangleGlobalIds.push_back(t);
          out.Corners.push_back(mesh.GetTriangle(t));
          for (int w : mesh.GetTriangle(t))
          {
            reach(w);
          }
        }
      }
    }
    std::fill(seen.begin(), seen.end(), 0);
    for (const std::array<int, 3>& corners : out.Corners)
    {
      for (int w : corners)
      {
        if (!seen[w])
        {
          seen[w] = 1;
          out.PointGlobalIds.push_back(w);
          out.Positions.push_back(mesh.GetPosition(w));
        }
      }
    }
    ++this->Requests;
    return true;
  }

  int Requests = 0;

private:
  const TriangleMesh& Mesh;
};

struct TestCurve
{
  std::vector<SurfacePoint> Points;
  CurveType Type = CurveType::GeodesicPolygon;
  bool Closed = true;
};

SurfacePoint RandomPointIn(int t, std::mt19937& random)
{
  std::uniform_real_distribution<double> unit(0.05, 0.95);
  double u = unit(random), v = unit(random);
  if (u + v > 0.95)
  {
    u = 0.95 - u * 0.5;
    v = 0.95 - u - 0.01;
  }
  return { t, u, v };
}

/// Triangles within `rings` vertex rings of triangle `center` (the whole surface when rings is
/// large), in breadth-first order.
std::vector<int> TrianglesNear(const TriangleMesh& mesh, int center, int rings)
{
  std::vector<char> in(mesh.GetNumberOfTriangles(), 0);
  std::vector<int> out{ center };
  in[center] = 1;
  size_t begin = 0;
  for (int ring = 0; ring < rings && begin < out.size(); ++ring)
  {
    const size_t end = out.size();
    for (size_t i = begin; i < end; ++i)
    {
      for (int v : mesh.GetTriangle(out[i]))
      {
        for (int corner : mesh.GetVertexCorners(v))
        {
          if (!in[corner / 3])
          {
            in[corner / 3] = 1;
            out.push_back(corner / 3);
          }
        }
      }
    }
    begin = end;
  }
  return out;
}

/// Closed and open polygons of 3 to 5 points and a closed Bezier spline of two segments, their
/// control points in triangles within `rings` rings of a random triangle.
std::vector<TestCurve> RandomCurves(const TriangleMesh& mesh, unsigned seed, int count, int rings)
{
  std::mt19937 random(seed);
  std::vector<TestCurve> curves;
  for (int c = 0; c < count; ++c)
  {
    const int center = static_cast<int>(random() % mesh.GetNumberOfTriangles());
    const std::vector<int> near = TrianglesNear(mesh, center, rings);
    TestCurve curve;
    curve.Type = c % 4 == 3 ? CurveType::CubicBezier : CurveType::GeodesicPolygon;
    curve.Closed = c % 4 != 1;
    const int n = curve.Type == CurveType::CubicBezier ? 6 : 3 + static_cast<int>(random() % 3);
    for (int i = 0; i < n; ++i)
    {
      curve.Points.push_back(RandomPointIn(near[random() % near.size()], random));
    }
    curves.push_back(curve);
  }
  return curves;
}

void ExpectSameTrace(const GlobalCurveTrace& a, const GlobalCurveTrace& b, const std::string& what)
{
  ASSERT_EQ(a.Points.size(), b.Points.size()) << what;
  for (size_t i = 0; i < a.Points.size(); ++i)
  {
    ASSERT_TRUE(a.Points[i] == b.Points[i]) << what << ", point " << i;
  }
  EXPECT_EQ(a.Closed, b.Closed) << what;
  EXPECT_EQ(a.ShapeId, b.ShapeId) << what;
  EXPECT_EQ(a.CurveId, b.CurveId) << what;
  EXPECT_EQ(a.Segment, b.Segment) << what;
  EXPECT_EQ(a.ControlPoint, b.ControlPoint) << what;
  EXPECT_EQ(a.Parameter, b.Parameter) << what;
  EXPECT_EQ(a.OnCurve, b.OnCurve) << what;
  EXPECT_EQ(a.Length, b.Length) << what;
}

constexpr int Resolution = 2;

/// Every curve traced on the whole surface with `method`.
std::vector<GlobalCurveTrace> TraceWhole(const TriangleMesh& mesh,
  const std::vector<TestCurve>& curves,
  GeodesicMethod method,
  std::vector<TracedCurve>* traced = nullptr)
{
  CurveTracer tracer(mesh);
  tracer.SetResolution(Resolution);
  GeodesicPathOptions options;
  options.Method = method;
  tracer.GetPathSolver().SetOptions(options);
  std::vector<GlobalCurveTrace> out;
  for (size_t c = 0; c < curves.size(); ++c)
  {
    CurveTrace trace;
    std::string error;
    EXPECT_TRUE(tracer.Trace(
      curves[c].Points, curves[c].Type, curves[c].Closed, trace, error, static_cast<int>(c)))
      << error;
    out.push_back(ToGlobalTrace(trace, mesh, {}, {}));
    if (traced)
    {
      traced->push_back(trace.Curve);
    }
  }
  return out;
}

struct SplitCounts
{
  int MaximumHeld = 0;  ///< largest piece after tracing every curve
  int MaximumOwned = 0; ///< largest piece with its ring, before
  int Rounds = 0, MaximumRounds = 0, Legs = 0;
  long long Fetched = 0;
};

/// Each piece of `owner` traces every curve and must give the whole surface's traces.
SplitCounts ExpectSameOnPieces(const TriangleMesh& mesh,
  const std::vector<TestCurve>& curves,
  const std::vector<GlobalCurveTrace>& whole,
  GeodesicMethod method,
  const std::vector<int>& owner,
  int pieces,
  const std::string& split)
{
  SplitCounts counts;
  WholeSurfaceFetcher fetcher(mesh);
  GeodesicPathOptions options;
  options.Method = method;
  for (int p = 0; p < pieces; ++p)
  {
    PieceCurveTracer tracer(MakePiece(mesh, owner, p), fetcher);
    tracer.SetOptions(options);
    tracer.SetResolution(Resolution);
    tracer.SetMeanEdgeLength(EstimateMeanEdgeLength(mesh));
    counts.MaximumOwned = std::max(counts.MaximumOwned, tracer.GetSurface().GetNumberOfTriangles());
    for (size_t c = 0; c < curves.size(); ++c)
    {
      GlobalCurveTrace trace;
      std::string error;
      const std::string what = split + ", piece " + std::to_string(p) + ", curve " +
        std::to_string(c) + ", " + GeodesicMethodName(method);
      EXPECT_TRUE(tracer.Trace(
        curves[c].Points, curves[c].Type, curves[c].Closed, trace, error, static_cast<int>(c)))
        << what << ": " << error;
      ExpectSameTrace(trace, whole[c], what);
      const PieceTracingStatistics& s = tracer.GetLastStatistics();
      counts.Rounds += s.Rounds;
      counts.MaximumRounds = std::max(counts.MaximumRounds, s.Rounds);
      counts.Fetched += s.FetchedTriangles;
    }
    counts.MaximumHeld = std::max(counts.MaximumHeld, tracer.GetSurface().GetNumberOfTriangles());
  }
  return counts;
}

void ExpectSameForEverySplit(const TriangleMesh& mesh, const std::vector<TestCurve>& curves)
{
  for (GeodesicMethod method : { GeodesicMethod::Exact, GeodesicMethod::Bounded })
  {
    const std::vector<GlobalCurveTrace> whole = TraceWhole(mesh, curves, method);
    struct Split
    {
      std::string Name;
      std::vector<int> Owner;
      int Pieces;
    };
    const std::vector<Split> splits{ { "2 slabs along x", SlabOwners(mesh, 2, 0), 2 },
      { "3 random regions", RegionOwners(mesh, 3, 7, -1), 3 },
      { "5 random regions, piece 2 empty", RegionOwners(mesh, 5, 11, 2), 5 },
      { "7 slabs along z", SlabOwners(mesh, 7, 2), 7 } };
    for (const Split& split : splits)
    {
      const SplitCounts counts =
        ExpectSameOnPieces(mesh, curves, whole, method, split.Owner, split.Pieces, split.Name);
      std::printf("%s, %s: %d triangles; largest piece %d with its ring, %d after tracing; "
                  "%d rounds (at most %d per curve), %lld triangles fetched\n",
        split.Name.c_str(),
        GeodesicMethodName(method),
        mesh.GetNumberOfTriangles(),
        counts.MaximumOwned,
        counts.MaximumHeld,
        counts.Rounds,
        counts.MaximumRounds,
        counts.Fetched);
    }
  }
}

TriangleMesh ToMesh(const MeshData& data)
{
  return TriangleMesh(data.Positions, data.Triangles);
}

} // namespace

TEST(PieceTracing, SphereCurvesEqualTheWholeSurfaces)
{
  const TriangleMesh mesh = ToMesh(MakeIcosphere(3));
  ExpectSameForEverySplit(mesh, RandomCurves(mesh, 3, 8, 100));
}

TEST(PieceTracing, TorusCurvesEqualTheWholeSurfaces)
{
  const TriangleMesh mesh = ToMesh(MakeTorus(1.0, 0.4, 32, 16));
  ExpectSameForEverySplit(mesh, RandomCurves(mesh, 5, 8, 100));
}

TEST(PieceTracing, GenusTwoCurvesEqualTheWholeSurfaces)
{
  MeshData data;
  std::string error;
  ASSERT_TRUE(
    ReadPly((boolsurf::testing::SourceTree() / "Data" / "eight.ply").string(), data, error))
    << error;
  const TriangleMesh mesh = ToMesh(data);
  ExpectSameForEverySplit(mesh, RandomCurves(mesh, 9, 8, 100));
}

TEST(PieceTracing, FlatCurvesEqualTheWholeSurfaces)
{
  // Jittered, so that legs have no ties; a regular grid's are tested below.
  const TriangleMesh mesh = ToMesh(MakeFlatSquare(16, 1.0, 0.2, 4));
  ExpectSameForEverySplit(mesh, RandomCurves(mesh, 13, 8, 100));
}

TEST(PieceTracing, RegularGridCurvesEqualTheWholeSurfaces)
{
  const TriangleMesh mesh = ToMesh(MakeFlatSquare(12));
  ExpectSameForEverySplit(mesh, RandomCurves(mesh, 17, 8, 100));
}

TEST(PieceTracing, ShortCurvesFetchAFewTrianglesOfALargeSphere)
{
  // 20,480 triangles in 8 slabs; short curves (control points within 6 rings of a triangle)
  // anywhere, each traced by every piece from its own triangles and ring alone: a piece
  // fetches the neighbourhood of the curve, not the surface. Margins of 1 to 3 rings trade
  // rounds for triangles.
  const TriangleMesh mesh = ToMesh(MakeIcosphere(5));
  const std::vector<TestCurve> curves = RandomCurves(mesh, 21, 8, 6);
  const int pieces = 8;
  const std::vector<int> owner = SlabOwners(mesh, pieces, 0);
  int legs = 0;
  for (const TestCurve& curve : curves)
  {
    const int n = static_cast<int>(curve.Points.size());
    legs += curve.Type == CurveType::CubicBezier ? (n / 3) * 3 * (1 << Resolution)
                                                 : (curve.Closed ? n : n - 1);
  }
  for (GeodesicMethod method : { GeodesicMethod::Exact, GeodesicMethod::Bounded })
  {
    const std::vector<GlobalCurveTrace> whole = TraceWhole(mesh, curves, method);
    GeodesicPathOptions options;
    options.Method = method;
    for (int margin = 1; margin <= 3; ++margin)
    {
      WholeSurfaceFetcher fetcher(mesh);
      int rounds = 0, maximumRounds = 0, maximumFetched = 0;
      long long fetched = 0;
      for (int p = 0; p < pieces; ++p)
      {
        for (size_t c = 0; c < curves.size(); ++c)
        {
          PieceCurveTracer tracer(MakePiece(mesh, owner, p), fetcher);
          tracer.SetOptions(options);
          tracer.SetResolution(Resolution);
          tracer.SetMeanEdgeLength(EstimateMeanEdgeLength(mesh));
          tracer.SetMarginRings(margin);
          GlobalCurveTrace trace;
          std::string error;
          ASSERT_TRUE(tracer.Trace(
            curves[c].Points, curves[c].Type, curves[c].Closed, trace, error, static_cast<int>(c)))
            << error;
          ExpectSameTrace(trace, whole[c], "piece " + std::to_string(p));
          const PieceTracingStatistics& s = tracer.GetLastStatistics();
          rounds += s.Rounds;
          maximumRounds = std::max(maximumRounds, s.Rounds);
          fetched += s.FetchedTriangles;
          maximumFetched = std::max(maximumFetched, s.FetchedTriangles);
        }
      }
      std::printf("%s, margin %d: %d triangles in %d slabs, %zu short curves (%d legs) each "
                  "traced by every piece alone: %.1f rounds per curve (at most %d), %.1f "
                  "triangles fetched per leg, at most %d per curve\n",
        GeodesicMethodName(method),
        margin,
        mesh.GetNumberOfTriangles(),
        pieces,
        curves.size(),
        legs,
        static_cast<double>(rounds) / (pieces * curves.size()),
        maximumRounds,
        static_cast<double>(fetched) / (pieces * legs),
        maximumFetched);
      // A curve's neighbourhood, far below the surface.
      EXPECT_LT(maximumFetched, mesh.GetNumberOfTriangles() / 10);
    }
  }
}

TEST(PieceTracing, MessageOfPieceTracesIsTheWholeSurfaces)
{
  // What a piece sends to every piece (message 0) is the buffer the whole surface's traces
  // give, and reads back to the same curves and edges.
  const TriangleMesh mesh = ToMesh(MakeTorus(1.0, 0.4, 32, 16));
  const std::vector<TestCurve> curves = RandomCurves(mesh, 23, 6, 100);
  std::vector<TracedCurve> traced;
  TraceWhole(mesh, curves, GeodesicMethod::Bounded, &traced);
  WireBuffer expected;
  PackTracedCurves(traced, mesh, {}, {}, expected);
  WholeSurfaceFetcher fetcher(mesh);
  PieceCurveTracer tracer(MakePiece(mesh, RegionOwners(mesh, 4, 3, -1), 1), fetcher);
  tracer.SetResolution(Resolution);
  tracer.SetMeanEdgeLength(EstimateMeanEdgeLength(mesh));
  std::vector<GlobalCurveTrace> traces(curves.size());
  for (size_t c = 0; c < curves.size(); ++c)
  {
    std::string error;
    ASSERT_TRUE(tracer.Trace(
      curves[c].Points, curves[c].Type, curves[c].Closed, traces[c], error, static_cast<int>(c)))
      << error;
  }
  WireBuffer sent;
  PackGlobalTraces(traces, sent);
  EXPECT_EQ(sent, expected);
  std::vector<TracedCurve> unpacked;
  std::vector<std::array<int, 2>> edges;
  std::string error;
  ASSERT_TRUE(UnpackTracedCurves(sent, unpacked, edges, error)) << error;
  ASSERT_EQ(unpacked.size(), traced.size());
  for (size_t c = 0; c < traced.size(); ++c)
  {
    EXPECT_EQ(unpacked[c].Points.size(), traced[c].Points.size());
  }
}

TEST(PieceTracing, MethodsNeedingTheWholeSurfaceSaySo)
{
  const TriangleMesh mesh = ToMesh(MakeIcosphere(3));
  WholeSurfaceFetcher fetcher(mesh);
  PieceCurveTracer tracer(MakePiece(mesh, SlabOwners(mesh, 2, 0), 0), fetcher);
  GeodesicPathOptions options;
  options.Method = GeodesicMethod::LocallyShortest;
  tracer.SetOptions(options);
  GlobalCurveTrace trace;
  std::string error;
  EXPECT_FALSE(tracer.Trace(
    { { 0, 0.3, 0.3 }, { 600, 0.3, 0.3 } }, CurveType::GeodesicPolygon, false, trace, error, 4));
  EXPECT_NE(error.find("curve 4"), std::string::npos) << error;
  EXPECT_NE(error.find("on a piece of the surface"), std::string::npos) << error;
  // A control point on a triangle no piece holds.
  options.Method = GeodesicMethod::Exact;
  tracer.SetOptions(options);
  EXPECT_FALSE(tracer.Trace({ { 0, 0.3, 0.3 }, { mesh.GetNumberOfTriangles(), 0.3, 0.3 } },
    CurveType::GeodesicPolygon,
    false,
    trace,
    error,
    5));
  EXPECT_NE(error.find("curve 5"), std::string::npos) << error;
  EXPECT_NE(error.find("no piece holds triangle"), std::string::npos) << error;
}

// Geodesic offsets (Core/Offset) on shared scans against an independent exact oracle built on
// CGAL's Surface_mesh_shortest_path (Chen-Han's algorithm with exact predicates). A geodesic
// polygon drawn around a random vertex is grown by 2 % and shrunk by 1 % of the bounding-box
// diagonal, and
// (a) every point of the offset's loops is at the oracle's distance |d| from the polygon (the
//     offset puts its contour points on mesh edges by bisection on an exact distance field, so
//     this holds far below mesh resolution);
// (b) every mesh vertex on the offset's side whose oracle distance is within half an edge of |d|
//     lies next to a loop piece: no part of the level set is missing;
// (c) random surface points near the level set lie in the labeled offset region exactly when
//     the oracle's signed distance is at most d, except within the contour's chord error of the
//     level set: the loops are oriented and chained into the right region.
//
// The oracle's distance from a point p to the polygon is the least single-source CGAL distance
// from p to points sampled densely along the polygon's straight pieces, on the patch of
// triangles within a 3D radius of p. CGAL's multi-source tree (add_source_points) is not used:
// in CGAL 5.5.1 it returns distances too long by up to 13 % of |d| at some points here (vertices
// too), where single-source trees, exact traced paths and Core's field agree to rounding.
#include "Arrangement/Arrangement.h"
#include "CgalFaceWeights.h"
#include "Geodesic/CurveTracer.h"
#include "Labeling/ArrangementLabelingInput.h"
#include "Labeling/CellLabeling.h"
#include "Mesh/MeshTopology.h"
#include "Mesh/PlyReader.h"
#include "Offset/GeodesicOffset.h"
#include "Offset/OffsetRegionOfCells.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_shortest_path.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <random>
#include <string>
#include <unordered_map>
#include <vector>

using namespace boolsurf;

namespace
{
/// The message of the last failed trace or path (a test reads it only after a failure).
std::string traceError;
}

namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalMesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Traits = CGAL::Surface_mesh_shortest_path_traits<Kernel, CgalMesh>;
using ShortestPaths = CGAL::Surface_mesh_shortest_path<Traits>;

constexpr double Pi = 3.14159265358979323846;

/// CGAL face location of the point with weights w (of the triangle's corners in order) in face
/// f, whose corners are the CGAL vertices `corners` in that order.
ShortestPaths::Face_location FaceLocation(const CgalMesh& cgal,
  CgalMesh::Face_index f,
  const std::array<int, 3>& corners,
  const std::array<double, 3>& w)
{
  std::array<double, 3> b = InCgalVertexOrder(cgal, f, corners, w);
  // CGAL 5.5's tree is wrong for some sources given exactly on an edge (a zero weight; see
  // TestGeodesicExactOracle.cxx): a point 1e-13 (relative) inside the face is the same point to
  // far below every tolerance here and takes the well-tested face path.
  if (b[0] == 0.0 || b[1] == 0.0 || b[2] == 0.0)
  {
    for (double& x : b)
    {
      x = x == 0.0 ? 1e-13 : x * (1 - 1e-13);
    }
  }
  return { f, Traits::Barycentric_coordinates{ b[0], b[1], b[2] } };
}

double BoundingDiagonal(const TriangleMesh& mesh)
{
  Vec3 lo = mesh.GetPosition(0), hi = lo;
  for (const Vec3& q : mesh.GetPositions())
  {
    lo = { std::min(lo.x, q.x), std::min(lo.y, q.y), std::min(lo.z, q.z) };
    hi = { std::max(hi.x, q.x), std::max(hi.y, q.y), std::max(hi.z, q.z) };
  }
  return Distance(lo, hi);
}

double MeanEdgeLength(const TriangleMesh& mesh)
{
  double sum = 0.0;
  for (int e = 0; e < mesh.GetNumberOfEdges(); ++e)
  {
    const std::array<int, 2> ev = mesh.GetEdgeVertices(e);
    sum += Distance(mesh.GetPosition(ev[0]), mesh.GetPosition(ev[1]));
  }
  return sum / mesh.GetNumberOfEdges();
}

double TriangleArea(const Vec3& a, const Vec3& b, const Vec3& c)
{
  return 0.5 * Length(Cross(b - a, c - a));
}

/// The point of triangle abc nearest to p (Ericson, Real-Time Collision Detection, 5.1.5).
Vec3 ClosestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = Dot(ab, ap), d2 = Dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0)
  {
    return a;
  }
  const Vec3 bp = p - b;
  const double d3 = Dot(ab, bp), d4 = Dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3)
  {
    return b;
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
  {
    return a + (d1 / (d1 - d3)) * ab;
  }
  const Vec3 cp = p - c;
  const double d5 = Dot(ab, cp), d6 = Dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6)
  {
    return c;
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
  {
    return a + (d2 / (d2 - d6)) * ac;
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
  {
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  }
  const double scale = 1.0 / (va + vb + vc);
  return a + (vb * scale) * ab + (vc * scale) * ac;
}

/// The surface point nearest to x (brute force over the triangles) and its distance to x.
SurfacePoint NearestSurfacePoint(const TriangleMesh& mesh, const Vec3& x, double& distance)
{
  int best = -1;
  Vec3 bestPoint{ 0.0, 0.0, 0.0 };
  distance = 1e300;
  for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    const Triangle& tri = mesh.GetTriangle(t);
    const Vec3 q = ClosestPointOnTriangle(
      x, mesh.GetPosition(tri[0]), mesh.GetPosition(tri[1]), mesh.GetPosition(tri[2]));
    if (Distance(q, x) < distance)
    {
      distance = Distance(q, x);
      best = t;
      bestPoint = q;
    }
  }
  return PointInTriangle(mesh, best, bestPoint);
}

double DistanceToSegment(const Vec3& p, const Vec3& a, const Vec3& b)
{
  const Vec3 ab = b - a;
  const double length2 = Dot(ab, ab);
  const double s = length2 > 0.0 ? std::min(1.0, std::max(0.0, Dot(p - a, ab) / length2)) : 0.0;
  return Distance(p, a + s * ab);
}

struct CurveSample
{
  int Triangle = -1;
  std::array<double, 3> Weights{}; ///< of the triangle's corners in order
  Vec3 Position{ 0.0, 0.0, 0.0 };
};

/// The closed polyline `curve` (consecutive points share a triangle) as points at most
/// `spacing` apart along its straight pieces: a point at distance r from the polyline is at most
/// spacing^2 / (8 r) farther from the samples.
std::vector<CurveSample> SampleCurve(const TriangleMesh& mesh,
  const std::vector<CanonicalPoint>& curve,
  double spacing)
{
  std::vector<CurveSample> samples;
  for (size_t i = 0; i < curve.size(); ++i)
  {
    const CanonicalPoint& a = curve[i];
    const CanonicalPoint& b = curve[(i + 1) % curve.size()];
    const int t = SharedTriangle(mesh, a, b);
    if (t < 0)
    {
      ADD_FAILURE() << "traced points " << i << " and " << i + 1 << " share no triangle";
      return {};
    }
    const std::array<double, 3> wa = WeightsInTriangle(mesh, a, t);
    const std::array<double, 3> wb = WeightsInTriangle(mesh, b, t);
    const Triangle& tri = mesh.GetTriangle(t);
    const int pieces = std::max(
      1, static_cast<int>(std::ceil(Distance(PositionOf(mesh, a), PositionOf(mesh, b)) / spacing)));
    for (int j = 0; j < pieces; ++j)
    {
      const double f = static_cast<double>(j) / pieces;
      CurveSample s;
      s.Triangle = t;
      for (int k = 0; k < 3; ++k)
      {
        s.Weights[k] = (1.0 - f) * wa[k] + f * wb[k];
        s.Position = s.Position + s.Weights[k] * mesh.GetPosition(tri[k]);
      }
      samples.push_back(s);
    }
  }
  return samples;
}

/// Exact geodesic distance from surface points to a sampled curve, up to a reach: one CGAL
/// single-source tree rooted at the point, on the triangles within the reach of it in 3D (every
/// path shorter than the reach stays in that ball), queried at the samples within the reach.
class CurveDistanceOracle
{
public:
  CurveDistanceOracle(const TriangleMesh& mesh,
    std::vector<CurveSample> samples,
    double maximumReach)
    : Mesh(mesh)
    , Samples(std::move(samples))
    , MaximumReach(maximumReach)
    , InPatch(mesh.GetNumberOfTriangles(), 0)
    , PatchVertex(mesh.GetNumberOfVertices(), -1)
  {
    for (const CurveSample& s : this->Samples)
    {
      this->Center = this->Center + (1.0 / this->Samples.size()) * s.Position;
    }
    for (const CurveSample& s : this->Samples)
    {
      this->Radius = std::max(this->Radius, Distance(s.Position, this->Center));
    }
    // Every ball of radius <= maximumReach around a point within maximumReach of a sample.
    for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
    {
      if (this->TriangleDistance(t, this->Center) <= this->Radius + 2.0 * maximumReach)
      {
        this->Nearby.push_back(t);
      }
    }
  }

  /// The 3D distance from x to the nearest sample, a lower bound of the geodesic distance (or a
  /// smaller lower bound beyond the maximum reach).
  double StraightDistance(const Vec3& x) const
  {
    const double fromCenter = Distance(x, this->Center);
    if (fromCenter > this->Radius + this->MaximumReach)
    {
      return fromCenter - this->Radius;
    }
    double best = 1e300;
    for (const CurveSample& s : this->Samples)
    {
      best = std::min(best, Distance(x, s.Position));
    }
    return best;
  }

  /// The geodesic distance from the point of triangle t with weights w to the nearest sample, or
  /// `reach` when that is farther.
  double GeodesicDistance(int t, const std::array<double, 3>& w, double reach)
  {
    EXPECT_LE(reach, this->MaximumReach);
    const TriangleMesh& mesh = this->Mesh;
    const Triangle& tri = mesh.GetTriangle(t);
    const Vec3 x = w[0] * mesh.GetPosition(tri[0]) + w[1] * mesh.GetPosition(tri[1]) +
      w[2] * mesh.GetPosition(tri[2]);
    std::vector<int> close;
    if (Distance(x, this->Center) <= this->Radius + reach)
    {
      for (size_t i = 0; i < this->Samples.size(); ++i)
      {
        if (Distance(x, this->Samples[i].Position) <= reach)
        {
          close.push_back(static_cast<int>(i));
        }
      }
    }
    if (close.empty())
    {
      return reach;
    }
    ++this->Trees;
    const std::unique_ptr<CgalMesh> patch = this->Patch(t, x, reach);
    if (!patch)
    {
      ADD_FAILURE() << "CGAL refused the patch around triangle " << t;
      return reach;
    }
    ShortestPaths tree(*patch);
    tree.add_source_point(this->Locate(*patch, t, w));
    tree.build_sequence_tree();
    double best = reach;
    for (int i : close)
    {
      const CurveSample& s = this->Samples[i];
      if (this->InPatch[s.Triangle])
      {
        const auto location = this->Locate(*patch, s.Triangle, s.Weights);
        // Negative: not reached (in another piece of the patch, farther than the reach).
        const double distance =
          tree.shortest_distance_to_source_points(location.first, location.second).first;
        if (distance >= 0.0)
        {
          best = std::min(best, distance);
        }
      }
    }
    this->Clear();
    return best;
  }

  double GeodesicDistance(const CanonicalPoint& p, double reach)
  {
    const int t = AnyTriangleOf(this->Mesh, p);
    return this->GeodesicDistance(t, WeightsInTriangle(this->Mesh, p, t), reach);
  }

  int GetNumberOfTrees() const { return this->Trees; }

private:
  double TriangleDistance(int t, const Vec3& x) const
  {
    const Triangle& tri = this->Mesh.GetTriangle(t);
    return Distance(x,
      ClosestPointOnTriangle(x,
        this->Mesh.GetPosition(tri[0]),
        this->Mesh.GetPosition(tri[1]),
        this->Mesh.GetPosition(tri[2])));
  }

  /// The triangles within `reach` of x, plus the whole star of every vertex where they meet
  /// only at that vertex (CGAL's halfedge mesh needs manifold vertices; more triangles only add
  /// paths that exist on the surface).
  std::unique_ptr<CgalMesh> Patch(int t, const Vec3& x, double reach)
  {
    const TriangleMesh& mesh = this->Mesh;
    auto add = [this](int f)
    {
      if (!this->InPatch[f])
      {
        this->InPatch[f] = 1;
        this->Selected.push_back(f);
      }
    };
    add(t);
    for (int f : this->Nearby)
    {
      if (this->TriangleDistance(f, x) <= reach)
      {
        add(f);
      }
    }
    for (bool changed = true; changed;)
    {
      changed = false;
      // Ends of the patch's boundary edges: a vertex is the end of two of them on a manifold
      // patch's boundary, of four or more where fans of the patch meet only at it.
      std::vector<int> ends;
      for (int f : this->Selected)
      {
        for (int k = 0; k < 3; ++k)
        {
          const int n = mesh.GetNeighbor(f, k);
          if (n < 0 || !this->InPatch[n])
          {
            ends.push_back(mesh.GetTriangle(f)[k]);
            ends.push_back(mesh.GetTriangle(f)[(k + 1) % 3]);
          }
        }
      }
      std::sort(ends.begin(), ends.end());
      for (size_t i = 0; i < ends.size();)
      {
        size_t j = i;
        while (j < ends.size() && ends[j] == ends[i])
        {
          ++j;
        }
        if (j - i > 2)
        {
          for (int corner : mesh.GetVertexCorners(ends[i]))
          {
            if (!this->InPatch[corner / 3])
            {
              add(corner / 3);
              changed = true;
            }
          }
        }
        i = j;
      }
    }
    auto out = std::make_unique<CgalMesh>();
    for (int f : this->Selected)
    {
      for (int v : mesh.GetTriangle(f))
      {
        if (this->PatchVertex[v] < 0)
        {
          this->PatchVertex[v] = static_cast<int>(out->number_of_vertices());
          this->UsedVertices.push_back(v);
          const Vec3& p = mesh.GetPosition(v);
          out->add_vertex(Kernel::Point_3(p.x, p.y, p.z));
        }
      }
    }
    for (int f : this->Selected)
    {
      const Triangle& tri = mesh.GetTriangle(f);
      this->PatchFace[f] = static_cast<int>(out->number_of_faces());
      if (out->add_face(CgalMesh::Vertex_index(this->PatchVertex[tri[0]]),
            CgalMesh::Vertex_index(this->PatchVertex[tri[1]]),
            CgalMesh::Vertex_index(this->PatchVertex[tri[2]])) == CgalMesh::null_face())
      {
        this->Clear();
        return nullptr;
      }
    }
    return out;
  }

  ShortestPaths::Face_location Locate(const CgalMesh& patch, int t, const std::array<double, 3>& w)
  {
    const Triangle& tri = this->Mesh.GetTriangle(t);
    return FaceLocation(patch,
      CgalMesh::Face_index(this->PatchFace.at(t)),
      { this->PatchVertex[tri[0]], this->PatchVertex[tri[1]], this->PatchVertex[tri[2]] },
      w);
  }

  void Clear()
  {
    for (int f : this->Selected)
    {
      this->InPatch[f] = 0;
    }
    for (int v : this->UsedVertices)
    {
      this->PatchVertex[v] = -1;
    }
    this->Selected.clear();
    this->UsedVertices.clear();
    this->PatchFace.clear();
  }

  const TriangleMesh& Mesh;
  const std::vector<CurveSample> Samples;
  const double MaximumReach;
  Vec3 Center{ 0.0, 0.0, 0.0 };
  double Radius = 0.0;
  std::vector<int> Nearby; // triangles any patch may use
  std::vector<char> InPatch;
  std::vector<int> PatchVertex;
  std::unordered_map<int, int> PatchFace;
  std::vector<int> Selected, UsedVertices;
  int Trees = 0;
};

struct Labeled
{
  Arrangement Arr;
  LabelingResult Labels;
  std::vector<char> Selected; // cells with a non-zero label of shape index 0
  double Area = 0;            // their area (3D)
};

// Arrangement, labels and the non-zero cells of the first shape of `curves` (as in the Core
// offset tests).
std::unique_ptr<Labeled> Label(const TriangleMesh& mesh,
  const MeshTopology& topology,
  const std::vector<TracedCurve>& curves)
{
  auto out = std::make_unique<Labeled>();
  std::string error;
  ArrangementOptions options;
  options.Threads = 1;
  if (!ComputeArrangement(mesh, curves, options, out->Arr, error))
  {
    ADD_FAILURE() << error;
    return nullptr;
  }
  out->Labels = LabelCells(MakeLabelingInput(mesh, topology, curves, out->Arr));
  if (!out->Labels.ShapeConsistent[0])
  {
    return nullptr;
  }
  out->Selected.assign(out->Arr.NumberOfCells, 0);
  for (int c = 0; c < out->Arr.NumberOfCells; ++c)
  {
    out->Selected[c] = out->Labels.GetLabel(c, 0) != 0;
  }
  for (size_t r = 0; r < static_cast<size_t>(out->Arr.GetNumberOfTriangles()); ++r)
  {
    if (out->Selected[out->Arr.CellOfTriangle(static_cast<int>(r))])
    {
      const auto& t = out->Arr.GetTriangle(mesh, r);
      out->Area += TriangleArea(out->Arr.GetPosition(mesh, t[0]),
        out->Arr.GetPosition(mesh, t[1]),
        out->Arr.GetPosition(mesh, t[2]));
    }
  }
  return out;
}

std::vector<TracedCurve> AsCurves(const std::vector<std::vector<CanonicalPoint>>& loops)
{
  std::vector<TracedCurve> curves;
  for (const auto& loop : loops)
  {
    TracedCurve c;
    c.Points = loop;
    c.Closed = true;
    c.ShapeId = 0;
    c.CurveId = static_cast<int>(curves.size());
    curves.push_back(std::move(c));
  }
  return curves;
}

/// A closed geodesic polygon through `corners` points on a circle of `radius` in the tangent
/// plane at a random vertex, each moved to the nearest surface point. Vertices where the
/// surface leaves the tangent plane by more than a fifth of the radius (an ear, a thin arm) are
/// passed over, so the polygon is a simple loop around a disk-like region.
bool DrawCircle(const TriangleMesh& mesh,
  const MeshTopology& topology,
  double radius,
  int corners,
  std::mt19937& rng,
  CurveTrace& trace,
  std::unique_ptr<Labeled>& shape,
  int& center)
{
  CurveTracer tracer(mesh);
  double surfaceArea = 0.0;
  for (const Triangle& t : mesh.GetTriangles())
  {
    surfaceArea +=
      TriangleArea(mesh.GetPosition(t[0]), mesh.GetPosition(t[1]), mesh.GetPosition(t[2]));
  }
  for (int attempt = 0; attempt < 200; ++attempt)
  {
    center = static_cast<int>(rng() % mesh.GetNumberOfVertices());
    const Vec3 c = mesh.GetPosition(center);
    // The mean normal of the surface within the radius (a scan's single vertex normal is noisy).
    Vec3 normal{ 0.0, 0.0, 0.0 };
    for (const Triangle& t : mesh.GetTriangles())
    {
      const Vec3 a = mesh.GetPosition(t[0]), b = mesh.GetPosition(t[1]), e = mesh.GetPosition(t[2]);
      if (Distance(a, c) < radius)
      {
        normal = normal + Cross(b - a, e - a);
      }
    }
    if (!(Length(normal) > 0.0))
    {
      continue;
    }
    normal = (1.0 / Length(normal)) * normal;
    const Vec3 helper = std::abs(normal.x) < 0.9 ? Vec3{ 1.0, 0.0, 0.0 } : Vec3{ 0.0, 1.0, 0.0 };
    Vec3 u = Cross(normal, helper);
    u = (1.0 / Length(u)) * u;
    const Vec3 v = Cross(normal, u);
    std::vector<SurfacePoint> control;
    bool flat = true;
    for (int i = 0; i < corners && flat; ++i)
    {
      const double angle = 2.0 * Pi * i / corners;
      const Vec3 x = c + (radius * std::cos(angle)) * u + (radius * std::sin(angle)) * v;
      double distance = 0.0;
      control.push_back(NearestSurfacePoint(mesh, x, distance));
      flat = distance < 0.2 * radius;
    }
    if (!flat || !tracer.Trace(control, CurveType::GeodesicPolygon, true, trace, traceError))
    {
      continue;
    }
    shape = Label(mesh, topology, { trace.Curve });
    // A disk-like region: a consistent shape, much smaller than the surface, holding its center.
    if (shape && shape->Area < 0.25 * surfaceArea)
    {
      OffsetRegion region = MakeOffsetRegion(mesh, shape->Arr, shape->Selected);
      if (region.Boundary.size() == 1 && region.InsideVertex(center))
      {
        return true;
      }
    }
  }
  return false;
}

std::string SharedMesh(const std::string& file)
{
  const char* root = std::getenv("BOOLSURF_SHARED_DATA");
  return root ? std::string(root) + "/meshes/" + file : std::string();
}

double Seconds(std::chrono::steady_clock::time_point from)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - from).count();
}
} // namespace

TEST(GeodesicOffsetOracle, MarginOnScansMatchesCgalDistance)
{
  const char* files[] = { "kitten.ply", "spot.ply", "fertility.ply" };
  int meshes = 0;
  for (const char* file : files)
  {
    const std::string path = SharedMesh(file);
    MeshData data;
    std::string error;
    if (path.empty() || !ReadPly(path, data, error))
    {
      continue;
    }
    ++meshes;
    const auto start = std::chrono::steady_clock::now();
    const TriangleMesh mesh(std::move(data.Positions), std::move(data.Triangles));
    const MeshTopology topology = MeshTopology::Compute(mesh);
    const double diagonal = BoundingDiagonal(mesh);
    const double h = MeanEdgeLength(mesh);

    std::mt19937 rng(7);
    CurveTrace trace;
    std::unique_ptr<Labeled> shape;
    int center = -1;
    ASSERT_TRUE(DrawCircle(mesh, topology, 0.05 * diagonal, 16, rng, trace, shape, center))
      << file << ": no disk-like place for the shape";
    const OffsetRegion region = MakeOffsetRegion(mesh, shape->Arr, shape->Selected);

    const double distances[] = { 0.02 * diagonal, -0.01 * diagonal };
    // Samples 2 % of the smaller |d| apart put the oracle at most 5e-5 |d| too far.
    CurveDistanceOracle oracle(mesh,
      SampleCurve(mesh, trace.Curve.Points, 0.02 * 0.01 * diagonal),
      0.03 * diagonal + 3.0 * h);
    std::cout << file << ": " << mesh.GetNumberOfTriangles() << " triangles, diagonal " << diagonal
              << ", mean edge h " << h << " (" << h / diagonal << " diagonal), center vertex "
              << center << ", " << trace.Curve.Points.size() << " traced points\n";

    for (const double d : distances)
    {
      const auto caseStart = std::chrono::steady_clock::now();
      const int treesBefore = oracle.GetNumberOfTrees();
      const double level = std::abs(d);
      const bool grow = d > 0.0;
      OffsetOptions options;
      options.Distance = d;
      std::vector<std::vector<CanonicalPoint>> loops;
      ASSERT_TRUE(ComputeGeodesicOffset(mesh, topology, region, options, loops, error))
        << file << " d " << d << ": " << error;
      ASSERT_FALSE(loops.empty());

      // (a) Every loop point at distance |d| from the polygon. Points on mesh edges lie on the
      // exact distance field's level set (line sources along the polygon's pieces,
      // GeodesicOffset.h): equal to the oracle's distance within the oracle's own sampling of
      // the polygon (it is at most 5e-5 |d| too far) and rounding (measured from -6e-9 to 5.6e-5
      // |d| on edges). Points inside triangles (kept sharp corners, where the level set's
      // tangents meet) within a small fraction of an edge: measured up to 0.0012 h.
      double worst = 0.0, sum = 0.0, nearest = 0.0, farthest = 0.0, worstOffEdge = 0.0;
      int points = 0, offEdge = 0;
      for (const auto& loop : loops)
      {
        for (const CanonicalPoint& p : loop)
        {
          const double error = oracle.GeodesicDistance(p, 1.5 * level) - level;
          worst = std::max(worst, std::abs(error));
          sum += std::abs(error);
          ++points;
          if (p.Location == PointLocation::Edge)
          {
            nearest = std::min(nearest, error);
            farthest = std::max(farthest, error);
          }
          else
          {
            worstOffEdge = std::max(worstOffEdge, std::abs(error));
            ++offEdge;
          }
        }
      }
      EXPECT_GE(nearest, -1e-6 * level) << file << " d " << d;
      EXPECT_LE(farthest, 1e-4 * level) << file << " d " << d;
      EXPECT_LE(worstOffEdge, 0.005 * h) << file << " d " << d;

      // (b) Vertices on the offset's side within half an edge of the level set lie next to a
      // loop piece: no farther than their distance to the level set plus the chords' error
      // (measured up to 0.1 h over 16 shapes per mesh; a quarter of a loop left out gives 2.8 h).
      double worstExcess = 0.0;
      int near = 0;
      for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
      {
        const Vec3 x = mesh.GetPosition(v);
        if (region.InsideVertex(v) == grow || oracle.StraightDistance(x) > level + 0.5 * h)
        {
          continue;
        }
        const int corner = *mesh.GetVertexCorners(v).begin();
        std::array<double, 3> w{ 0.0, 0.0, 0.0 };
        w[corner % 3] = 1.0;
        const double gap =
          std::abs(oracle.GeodesicDistance(corner / 3, w, level + 0.6 * h) - level);
        if (gap > 0.5 * h)
        {
          continue;
        }
        ++near;
        double toLoops = 1e300;
        for (const auto& loop : loops)
        {
          for (size_t i = 0; i < loop.size(); ++i)
          {
            toLoops = std::min(toLoops,
              DistanceToSegment(
                x, PositionOf(mesh, loop[i]), PositionOf(mesh, loop[(i + 1) % loop.size()])));
          }
        }
        worstExcess = std::max(worstExcess, toLoops - gap);
      }
      EXPECT_GT(near, 0) << file << " d " << d;
      EXPECT_LE(worstExcess, 0.15 * h) << file << " d " << d;

      // (c) Random points of the triangles near the level set: in the labeled offset region
      // exactly when the oracle's signed distance (negative inside the shape) is at most d, but
      // near the level set, where the loops' chords cut its curves and a sharp tip thinner than a
      // triangle is lost (measured up to 0.34 h from it over 16 shapes per mesh). The mismatching
      // area per length of loop is the mean width between the offset region and the exact one
      // (measured up to 0.06 h; reversed loops fail both bounds).
      std::unique_ptr<Labeled> offset = Label(mesh, topology, AsCurves(loops));
      ASSERT_TRUE(offset) << file << " d " << d << ": the loops do not bound a consistent shape";
      std::vector<int> band;
      std::vector<double> bandArea;
      double bandTotal = 0.0;
      for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
      {
        const Triangle& tri = mesh.GetTriangle(t);
        const Vec3 a = mesh.GetPosition(tri[0]), b = mesh.GetPosition(tri[1]),
                   c = mesh.GetPosition(tri[2]);
        const double straight = oracle.StraightDistance((1.0 / 3.0) * (a + b + c));
        if (straight > level - 2.0 * h && straight < level + 2.0 * h)
        {
          band.push_back(t);
          bandArea.push_back(TriangleArea(a, b, c));
          bandTotal += bandArea.back();
        }
      }
      double loopLength = 0.0;
      for (const auto& loop : loops)
      {
        for (size_t i = 0; i < loop.size(); ++i)
        {
          loopLength +=
            Distance(PositionOf(mesh, loop[i]), PositionOf(mesh, loop[(i + 1) % loop.size()]));
        }
      }
      std::discrete_distribution<int> pick(bandArea.begin(), bandArea.end());
      std::uniform_real_distribution<double> unit(0.0, 1.0);
      const int samples = 2000;
      int mismatches = 0;
      double worstMismatch = 0.0;
      for (int s = 0; s < samples; ++s)
      {
        const int t = band[pick(rng)];
        double u = unit(rng), v = unit(rng);
        if (u + v > 1.0)
        {
          u = 1.0 - u;
          v = 1.0 - v;
        }
        const double distance = oracle.GeodesicDistance(t, { 1.0 - u - v, u, v }, level + 3.0 * h);
        const int shapeCell = CellAtSurfacePoint(mesh, shape->Arr, t, u, v);
        const int offsetCell = CellAtSurfacePoint(mesh, offset->Arr, t, u, v);
        const double signedDistance = shape->Selected[shapeCell] ? -distance : distance;
        if ((signedDistance <= d) != (offset->Selected[offsetCell] != 0))
        {
          ++mismatches;
          worstMismatch = std::max(worstMismatch, std::abs(signedDistance - d));
        }
      }
      const double width = bandTotal * mismatches / samples / loopLength;
      EXPECT_LE(worstMismatch, 0.5 * h) << file << " d " << d;
      EXPECT_LE(width, 0.1 * h) << file << " d " << d;

      std::cout << file << " d " << d / diagonal << " diagonal: " << loops.size() << " loop(s), "
                << points << " points (" << offEdge << " inside triangles); (a) distance error max "
                << worst / level << " |d|, mean " << sum / points / level << " |d|; on edges from "
                << nearest / level << " to " << farthest / level << " |d|; inside triangles max "
                << worstOffEdge / h << " h; (b) " << near << " vertices, worst excess "
                << worstExcess / h << " h; (c) " << mismatches << " of " << samples
                << " samples mismatch, at most " << worstMismatch / h
                << " h from the level set, mean width " << width / h << " h; offset area "
                << offset->Area << " (shape " << shape->Area << "); "
                << oracle.GetNumberOfTrees() - treesBefore << " oracle trees, "
                << Seconds(caseStart) << " s\n";
    }
  }
  if (meshes == 0)
  {
    GTEST_SKIP() << "shared meshes not found (set BOOLSURF_SHARED_DATA to the shared data folder)";
  }
}

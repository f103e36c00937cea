// The three resolutions on the procedural torus: after each, tracing + arrangement + labeling
// find every shape consistent; RemoveCurves keeps a null-homologous set of curves;
// DuplicateReversed strips never cross the curve they duplicate; consistent shapes and genus-0
// surfaces are left alone with a note.
#include "Homology/ShapeResolution.h"

#include "Arrangement/Arrangement.h"
#include "Labeling/ArrangementLabelingInput.h"
#include "Mesh/ProceduralMeshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

using namespace boolsurf;

namespace
{

const double R = 3.0, r = 1.0;

struct Torus
{
  TriangleMesh Mesh;
  MeshTopology Topology;
  HomologyBasis Basis;
  Torus()
  {
    const MeshData d = MakeTorus(R, r, 48, 24);
    this->Mesh = TriangleMesh(d.Positions, d.Triangles);
    this->Topology = MeshTopology::Compute(this->Mesh);
    std::string error;
    EXPECT_TRUE(this->Basis.Compute(this->Mesh, this->Topology, HomologyOptions(), error)) << error;
  }
  SurfacePoint At(double u, double v) const
  {
    const Vec3 x{
      (R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)
    };
    return ClosestSurfacePointNear(this->Mesh, x, 0, HUGE_VAL);
  }
  // Around the tube at angle u (reverse: the other way).
  ControlCurve Meridian(double u, int shape, int id, bool reverse = false) const
  {
    ControlCurve c;
    c.ShapeId = shape;
    c.CurveId = id;
    for (int k = 0; k < 12; ++k)
    {
      const double v = 0.1 + 2 * M_PI * (reverse ? 12 - k : k) / 12.0;
      c.Points.push_back(this->At(u, v));
    }
    return c;
  }
  // Around the axis at tube angle v.
  ControlCurve Parallel(double v, int shape, int id) const
  {
    ControlCurve c;
    c.ShapeId = shape;
    c.CurveId = id;
    for (int k = 0; k < 16; ++k)
    {
      c.Points.push_back(this->At(0.05 + 2 * M_PI * k / 16.0, v));
    }
    return c;
  }
  ControlCurve SmallLoop(int shape, int id) const
  {
    ControlCurve c;
    c.ShapeId = shape;
    c.CurveId = id;
    for (int k = 0; k < 6; ++k)
    {
      c.Points.push_back(
        this->At(4.0 + 0.2 * std::cos(2 * M_PI * k / 6), 2.0 + 0.3 * std::sin(2 * M_PI * k / 6)));
    }
    return c;
  }
};

std::vector<ControlCurve> Scene(const Torus& t)
{
  return { t.Meridian(0.2, 0, 0),
    t.Meridian(1.0, 1, 1),
    t.Meridian(1.3, 1, 2),
    t.Meridian(2.5, 2, 3),
    t.Parallel(1.2, 2, 4),
    t.SmallLoop(3, 5) };
}

std::vector<ControlCurve> CurvesOf(const ResolveResult& r)
{
  std::vector<ControlCurve> out;
  for (const ResolvedCurve& c : r.Curves)
  {
    out.push_back(c.Curve);
  }
  return out;
}

// Traces, arranges and labels; returns ShapeConsistent per shape id.
std::map<int, bool> Consistency(const Torus& t,
  const std::vector<ControlCurve>& curves,
  std::vector<TracedCurve>& traced)
{
  CurveTracer tracer(t.Mesh);
  std::vector<std::vector<int>> classes;
  std::string error;
  EXPECT_TRUE(ClassifyControlCurves(tracer, t.Basis, curves, classes, &traced, error)) << error;
  Arrangement arr;
  EXPECT_TRUE(ComputeArrangement(t.Mesh, traced, ArrangementOptions(), arr, error)) << error;
  const LabelingResult labels = LabelCells(MakeLabelingInput(t.Mesh, t.Topology, traced, arr));
  std::map<int, bool> out;
  for (int s = 0; s < labels.NumberOfShapes; ++s)
  {
    out[labels.ShapeIdOf(s)] = labels.ShapeConsistent[s] != 0;
  }
  return out;
}

ResolveResult Resolve(const Torus& t, const std::vector<ControlCurve>& curves, ResolveStrategy s)
{
  CurveTracer tracer(t.Mesh);
  std::vector<std::vector<int>> classes;
  std::string error;
  EXPECT_TRUE(ClassifyControlCurves(tracer, t.Basis, curves, classes, nullptr, error)) << error;
  ResolveOptions options;
  options.StrategyOf = [s](int) { return s; };
  return ResolveShapes(t.Mesh, t.Basis, curves, classes, options);
}

// True when a segment of `a` and a segment of `b` in a common triangle meet (exact 2D test in
// that triangle's barycentric plane).
bool CurvesMeet(const TriangleMesh& mesh, const TracedCurve& a, const TracedCurve& b)
{
  auto orient = [](Vec2 p, Vec2 q, Vec2 s) { return Cross(q - p, s - p); };
  std::vector<int> ta, tb;
  const size_t na = a.Points.size(), nb = b.Points.size();
  for (size_t i = 0; i < na; ++i)
  {
    const CanonicalPoint &p0 = a.Points[i], &p1 = a.Points[(i + 1) % na];
    const int t = SharedTriangle(mesh, p0, p1);
    for (size_t j = 0; j < nb; ++j)
    {
      const CanonicalPoint &q0 = b.Points[j], &q1 = b.Points[(j + 1) % nb];
      if (!TriangleContains(mesh, q0, t) || !TriangleContains(mesh, q1, t))
      {
        continue;
      }
      auto flat = [&](const CanonicalPoint& c)
      {
        const auto w = WeightsInTriangle(mesh, c, t);
        return Vec2{ w[1], w[2] };
      };
      const Vec2 A = flat(p0), B = flat(p1), C = flat(q0), D = flat(q1);
      const double d1 = orient(A, B, C), d2 = orient(A, B, D), d3 = orient(C, D, A),
                   d4 = orient(C, D, B);
      if (((d1 <= 0 && d2 >= 0) || (d1 >= 0 && d2 <= 0)) &&
        ((d3 <= 0 && d4 >= 0) || (d3 >= 0 && d4 <= 0)))
      {
        return true;
      }
    }
  }
  return false;
}

} // namespace

TEST(ShapeResolution, SceneStartsWithInconsistentShapes)
{
  Torus t;
  std::vector<TracedCurve> traced;
  const auto consistent = Consistency(t, Scene(t), traced);
  EXPECT_FALSE(consistent.at(0));
  EXPECT_FALSE(consistent.at(1));
  EXPECT_FALSE(consistent.at(2));
  EXPECT_TRUE(consistent.at(3));
}

TEST(ShapeResolution, AddGeneratorsMakesEveryShapeConsistent)
{
  Torus t;
  const ResolveResult r = Resolve(t, Scene(t), ResolveStrategy::AddGenerators);
  EXPECT_EQ(r.TreatedShapes, (std::vector<int>{ 0, 1, 2 }));
  int added = 0, shape1 = 0;
  for (const ResolvedCurve& c : r.Curves)
  {
    if (c.Action == ResolutionAction::AddedGenerator)
    {
      ++added;
      shape1 += c.Curve.ShapeId == 1;
      EXPECT_FALSE(c.Reason.empty());
    }
  }
  EXPECT_EQ(shape1, 2); // twice the meridian's class: two offset copies
  EXPECT_GE(added, 4);
  EXPECT_TRUE(r.Removed.empty());
  std::vector<TracedCurve> traced;
  for (const auto& [shape, ok] : Consistency(t, CurvesOf(r), traced))
  {
    EXPECT_TRUE(ok) << "shape " << shape;
  }
}

TEST(ShapeResolution, DuplicateReversedMakesStripsThatDoNotCrossTheirCurve)
{
  Torus t;
  const std::vector<ControlCurve> scene = Scene(t);
  const ResolveResult r = Resolve(t, scene, ResolveStrategy::DuplicateReversed);
  std::vector<TracedCurve> traced;
  const auto consistent = Consistency(t, CurvesOf(r), traced);
  for (const auto& [shape, ok] : consistent)
  {
    EXPECT_TRUE(ok) << "shape " << shape;
  }
  int duplicates = 0;
  for (size_t i = 0; i < r.Curves.size(); ++i)
  {
    if (r.Curves[i].Action != ResolutionAction::DuplicatedReversed)
    {
      continue;
    }
    ++duplicates;
    // Its original is the input curve with CurveId Source (kept at the same index).
    const int source = r.Curves[i].Source;
    EXPECT_FALSE(CurvesMeet(t.Mesh, traced[source], traced[i])) << "curve " << source;
  }
  EXPECT_EQ(duplicates, 5); // every curve but the small loop winds
}

TEST(ShapeResolution, RemoveCurvesLeavesNullHomologousSets)
{
  Torus t;
  const ResolveResult r = Resolve(t, Scene(t), ResolveStrategy::RemoveCurves);
  // Shape 0: its meridian removed; shape 1: one meridian flipped (fewer changes than removing
  // both); shape 2: both curves removed.
  ASSERT_EQ(r.Removed.size(), 3u);
  int flipped = 0;
  for (const ResolvedCurve& c : r.Curves)
  {
    flipped += c.Action == ResolutionAction::Flipped;
  }
  EXPECT_EQ(flipped, 1);
  CurveTracer tracer(t.Mesh);
  std::vector<std::vector<int>> classes;
  std::string error;
  const std::vector<ControlCurve> left = CurvesOf(r);
  ASSERT_TRUE(ClassifyControlCurves(tracer, t.Basis, left, classes, nullptr, error)) << error;
  std::map<int, std::vector<int>> sums;
  for (size_t i = 0; i < left.size(); ++i)
  {
    auto& s = sums.emplace(left[i].ShapeId, std::vector<int>(2, 0)).first->second;
    s[0] += classes[i][0];
    s[1] += classes[i][1];
  }
  for (const auto& [shape, sum] : sums)
  {
    EXPECT_EQ(sum, (std::vector<int>{ 0, 0 })) << "shape " << shape;
  }
  std::vector<TracedCurve> traced;
  for (const auto& [shape, ok] : Consistency(t, left, traced))
  {
    EXPECT_TRUE(ok) << "shape " << shape;
  }
}

TEST(ShapeResolution, ConsistentShapesAndGenusZeroAreLeftAlone)
{
  Torus t;
  const ResolveResult r = Resolve(t, { t.SmallLoop(3, 0) }, ResolveStrategy::AddGenerators);
  ASSERT_EQ(r.Curves.size(), 1u);
  EXPECT_EQ(r.Curves[0].Action, ResolutionAction::Kept);
  EXPECT_TRUE(r.TreatedShapes.empty());
  ASSERT_EQ(r.Notes.size(), 1u);
  EXPECT_NE(r.Notes[0].find("nothing to do"), std::string::npos) << r.Notes[0];

  const MeshData d = MakeIcosphere(2);
  TriangleMesh sphere(d.Positions, d.Triangles);
  MeshTopology topo = MeshTopology::Compute(sphere);
  HomologyBasis basis;
  std::string error;
  ASSERT_TRUE(basis.Compute(sphere, topo, HomologyOptions(), error));
  ControlCurve loop;
  loop.CurveId = 0;
  loop.Points = { { 0, 0.3, 0.3 }, { 5, 0.3, 0.3 }, { 9, 0.3, 0.3 } };
  ResolveOptions options;
  const ResolveResult s = ResolveShapes(sphere, basis, { loop }, { {} }, options);
  ASSERT_EQ(s.Curves.size(), 1u);
  EXPECT_TRUE(s.TreatedShapes.empty());
  EXPECT_NE(s.Notes[0].find("no homology generators"), std::string::npos) << s.Notes[0];
}

// Drawings of integer polygons on flat meshes, answered by the whole Core chain (tracing as
// straight lines, arrangement, labeling, Boolean selection) and by Clipper, which is exact on
// integer input: the oracle for degenerate but valid drawings (touching, overlapping,
// retracing, spikes, keyholes), where the planar answer is known exactly.
#ifndef boolsurf_FlatDrawingOracle_h
#define boolsurf_FlatDrawingOracle_h

#include "Arrangement/Arrangement.h"
#include "Labeling/ArrangementLabelingInput.h"
#include "Mesh/MeshTopology.h"
#include "Mesh/ProceduralMeshes.h"
#include "Mesh/TriangleMesh.h"
#include "Selection/BooleanSelection.h"
#include "Support/PlanarWinding.h"
#include "Support/SyntheticCurves.h"

#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

namespace boolsurf
{
namespace testing
{

/// A flat square mesh [lo, hi]^2 (z = 0): either aligned with the integer lattice (a grid of
/// unit cells, every vertex on a lattice point) or irregular (jittered vertices, random
/// diagonals), so that the lattice polygons fall on it in general or in special position.
inline TriangleMesh FlatMeshFor(double lo, double hi, int cells, bool aligned, std::uint32_t seed)
{
  MeshData d = MakeFlatSquare(cells, hi - lo, aligned ? 0.0 : 0.45, seed);
  for (Vec3& p : d.Positions)
  {
    p.x += lo;
    p.y += lo;
  }
  return TriangleMesh(d.Positions, d.Triangles);
}

/// An axis-aligned hole cut out of a flat mesh, or none (the default, empty).
struct FlatHole
{
  double X0 = 0, Y0 = 0, X1 = 0, Y1 = 0;
  bool Empty() const { return this->X1 <= this->X0 || this->Y1 <= this->Y0; }
  double Area() const
  {
    return this->Empty() ? 0.0 : (this->X1 - this->X0) * (this->Y1 - this->Y0);
  }
  Vec2 Center() const { return { 0.5 * (this->X0 + this->X1), 0.5 * (this->Y0 + this->Y1) }; }
  /// Whether the segment a-b meets the open hole (Liang-Barsky clipping: the part of the
  /// segment strictly inside has positive length, or the segment is a point inside).
  bool Enters(Vec2 a, Vec2 b) const
  {
    if (this->Empty())
      return false;
    double t0 = 0, t1 = 1;
    const double d[2] = { b.x - a.x, b.y - a.y }, lo[2] = { this->X0, this->Y0 },
                 hi[2] = { this->X1, this->Y1 }, p[2] = { a.x, a.y };
    for (int k = 0; k < 2; ++k)
    {
      if (d[k] == 0)
      {
        if (p[k] <= lo[k] || p[k] >= hi[k])
          return false;
        continue;
      }
      double s0 = (lo[k] - p[k]) / d[k], s1 = (hi[k] - p[k]) / d[k];
      if (s0 > s1)
        std::swap(s0, s1);
      t0 = std::max(t0, s0);
      t1 = std::min(t1, s1);
    }
    return t0 < t1 || (a.x == b.x && a.y == b.y && t0 <= t1);
  }
  /// Whether a drawing keeps out of the hole (it may run along its boundary).
  bool Avoids(const std::vector<LatticePolygon>& drawing) const
  {
    for (const auto& poly : drawing)
    {
      const size_t n = poly.Points.size();
      for (size_t i = 0; i < n; ++i)
      {
        const auto &p = poly.Points[i], &q = poly.Points[(i + 1) % n];
        if (this->Enters({ double(p[0]), double(p[1]) }, { double(q[0]), double(q[1]) }))
          return false;
      }
    }
    return true;
  }
};

/// A flat square mesh [lo, hi]^2 aligned with the integer lattice (unit cells), without the
/// triangles inside `hole` (whose corners are lattice points): a second boundary loop.
inline TriangleMesh FlatMeshWithHole(double lo, double hi, const FlatHole& hole)
{
  MeshData d = MakeFlatSquare(static_cast<int>(hi - lo), hi - lo, 0.0, 0);
  std::vector<Triangle> kept;
  for (Vec3& p : d.Positions)
  {
    p.x += lo;
    p.y += lo;
  }
  for (const Triangle& t : d.Triangles)
  {
    const Vec3 &a = d.Positions[t[0]], &b = d.Positions[t[1]], &c = d.Positions[t[2]];
    const Vec2 g{ (a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0 };
    if (!(g.x > hole.X0 && g.x < hole.X1 && g.y > hole.Y0 && g.y < hole.Y1))
      kept.push_back(t);
  }
  return TriangleMesh(d.Positions, kept);
}

/// The chain's answer for a drawing: per-cell areas and labels, or the error that refused it.
struct FlatDrawingAnswer
{
  bool Ok = false;
  std::string Error;
  Arrangement Arr;
  LabelingResult Labels;
  std::vector<double> CellArea;
};

inline FlatDrawingAnswer AnswerDrawing(const TriangleMesh& mesh,
  const std::vector<LatticePolygon>& polygons)
{
  FlatDrawingAnswer answer;
  FlatPolygonTracer tracer(mesh);
  std::vector<TracedCurve> curves;
  for (size_t i = 0; i < polygons.size(); ++i)
  {
    // A polygon whose points are all equal has no length: the filters skip it with a warning.
    const auto& first = polygons[i].Points.front();
    if (std::all_of(polygons[i].Points.begin(),
          polygons[i].Points.end(),
          [&](const std::array<long long, 2>& p) { return p == first; }))
      continue;
    std::vector<Vec2> pts;
    for (const auto& p : polygons[i].Points)
      pts.push_back({ static_cast<double>(p[0]), static_cast<double>(p[1]) });
    TracedCurve c;
    if (!tracer.Trace(pts, true, polygons[i].Shape, static_cast<int>(i), c))
    {
      answer.Error = "polygon " + std::to_string(i) + " leaves the mesh";
      return answer;
    }
    curves.push_back(std::move(c));
  }
  ArrangementOptions options;
  options.Threads = 1;
  if (!ComputeArrangement(mesh, curves, options, answer.Arr, answer.Error))
    return answer;
  const MeshTopology topology = MeshTopology::Compute(mesh);
  answer.Labels = LabelCells(MakeLabelingInput(mesh, topology, curves, answer.Arr));
  for (int s = 0; s < answer.Labels.NumberOfShapes; ++s)
  {
    if (!answer.Labels.ShapeConsistent[s])
    {
      const LabelConflict* c = nullptr;
      for (const auto& k : answer.Labels.Conflicts)
        if (k.Shape == s)
          c = &k;
      answer.Error = "shape " + std::to_string(answer.Labels.ShapeIdOf(s)) + " is inconsistent";
      if (c)
        answer.Error += ": cell " + std::to_string(c->Cell) + " reached with labels " +
          std::to_string(c->FirstLabel) + " and " + std::to_string(c->SecondLabel);
      return answer;
    }
  }
  answer.CellArea.assign(answer.Arr.NumberOfCells, 0.0);
  for (size_t r = 0; r < static_cast<size_t>(answer.Arr.GetNumberOfTriangles()); ++r)
  {
    const auto& t = answer.Arr.GetTriangle(mesh, r);
    const Vec3 &a = answer.Arr.GetPosition(mesh, t[0]), &b = answer.Arr.GetPosition(mesh, t[1]),
               &c = answer.Arr.GetPosition(mesh, t[2]);
    answer.CellArea[answer.Arr.CellOfTriangle(static_cast<int>(r))] +=
      0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  }
  answer.Ok = true;
  return answer;
}

/// Area of the cells where `inside(labels of the cell)` holds.
template <class Inside>
double SelectedArea(const FlatDrawingAnswer& answer, Inside inside)
{
  double area = 0;
  std::vector<int> labels(answer.Labels.NumberOfShapes);
  for (int c = 0; c < answer.Arr.NumberOfCells; ++c)
  {
    for (int s = 0; s < answer.Labels.NumberOfShapes; ++s)
      labels[s] = answer.Labels.GetLabel(c, s);
    if (inside(labels))
      area += answer.CellArea[c];
  }
  return area;
}

/// Clipper rounds the crossings it computes to its integer grid, so lattice points are scaled
/// by 2^40 (exact) and its crossings land within ~1e-12 of the true ones.
constexpr double ClipperScale = 1099511627776.0; // 2^40

inline ClipperLib::Paths ClipperPathsOf(const std::vector<LatticePolygon>& polygons, int shape)
{
  ClipperLib::Paths paths;
  for (const auto& p : polygons)
  {
    if (p.Shape != shape)
      continue;
    ClipperLib::Path path;
    for (const auto& x : p.Points)
      path.emplace_back(static_cast<ClipperLib::cInt>(x[0] * ClipperScale),
        static_cast<ClipperLib::cInt>(x[1] * ClipperScale));
    paths.push_back(path);
  }
  return paths;
}

inline double ClipperAreaOf(const ClipperLib::Paths& paths)
{
  double area = 0;
  for (const auto& p : paths)
    area += ClipperLib::Area(p);
  return area / (ClipperScale * ClipperScale);
}

} // namespace testing
} // namespace boolsurf

#endif

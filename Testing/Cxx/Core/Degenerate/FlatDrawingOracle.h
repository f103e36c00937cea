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

/// A closed polygon with integer vertices, of one shape.
struct LatticePolygon
{
  int Shape = 0;
  std::vector<std::array<long long, 2>> Points;
};

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
  for (size_t r = 0; r < answer.Arr.Triangles.size(); ++r)
  {
    const auto& t = answer.Arr.Triangles[r];
    const Vec3 &a = answer.Arr.Positions[t[0]], &b = answer.Arr.Positions[t[1]],
               &c = answer.Arr.Positions[t[2]];
    answer.CellArea[answer.Arr.TriangleCell[r]] +=
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

/// Exact planar area of {p : inside(winding numbers of the shapes at p)}, by vertical slabs:
/// between consecutive x coordinates of polygon vertices and crossings no side starts, ends or
/// crosses another, so the selected length of a vertical line is linear in x and the slab's
/// area is that length at the slab's middle times its width. Independent of the arrangement
/// and of Clipper (which, on overlapping edges, is sometimes wrong); exact up to rounding.
template <class Inside>
double SweepArea(const std::vector<LatticePolygon>& polygons, int numberOfShapes, Inside inside)
{
  struct Side
  {
    double X0, Y0, X1, Y1;
    int Shape;
  };
  std::vector<Side> sides;
  std::vector<double> xs;
  for (const auto& p : polygons)
  {
    const size_t n = p.Points.size();
    for (size_t i = 0; i < n; ++i)
    {
      const auto &a = p.Points[i], &b = p.Points[(i + 1) % n];
      xs.push_back(static_cast<double>(a[0]));
      if (a[0] != b[0])
        sides.push_back({ double(a[0]), double(a[1]), double(b[0]), double(b[1]), p.Shape });
    }
  }
  for (size_t i = 0; i < sides.size(); ++i)
  {
    for (size_t j = i + 1; j < sides.size(); ++j)
    {
      const Side &s = sides[i], &r = sides[j];
      const double dx1 = s.X1 - s.X0, dy1 = s.Y1 - s.Y0, dx2 = r.X1 - r.X0, dy2 = r.Y1 - r.Y0;
      const double den = dx1 * dy2 - dy1 * dx2;
      if (den == 0)
        continue;
      const double t = ((r.X0 - s.X0) * dy2 - (r.Y0 - s.Y0) * dx2) / den;
      const double u = ((r.X0 - s.X0) * dy1 - (r.Y0 - s.Y0) * dx1) / den;
      if (t > 0 && t < 1 && u > 0 && u < 1)
        xs.push_back(s.X0 + t * dx1);
    }
  }
  std::sort(xs.begin(), xs.end());
  double area = 0;
  std::vector<std::pair<double, const Side*>> hits;
  std::vector<int> winding(numberOfShapes);
  for (size_t k = 0; k + 1 < xs.size(); ++k)
  {
    const double x0 = xs[k], x1 = xs[k + 1];
    if (x1 - x0 <= 0)
      continue;
    const double xm = 0.5 * (x0 + x1);
    hits.clear();
    for (const Side& s : sides)
    {
      if ((s.X0 < xm && xm < s.X1) || (s.X1 < xm && xm < s.X0))
        hits.emplace_back(s.Y0 + (xm - s.X0) / (s.X1 - s.X0) * (s.Y1 - s.Y0), &s);
    }
    std::sort(hits.begin(), hits.end(),
      [](const auto& a, const auto& b) { return a.first < b.first; });
    // Going up across a side that runs left -> right enters its left side: +1.
    std::fill(winding.begin(), winding.end(), 0);
    double length = 0;
    for (size_t h = 0; h < hits.size(); ++h)
    {
      const Side& s = *hits[h].second;
      if (s.Shape >= 0 && s.Shape < numberOfShapes)
        winding[s.Shape] += s.X1 > s.X0 ? 1 : -1;
      if (h + 1 < hits.size() && inside(winding))
        length += hits[h + 1].first - hits[h].first;
    }
    area += length * (x1 - x0);
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

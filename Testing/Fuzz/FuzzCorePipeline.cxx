// libFuzzer target: the Core pipeline, surface + control points -> tracing -> arrangement ->
// labeling -> Boolean selection -> region and boundary.
//
// Input bytes decode (ByteReader: zeros past the end) into
//  * a surface: a small procedural mesh (flat square, jittered or not, icosphere, torus,
//    cylinder, box sides) or a few triangles decoded from the bytes (refused, as the filters
//    do, when the surface check finds errors);
//  * 1-4 curves: shape id, curve type, closed flag and 1-8 control points given exactly
//    (triangle id + barycentric), with special values (0, 1, 1/2, within rounding of an edge,
//    slightly outside, NaN, huge) so that points on edges and vertices are common;
//  * an operation (union, intersection, difference, symmetric difference of two shapes, or
//    all shapes) and a fill rule.
// The winding numbers of the curves run on the same arrangement: finite everywhere, equal to
// the labels up to a constant for consistent shapes of closed curves on a connected surface,
// and their level set closes into loops that are valid traced curves.
// Every stage must give a result or a message. Where there is a result, cheap invariants are
// checked (a violation aborts, which libFuzzer reports): the refined triangles cover the
// surface with its area (no fold, no gap), cells and points are in range, labels are finite
// and bounded by the curves' sizes, a region and its complement split the surface's area.
#include "FuzzSupport.h"

#include "Arrangement/Arrangement.h"
#include "Arrangement/RefinedSurfaceArrays.h"
#include "Geodesic/CurveTracer.h"
#include "Labeling/ArrangementLabelingInput.h"
#include "Labeling/CellLabeling.h"
#include "Mesh/MeshTopology.h"
#include "Mesh/ProceduralMeshes.h"
#include "Mesh/SurfaceCheck.h"
#include "Mesh/TriangleMesh.h"
#include "Selection/BooleanExpression.h"
#include "Selection/BooleanSelection.h"
#include "Selection/RegionBoundary.h"
#include "Selection/RegionExtraction.h"
#include "Winding/SurfaceWinding.h"
#include "Winding/WindingLevelSet.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

namespace
{
using namespace boolsurf;
using fuzz::ByteReader;

/// With BOOLSURF_FUZZ_STAGES set, each input prints the last stage it reached (to tune the
/// decoding: a run over a corpus shows how many inputs get past tracing, arrangement, ...).
void Reached(const char* stage)
{
  static const bool print = std::getenv("BOOLSURF_FUZZ_STAGES") != nullptr;
  if (print)
  {
    std::fprintf(stderr, "stage: %s\n", stage);
  }
}

double TriangleArea(const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 n = Cross(b - a, c - a);
  return 0.5 * std::sqrt(Dot(n, n));
}

MeshData DecodeSurface(ByteReader& in)
{
  const std::uint8_t kind = in.Byte();
  const std::uint8_t size = in.Byte();
  switch (kind % 6)
  {
    case 0:
      return MakeFlatSquare(1 + size % 5, 1.0, 0.0);
    case 1:
      return MakeFlatSquare(2 + size % 4, 1.0, 0.05 * (1 + size % 6), in.Byte());
    case 2:
      return MakeIcosphere(size % 2);
    case 3:
      return MakeTorus(1.0, 0.4, 3 + size % 4, 3 + (size >> 4) % 4);
    case 4:
      return size & 1 ? MakeOpenCylinder(1.0, 1.0, 3 + (size >> 1) % 5, 1 + (size >> 4) % 3)
                      : MakeBoxLateral(1.0, 2.0, 1.0, 1 + (size >> 1) % 3);
    default:
    {
      // 3-10 points on a small integer grid, 1-8 triangles: anything the surface check lets
      // through must work.
      MeshData mesh;
      const int points = 3 + size % 8;
      const int triangles = 1 + (size >> 3) % 8;
      for (int i = 0; i < points; ++i)
      {
        const double x = in.Byte() % 5, y = in.Byte() % 5, z = (in.Byte() % 3) * 0.5;
        mesh.Positions.push_back({ x, y, z });
      }
      for (int t = 0; t < triangles; ++t)
      {
        mesh.Triangles.push_back({ in.Byte() % points, in.Byte() % points, in.Byte() % points });
      }
      return mesh;
    }
  }
}

/// A barycentric weight: often one of the values where points land on edges and vertices.
double DecodeWeight(ByteReader& in)
{
  static const double special[] = { 0.0,
    1.0,
    0.5,
    1.0 / 3.0,
    1e-15,
    -1e-15,
    1.0 - 1e-15,
    0.25,
    0.75,
    1.5e-14,
    2.0 / 3.0,
    -0.25,
    1.25,
    std::numeric_limits<double>::quiet_NaN(),
    std::numeric_limits<double>::infinity(),
    1e300 };
  const std::uint8_t b = in.Byte();
  if (b < 64)
  {
    return special[b % 16];
  }
  return (b - 64) / 191.0;
}

struct DecodedCurve
{
  std::vector<SurfacePoint> Points;
  CurveType Type = CurveType::GeodesicPolygon;
  bool Closed = true;
  int ShapeId = 0;
};

std::vector<DecodedCurve> DecodeCurves(ByteReader& in, int numberOfTriangles)
{
  std::vector<DecodedCurve> curves(1 + in.Byte() % 4);
  for (DecodedCurve& c : curves)
  {
    const std::uint8_t flags = in.Byte();
    c.Type = flags & 1 ? CurveType::CubicBezier : CurveType::GeodesicPolygon;
    c.Closed = (flags & 2) == 0;
    // Mostly small shape ids; sometimes the largest ones.
    c.ShapeId = flags & 4 ? 2147483647 - (flags >> 3) % 3 : (flags >> 3) % 4;
    const int n = 1 + in.Byte() % 8;
    for (int i = 0; i < n; ++i)
    {
      SurfacePoint p;
      const std::uint8_t t = in.Byte();
      // One in 128: a triangle id out of range (the tracer must refuse it).
      p.Triangle = t == 255 ? numberOfTriangles : t == 254 ? -1 : t % numberOfTriangles;
      p.U = DecodeWeight(in);
      p.V = DecodeWeight(in);
      c.Points.push_back(p);
    }
  }
  return curves;
}

/// Area of the refined triangles of the selected cells.
double RegionArea(const TriangleMesh& mesh,
  const Arrangement& arr,
  const std::vector<char>& selected)
{
  std::vector<int> triangles;
  RegionExtractor::SelectedTriangles(selected, arr, triangles);
  double area = 0;
  for (int r : triangles)
  {
    BOOLSURF_FUZZ_CHECK(r >= 0 && r < arr.GetNumberOfTriangles(), std::to_string(r));
    const Triangle tri = arr.GetTriangle(mesh, r);
    area += TriangleArea(
      arr.GetPosition(mesh, tri[0]), arr.GetPosition(mesh, tri[1]), arr.GetPosition(mesh, tri[2]));
  }
  return area;
}

void CheckArrangement(const TriangleMesh& mesh, const Arrangement& arr, double surfaceArea)
{
  // The whole refined surface as an output writes it (RefinedSurfaceArrays).
  const RefinedSurfaceArrays whole = RefinedSurfaceArrays::Of(mesh, arr);
  const int points = arr.GetNumberOfPoints();
  const std::size_t refined = arr.GetNumberOfTriangles();
  BOOLSURF_FUZZ_CHECK(
    whole.Positions.size() == static_cast<std::size_t>(points) && whole.Triangles.size() == refined,
    "whole arrays size");
  std::vector<int> cells;
  WriteTriangleCells(arr, cells);
  BOOLSURF_FUZZ_CHECK(cells.size() == refined, "cells size");
  int holes = 0;
  BOOLSURF_FUZZ_CHECK(whole.SourceTriangle.size() == refined, "SourceTriangle size");
  BOOLSURF_FUZZ_CHECK(arr.NumberOfMeshVertices == mesh.GetNumberOfVertices() &&
      arr.CurvePointOnMesh.size() + arr.NumberOfMeshVertices == whole.Positions.size(),
    "CurvePointOnMesh size");
  for (const Vec3& p : whole.Positions)
  {
    BOOLSURF_FUZZ_CHECK(
      std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z), "non-finite refined point");
  }
  double area = 0;
  for (std::size_t r = 0; r < refined; ++r)
  {
    if (static_cast<int>(r) < mesh.GetNumberOfTriangles() && !mesh.IsUsable(static_cast<int>(r)))
    {
      // An unusable mesh triangle keeps its index as a hole: no points, no source, no cell.
      BOOLSURF_FUZZ_CHECK(whole.SourceTriangle[r] < 0 && cells[r] < 0 && whole.Triangles[r][0] < 0,
        "hole " + std::to_string(r));
      ++holes;
      continue;
    }
    for (int v : whole.Triangles[r])
    {
      BOOLSURF_FUZZ_CHECK(v >= 0 && v < points, "refined triangle " + std::to_string(r));
    }
    const int cell = cells[r];
    BOOLSURF_FUZZ_CHECK(cell >= 0 && cell < arr.NumberOfCells, "cell " + std::to_string(cell));
    const int source = whole.SourceTriangle[r];
    BOOLSURF_FUZZ_CHECK(
      source >= 0 && source < mesh.GetNumberOfTriangles() && mesh.IsUsable(source),
      "source " + std::to_string(source));
    const auto& tri = whole.Triangles[r];
    area += TriangleArea(whole.Positions[tri[0]], whole.Positions[tri[1]], whole.Positions[tri[2]]);
  }
  BOOLSURF_FUZZ_CHECK(holes == arr.NumberOfHoles, "hole count");
  // Unsigned areas: a folded or overlapping refinement has more area, a gap less.
  BOOLSURF_FUZZ_CHECK(std::fabs(area - surfaceArea) <= 1e-9 * surfaceArea,
    "refined area " + std::to_string(area) + " vs surface " + std::to_string(surfaceArea));
  for (const ArrangementPatch& patch : arr.Patches)
  {
    BOOLSURF_FUZZ_CHECK(patch.LeftCell >= -1 && patch.LeftCell < arr.NumberOfCells &&
        patch.RightCell >= -1 && patch.RightCell < arr.NumberOfCells,
      "patch cells");
    for (int p : patch.Points)
    {
      BOOLSURF_FUZZ_CHECK(p >= 0 && p < points, "patch point " + std::to_string(p));
    }
  }
}

void CheckLabels(const LabelingResult& labels, int cells, std::size_t curvePoints)
{
  BOOLSURF_FUZZ_CHECK(labels.Labels.size() ==
      static_cast<std::size_t>(cells) * static_cast<std::size_t>(labels.NumberOfShapes),
    "label table size");
  BOOLSURF_FUZZ_CHECK(
    labels.ShapeConsistent.size() == static_cast<std::size_t>(labels.NumberOfShapes),
    "ShapeConsistent size");
  for (int s = 0; s < labels.NumberOfShapes; ++s)
  {
    if (!labels.ShapeConsistent[s])
    {
      continue;
    }
    for (int c = 0; c < cells; ++c)
    {
      // A winding number cannot exceed the number of curve segments around the cell.
      const long long label = labels.GetLabel(c, s);
      BOOLSURF_FUZZ_CHECK(std::llabs(label) <= static_cast<long long>(curvePoints),
        "cell " + std::to_string(c) + " shape " + std::to_string(s) + " label " +
          std::to_string(label));
    }
  }
}
/// Winding numbers on the fuzzed arrangement (see the file's comment).
void CheckWindingNumbers(const TriangleMesh& mesh,
  const MeshTopology& topology,
  const std::vector<TracedCurve>& curves,
  const Arrangement& arr,
  const LabelingResult& labels)
{
  SurfaceWinding winding;
  WindingResult w;
  std::string error;
  WindingOptions options;
  options.Threads = 1;
  if (!winding.Compute(mesh, arr, curves, options, w, error))
  {
    BOOLSURF_FUZZ_CHECK(!error.empty(), "refused winding numbers must say why");
    Reached("winding numbers refused");
    return;
  }
  const int nr = arr.GetNumberOfTriangles();
  for (int s = 0; s < w.GetNumberOfShapes(); ++s)
  {
    // Labels' shape index of this shape, and whether all its curves are closed.
    int ls = -1;
    for (int k = 0; k < labels.NumberOfShapes; ++k)
    {
      ls = labels.ShapeIdOf(k) == w.ShapeIds[s] ? k : ls;
    }
    bool closed = true;
    for (const TracedCurve& c : curves)
    {
      closed = closed && (c.ShapeId != w.ShapeIds[s] || c.Closed);
    }
    const bool exact =
      closed && ls >= 0 && labels.ShapeConsistent[ls] && topology.GetNumberOfComponents() == 1;
    double offset = std::numeric_limits<double>::quiet_NaN();
    for (int r = 0; r < nr; ++r)
    {
      const int cell = arr.CellOfTriangle(r);
      // Zero-area pieces are left out of the comparison: a curve that retraces itself leaves
      // cells of no area between its coincident passes, labeled as if they had a side (w has
      // no jump there, rightly).
      const Triangle tri = arr.GetTriangle(mesh, r);
      const Vec3 a = arr.GetPosition(mesh, tri[0]), b = arr.GetPosition(mesh, tri[1]),
                 c = arr.GetPosition(mesh, tri[2]);
      const double longest =
        std::max(Dot(b - a, b - a), std::max(Dot(c - b, c - b), Dot(a - c, a - c)));
      const bool flat = TriangleArea(a, b, c) <= 1e-9 * longest;
      for (int k = 0; k < 3 && cell >= 0; ++k)
      {
        const double value = w.Corner(arr, mesh, s, r, k);
        BOOLSURF_FUZZ_CHECK(std::isfinite(value), "winding number not finite");
        if (exact && !flat)
        {
          const double d = value - labels.GetLabel(cell, ls);
          offset = std::isnan(offset) ? d : offset;
          BOOLSURF_FUZZ_CHECK(std::fabs(d - offset) <= 1e-6,
            "winding number of a consistent closed shape off its label by " + std::to_string(d) +
              " against " + std::to_string(offset));
        }
      }
    }
  }
  LevelSetInput input;
  input.CornerValue = [&](int r, int k) { return w.Corner(arr, mesh, 0, r, k); };
  input.JumpTriangles = &w.JumpTriangles;
  std::vector<LevelSetLoop> loops;
  BOOLSURF_FUZZ_CHECK(ExtractLevelSet(mesh, arr, input, loops, error), error);
  for (const LevelSetLoop& loop : loops)
  {
    const std::size_t n = loop.Points.size();
    for (std::size_t i = 0; i < n; ++i)
    {
      BOOLSURF_FUZZ_CHECK(SharedTriangle(mesh, loop.Points[i], loop.Points[(i + 1) % n]) >= 0,
        "consecutive level-set points share no triangle");
    }
  }
  Reached(loops.empty() ? "winding numbers (no level set)" : "winding numbers with a level set");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  ByteReader in(data, size);
  MeshData surface = DecodeSurface(in);
  const TriangleMesh mesh(surface.Positions, surface.Triangles);
  const MeshTopology topology = MeshTopology::Compute(mesh);
  if (CheckSurface(mesh, topology).HasErrors())
  {
    Reached("surface refused");
    return 0; // refused before any stage, as the filters do
  }
  double surfaceArea = 0;
  for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    if (mesh.IsUsable(t))
    {
      surfaceArea += TriangleArea(
        mesh.GetCornerPosition(t, 0), mesh.GetCornerPosition(t, 1), mesh.GetCornerPosition(t, 2));
    }
  }

  // Tracing: a curve the tracer refuses is a clean error for the whole input.
  const std::vector<DecodedCurve> decoded = DecodeCurves(in, mesh.GetNumberOfTriangles());
  CurveTracer tracer(mesh);
  tracer.SetResolution(in.Byte() % 4);
  std::vector<TracedCurve> curves;
  std::size_t curvePoints = 0;
  for (std::size_t c = 0; c < decoded.size(); ++c)
  {
    CurveTrace trace;
    std::string traceError;
    const bool traced = tracer.Trace(decoded[c].Points,
      decoded[c].Type,
      decoded[c].Closed,
      trace,
      traceError,
      static_cast<int>(c));
    if (!traced)
    {
      BOOLSURF_FUZZ_CHECK(!traceError.empty(), "a failed trace must say why");
      Reached("trace refused");
      return 0;
    }
    trace.Curve.ShapeId = decoded[c].ShapeId;
    trace.Curve.CurveId = static_cast<int>(c);
    curvePoints += trace.Curve.Points.size();
    curves.push_back(trace.Curve);
  }

  ArrangementOptions options;
  options.Threads = 1; // reproducible runs
  options.FloodFill = static_cast<FloodFillMethod>(in.Byte() % 3);
  Arrangement arr;
  std::string error;
  if (!ComputeArrangement(mesh, curves, options, arr, error))
  {
    BOOLSURF_FUZZ_CHECK(!error.empty(), "a failed arrangement must say why");
    Reached(("arrangement refused: " + error).c_str());
    // Curves the tracer accepted should always be arranged, but some are still refused with a
    // message ("a point to insert is not on the edge it should split", "two points of edge N
    // are closer than the coordinate precision"; Docs/Fuzzing.md): a clean error, so only a
    // finding when BOOLSURF_FUZZ_STRICT_ARRANGEMENT is set (one-point curves excepted: the
    // filters skip them before the arrangement).
    static const bool strict = std::getenv("BOOLSURF_FUZZ_STRICT_ARRANGEMENT") != nullptr;
    BOOLSURF_FUZZ_CHECK(
      !strict || error.find("needs at least two points") != std::string::npos, error);
    return 0;
  }
  CheckArrangement(mesh, arr, surfaceArea);

  const LabelingResult labels = LabelCells(MakeLabelingInput(mesh, topology, curves, arr));
  CheckLabels(labels, arr.NumberOfCells, curvePoints);
  CheckWindingNumbers(mesh, topology, curves, arr, labels);

  // Boolean selection of a named operation, and of its complement.
  const std::vector<int> shapeIds = DistinctShapeIds(curves);
  const std::uint8_t op = in.Byte();
  const int n = static_cast<int>(shapeIds.size());
  const std::uint8_t pickA = in.Byte(), pickB = in.Byte();
  const int a = pickA == 255 ? -1 : shapeIds[pickA % n];
  const int b = pickB == 255 ? -1 : shapeIds[pickB % n];
  std::string text;
  switch (op % 4)
  {
    case 0:
      text = BooleanExpression::Union(a, b, shapeIds);
      break;
    case 1:
      text = BooleanExpression::Intersection(a, b, shapeIds);
      break;
    case 2:
      text = BooleanExpression::Difference(a, b, shapeIds);
      break;
    default:
      text = BooleanExpression::SymmetricDifference(a, b, shapeIds);
      break;
  }
  BooleanExpression expression, complement;
  BOOLSURF_FUZZ_CHECK(expression.Parse(text, shapeIds, error), text + ": " + error);
  BOOLSURF_FUZZ_CHECK(complement.Parse("~(" + text + ")", shapeIds, error), text + ": " + error);
  const FillRule rule = static_cast<FillRule>((op >> 2) % 4);
  std::vector<char> selected, rest;
  if (!SelectCells(labels, expression, rule, selected, error))
  {
    BOOLSURF_FUZZ_CHECK(!error.empty(), "a refused selection must say why");
    Reached("selection refused");
    return 0; // an inconsistent shape
  }
  BOOLSURF_FUZZ_CHECK(SelectCells(labels, complement, rule, rest, error), error);
  BOOLSURF_FUZZ_CHECK(selected.size() == static_cast<std::size_t>(arr.NumberOfCells) &&
      rest.size() == selected.size(),
    "selection size");
  const double area = RegionArea(mesh, arr, selected), restArea = RegionArea(mesh, arr, rest);
  BOOLSURF_FUZZ_CHECK(area <= surfaceArea * (1 + 1e-9), std::to_string(area));
  BOOLSURF_FUZZ_CHECK(std::fabs(area + restArea - surfaceArea) <= 1e-9 * surfaceArea,
    text + ": " + std::to_string(area) + " + " + std::to_string(restArea) + " vs " +
      std::to_string(surfaceArea));

  // The region as a mesh of its own, and its boundary.
  std::vector<int> triangles;
  RegionExtractor::SelectedTriangles(selected, arr, triangles);
  RegionExtractor extractor;
  RegionMesh region;
  extractor.Extract(
    triangles, arr.GetNumberOfPoints(), [&](int t) { return arr.GetTriangle(mesh, t); }, region);
  BOOLSURF_FUZZ_CHECK(region.Connectivity.size() == 3 * triangles.size(), "region size");
  for (int p : region.Connectivity)
  {
    BOOLSURF_FUZZ_CHECK(p >= 0 && p < static_cast<int>(region.Points.size()), "region point");
  }
  for (const BoundaryPolyline& line : ExtractRegionBoundary(arr.Patches, selected))
  {
    for (int p : line.Points)
    {
      BOOLSURF_FUZZ_CHECK(p >= 0 && p < arr.GetNumberOfPoints(), "boundary point");
    }
  }
  Reached(arr.NumberOfCells > 1 ? "region (several cells)" : "region (one cell)");
  return 0;
}

#include "Distributed/PieceCurves.h"

#include <algorithm>

namespace boolsurf
{
namespace
{

// Local triangle and local edge of the piece joining local vertices a and b (-1 when none).
bool FindLocalEdge(const TriangleMesh& mesh, int a, int b, int& triangle, int& k)
{
  for (int c : mesh.GetVertexCorners(a))
  {
    const int t = c / 3;
    const Triangle& tri = mesh.GetTriangle(t);
    for (int j = 0; j < 3; ++j)
    {
      const int x = tri[j], y = tri[(j + 1) % 3];
      if ((x == a && y == b) || (x == b && y == a))
      {
        triangle = t;
        k = j;
        return true;
      }
    }
  }
  return false;
}

// A global curve point on the piece: its local canonical form and the local triangles that
// hold it (none when the piece does not have it).
struct LocalPoint
{
  CanonicalPoint Point;
  std::vector<int> Triangles;
};

LocalPoint Localize(const PieceMesh& piece, const CanonicalPoint& p, const GlobalEdgeVertices& ev)
{
  const TriangleMesh& mesh = piece.Mesh;
  LocalPoint out;
  out.Point = p;
  if (p.Location == PointLocation::Face)
  {
    const int t = piece.LocalTriangle(p.Id);
    if (t >= 0)
    {
      out.Point.Id = t;
      out.Triangles.push_back(t);
    }
  }
  else if (p.Location == PointLocation::Vertex)
  {
    const int v = piece.LocalVertex(p.Id);
    if (v >= 0)
    {
      out.Point.Id = v;
      for (int c : mesh.GetVertexCorners(v))
      {
        out.Triangles.push_back(c / 3);
      }
    }
  }
  else
  {
    const std::array<int, 2> g = ev(p.Id);
    const int a = piece.LocalVertex(g[0]), b = piece.LocalVertex(g[1]);
    int t = -1, k = -1;
    if (a >= 0 && b >= 0 && FindLocalEdge(mesh, a, b, t, k))
    {
      const int e = mesh.GetEdgeId(t, k);
      out.Point.Id = e;
      // The piece's edge runs the other way when the piece lacks the edge's lowest global
      // triangle (only on the outer ring of ghosts): the parameter is measured from the other end.
      out.Point.T = mesh.GetEdgeVertices(e)[0] == a ? p.T : 1.0 - p.T;
      for (int c : mesh.GetVertexCorners(a))
      {
        const Triangle& tri = mesh.GetTriangle(c / 3);
        if (tri[0] == b || tri[1] == b || tri[2] == b)
        {
          out.Triangles.push_back(c / 3);
        }
      }
    }
  }
  std::sort(out.Triangles.begin(), out.Triangles.end());
  return out;
}

bool ShareTriangle(const std::vector<int>& a, const std::vector<int>& b)
{
  for (int t : a)
  {
    if (std::binary_search(b.begin(), b.end(), t))
    {
      return true;
    }
  }
  return false;
}

// Appends the run of global points [first, first + count] (indices modulo n) as a piece curve.
void AppendRun(const TracedCurve& curve,
  int source,
  const std::vector<LocalPoint>& local,
  int first,
  int count,
  bool whole,
  PieceCurves& out)
{
  const int n = static_cast<int>(local.size());
  TracedCurve run;
  run.ShapeId = curve.ShapeId;
  run.CurveId = curve.CurveId;
  run.Closed = whole && curve.Closed;
  const int points = whole ? n : count + 1;
  run.Points.reserve(points);
  for (int i = 0; i < points; ++i)
  {
    run.Points.push_back(local[(first + i) % n].Point);
  }
  out.Curves.push_back(std::move(run));
  out.SourceCurve.push_back(source);
  out.FirstPoint.push_back(first);
  out.CutFromClosed.push_back(!whole && curve.Closed ? 1 : 0);
}

} // namespace

//------------------------------------------------------------------------------
void RestrictCurvesToPiece(const PieceMesh& piece,
  const std::vector<TracedCurve>& curves,
  const GlobalEdgeVertices& edgeVertices,
  PieceCurves& out)
{
  out = PieceCurves();
  for (size_t ci = 0; ci < curves.size(); ++ci)
  {
    const TracedCurve& curve = curves[ci];
    const int n = static_cast<int>(curve.Points.size());
    std::vector<LocalPoint> local(n);
    for (int i = 0; i < n; ++i)
    {
      local[i] = Localize(piece, curve.Points[i], edgeVertices);
    }
    const int segments = curve.Closed ? n : n - 1;
    std::vector<char> kept(std::max(segments, 0));
    int keptCount = 0;
    for (int i = 0; i < segments; ++i)
    {
      kept[i] = ShareTriangle(local[i].Triangles, local[(i + 1) % n].Triangles) ? 1 : 0;
      keptCount += kept[i];
    }
    if (n == 1 && !local[0].Triangles.empty())
    {
      AppendRun(curve, static_cast<int>(ci), local, 0, 0, true, out);
      continue;
    }
    if (keptCount == segments && segments > 0)
    {
      AppendRun(curve, static_cast<int>(ci), local, 0, segments, true, out);
      continue;
    }
    // Runs of kept segments in the curve's own order (a closed curve's run through its first
    // point is cut there, so segment order inside every triangle is the global one).
    for (int i = 0; i < segments;)
    {
      if (!kept[i])
      {
        ++i;
        continue;
      }
      int j = i;
      while (j < segments && kept[j])
      {
        ++j;
      }
      AppendRun(curve, static_cast<int>(ci), local, i, j - i, false, out);
      i = j;
    }
  }
}

} // namespace boolsurf

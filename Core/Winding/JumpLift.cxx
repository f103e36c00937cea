#include "Winding/JumpLift.h"

#include <algorithm>
#include <cstdint>
#include <unordered_map>

namespace boolsurf
{

void AppendCurveEdges(const Arrangement& arr, int c, bool closed, CurveEdgeList& edges)
{
  const std::vector<int>& points = arr.CurvePoints[c];
  const size_t n = points.size();
  for (size_t i = 0; i + 1 < n; ++i)
  {
    edges.emplace_back(points[i], points[i + 1]);
  }
  if (closed && n > 1)
  {
    edges.emplace_back(points[n - 1], points[0]);
  }
}

namespace
{

std::uint64_t EdgeKey(int a, int b)
{
  const int lo = std::min(a, b), hi = std::max(a, b);
  return (static_cast<std::uint64_t>(lo) << 32) | static_cast<std::uint32_t>(hi);
}

/// Net number of curve traversals per undirected refined edge (positive from lower to higher
/// point id).
class JumpTable
{
public:
  explicit JumpTable(const CurveEdgeList& edges)
  {
    this->Net.reserve(edges.size() * 2);
    for (const auto& e : edges)
    {
      if (e.first != e.second)
      {
        this->Net[EdgeKey(e.first, e.second)] += e.first < e.second ? 1 : -1;
      }
    }
  }
  /// Signed traversals from a to b.
  int Along(int a, int b) const
  {
    const auto it = this->Net.find(EdgeKey(a, b));
    if (it == this->Net.end())
    {
      return 0;
    }
    return a < b ? it->second : -it->second;
  }
  /// What a walk gains entering a refined triangle across its edge (a, b) where a -> b is the
  /// triangle's own (counter-clockwise) direction: the triangle is on the left of a -> b.
  int Entering(int a, int b) const { return this->Along(a, b); }
  template <class F>
  void ForEachCurvePoint(F f) const
  {
    for (const auto& entry : this->Net)
    {
      if (entry.second != 0)
      {
        f(static_cast<int>(entry.first >> 32));
        f(static_cast<int>(entry.first & 0xffffffffu));
      }
    }
  }

private:
  std::unordered_map<std::uint64_t, int> Net;
};

/// The pieces of the touched mesh triangles, with their corners.
struct TouchedPieces
{
  std::vector<int> MeshTriangles;
  std::vector<int> Offset; ///< pieces of MeshTriangles[h]: [Offset[h], Offset[h + 1])
  std::vector<int> Pieces; ///< refined triangle ids
  std::vector<Triangle> Corners;
  std::vector<int> Owner; ///< index h of each piece's mesh triangle
};

/// Where a walk around one point of the curves stands in each of its pieces: chi(piece) =
/// W(piece) - W(anchor), anchor being its lowest piece. Pieces that no curve separates around
/// the point (one wedge) get the same value.
struct PointWedges
{
  std::vector<int> Pieces; ///< local piece indices, ascending
  std::vector<double> Chi;
  double Of(int piece) const
  {
    const auto it = std::lower_bound(this->Pieces.begin(), this->Pieces.end(), piece);
    return it != this->Pieces.end() && *it == piece ? this->Chi[it - this->Pieces.begin()] : 0.0;
  }
};

void WalkAroundPoint(int p, const TouchedPieces& touched, const JumpTable& jumps, PointWedges& w)
{
  // Half-edges at p: (other end, piece, piece runs p -> other end).
  struct Spoke
  {
    int Other, Piece;
    bool Outgoing;
  };
  std::vector<Spoke> spokes;
  for (int piece : w.Pieces)
  {
    const Triangle& tri = touched.Corners[piece];
    for (int k = 0; k < 3; ++k)
    {
      if (tri[k] == p)
      {
        spokes.push_back({ tri[(k + 1) % 3], piece, true });
        spokes.push_back({ tri[(k + 2) % 3], piece, false });
      }
    }
  }
  std::sort(spokes.begin(),
    spokes.end(),
    [](const Spoke& a, const Spoke& b)
    { return a.Other != b.Other ? a.Other < b.Other : a.Piece < b.Piece; });
  const int n = static_cast<int>(w.Pieces.size());
  auto local = [&](int piece)
  {
    return static_cast<int>(
      std::lower_bound(w.Pieces.begin(), w.Pieces.end(), piece) - w.Pieces.begin());
  };
  // Wedges: pieces joined across spokes no curve runs along.
  std::vector<int> parent(n);
  for (int i = 0; i < n; ++i)
  {
    parent[i] = i;
  }
  auto root = [&](int i)
  {
    while (parent[i] != i)
    {
      i = parent[i] = parent[parent[i]];
    }
    return i;
  };
  struct Crossing
  {
    int From, To;
    double Gain;
  };
  std::vector<Crossing> crossings;
  for (size_t i = 0; i < spokes.size();)
  {
    size_t j = i;
    while (j < spokes.size() && spokes[j].Other == spokes[i].Other)
    {
      ++j;
    }
    const int jump = jumps.Along(p, spokes[i].Other);
    for (size_t a = i; a < j; ++a)
    {
      for (size_t b = a + 1; b < j; ++b)
      {
        const int la = local(spokes[a].Piece), lb = local(spokes[b].Piece);
        if (jump == 0)
        {
          const int ra = root(la), rb = root(lb);
          if (ra != rb)
          {
            parent[std::max(ra, rb)] = std::min(ra, rb);
          }
        }
        else
        {
          // Entering a piece across (p, other): +J(p -> other) when the piece runs p -> other.
          const double gainB = spokes[b].Outgoing ? jump : -jump;
          const double gainA = spokes[a].Outgoing ? jump : -jump;
          crossings.push_back({ la, lb, gainB });
          crossings.push_back({ lb, la, gainA });
        }
      }
    }
    i = j;
  }
  // Walk the wedges from the anchor's, in a fixed order.
  std::vector<double> wedgeChi(n, 0.0);
  std::vector<char> reached(n, 0);
  std::vector<int> queue;
  for (int start = 0; start < n; ++start)
  {
    const int rs = root(start);
    if (reached[rs])
    {
      continue;
    }
    reached[rs] = 1;
    wedgeChi[rs] = 0.0;
    queue.assign(1, rs);
    for (size_t q = 0; q < queue.size(); ++q)
    {
      const int wedge = queue[q];
      for (const Crossing& c : crossings)
      {
        if (root(c.From) != wedge)
        {
          continue;
        }
        const int to = root(c.To);
        if (!reached[to])
        {
          reached[to] = 1;
          wedgeChi[to] = wedgeChi[wedge] + c.Gain;
          queue.push_back(to);
        }
      }
    }
  }
  w.Chi.resize(n);
  for (int i = 0; i < n; ++i)
  {
    w.Chi[i] = wedgeChi[root(i)];
  }
}

/// phi(piece) = W(piece) - W(first piece) for the pieces of one mesh triangle, by a walk
/// across their shared edges.
void WalkInsideTriangle(int h,
  const TouchedPieces& touched,
  const JumpTable& jumps,
  std::vector<double>& phi)
{
  const int first = touched.Offset[h], last = touched.Offset[h + 1];
  phi[first] = 0.0;
  if (last - first == 1)
  {
    return;
  }
  struct Side
  {
    std::uint64_t Key;
    int Piece, From, To;
  };
  std::vector<Side> sides;
  for (int i = first; i < last; ++i)
  {
    const Triangle& tri = touched.Corners[i];
    for (int k = 0; k < 3; ++k)
    {
      sides.push_back({ EdgeKey(tri[k], tri[(k + 1) % 3]), i, tri[k], tri[(k + 1) % 3] });
    }
  }
  std::sort(sides.begin(),
    sides.end(),
    [](const Side& a, const Side& b)
    { return a.Key != b.Key ? a.Key < b.Key : a.Piece < b.Piece; });
  std::vector<std::vector<std::pair<int, double>>> next(last - first);
  for (size_t i = 0; i + 1 < sides.size(); ++i)
  {
    if (sides[i].Key == sides[i + 1].Key)
    {
      const Side& a = sides[i];
      const Side& b = sides[i + 1];
      next[a.Piece - first].emplace_back(b.Piece, jumps.Entering(b.From, b.To));
      next[b.Piece - first].emplace_back(a.Piece, jumps.Entering(a.From, a.To));
    }
  }
  std::vector<char> reached(last - first, 0);
  std::vector<int> queue(1, first);
  reached[0] = 1;
  for (size_t q = 0; q < queue.size(); ++q)
  {
    const int piece = queue[q];
    for (const auto& step : next[piece - first])
    {
      if (!reached[step.first - first])
      {
        reached[step.first - first] = 1;
        phi[step.first] = phi[piece] + step.second;
        queue.push_back(step.first);
      }
    }
  }
}

//------------------------------------------------------------------------------
// The mesh triangles whose closure the curve points touch, and their refined pieces.
void CollectTouchedPieces(const TriangleMesh& mesh,
  const Arrangement& arr,
  const std::vector<int>& curvePoints,
  TouchedPieces& touched)
{
  std::vector<int> around;
  for (int p : curvePoints)
  {
    TrianglesOf(mesh, arr.GetPointOnMesh(p), around);
    touched.MeshTriangles.insert(touched.MeshTriangles.end(), around.begin(), around.end());
  }
  std::sort(touched.MeshTriangles.begin(), touched.MeshTriangles.end());
  touched.MeshTriangles.erase(
    std::unique(touched.MeshTriangles.begin(), touched.MeshTriangles.end()),
    touched.MeshTriangles.end());
  const int nh = static_cast<int>(touched.MeshTriangles.size());
  touched.Offset.assign(1, 0);
  for (int h = 0; h < nh; ++h)
  {
    ForEachRefinedTriangle(mesh,
      arr,
      touched.MeshTriangles[h],
      [&](int r)
      {
        touched.Pieces.push_back(r);
        touched.Corners.push_back(arr.GetTriangle(mesh, r));
        touched.Owner.push_back(h);
      });
    touched.Offset.push_back(static_cast<int>(touched.Pieces.size()));
  }
}

//------------------------------------------------------------------------------
// Index of mesh triangle t among the touched ones, -1 when untouched.
int TouchedIndex(const TouchedPieces& touched, int t)
{
  const auto it = std::lower_bound(touched.MeshTriangles.begin(), touched.MeshTriangles.end(), t);
  return it != touched.MeshTriangles.end() && *it == t
    ? static_cast<int>(it - touched.MeshTriangles.begin())
    : -1;
}

//------------------------------------------------------------------------------
// K(z) of the refined points z inside mesh edge e (into pointConstant): from the lowest
// touched triangle of the edge, its pieces along the edge in order (chi(point, piece): the
// wedge values; `around`: scratch).
template <class Chi>
void AddEdgePointConstants(const TriangleMesh& mesh,
  const Arrangement& arr,
  const TouchedPieces& touched,
  const Chi& chi,
  int e,
  std::vector<int>& around,
  std::unordered_map<int, double>& pointConstant)
{
  // The lowest touched triangle of the edge; its pieces along the edge, in order.
  CanonicalPoint ce;
  ce.Location = PointLocation::Edge;
  ce.Id = e;
  ce.T = 0.5;
  TrianglesOf(mesh, ce, around);
  int h = -1;
  for (int t : around)
  {
    h = TouchedIndex(touched, t);
    if (h >= 0)
    {
      break;
    }
  }
  const std::array<int, 2> ends = mesh.GetEdgeVertices(e);
  auto parameter = [&](int p) -> double
  {
    if (p == ends[0])
    {
      return 0.0;
    }
    if (p == ends[1])
    {
      return 1.0;
    }
    if (p < arr.NumberOfMeshVertices)
    {
      return -1.0;
    }
    const CanonicalPoint c = arr.GetPointOnMesh(p);
    return c.Location == PointLocation::Edge && c.Id == e ? c.T : -1.0;
  };
  struct SubEdge
  {
    double From, To;
    int A, B, Piece;
  };
  std::vector<SubEdge> chain;
  for (int i = touched.Offset[h]; i < touched.Offset[h + 1]; ++i)
  {
    const Triangle& tri = touched.Corners[i];
    for (int k = 0; k < 3; ++k)
    {
      int a = tri[k], b = tri[(k + 1) % 3];
      double ta = parameter(a), tb = parameter(b);
      if (ta < 0.0 || tb < 0.0)
      {
        continue;
      }
      if (ta > tb)
      {
        std::swap(ta, tb);
        std::swap(a, b);
      }
      chain.push_back({ ta, tb, a, b, i });
    }
  }
  std::sort(
    chain.begin(), chain.end(), [](const SubEdge& x, const SubEdge& y) { return x.From < y.From; });
  const int m = static_cast<int>(chain.size());
  // CA[j] = W(piece j) - W(reference wedge of A), CB[j] the same from B.
  std::vector<double> ca(m), cb(m);
  for (int j = 0; j < m; ++j)
  {
    ca[j] = j == 0
      ? chi(chain[0].A, chain[0].Piece)
      : ca[j - 1] + chi(chain[j].A, chain[j].Piece) - chi(chain[j].A, chain[j - 1].Piece);
  }
  for (int j = m - 1; j >= 0; --j)
  {
    cb[j] = j == m - 1
      ? chi(chain[j].B, chain[j].Piece)
      : cb[j + 1] + chi(chain[j].B, chain[j].Piece) - chi(chain[j].B, chain[j + 1].Piece);
  }
  for (int j = 1; j < m; ++j)
  {
    const int z = chain[j].A;
    const double t = chain[j].From;
    pointConstant[z] =
      (1.0 - t) * (ca[j - 1] - chi(z, chain[j - 1].Piece)) + t * (cb[j] - chi(z, chain[j].Piece));
  }
}

//------------------------------------------------------------------------------
// Flux per touched mesh triangle: sum over its pieces of area * grad v.
void ComputeLiftFlux(const TriangleMesh& mesh,
  const Arrangement& arr,
  const TouchedPieces& touched,
  JumpLift& out)
{
  const int nh = static_cast<int>(touched.MeshTriangles.size());
  out.MeshTriangles = touched.MeshTriangles;
  out.Flux.assign(nh, Vec3{ 0, 0, 0 });
  for (int h = 0; h < nh; ++h)
  {
    const TriangleGradients g = ComputeTriangleGradients(mesh, touched.MeshTriangles[h]);
    if (g.Area == 0.0)
    {
      continue;
    }
    Vec3 flux{ 0, 0, 0 };
    for (int i = touched.Offset[h]; i < touched.Offset[h + 1]; ++i)
    {
      const Triangle& tri = touched.Corners[i];
      const Vec3 p[3] = {
        arr.GetPosition(mesh, tri[0]), arr.GetPosition(mesh, tri[1]), arr.GetPosition(mesh, tri[2])
      };
      for (int k = 0; k < 3; ++k)
      {
        // area * grad(hat_k) = (n x opposite edge) / 2, finite on slivers.
        flux = flux + (0.5 * out.Values[i][k]) * Cross(g.Normal, p[(k + 2) % 3] - p[(k + 1) % 3]);
      }
    }
    out.Flux[h] = flux;
  }
}

//------------------------------------------------------------------------------
// Pieces in ascending refined id (the pieces of one triangle are not contiguous ids).
void SortPiecesById(JumpLift& out)
{
  const int np = static_cast<int>(out.Triangles.size());
  std::vector<int> order(np);
  for (int i = 0; i < np; ++i)
  {
    order[i] = i;
  }
  std::sort(
    order.begin(), order.end(), [&](int a, int b) { return out.Triangles[a] < out.Triangles[b]; });
  JumpLift sorted;
  sorted.Triangles.resize(np);
  sorted.Values.resize(np);
  for (int i = 0; i < np; ++i)
  {
    sorted.Triangles[i] = out.Triangles[order[i]];
    sorted.Values[i] = out.Values[order[i]];
  }
  out.Triangles.swap(sorted.Triangles);
  out.Values.swap(sorted.Values);
}

} // namespace

void ComputeJumpLift(const TriangleMesh& mesh,
  const Arrangement& arr,
  const CurveEdgeList& edges,
  JumpLift& out)
{
  out = JumpLift();
  const JumpTable jumps(edges);

  // Points of the curves and the mesh triangles whose closure they touch.
  std::vector<int> curvePoints;
  jumps.ForEachCurvePoint([&](int p) { curvePoints.push_back(p); });
  std::sort(curvePoints.begin(), curvePoints.end());
  curvePoints.erase(std::unique(curvePoints.begin(), curvePoints.end()), curvePoints.end());
  if (curvePoints.empty())
  {
    return;
  }
  TouchedPieces touched;
  CollectTouchedPieces(mesh, arr, curvePoints, touched);
  const int nh = static_cast<int>(touched.MeshTriangles.size());
  const int np = static_cast<int>(touched.Pieces.size());

  // Wedges around every point of the curves.
  std::unordered_map<int, int> curvePointIndex;
  curvePointIndex.reserve(curvePoints.size() * 2);
  for (size_t i = 0; i < curvePoints.size(); ++i)
  {
    curvePointIndex[curvePoints[i]] = static_cast<int>(i);
  }
  std::vector<PointWedges> wedges(curvePoints.size());
  for (int i = 0; i < np; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      const auto it = curvePointIndex.find(touched.Corners[i][k]);
      if (it != curvePointIndex.end())
      {
        wedges[it->second].Pieces.push_back(i); // ascending: i grows
      }
    }
  }
  for (size_t i = 0; i < curvePoints.size(); ++i)
  {
    WalkAroundPoint(curvePoints[i], touched, jumps, wedges[i]);
  }
  auto chi = [&](int point, int piece) -> double
  {
    const auto it = curvePointIndex.find(point);
    return it == curvePointIndex.end() ? 0.0 : wedges[it->second].Of(piece);
  };

  std::vector<double> phi(np, 0.0);
  for (int h = 0; h < nh; ++h)
  {
    WalkInsideTriangle(h, touched, jumps, phi);
  }
  auto lowestPieceWithCorner = [&](int h, int point)
  {
    for (int i = touched.Offset[h]; i < touched.Offset[h + 1]; ++i)
    {
      const Triangle& tri = touched.Corners[i];
      if (tri[0] == point || tri[1] == point || tri[2] == point)
      {
        return i;
      }
    }
    return -1;
  };
  // K(q): v(q, piece) = chi_q(piece) + K(q), one number per refined point.
  std::unordered_map<int, double> pointConstant;
  std::vector<int> around;
  auto constantOf = [&](int q, int piece) -> double
  {
    if (q < arr.NumberOfMeshVertices)
    {
      return 0.0;
    }
    const auto it = pointConstant.find(q);
    if (it != pointConstant.end())
    {
      return it->second;
    }
    const CanonicalPoint c = arr.GetPointOnMesh(q);
    if (c.Location == PointLocation::Edge)
    {
      AddEdgePointConstants(mesh, arr, touched, chi, c.Id, around, pointConstant);
      const auto found = pointConstant.find(q);
      return found != pointConstant.end() ? found->second : 0.0;
    }
    // Inside mesh triangle T: sum_i lambda_i (W(anchor) - W(reference wedge of x_i)).
    const int h = touched.Owner[piece];
    const int t = touched.MeshTriangles[h];
    const Triangle& tri = mesh.GetTriangle(t);
    const std::array<double, 3> lambda = WeightsInTriangle(mesh, c, t);
    const int anchor = lowestPieceWithCorner(h, q);
    double k = -chi(q, anchor);
    for (int i = 0; i < 3; ++i)
    {
      const int ri = lowestPieceWithCorner(h, tri[i]);
      k += lambda[i] * (phi[anchor] - phi[ri] + chi(tri[i], ri));
    }
    pointConstant[q] = k;
    return k;
  };

  out.Triangles.resize(np);
  out.Values.resize(np);
  for (int i = 0; i < np; ++i)
  {
    out.Triangles[i] = touched.Pieces[i];
    for (int k = 0; k < 3; ++k)
    {
      const int q = touched.Corners[i][k];
      out.Values[i][k] = chi(q, i) + constantOf(q, i);
    }
  }

  ComputeLiftFlux(mesh, arr, touched, out);
  SortPiecesById(out);
}

void AddLiftLoad(const TriangleMesh& mesh, const JumpLift& lift, double* rhs)
{
  for (size_t h = 0; h < lift.MeshTriangles.size(); ++h)
  {
    const int t = lift.MeshTriangles[h];
    const TriangleGradients g = ComputeTriangleGradients(mesh, t);
    const Triangle& tri = mesh.GetTriangle(t);
    for (int k = 0; k < 3; ++k)
    {
      rhs[tri[k]] += Dot(g.Hat[k], lift.Flux[h]);
    }
  }
}

} // namespace boolsurf

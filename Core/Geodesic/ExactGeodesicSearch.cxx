#include "Geodesic/ExactGeodesicSearch.h"

#include "Mesh/PerMeshRegistry.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>

namespace boolsurf
{
namespace
{
constexpr double Pi = 3.14159265358979323846;
constexpr double Infinity = std::numeric_limits<double>::infinity();

// Vertices whose angle sum exceeds 2 pi by more than this are saddles: exactly flat vertices
// (planar and subdivided meshes) are no sources, and the rays through one carry on by the
// windows on both its sides (Propagate relaxes it from either to within rounding).
constexpr double SaddleTolerance = 1e-9;

// Windows narrower than this fraction of their edge are dropped: the rays they carry pass
// within rounding of a vertex, whose own distance (and, for saddles, windows) covers them.
constexpr double MinimumWidth = 1e-12;

int CornerOf(const Triangle& tri, int v)
{
  return tri[0] == v ? 0 : (tri[1] == v ? 1 : (tri[2] == v ? 2 : -1));
}

double Hypot(double x, double y)
{
  return std::sqrt(x * x + y * y);
}

// Parameter u along a -> c where the line through p and q meets it.
double LineHit(Vec2 p, Vec2 q, Vec2 a, Vec2 c)
{
  const double den = Cross(q - p, c - a);
  return den != 0.0 ? Cross(q - p, p - a) / den : 0.0;
}

// The corner of a triangle opposite its side of length `length`, l0 and l1 from the side's
// ends, in the side's frame: end 0 at the origin, end 1 on +x, the corner above.
Vec2 OppositeCorner(double length, double l0, double l1)
{
  const double cx = (length * length + l0 * l0 - l1 * l1) / (2.0 * length);
  return { cx, std::sqrt(std::max(0.0, l0 * l0 - cx * cx)) };
}

// The angle of triangle `tri` at its corner k.
double CornerAngle(const TriangleMesh& mesh, const Triangle& tri, int k)
{
  const Vec3 p = mesh.GetPosition(tri[k]);
  const Vec3 a = mesh.GetPosition(tri[(k + 1) % 3]) - p;
  const Vec3 b = mesh.GetPosition(tri[(k + 2) % 3]) - p;
  return std::atan2(Length(Cross(a, b)), Dot(a, b));
}

// Where the segment from source s (y <= 0) to point x (y > 0) crosses the line y = 0.
double CrossingOf(Vec2 s, Vec2 x)
{
  const double den = x.y - s.y;
  return den > 0.0 ? s.x + (x.x - s.x) * (-s.y) / den : x.x;
}

// Whether vertex v is a saddle (angle sum above 2 pi) or a boundary vertex, one of the
// vertices from which windows restart. The angle sum is added over v's corners in increasing
// order, as a loop over triangles would, bit for bit.
bool ComputeIsPseudoSource(const TriangleMesh& mesh, int v)
{
  double angle = 0.0;
  int boundaryEdges = 0;
  for (int corner : mesh.GetVertexCorners(v))
  {
    const int t = corner / 3, k = corner % 3;
    angle += CornerAngle(mesh, mesh.GetTriangle(t), k);
    boundaryEdges += (mesh.GetNeighbor(t, k) < 0) + (mesh.GetNeighbor(t, (k + 2) % 3) < 0);
  }
  if (boundaryEdges == 0)
  {
    return angle > 2.0 * Pi + SaddleTolerance;
  }
  // A shortest path through a boundary vertex keeps at least pi of surface on one side (else
  // a shortcut inside the angle exists), so a vertex with one fan and less than pi around it
  // is never on one: only boundary corners of pi or more (and every vertex of several fans)
  // restart windows. On scans with holes this removes about half the boundary sources.
  return boundaryEdges > 2 || angle > Pi - SaddleTolerance;
}

} // namespace

// Per mesh vertex, decided on first use and shared by every search on the mesh (the solver
// and its helpers): Unknown, then No or Yes. Searches touch a small part of a large mesh, and
// deciding every vertex up front was 13M atan2 calls on 4M triangles (a third of a second of
// the first update on two threads). Threads that decide the same vertex at once store the same
// value.
struct ExactGeodesicSearch::PseudoSources
{
  enum : std::uint8_t
  {
    Unknown,
    No,
    Yes
  };
  const TriangleMesh* Mesh = nullptr;
  std::unique_ptr<std::atomic<std::uint8_t>[]> Flags;

  bool Is(int v) const
  {
    std::uint8_t flag = this->Flags[v].load(std::memory_order_relaxed);
    if (flag == Unknown)
    {
      flag = ComputeIsPseudoSource(*this->Mesh, v) ? Yes : No;
      this->Flags[v].store(flag, std::memory_order_relaxed);
    }
    return flag == Yes;
  }
};

namespace
{
using PseudoSources = ExactGeodesicSearch::PseudoSources;

std::shared_ptr<const PseudoSources> ComputePseudoSources(const TriangleMesh& mesh)
{
  auto out = std::make_shared<PseudoSources>();
  out->Mesh = &mesh;
  out->Flags = std::make_unique<std::atomic<std::uint8_t>[]>(
    static_cast<std::size_t>(mesh.GetNumberOfVertices())); // value-initialized: Unknown
  return out;
}

PerMeshRegistry<const PseudoSources> pseudoSourceRegistry;

std::shared_ptr<const PseudoSources> PseudoSourcesOf(const TriangleMesh& mesh)
{
  if (mesh.GetSerial() == 0)
  {
    return ComputePseudoSources(mesh);
  }
  return pseudoSourceRegistry.Get(
    mesh,
    [&] { return ComputePseudoSources(mesh); },
    [&](const PseudoSources& flags) { return flags.Mesh == &mesh; });
}

} // namespace

//------------------------------------------------------------------------------
ExactGeodesicSearch::ExactGeodesicSearch(const TriangleMesh& mesh)
  : Mesh(mesh)
{
}

//------------------------------------------------------------------------------
void ExactGeodesicSearch::Prepare()
{
  if (this->Prepared)
  {
    return;
  }
  const TriangleMesh& mesh = this->Mesh;
  const int nv = mesh.GetNumberOfVertices();
  const int nt = mesh.GetNumberOfTriangles();
  this->PseudoSource = PseudoSourcesOf(mesh);
  this->Labels.Reset(nv);
  this->EndMark.Reset(nt);
  this->EdgeSlot.Reset(mesh.GetNumberOfEdges());
  this->Prepared = true;
}

//------------------------------------------------------------------------------
void ExactGeodesicSearch::ResetMarks()
{
  for (const EdgeSampleSlot& slot : this->SamplePool)
  {
    this->EdgeSlot[slot.Edge] = 0;
  }
  this->SamplePool.clear();
  if (++this->CurrentStamp == 0)
  {
    this->Labels.Zero();
    this->EndMark.Zero();
    this->CurrentStamp = 1;
  }
}

//------------------------------------------------------------------------------
void ExactGeodesicSearch::OfferTarget(double length, int kind, int id)
{
  if (length < this->Best)
  {
    this->Best = length;
    this->BestKind = kind;
    this->BestId = id;
  }
}

//------------------------------------------------------------------------------
void ExactGeodesicSearch::Relax(int v, double d, int kind, int parent, int arrival)
{
  if (this->Labels[v].Stamp != this->CurrentStamp)
  {
    this->Labels[v].Stamp = this->CurrentStamp;
    this->Labels[v].Distance = Infinity;
  }
  if (!(d < this->Labels[v].Distance))
  {
    return;
  }
  if (this->FieldMode && this->Labels[v].Distance == Infinity)
  {
    this->FieldVertices.push_back(v);
  }
  this->Labels[v].Distance = d;
  this->Labels[v].Kind = kind;
  this->Labels[v].Parent = parent;
  this->Labels[v].Arrival = arrival;
  const double toTarget =
    this->FieldMode ? 0.0 : ::boolsurf::Distance(this->Mesh.GetPosition(v), this->Target);
  this->Heap.push_back({ d + toTarget, -(v + 1), d });
  std::push_heap(this->Heap.begin(), this->Heap.end());
}

//------------------------------------------------------------------------------
// Filtering: a window is useless when a known path through one of its edge's vertices reaches
// every point of it sooner (the difference is monotone along the edge, so one end decides).
bool ExactGeodesicSearch::Dominated(const Window& w,
  const std::array<int, 2>& ev,
  double length) const
{
  auto distanceAt = [&](double b) { return w.Sigma + Hypot(w.Sx - b, w.Sy); };
  const double d0 =
    this->Labels[ev[0]].Stamp == this->CurrentStamp ? this->Labels[ev[0]].Distance : Infinity;
  const double d1 =
    this->Labels[ev[1]].Stamp == this->CurrentStamp ? this->Labels[ev[1]].Distance : Infinity;
  return d0 + w.B1 < distanceAt(w.B1) || d1 + (length - w.B0) < distanceAt(w.B0);
}

//------------------------------------------------------------------------------
// Where sample j (1 .. EdgeSamples) of an edge of length `length` lies on it.
double ExactGeodesicSearch::EdgeSampleAt(double length, int j)
{
  return length * j / (EdgeSamples + 1);
}

//------------------------------------------------------------------------------
// Filtering and trimming by the edge's own points. Besides its two vertices, each edge keeps
// the shortest distance kept windows gave at EdgeSamples interior points q (real paths). Any
// point p of the edge is then reached within D(q) + |p - q| (to q, then along the edge): a
// cone of slope 1. The window's distance g(p) = sigma + |S p| has slope below 1 in magnitude,
// so g minus a cone grows towards q and falls away from it: each cone beats the window on one
// interval around q (or nowhere). Those intervals are cut off the window's ends, as long as
// one covers an end; the window is useless when nothing is left. Cuts stop short of the
// crossing by a margin: a window never loses a point it reaches first.
bool ExactGeodesicSearch::TrimOnEdge(Window& w, const std::array<int, 2>& ev, double length) const
{
  constexpr int n = EdgeSamples;
  const int slot = this->EdgeSlot[w.Edge];
  const double* samples = slot > 0 ? this->SamplePool[slot - 1].D : nullptr;
  double q[n + 2], d[n + 2];
  q[0] = 0.0;
  d[0] = this->Labels[ev[0]].Stamp == this->CurrentStamp ? this->Labels[ev[0]].Distance : Infinity;
  for (int j = 1; j <= n; ++j)
  {
    q[j] = EdgeSampleAt(length, j);
    d[j] = samples ? samples[j - 1] : Infinity;
  }
  q[n + 1] = length;
  d[n + 1] =
    this->Labels[ev[1]].Stamp == this->CurrentStamp ? this->Labels[ev[1]].Distance : Infinity;
  const double margin = 1e-9 * length;
  const double s2 = w.Sx * w.Sx + w.Sy * w.Sy;
  // The interval [lo, hi] where cone j is shorter than the window (lo > hi: nowhere).
  double lo[n + 2], hi[n + 2];
  int cones = 0;
  for (int j = 0; j <= n + 1; ++j)
  {
    lo[j] = 1.0;
    hi[j] = 0.0;
    if (d[j] == Infinity || !(d[j] < w.Sigma + Hypot(q[j] - w.Sx, w.Sy)))
    {
      continue;
    }
    ++cones;
    // Right of q: sigma + |S p| = d + p - q, i.e. |S p| = p + c.
    const double c = d[j] - q[j] - w.Sigma;
    const double right = c + w.Sx > 0.0 ? (s2 - c * c) / (2.0 * (c + w.Sx)) : Infinity;
    // Left of q: |S p| = e - p.
    const double e = d[j] + q[j] - w.Sigma;
    const double left = e - w.Sx > 0.0 ? (e * e - s2) / (2.0 * (e - w.Sx)) : -Infinity;
    lo[j] = std::min(q[j], left) + margin;
    hi[j] = std::max(q[j], right) - margin;
  }
  if (cones == 0)
  {
    return true;
  }
  for (int round = 0; round < n + 2 && w.B0 < w.B1; ++round)
  {
    bool cut = false;
    for (int j = 0; j <= n + 1; ++j)
    {
      if (lo[j] <= w.B0 && w.B0 < hi[j])
      {
        w.B0 = hi[j];
        cut = true;
      }
      if (lo[j] < w.B1 && w.B1 <= hi[j])
      {
        w.B1 = lo[j];
        cut = true;
      }
    }
    if (!cut)
    {
      break;
    }
  }
  return w.B0 < w.B1;
}

//------------------------------------------------------------------------------
// A kept window lowers its edge's samples that it lights.
void ExactGeodesicSearch::RecordOnEdge(const Window& w, double length)
{
  constexpr int n = EdgeSamples;
  int& slot = this->EdgeSlot[w.Edge];
  if (slot == 0)
  {
    EdgeSampleSlot fresh;
    fresh.Edge = w.Edge;
    std::fill(fresh.D, fresh.D + n, Infinity);
    this->SamplePool.push_back(fresh);
    slot = static_cast<int>(this->SamplePool.size());
  }
  double* samples = this->SamplePool[slot - 1].D;
  for (int j = 1; j <= n; ++j)
  {
    const double q = EdgeSampleAt(length, j);
    if (q >= w.B0 && q <= w.B1)
    {
      samples[j - 1] = std::min(samples[j - 1], w.Sigma + Hypot(q - w.Sx, w.Sy));
    }
  }
}

//------------------------------------------------------------------------------
// A lower bound of every path through the window to the target: min over the lit points p of
// (the window's distance at p) + |p - target|. In the edge frame the source S lies below the
// edge (Sy <= 0); the target, at height h from the edge's line and abscissa tx, can be turned
// about that line onto the other side, and the sum is then the length of a broken line from
// S to (tx, h) through p: convex in p's abscissa and smallest where the straight line
// crosses the edge, so the lit interval's point nearest that crossing gives the minimum.
// Bounding by each term's own minimum (at two different points) let far more windows in.
double ExactGeodesicSearch::WindowKey(const Window& w,
  const Vec3& p0,
  const Vec3& p1,
  double length) const
{
  const Vec3 toTarget = this->Target - p0;
  const double tx = Dot(toTarget, p1 - p0) / length;
  const double h = std::sqrt(std::max(0.0, Dot(toTarget, toTarget) - tx * tx));
  const double below = -w.Sy;
  const double x = below + h > 0.0 ? w.Sx + (tx - w.Sx) * below / (below + h) : w.Sx;
  const double p = std::min(w.B1, std::max(w.B0, x));
  return w.Sigma + Hypot(p - w.Sx, w.Sy) + Hypot(p - tx, h);
}

//------------------------------------------------------------------------------
void ExactGeodesicSearch::AddWindow(const Window& w)
{
  const TriangleMesh& mesh = this->Mesh;
  const std::array<int, 2> ev = mesh.GetEdgeVertices(w.Edge);
  const Vec3 p0 = mesh.GetPosition(ev[0]), p1 = mesh.GetPosition(ev[1]);
  this->AddWindowOnEdge(w, ev, p0, p1, ::boolsurf::Distance(p0, p1));
}

//------------------------------------------------------------------------------
// AddWindow with the edge's vertices, their positions and its length already at hand (a
// window's children: Propagate has loaded them).
void ExactGeodesicSearch::AddWindowOnEdge(Window w,
  const std::array<int, 2>& ev,
  const Vec3& p0,
  const Vec3& p1,
  double length)
{
  if (!(w.B1 - w.B0 > MinimumWidth * length))
  {
    return;
  }
  if (this->Dominated(w, ev, length))
  {
    return;
  }
  // Searches that stay small keep the cheaper filter alone (see TrimAfterWindows).
  const bool trim =
    this->Pruning && !this->FieldMode && static_cast<int>(this->Windows.size()) >= TrimAfterWindows;
  if (trim && !this->TrimOnEdge(w, ev, length))
  {
    return;
  }
  if (this->Allowed && !this->Allowed(w.Face))
  {
    return;
  }
  // Windows are dropped by the tightest lower bound (WindowKey) but queued, when the search
  // was given an upper bound, by the looser sum of the two terms' own minima (OrderByBound).
  const double nearest = w.Sigma + Hypot(w.Sx - std::min(w.B1, std::max(w.B0, w.Sx)), w.Sy);
  double order = nearest, bound = nearest;
  if (!this->FieldMode)
  {
    bound = this->WindowKey(w, p0, p1, length);
    if (this->OrderByBound)
    {
      order = bound;
    }
    else
    {
      const double scale = 1.0 / length;
      const Vec3 a = p0 + (w.B0 * scale) * (p1 - p0);
      const Vec3 b = p0 + (w.B1 * scale) * (p1 - p0);
      order = nearest + SegmentPointDistance(a, b, this->Target);
    }
  }
  if (bound >= this->Best)
  {
    return;
  }
  if (trim)
  {
    this->RecordOnEdge(w, length);
  }
  const int id = static_cast<int>(this->Windows.size());
  this->Windows.push_back(w);
  if (this->FieldMode)
  {
    this->LinkToEdge(id);
  }
  this->Heap.push_back({ order, id, bound });
  std::push_heap(this->Heap.begin(), this->Heap.end());
}

//------------------------------------------------------------------------------
void ExactGeodesicSearch::Propagate(int id)
{
  const TriangleMesh& mesh = this->Mesh;
  const Window w = this->Windows[id];
  const int face = w.Face;
  const Triangle& tri = mesh.GetTriangle(face);
  // The window's side of its face, by the edge's vertices (one vertex pair is one edge): edge
  // ids are derived (TriangleMesh::GetEdgeId), and the vertices are needed below anyway.
  const std::array<int, 2> ev = mesh.GetEdgeVertices(w.Edge);
  int k = 0;
  while (k < 3 &&
    !((tri[k] == ev[0] && tri[(k + 1) % 3] == ev[1]) ||
      (tri[k] == ev[1] && tri[(k + 1) % 3] == ev[0])))
  {
    ++k;
  }
  if (k == 3)
  {
    return;
  }
  const int c = tri[(k + 2) % 3];
  const Vec3 p0 = mesh.GetPosition(ev[0]), p1 = mesh.GetPosition(ev[1]);
  const Vec3 pc = mesh.GetPosition(c);
  const double length = ::boolsurf::Distance(p0, p1);
  if (this->Dominated(w, ev, length))
  {
    return; // vertex distances improved since the window was queued
  }
  const double l0 = ::boolsurf::Distance(p0, pc), l1 = ::boolsurf::Distance(p1, pc);
  const Vec2 C = OppositeCorner(length, l0, l1);
  const Vec2 E0{ 0.0, 0.0 }, E1{ length, 0.0 };
  const Vec2 S{ w.Sx, w.Sy };

  // The end point inside this triangle: straight through the window when visible, else
  // around a window end (a real path, so an upper bound; the visible case is exact).
  if (this->EndMark[face] == this->CurrentStamp)
  {
    const std::array<double, 3> wt = WeightsInTriangle(mesh, this->End, face);
    Vec2 t{ 0.0, 0.0 };
    for (int j = 0; j < 3; ++j)
    {
      const Vec2 q = tri[j] == ev[0] ? E0 : (tri[j] == ev[1] ? E1 : C);
      t = t + wt[j] * q;
    }
    const double x = CrossingOf(S, t);
    double length2;
    if (x >= w.B0 && x <= w.B1)
    {
      length2 = w.Sigma + Length(t - S);
    }
    else
    {
      const Vec2 a{ w.B0, 0.0 }, b{ w.B1, 0.0 };
      length2 = w.Sigma + std::min(Length(a - S) + Length(t - a), Length(b - S) + Length(t - b));
    }
    this->OfferTarget(length2, FromWindow, id);
  }

  const double xc = CrossingOf(S, C);
  const double throughC = w.Sigma + Length(C - S);
  if (xc >= w.B0 && xc <= w.B1)
  {
    this->Relax(c, throughC, FromWindow, id, face);
  }
  else
  {
    // Out of sight: around the window's nearer end, a real path. Where the window's end ray
    // runs exactly through c (every lattice direction of a regular grid meets vertices),
    // rounding puts xc on either side of that end; the windows on both sides of the ray then
    // may both miss c, which, flat, is no source and has nothing else to set it. This path
    // is then straight to within rounding (elsewhere it bends at a point inside an edge, so a
    // shorter path replaces it). An end at a vertex of the edge is left to that vertex: it
    // relaxes c with the same length as a path through it (EmitFromVertex), the form a
    // saddle's shadow (ShadowFan) and the strip (Backtrack) need.
    const double end = xc < w.B0 ? w.B0 : w.B1;
    if (end > 0.0 && end < length)
    {
      const Vec2 e{ end, 0.0 };
      this->Relax(c, w.Sigma + Length(e - S) + Length(C - e), FromWindow, id, face);
    }
  }
  // One angle, one split (Xin-Wang), in the form that only needs c's current label: when c is
  // reached sooner by a path P whose last segment crosses this same edge into this triangle
  // (at x = cross), P cuts the triangle in two. A ray of this window reaching the part beyond
  // P would cross P at some y, and there P is strictly shorter (|S - c| <= |S - y| + |y - c|),
  // so that child holds no shortest path.
  bool blocked[2] = { false, false };
  if (this->Labels[c].Stamp == this->CurrentStamp && this->Labels[c].Kind == FromWindow &&
    this->Labels[c].Parent != id && this->Labels[c].Distance < throughC)
  {
    const Window& other = this->Windows[this->Labels[c].Parent];
    if (other.Edge == w.Edge && other.Face == face)
    {
      // Where that path crosses the edge: straight from its source, or around the nearer
      // end of its window (above).
      const double cross =
        std::min(other.B1, std::max(other.B0, CrossingOf(Vec2{ other.Sx, other.Sy }, C)));
      blocked[0] = w.B0 >= cross;
      blocked[1] = w.B1 <= cross;
    }
  }
  if (w.B0 <= 0.0)
  {
    this->Relax(ev[0], w.Sigma + Length(S), FromWindow, id, face);
  }
  if (w.B1 >= length)
  {
    this->Relax(ev[1], w.Sigma + Length(E1 - S), FromWindow, id, face);
  }

  // Children on the edges (vertex 0, c) and (vertex 1, c).
  for (int side = 0; side < 2; ++side)
  {
    if (blocked[side])
    {
      continue;
    }
    const Vec2 X = side == 0 ? E0 : E1;
    const int xv = ev[side];
    double u0, u1;
    if (side == 0)
    {
      if (!(xc > w.B0))
      {
        continue;
      }
      u0 = w.B0 <= 0.0 ? 0.0 : LineHit(S, Vec2{ w.B0, 0.0 }, X, C);
      u1 = w.B1 >= xc ? 1.0 : LineHit(S, Vec2{ w.B1, 0.0 }, X, C);
    }
    else
    {
      if (!(xc < w.B1))
      {
        continue;
      }
      u0 = w.B1 >= length ? 0.0 : LineHit(S, Vec2{ w.B1, 0.0 }, X, C);
      u1 = w.B0 <= xc ? 1.0 : LineHit(S, Vec2{ w.B0, 0.0 }, X, C);
    }
    u0 = std::min(1.0, std::max(0.0, u0));
    u1 = std::min(1.0, std::max(0.0, u1));
    if (!(u1 > u0))
    {
      continue;
    }
    // Local edge of `face` joining xv and c.
    int local = -1;
    for (int j = 0; j < 3; ++j)
    {
      const int a = tri[j], b = tri[(j + 1) % 3];
      if ((a == xv && b == c) || (a == c && b == xv))
      {
        local = j;
      }
    }
    const int next = mesh.GetNeighbor(face, local);
    if (next < 0)
    {
      continue;
    }
    const int edge = mesh.GetEdgeId(face, local);
    const std::array<int, 2> nv = mesh.GetEdgeVertices(edge);
    const Vec2 F0 = nv[0] == c ? C : X, F1 = nv[0] == c ? X : C;
    const Vec2 axis = F1 - F0;
    const double newLength = Length(axis);
    if (!(newLength > 0.0))
    {
      continue;
    }
    const Vec2 ex = (1.0 / newLength) * axis;
    Vec2 ey{ -ex.y, ex.x };
    const Vec2 other = side == 0 ? E1 : E0; // the third vertex of `face`: must get y < 0
    if (Dot(other - F0, ey) > 0.0)
    {
      ey = -1.0 * ey;
    }
    Window child;
    child.Edge = edge;
    child.Face = next;
    child.Origin = face;
    child.Parent = id;
    child.Kind = FromWindow;
    child.Sigma = w.Sigma;
    child.Sx = Dot(S - F0, ex);
    child.Sy = std::min(0.0, Dot(S - F0, ey));
    // u runs from X to C; the new edge parameter runs from F0 to F1.
    const double t0 = (nv[0] == c ? 1.0 - u1 : u0) * newLength;
    const double t1 = (nv[0] == c ? 1.0 - u0 : u1) * newLength;
    child.B0 = t0;
    child.B1 = t1;
    // The new edge joins xv and c: its positions and length are those of this triangle's
    // sides (Distance is symmetric bit for bit, so AddWindow would compute the same length).
    const Vec3& px = side == 0 ? p0 : p1;
    this->AddWindowOnEdge(
      child, nv, nv[0] == c ? pc : px, nv[0] == c ? px : pc, side == 0 ? l0 : l1);
  }
}

//------------------------------------------------------------------------------
// A window over all of `edge`, lighting `face`, from a source at `point` in the plane of
// `origin` (the triangle on the other side of the edge) reached at distance `sigma`.
ExactGeodesicSearch::Window ExactGeodesicSearch::WholeEdgeWindow(int edge,
  int face,
  int origin,
  const Vec3& point,
  double sigma,
  int kind,
  int parent) const
{
  const TriangleMesh& mesh = this->Mesh;
  const std::array<int, 2> ev = mesh.GetEdgeVertices(edge);
  const Vec3 p0 = mesh.GetPosition(ev[0]);
  const Vec3 axis = mesh.GetPosition(ev[1]) - p0;
  const double length = Length(axis);
  const Vec3 ex = (1.0 / length) * axis;
  const double x = Dot(point - p0, ex);
  Window w;
  w.Edge = edge;
  w.Face = face;
  w.Origin = origin;
  w.Parent = parent;
  w.Kind = kind;
  w.Sigma = sigma;
  w.Sx = x;
  w.Sy = -Length(point - p0 - x * ex);
  w.B0 = 0.0;
  w.B1 = length;
  return w;
}

//------------------------------------------------------------------------------
void ExactGeodesicSearch::EmitFromVertex(int v)
{
  const TriangleMesh& mesh = this->Mesh;
  const double d = this->Labels[v].Distance;
  const Vec3 pv = mesh.GetPosition(v);
  const bool source = this->PseudoSource->Is(v) || v == this->ForcedVertex ||
    (this->FieldMode && this->ForcedMark[v] == this->CurrentStamp);
  // A saddle reached along a known path restarts windows only into its shadow (ShadowFan).
  const bool shadowOnly = this->Pruning && source && !this->FieldMode && v != this->ForcedVertex &&
    this->ShadowFan(v, this->ShadowTriangles);
  for (int corner : mesh.GetVertexCorners(v))
  {
    const int t = corner / 3, k = corner % 3;
    if (this->Allowed && !this->Allowed(t))
    {
      continue;
    }
    const Triangle& tri = mesh.GetTriangle(t);
    for (int j = 1; j <= 2; ++j)
    {
      const int u = tri[(k + j) % 3];
      this->Relax(u, d + ::boolsurf::Distance(pv, mesh.GetPosition(u)), FromVertex, v, t);
    }
    if (source && !shadowOnly)
    {
      this->EmitAcrossOpposite(v, t, k, pv, d, 0.0, Pi);
    }
  }
  if (shadowOnly)
  {
    for (const ShadowCorner& corner : this->ShadowTriangles)
    {
      if (!this->Allowed || this->Allowed(corner.Corner / 3))
      {
        this->EmitAcrossOpposite(
          v, corner.Corner / 3, corner.Corner % 3, pv, d, corner.From, corner.To);
      }
    }
  }
}

//------------------------------------------------------------------------------
// A window from source vertex v (corner k of triangle t) over the side of t opposite v, or the
// part of it that the rays from v at angles [from, to] reach (measured in t from its side
// towards the corner after v; 0 and the corner's angle: the whole side).
void ExactGeodesicSearch::EmitAcrossOpposite(int v,
  int t,
  int k,
  const Vec3& pv,
  double d,
  double from,
  double to)
{
  const TriangleMesh& mesh = this->Mesh;
  const int local = (k + 1) % 3; // the edge opposite v
  const int next = mesh.GetNeighbor(t, local);
  if (next < 0)
  {
    return;
  }
  const int edge = mesh.GetEdgeId(t, local);
  Window w = this->WholeEdgeWindow(edge, next, t, pv, d, FromVertex, v);
  if (from > 0.0 || to < Pi)
  {
    // In t's plane, v at the origin, the side towards a = tri[k + 1] along x, b above.
    const Triangle& tri = mesh.GetTriangle(t);
    const Vec3 ea = mesh.GetPosition(tri[(k + 1) % 3]) - pv;
    const Vec3 eb = mesh.GetPosition(tri[(k + 2) % 3]) - pv;
    const double la = Length(ea);
    const Vec3 n = Cross(ea, eb);
    const double nl = Length(n);
    if (la > 0.0 && nl > 0.0)
    {
      const Vec2 a{ la, 0.0 };
      const Vec2 b{ Dot(eb, ea) / la, nl / la };
      // Fraction u along a -> b where the ray at angle phi meets the side.
      const auto hit = [&](double phi)
      {
        const Vec2 r{ std::cos(phi), std::sin(phi) };
        const double den = Cross(b - a, r);
        return den != 0.0 ? std::min(1.0, std::max(0.0, -Cross(a, r) / den)) : 0.0;
      };
      constexpr double Margin = 1e-9;
      const double u0 = std::max(0.0, hit(from) - Margin), u1 = std::min(1.0, hit(to) + Margin);
      // The window's parameter runs from the edge's canonical vertex 0.
      const bool fromA = mesh.GetEdgeVertices(edge)[0] == tri[(k + 1) % 3];
      w.B0 = (fromA ? u0 : 1.0 - u1) * w.B1;
      w.B1 = (fromA ? u1 : 1.0 - u0) * w.B1;
    }
  }
  this->AddWindow(w);
}

//------------------------------------------------------------------------------
// A shortest path bends at a saddle v only where it keeps at least pi of angle on both sides:
// measured around v from the direction back along the path that reached it, a path leaving at
// angle a is shortened inside the fan unless pi <= a <= (angle sum) - pi (Chen-Han). On a
// noisy scan that shadow is a few hundredths of a radian wide, so instead of a window over
// every side opposite v, only the triangles of v's fan that meet it get one. False (restart
// everywhere) when v's triangles do not close into one fan or the way back is unknown; else
// `corners` lists those triangles' corners at v.
bool ExactGeodesicSearch::ShadowFan(int v, std::vector<ShadowCorner>& corners) const
{
  const TriangleMesh& mesh = this->Mesh;
  corners.clear();
  const int t0 = this->Labels[v].Arrival;
  if (t0 < 0)
  {
    return false;
  }
  const int k0 = CornerOf(mesh.GetTriangle(t0), v);
  double back = 0.0;
  if (k0 < 0 || !this->BackAngle(v, t0, k0, back))
  {
    return false;
  }
  // The fan counter-clockwise from t0 (the triangles' own orientation), with each corner's
  // angle at v.
  thread_local std::vector<std::pair<int, double>> fan;
  fan.clear();
  const int limit = static_cast<int>(mesh.GetVertexCorners(v).size());
  double total = 0.0;
  int t = t0, k = k0;
  for (;;)
  {
    const double angle = CornerAngle(mesh, mesh.GetTriangle(t), k);
    fan.push_back({ 3 * t + k, angle });
    total += angle;
    const int next = mesh.GetNeighbor(t, (k + 2) % 3); // across the side (v, tri[k + 2])
    if (next < 0 || static_cast<int>(fan.size()) > limit)
    {
      return false;
    }
    if (next == t0)
    {
      break;
    }
    k = CornerOf(mesh.GetTriangle(next), v);
    if (k < 0)
    {
      return false;
    }
    t = next;
  }
  if (static_cast<int>(fan.size()) != limit)
  {
    return false; // more than one fan
  }
  // The way back crosses t0 (a window through the side opposite v, a start inside t0, a
  // parent vertex of t0): its angle lies within t0's corner.
  constexpr double Margin = 1e-7;
  if (back < -Margin || back > fan.front().second + Margin)
  {
    return false;
  }
  // Directions at angles [pi, total - pi] from the way back, widened by a margin for rounding
  // (a wider shadow only costs windows).
  const double from = Pi - Margin, to = total - Pi + Margin;
  double start = -back;
  for (const auto& [corner, angle] : fan)
  {
    if (start <= to && start + angle >= from)
    {
      corners.push_back({ corner, std::max(0.0, from - start), std::min(angle, to - start) });
    }
    start += angle;
  }
  return true;
}

//------------------------------------------------------------------------------
// The direction from v back along the path that set its distance, as an angle at v
// counter-clockwise (in the orientation of triangle t0, v's arrival triangle and its corner k0)
// from the side towards the corner after v. The path reached v inside t0 or through one of
// its sides, so the angle is that of the unfolded plane of t0 and its neighbours.
bool ExactGeodesicSearch::BackAngle(int v, int t0, int k0, double& angle) const
{
  const TriangleMesh& mesh = this->Mesh;
  const Triangle& tri = mesh.GetTriangle(t0);
  const int kind = this->Labels[v].Kind;
  if (kind == FromWindow)
  {
    // In the window's frame: its edge from (0, 0) to (L, 0), t0 above, the source below.
    const Window& w = this->Windows[this->Labels[v].Parent];
    if (w.Face != t0)
    {
      return false;
    }
    const std::array<int, 2> ev = mesh.GetEdgeVertices(w.Edge);
    const int i0 = CornerOf(tri, ev[0]);
    if (i0 < 0)
    {
      return false;
    }
    const bool forward = tri[(i0 + 1) % 3] == ev[1];
    if (v != (forward ? tri[(i0 + 2) % 3] : tri[(i0 + 1) % 3]))
    {
      // An end of the window's edge, reached by the window's end ray: that ray may graze the
      // vertex from another triangle of its fan, whose angle this frame does not give.
      return false;
    }
    const Vec3 p0 = mesh.GetPosition(ev[0]), p1 = mesh.GetPosition(ev[1]);
    const Vec3 pc = mesh.GetPosition(v);
    const double length = ::boolsurf::Distance(p0, p1);
    const Vec2 C =
      OppositeCorner(length, ::boolsurf::Distance(p0, pc), ::boolsurf::Distance(p1, pc));
    const Vec2 next = tri[(k0 + 1) % 3] == ev[0] ? Vec2{ 0.0, 0.0 } : Vec2{ length, 0.0 };
    const Vec2 a = next - C, s = Vec2{ w.Sx, w.Sy } - C;
    // (0,0), (L,0), C run counter-clockwise in the frame: t0's own order when forward.
    angle = (forward ? 1.0 : -1.0) * std::atan2(Cross(a, s), Dot(a, s));
    return true;
  }
  Vec3 from;
  if (kind == FromVertex)
  {
    from = mesh.GetPosition(this->Labels[v].Parent);
  }
  else if (kind == FromSource && this->HasStartPoint)
  {
    from = this->StartPoint;
  }
  else
  {
    return false;
  }
  const Vec3 pv = mesh.GetPosition(v);
  const Vec3 e1 = mesh.GetPosition(tri[(k0 + 1) % 3]) - pv;
  const Vec3 n = Cross(e1, mesh.GetPosition(tri[(k0 + 2) % 3]) - pv);
  const double nl = Length(n);
  if (!(nl > 0.0))
  {
    return false;
  }
  const Vec3 back = from - pv;
  // atan2 of the components along e1 and along n x e1 (|n x e1| = |n| |e1|).
  angle = std::atan2(Dot(back, Cross(n, e1)) / nl, Dot(back, e1));
  return true;
}

//------------------------------------------------------------------------------
// The start's triangle corners get their straight distances and each edge of a start triangle
// (but the one the start lies on) a window lighting the triangle beyond; a vertex start is a
// source vertex instead.
void ExactGeodesicSearch::SeedFromPoint(const CanonicalPoint& start,
  const std::vector<int>& startTriangles)
{
  const TriangleMesh& mesh = this->Mesh;
  if (start.Location == PointLocation::Vertex)
  {
    if (this->FieldMode)
    {
      this->ForcedMark[start.Id] = this->CurrentStamp;
    }
    else
    {
      this->ForcedVertex = start.Id;
    }
    this->Relax(start.Id, 0.0, FromSource, -1, startTriangles.front());
    return;
  }
  const Vec3 source = PositionOf(mesh, start);
  this->StartPoint = source;
  this->HasStartPoint = true;
  for (int t : startTriangles)
  {
    const Triangle& tri = mesh.GetTriangle(t);
    const std::array<double, 3> weights = WeightsInTriangle(mesh, start, t);
    for (int k = 0; k < 3; ++k)
    {
      this->Relax(
        tri[k], ::boolsurf::Distance(source, mesh.GetPosition(tri[k])), FromSource, -1, t);
    }
    for (int k = 0; k < 3; ++k)
    {
      const int next = mesh.GetNeighbor(t, k);
      if (next < 0 || weights[(k + 2) % 3] <= 0.0)
      {
        continue; // boundary, or the start lies on this edge
      }
      this->AddWindow(
        this->WholeEdgeWindow(mesh.GetEdgeId(t, k), next, t, source, 0.0, FromSource, t));
    }
  }
}

//------------------------------------------------------------------------------
// Pops events until the heap is empty or the next one cannot beat Best. False when the window
// budget ran out.
bool ExactGeodesicSearch::Run(const std::vector<int>& endTriangles)
{
  const TriangleMesh& mesh = this->Mesh;
  while (!this->Heap.empty())
  {
    std::pop_heap(this->Heap.begin(), this->Heap.end());
    const Event e = this->Heap.back();
    this->Heap.pop_back();
    if (e.Key >= this->Best || (this->StoppedAtWall && e.Key > this->WallKey))
    {
      break;
    }
    if (e.Id >= 0)
    {
      if (e.D >= this->Best)
      {
        continue;
      }
      if (this->PieceExact && !this->PieceWindow(e))
      {
        continue;
      }
      this->Propagate(e.Id);
      if (static_cast<int>(this->Windows.size()) > this->MaximumWindows)
      {
        this->BudgetExceeded = true;
        return false;
      }
      continue;
    }
    const int v = -e.Id - 1;
    if (e.D != this->Labels[v].Distance)
    {
      continue; // stale
    }
    ++this->LastVertexCount;
    for (int t : endTriangles)
    {
      if (CornerOf(mesh.GetTriangle(t), v) >= 0)
      {
        this->OfferTarget(
          e.D + ::boolsurf::Distance(mesh.GetPosition(v), this->Target), FromVertex, v);
        break;
      }
    }
    this->EmitFromVertex(v);
  }
  return true;
}

//------------------------------------------------------------------------------
// On a part of a surface: records the window's triangles; false (a wall, not propagated) when
// its lit triangle's neighbourhood is not the surface's.
bool ExactGeodesicSearch::PieceWindow(const Event& e)
{
  const Window& w = this->Windows[e.Id];
  this->PieceRead.push_back(w.Face);
  this->PieceRead.push_back(w.Origin);
  if (this->PieceExact(w.Face))
  {
    return true;
  }
  if (!this->StoppedAtWall)
  {
    this->StoppedAtWall = true;
    this->WallKey = e.Key + this->WallSlack;
  }
  return false;
}

//------------------------------------------------------------------------------
double ExactGeodesicSearch::FindStrip(const CanonicalPoint& start,
  const std::vector<int>& startTriangles,
  const CanonicalPoint& end,
  const std::vector<int>& endTriangles,
  std::vector<int>& strip)
{
  const TriangleMesh& mesh = this->Mesh;
  this->Prepare();
  this->ResetMarks();
  this->FieldMode = false;
  this->Windows.clear();
  this->Heap.clear();
  this->Target = PositionOf(mesh, end);
  this->End = end;
  this->Best = this->UpperBound > 0.0 ? this->UpperBound : Infinity;
  this->OrderByBound = !(this->UpperBound > 0.0);
  this->UpperBound = 0.0;
  this->BestKind = this->BestId = -1;
  this->ForcedVertex = -1;
  this->HasStartPoint = false;
  this->LastVertexCount = 0;
  this->BudgetExceeded = false;
  this->StoppedAtWall = false;
  this->PieceRead.clear();
  strip.clear();
  for (int t : endTriangles)
  {
    this->EndMark[t] = this->CurrentStamp;
  }
  this->SeedFromPoint(start, startTriangles);
  if (!this->Run(endTriangles) || this->StoppedAtWall)
  {
    return -1.0;
  }
  if (this->BestKind < 0 || !this->Backtrack(strip))
  {
    return -1.0;
  }
  return this->Best;
}

//------------------------------------------------------------------------------
void ExactGeodesicSearch::AppendLitTriangles(std::vector<int>& out) const
{
  if (this->PieceExact)
  {
    out.insert(out.end(), this->PieceRead.begin(), this->PieceRead.end());
    return;
  }
  for (const Window& w : this->Windows)
  {
    out.push_back(w.Face);
    out.push_back(w.Origin);
  }
}

//------------------------------------------------------------------------------
// Triangles around v from `from` (excluded) to `to` (included), the shorter way round.
bool ExactGeodesicSearch::FanWalk(int v, int from, int to, std::vector<int>& out) const
{
  if (from == to)
  {
    return true;
  }
  const TriangleMesh& mesh = this->Mesh;
  const Triangle& tri = mesh.GetTriangle(from);
  const int kv = CornerOf(tri, v);
  if (kv < 0)
  {
    return false;
  }
  const int limit = mesh.GetVertexCorners(v).size();
  thread_local std::vector<int> ways[2];
  int bestWay = -1;
  for (int way = 0; way < 2; ++way)
  {
    ways[way].clear();
    int t = from, edge = way == 0 ? kv : (kv + 2) % 3;
    bool reached = false;
    for (int steps = 0; steps <= limit; ++steps)
    {
      const int next = mesh.GetNeighbor(t, edge);
      if (next < 0)
      {
        break;
      }
      const int entry = mesh.GetNeighborEdge(t, edge);
      const int kn = CornerOf(mesh.GetTriangle(next), v);
      if (kn < 0)
      {
        break;
      }
      ways[way].push_back(next);
      if (next == to)
      {
        reached = true;
        break;
      }
      edge = entry == kn ? (kn + 2) % 3 : kn;
      t = next;
    }
    if (reached && (bestWay < 0 || ways[way].size() < ways[bestWay].size()))
    {
      bestWay = way;
    }
  }
  if (bestWay < 0)
  {
    return false;
  }
  out.insert(out.end(), ways[bestWay].begin(), ways[bestWay].end());
  return true;
}

//------------------------------------------------------------------------------
// Walks the parents back from the end to the start, collecting the triangles crossed (in
// reverse), then reverses them.
bool ExactGeodesicSearch::Backtrack(std::vector<int>& strip)
{
  const TriangleMesh& mesh = this->Mesh;
  std::vector<int>& r = strip;
  r.clear();
  int vertex = -1, next = -1; // vertex state: at `vertex`, the strip continues in `next`
  int window = -1;
  if (this->BestKind == FromWindow)
  {
    window = this->BestId;
  }
  else
  {
    vertex = this->BestId;
    for (int corner : mesh.GetVertexCorners(vertex))
    {
      if (this->EndMark[corner / 3] == this->CurrentStamp)
      {
        next = corner / 3;
        break;
      }
    }
    if (next < 0)
    {
      return false;
    }
    r.push_back(next);
  }
  const size_t guard = 4 * this->Windows.size() + 4 * mesh.GetNumberOfVertices() + 16;
  while (r.size() < guard)
  {
    if (window >= 0)
    {
      const Window& w = this->Windows[window];
      if (r.empty() || r.back() != w.Face)
      {
        r.push_back(w.Face);
      }
      if (w.Kind == FromWindow)
      {
        window = w.Parent;
        continue;
      }
      r.push_back(w.Origin);
      if (w.Kind == FromSource)
      {
        break;
      }
      vertex = w.Parent;
      next = w.Origin;
      window = -1;
      continue;
    }
    // Vertex state.
    const int arrival = this->Labels[vertex].Arrival;
    if (!this->FanWalk(vertex, next, arrival, r))
    {
      return false;
    }
    const int kind = this->Labels[vertex].Kind;
    if (kind == FromSource)
    {
      break;
    }
    if (kind == FromWindow)
    {
      window = this->Labels[vertex].Parent; // its Face is `arrival`, already in r
      continue;
    }
    next = arrival;
    vertex = this->Labels[vertex].Parent;
  }
  std::reverse(r.begin(), r.end());
  return true;
}

} // namespace boolsurf

#include "Homology/HomologyBasis.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <queue>
#include <unordered_map>

namespace boolsurf
{
namespace
{

Vec3 Centroid(const TriangleMesh& mesh, int t)
{
  const Vec3& a = mesh.GetCornerPosition(t, 0);
  const Vec3& b = mesh.GetCornerPosition(t, 1);
  const Vec3& c = mesh.GetCornerPosition(t, 2);
  return (1.0 / 3.0) * (a + b + c);
}

// The two triangles of interior edge e: the one on the left of its canonical direction first.
std::array<int, 2> EdgeSides(const TriangleMesh& mesh, int e)
{
  const int h = mesh.GetEdgeHalfEdge(e);
  const int twin = mesh.GetTwin(h);
  return { h / 3, twin < 0 ? -1 : twin / 3 };
}

struct UnionFind
{
  std::vector<int> Parent;
  explicit UnionFind(int n)
    : Parent(n)
  {
    std::iota(this->Parent.begin(), this->Parent.end(), 0);
  }
  int Find(int a)
  {
    while (this->Parent[a] != a)
    {
      a = this->Parent[a] = this->Parent[this->Parent[a]];
    }
    return a;
  }
  bool Join(int a, int b)
  {
    a = this->Find(a);
    b = this->Find(b);
    if (a == b)
    {
      return false;
    }
    this->Parent[a] = b;
    return true;
  }
};

// Position of an edge point on the boundary of triangle t, counter-clockwise in [0, 3):
// local edge k covers (k, k+1) from corner k to corner k+1.
double BoundaryCoordinate(const TriangleMesh& mesh, int t, int edge, double param)
{
  for (int k = 0; k < 3; ++k)
  {
    if (mesh.GetEdgeId(t, k) == edge)
    {
      const bool along = mesh.GetEdgeHalfEdge(edge) == 3 * t + k;
      return k + (along ? param : 1.0 - param);
    }
  }
  return -1.0;
}

// True when r lies strictly inside the counter-clockwise boundary arc from p to q.
bool InArc(double p, double q, double r)
{
  auto wrap = [](double d) { return d < 0 ? d + 3.0 : d; };
  return wrap(r - p) < wrap(q - p);
}

//------------------------------------------------------------------------------
// Every component must be orientable: a non-orientable one has no winding numbers.
bool CheckOrientable(const MeshTopology& topology, std::string& error)
{
  const int nc = topology.GetNumberOfComponents();
  for (int c = 0; c < nc; ++c)
  {
    if (!topology.Components[c].Orientable)
    {
      error = "surface component " + std::to_string(c) +
        " is not orientable: it has no homology generators for winding numbers";
      return false;
    }
  }

  return true;
}

//------------------------------------------------------------------------------
// Base triangle per component: the one given in the options, else its first triangle.
bool ChooseBaseTriangles(const TriangleMesh& mesh,
  const MeshTopology& topology,
  const HomologyOptions& options,
  std::vector<int>& baseTriangles,
  std::string& error)
{
  const int nt = mesh.GetNumberOfTriangles();
  const int nc = topology.GetNumberOfComponents();
  baseTriangles.assign(nc, -1);
  for (int c = 0; c < nc && c < static_cast<int>(options.BaseTriangles.size()); ++c)
  {
    const int b = options.BaseTriangles[c];
    if (b < 0)
    {
      continue;
    }
    if (b >= nt || topology.TriangleComponent[b] != c)
    {
      error = "base triangle " + std::to_string(b) + " given for surface component " +
        std::to_string(c) +
        (b >= nt ? " is out of range (" + std::to_string(nt) + " triangles)"
                 : " is not in that component");
      return false;
    }
    baseTriangles[c] = b;
  }
  for (int t = 0; t < nt; ++t)
  {
    const int c = topology.TriangleComponent[t];
    if (c >= 0 && baseTriangles[c] < 0)
    {
      baseTriangles[c] = t;
    }
  }

  return true;
}

//------------------------------------------------------------------------------
// C: shortest-path tree of the dual graph from the base triangles (centroid distances).
struct DualTree
{
  std::vector<Vec3> Centroid;
  std::vector<double> Distance;
  std::vector<int> ParentTriangle;
  std::vector<int>& ParentEdge; ///< per triangle: edge crossed towards the root, -1 at roots
  std::vector<int>& Depth;
};

void BuildDualTree(const TriangleMesh& mesh, const std::vector<int>& baseTriangles, DualTree& tree)
{
  const int nt = mesh.GetNumberOfTriangles();
  std::vector<Vec3>& centroid = tree.Centroid;
  centroid.resize(nt);
  for (int t = 0; t < nt; ++t)
  {
    if (mesh.IsUsable(t))
    {
      centroid[t] = Centroid(mesh, t);
    }
  }
  std::vector<double>& dist = tree.Distance;
  dist.assign(nt, HUGE_VAL);
  tree.ParentEdge.assign(nt, -1);
  std::vector<int>& parentTriangle = tree.ParentTriangle;
  parentTriangle.assign(nt, -1);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (int b : baseTriangles)
  {
    if (b >= 0)
    {
      dist[b] = 0;
      queue.push({ 0.0, b });
    }
  }
  while (!queue.empty())
  {
    const auto [d, t] = queue.top();
    queue.pop();
    if (d > dist[t])
    {
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      const int n = mesh.GetNeighbor(t, k);
      if (n < 0)
      {
        continue;
      }
      const double dn = d + Distance(centroid[t], centroid[n]);
      if (dn < dist[n])
      {
        dist[n] = dn;
        tree.ParentEdge[n] = mesh.GetEdgeId(t, k);
        parentTriangle[n] = t;
        queue.push({ dn, n });
      }
    }
  }
  tree.Depth.assign(nt, 0);
  {
    std::vector<int> order(nt);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return dist[a] < dist[b]; });
    for (int t : order)
    {
      if (parentTriangle[t] >= 0)
      {
        tree.Depth[t] = tree.Depth[parentTriangle[t]] + 1;
      }
    }
  }
}

//------------------------------------------------------------------------------
// T: spanning tree of the primal graph on the edges C does not cross (inT); boundary edges
// first, then the others by decreasing length of the dual loop they close (greedy system of
// loops). Returns the edges in neither tree, by component then id: one generator each.
std::vector<int> CutEdgesOfTheTrees(const TriangleMesh& mesh,
  const MeshTopology& topology,
  const DualTree& tree,
  std::vector<char>& inT)
{
  const int nt = mesh.GetNumberOfTriangles();
  const int ne = mesh.GetNumberOfEdges();
  const int nv = mesh.GetNumberOfVertices();
  std::vector<char> inC(ne, 0);
  for (int t = 0; t < nt; ++t)
  {
    if (tree.ParentEdge[t] >= 0)
    {
      inC[tree.ParentEdge[t]] = 1;
    }
  }
  // Each boundary loop is a virtual face, a leaf of C hanging on its first edge.
  for (const BoundaryLoop& loop : topology.BoundaryLoops)
  {
    if (!loop.HalfEdges.empty())
    {
      const int h = loop.HalfEdges[0];
      inC[mesh.GetEdgeId(h / 3, h % 3)] = 1;
    }
  }

  UnionFind forest(nv);
  inT.assign(ne, 0);
  std::vector<int> interior;
  for (int e = 0; e < ne; ++e)
  {
    if (inC[e] || mesh.GetEdgeValence(e) > 2)
    {
      continue;
    }
    const auto ends = mesh.GetEdgeVertices(e);
    if (mesh.IsBoundaryEdge(e))
    {
      inT[e] = forest.Join(ends[0], ends[1]) ? 1 : 0;
    }
    else
    {
      interior.push_back(e);
    }
  }
  std::vector<double> loopLength(ne, 0);
  for (int e : interior)
  {
    const auto sides = EdgeSides(mesh, e);
    loopLength[e] = tree.Distance[sides[0]] + tree.Distance[sides[1]] +
      Distance(tree.Centroid[sides[0]], tree.Centroid[sides[1]]);
  }
  std::stable_sort(
    interior.begin(), interior.end(), [&](int a, int b) { return loopLength[a] > loopLength[b]; });
  std::vector<int> leftover;
  for (int e : interior)
  {
    const auto ends = mesh.GetEdgeVertices(e);
    if (forest.Join(ends[0], ends[1]))
    {
      inT[e] = 1;
    }
    else
    {
      leftover.push_back(e);
    }
  }
  std::sort(leftover.begin(),
    leftover.end(),
    [&](int a, int b)
    {
      const int ca = topology.TriangleComponent[EdgeSides(mesh, a)[0]];
      const int cb = topology.TriangleComponent[EdgeSides(mesh, b)[0]];
      return ca != cb ? ca < cb : a < b;
    });

  return leftover;
}

//------------------------------------------------------------------------------
// Generator count per component must be 2g (else the mesh is not a manifold surface).
bool CheckGeneratorCounts(const TriangleMesh& mesh,
  const MeshTopology& topology,
  const std::vector<int>& leftover,
  std::vector<int>& perComponent,
  std::string& error)
{
  const int nc = topology.GetNumberOfComponents();
  perComponent.assign(nc, 0);
  for (int e : leftover)
  {
    ++perComponent[topology.TriangleComponent[EdgeSides(mesh, e)[0]]];
  }
  for (int c = 0; c < nc; ++c)
  {
    if (perComponent[c] != 2 * topology.Components[c].Genus)
    {
      error = "surface component " + std::to_string(c) + " of genus " +
        std::to_string(topology.Components[c].Genus) + " gave " + std::to_string(perComponent[c]) +
        " homology generators instead of " + std::to_string(2 * topology.Components[c].Genus) +
        " (non-manifold edges or vertices?)";
      return false;
    }
  }

  return true;
}

//------------------------------------------------------------------------------
// Generators: from the left side of x along C to the right side, then across x.
void BuildGenerators(const TriangleMesh& mesh,
  const MeshTopology& topology,
  const DualTree& tree,
  const std::vector<int>& leftover,
  const std::vector<int>& perComponent,
  std::vector<HomologyGenerator>& generators)
{
  const int nc = topology.GetNumberOfComponents();
  std::vector<int> indexInComponent(nc, 0);
  for (int x : leftover)
  {
    const auto sides = EdgeSides(mesh, x);
    HomologyGenerator g;
    g.CutEdge = x;
    g.Component = topology.TriangleComponent[sides[0]];
    std::vector<int> up0{ sides[0] }, up1{ sides[1] }, edges0, edges1;
    int a = sides[0], b = sides[1];
    while (a != b)
    {
      if (tree.Depth[a] >= tree.Depth[b])
      {
        edges0.push_back(tree.ParentEdge[a]);
        a = tree.ParentTriangle[a];
        up0.push_back(a);
      }
      else
      {
        edges1.push_back(tree.ParentEdge[b]);
        b = tree.ParentTriangle[b];
        up1.push_back(b);
      }
    }
    g.Triangles = up0; // left side ... common ancestor
    g.Triangles.insert(g.Triangles.end(), up1.rbegin() + 1, up1.rend());
    g.Edges = edges0;
    g.Edges.insert(g.Edges.end(), edges1.rbegin(), edges1.rend());
    g.Edges.push_back(x);
    const int index = indexInComponent[g.Component]++;
    g.CrossingParameter = (index + 1.0) / (perComponent[g.Component] + 1.0);
    for (int e : g.Edges)
    {
      CanonicalPoint p;
      p.Location = PointLocation::Edge;
      p.Id = e;
      p.T = g.CrossingParameter;
      g.Points.push_back(p);
    }
    generators.push_back(std::move(g));
  }
}

//------------------------------------------------------------------------------
// Dual basis: primal loop l_x = x (canonical direction), then T from its end back to its
// start through the root; stored per edge as (generator, coefficient).
void BuildDualBasis(const TriangleMesh& mesh,
  const std::vector<char>& inT,
  const std::vector<HomologyGenerator>& generators,
  std::vector<int>& cochainOffset,
  std::vector<std::pair<int, int>>& cochainEntries)
{
  const int ne = mesh.GetNumberOfEdges();
  const int nv = mesh.GetNumberOfVertices();
  std::vector<std::vector<std::pair<int, int>>> adjacency(nv); // (neighbour, edge)
  for (int e = 0; e < ne; ++e)
  {
    if (inT[e])
    {
      const auto ends = mesh.GetEdgeVertices(e);
      adjacency[ends[0]].push_back({ ends[1], e });
      adjacency[ends[1]].push_back({ ends[0], e });
    }
  }
  std::vector<int> vertexParent(nv, -1), vertexParentEdge(nv, -1);
  std::vector<char> seen(nv, 0);
  for (int v0 = 0; v0 < nv; ++v0)
  {
    if (seen[v0] || adjacency[v0].empty())
    {
      continue;
    }
    seen[v0] = 1;
    std::vector<int> stack{ v0 };
    while (!stack.empty())
    {
      const int v = stack.back();
      stack.pop_back();
      for (const auto& [w, e] : adjacency[v])
      {
        if (!seen[w])
        {
          seen[w] = 1;
          vertexParent[w] = v;
          vertexParentEdge[w] = e;
          stack.push_back(w);
        }
      }
    }
  }
  std::vector<std::vector<std::pair<int, int>>> perEdge(ne);
  for (int gi = 0; gi < static_cast<int>(generators.size()); ++gi)
  {
    const int x = generators[gi].CutEdge;
    std::unordered_map<int, int> chain;
    chain[x] += 1;
    const auto ends = mesh.GetEdgeVertices(x);
    // ends[1] -> root: +direction of each step; ends[0] -> root: walked backwards.
    for (int side = 1; side >= 0; --side)
    {
      const int sign = side == 1 ? 1 : -1;
      for (int v = ends[side]; vertexParent[v] >= 0; v = vertexParent[v])
      {
        const int e = vertexParentEdge[v];
        const int along = mesh.GetEdgeVertices(e)[0] == v ? 1 : -1;
        chain[e] += sign * along;
      }
    }
    for (const auto& [e, coef] : chain)
    {
      if (coef != 0)
      {
        perEdge[e].push_back({ gi, coef });
      }
    }
  }
  cochainOffset.assign(ne + 1, 0);
  for (int e = 0; e < ne; ++e)
  {
    cochainOffset[e + 1] = cochainOffset[e] + static_cast<int>(perEdge[e].size());
    cochainEntries.insert(cochainEntries.end(), perEdge[e].begin(), perEdge[e].end());
  }
}

} // namespace

//------------------------------------------------------------------------------
bool HomologyBasis::Compute(const TriangleMesh& mesh,
  const MeshTopology& topology,
  const HomologyOptions& options,
  std::string& error)
{
  *this = HomologyBasis();
  this->Mesh = &mesh;
  this->MeshSerial = mesh.GetSerial();
  if (!CheckOrientable(topology, error) ||
    !ChooseBaseTriangles(mesh, topology, options, this->BaseTriangles, error))
  {
    return false;
  }
  DualTree tree{ {}, {}, {}, this->DualParentEdge, this->DualDepth };
  BuildDualTree(mesh, this->BaseTriangles, tree);
  std::vector<char> inT;
  const std::vector<int> leftover = CutEdgesOfTheTrees(mesh, topology, tree, inT);
  std::vector<int> perComponent;
  if (!CheckGeneratorCounts(mesh, topology, leftover, perComponent, error))
  {
    return false;
  }
  BuildGenerators(mesh, topology, tree, leftover, perComponent, this->Generators);
  BuildDualBasis(mesh, inT, this->Generators, this->CochainOffset, this->CochainEntries);
  return true;
}

//------------------------------------------------------------------------------
void HomologyBasis::AddCrossing(int edge, int enteredTriangle, std::vector<int>& homology) const
{
  const int sign = this->Mesh->GetEdgeHalfEdge(edge) / 3 == enteredTriangle ? 1 : -1;
  for (int i = this->CochainOffset[edge]; i < this->CochainOffset[edge + 1]; ++i)
  {
    homology[this->CochainEntries[i].first] += sign * this->CochainEntries[i].second;
  }
}

//------------------------------------------------------------------------------
bool HomologyBasis::AroundVertex(int vertex,
  int from,
  int to,
  std::vector<int>& edges,
  std::vector<int>& entered) const
{
  const TriangleMesh& mesh = *this->Mesh;
  const int limit = mesh.GetVertexCorners(vertex).size() + 2;
  auto corner = [&](int t)
  {
    for (int k = 0; k < 3; ++k)
    {
      if (mesh.GetTriangle(t)[k] == vertex)
      {
        return k;
      }
    }
    return -1;
  };
  for (int direction = 0; direction < 2; ++direction)
  {
    edges.clear();
    entered.clear();
    int t = from;
    int k = corner(t);
    if (k < 0)
    {
      return false;
    }
    int exit = direction == 0 ? k : (k + 2) % 3; // local edge at the vertex to cross
    for (int step = 0; step < limit; ++step)
    {
      const int n = mesh.GetNeighbor(t, exit);
      if (n < 0)
      {
        break;
      }
      edges.push_back(mesh.GetEdgeId(t, exit));
      entered.push_back(n);
      if (n == to)
      {
        return true;
      }
      const int came = mesh.GetNeighborEdge(t, exit);
      const int kn = corner(n);
      exit = came == kn ? (kn + 2) % 3 : kn;
      t = n;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
bool HomologyBasis::ClassOf(const TracedCurve& curve,
  std::vector<int>& homology,
  std::string& error) const
{
  homology.assign(this->Generators.size(), 0);
  const int n = static_cast<int>(curve.Points.size());
  if (!curve.Closed || n < 2 || this->Generators.empty())
  {
    return true;
  }
  const TriangleMesh& mesh = *this->Mesh;
  std::vector<int> segmentTriangle(n);
  for (int i = 0; i < n; ++i)
  {
    segmentTriangle[i] = SharedTriangle(mesh, curve.Points[i], curve.Points[(i + 1) % n]);
    if (segmentTriangle[i] < 0)
    {
      error = "curve " + std::to_string(curve.CurveId) + ": points " + std::to_string(i) + " and " +
        std::to_string((i + 1) % n) + " share no triangle";
      return false;
    }
  }
  std::vector<int> edges, entered;
  for (int i = 0; i < n; ++i)
  {
    const int from = segmentTriangle[(i + n - 1) % n];
    const int to = segmentTriangle[i];
    if (from == to)
    {
      continue;
    }
    const CanonicalPoint& p = curve.Points[i];
    if (p.Location == PointLocation::Edge)
    {
      this->AddCrossing(p.Id, to, homology);
    }
    else if (p.Location == PointLocation::Vertex &&
      this->AroundVertex(p.Id, from, to, edges, entered))
    {
      for (size_t j = 0; j < edges.size(); ++j)
      {
        this->AddCrossing(edges[j], entered[j], homology);
      }
    }
    else
    {
      error = "curve " + std::to_string(curve.CurveId) + ": cannot walk around point " +
        std::to_string(i) + " (" + Describe(p) + ") from triangle " + std::to_string(from) +
        " to triangle " + std::to_string(to);
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void HomologyBasis::ClassOfWalk(const std::vector<int>& crossedEdges,
  const std::vector<int>& enteredTriangles,
  std::vector<int>& homology) const
{
  homology.assign(this->Generators.size(), 0);
  for (size_t i = 0; i < crossedEdges.size(); ++i)
  {
    this->AddCrossing(crossedEdges[i], enteredTriangles[i], homology);
  }
}

//------------------------------------------------------------------------------
int HomologyBasis::Intersection(int a, int b) const
{
  if (a == b)
  {
    return 0;
  }
  const TriangleMesh& mesh = *this->Mesh;
  const HomologyGenerator& ga = this->Generators[a];
  const HomologyGenerator& gb = this->Generators[b];
  if (ga.Component != gb.Component)
  {
    return 0;
  }
  // Chord of generator g in its i-th triangle: entered across Edges[i-1], left across Edges[i].
  std::unordered_map<int, int> chordOfB;
  for (size_t i = 0; i < gb.Triangles.size(); ++i)
  {
    chordOfB[gb.Triangles[i]] = static_cast<int>(i);
  }
  int sum = 0;
  const size_t na = ga.Triangles.size(), nb = gb.Triangles.size();
  for (size_t i = 0; i < na; ++i)
  {
    const int t = ga.Triangles[i];
    const auto it = chordOfB.find(t);
    if (it == chordOfB.end())
    {
      continue;
    }
    const size_t j = static_cast<size_t>(it->second);
    const double p = BoundaryCoordinate(mesh, t, ga.Edges[(i + na - 1) % na], ga.CrossingParameter);
    const double q = BoundaryCoordinate(mesh, t, ga.Edges[i], ga.CrossingParameter);
    const double r = BoundaryCoordinate(mesh, t, gb.Edges[(j + nb - 1) % nb], gb.CrossingParameter);
    const double s = BoundaryCoordinate(mesh, t, gb.Edges[j], gb.CrossingParameter);
    const bool rRight = InArc(p, q, r), sRight = InArc(p, q, s);
    if (rRight != sRight)
    {
      sum += rRight ? 1 : -1; // b goes from the right of a to its left: +1
    }
  }
  return sum;
}

//------------------------------------------------------------------------------
std::vector<int> HomologyBasis::CutGraphEdges() const
{
  std::vector<char> in(this->Mesh ? this->Mesh->GetNumberOfEdges() : 0, 0);
  std::vector<int> out;
  auto add = [&](int e)
  {
    if (!in[e])
    {
      in[e] = 1;
      out.push_back(e);
    }
  };
  for (const HomologyGenerator& g : this->Generators)
  {
    add(g.CutEdge);
    for (int t : EdgeSides(*this->Mesh, g.CutEdge))
    {
      for (; this->DualParentEdge[t] >= 0;)
      {
        const int e = this->DualParentEdge[t];
        add(e);
        const auto sides = EdgeSides(*this->Mesh, e);
        t = sides[0] == t ? sides[1] : sides[0];
      }
    }
  }
  return out;
}

//------------------------------------------------------------------------------
std::vector<std::vector<int>> HomologyExcess(const std::vector<TracedCurve>& curves,
  const std::vector<std::vector<int>>& curveHomology,
  const std::vector<int>& shapeIds,
  int numberOfGenerators)
{
  std::vector<std::vector<int>> excess(shapeIds.size(), std::vector<int>(numberOfGenerators, 0));
  for (size_t c = 0; c < curves.size() && c < curveHomology.size(); ++c)
  {
    const auto it = std::lower_bound(shapeIds.begin(), shapeIds.end(), curves[c].ShapeId);
    if (it == shapeIds.end() || *it != curves[c].ShapeId)
    {
      continue;
    }
    std::vector<int>& sum = excess[it - shapeIds.begin()];
    for (int g = 0; g < numberOfGenerators && g < static_cast<int>(curveHomology[c].size()); ++g)
    {
      sum[g] += curveHomology[c][g];
    }
  }
  return excess;
}

} // namespace boolsurf

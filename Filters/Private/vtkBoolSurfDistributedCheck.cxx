#include "vtkBoolSurfDistributedCheck.h"

#include "Mesh/SurfaceCheck.h"
#include "vtkBoolSurfSurfacePiece.h"

#include <vtkCommunicator.h>
#include <vtkMultiProcessController.h>

#include <algorithm>
#include <deque>
#include <map>
#include <numeric>
#include <set>

namespace boolsurf
{
namespace
{

/// Union-find with the parity of each element relative to its root (orientation).
struct ParityUnionFind
{
  std::vector<int> Parent;
  std::vector<int> Parity;
  explicit ParityUnionFind(int n)
    : Parent(n)
    , Parity(n, 0)
  {
    std::iota(this->Parent.begin(), this->Parent.end(), 0);
  }
  int Find(int i)
  {
    int parity = 0, root = i;
    while (this->Parent[root] != root)
    {
      parity ^= this->Parity[root];
      root = this->Parent[root];
    }
    // Path compression, keeping each element's parity to the root.
    while (this->Parent[i] != root)
    {
      const int next = this->Parent[i];
      const int own = this->Parity[i];
      this->Parity[i] = parity;
      this->Parent[i] = root;
      parity ^= own;
      i = next;
    }
    return root;
  }
  int ParityOf(int i)
  {
    this->Find(i);
    return this->Parent[i] == i ? 0 : this->Parity[i];
  }
  /// False when a and b are already joined with the other parity.
  bool Union(int a, int b, int parity)
  {
    const int ra = this->Find(a), rb = this->Find(b);
    const int pa = this->ParityOf(a), pb = this->ParityOf(b);
    if (ra == rb)
    {
      return (pa ^ pb) == parity;
    }
    this->Parent[ra] = rb;
    this->Parity[ra] = pa ^ pb ^ parity;
    return true;
  }
};

enum UnionKind
{
  ComponentUnion = 0,
  FanUnion = 1,
  VertexUnion = 2,
  ChainUnion = 3,
};

/// Per triangle, its orientation relative to its component's first triangle: the flip flags
/// of MeshTopology's breadth-first search (a misoriented neighbour flips it).
std::vector<int> OrientationFlips(const TriangleMesh& mesh)
{
  const int nt = mesh.GetNumberOfTriangles();
  std::vector<int> flip(nt, 0);
  std::vector<char> reached(nt, 0);
  std::deque<int> queue;
  for (int seed = 0; seed < nt; ++seed)
  {
    if (!mesh.IsUsable(seed) || reached[seed])
    {
      continue;
    }
    reached[seed] = 1;
    queue.push_back(seed);
    while (!queue.empty())
    {
      const int t = queue.front();
      queue.pop_front();
      for (int k = 0; k < 3; ++k)
      {
        const int n = mesh.GetNeighbor(t, k);
        if (n >= 0 && !reached[n])
        {
          const bool same =
            mesh.GetTriangle(n)[mesh.GetNeighborEdge(t, k)] == mesh.GetTriangle(t)[k];
          reached[n] = 1;
          flip[n] = flip[t] ^ (same ? 1 : 0);
          queue.push_back(n);
        }
      }
    }
  }
  return flip;
}

/// One rank's record for the first rank, in the order Resolve() reads it.
struct RankRecord
{
  std::vector<long long> Components; ///< per local component: min gid, triangles, edges,
                                     ///< fans at unshared points, orientable
  std::vector<long long> Fans;       ///< per fan at a shared point: component, vertex node
  long long VertexNodes = 0;
  std::vector<long long> Chains; ///< per boundary chain: first half-edge key, component
  std::vector<double> ChainLengths;
  std::vector<long long> Unions;     ///< kind, local node, other rank, its node, parity
  long long NonManifoldVertices = 0; ///< at unshared points
  /// Problem ids by kind (global cell ids; pairs for orientation).
  std::vector<long long> NonFinite, Repeated, Degenerate, NonManifoldEdges, Misoriented;

  std::vector<long long> Flatten() const
  {
    std::vector<long long> all;
    auto list = [&all](const std::vector<long long>& v)
    {
      all.push_back(static_cast<long long>(v.size()));
      all.insert(all.end(), v.begin(), v.end());
    };
    list(this->Components);
    list(this->Fans);
    all.push_back(this->VertexNodes);
    list(this->Chains);
    list(this->Unions);
    all.push_back(this->NonManifoldVertices);
    for (const auto* v : { &this->NonFinite,
           &this->Repeated,
           &this->Degenerate,
           &this->NonManifoldEdges,
           &this->Misoriented })
    {
      list(*v);
    }
    return all;
  }
  static RankRecord Read(const long long* at)
  {
    RankRecord r;
    auto list = [&at](std::vector<long long>& v)
    {
      const long long n = *at++;
      v.assign(at, at + n);
      at += n;
    };
    list(r.Components);
    list(r.Fans);
    r.VertexNodes = *at++;
    list(r.Chains);
    list(r.Unions);
    r.NonManifoldVertices = *at++;
    for (auto* v :
      { &r.NonFinite, &r.Repeated, &r.Degenerate, &r.NonManifoldEdges, &r.Misoriented })
    {
      list(*v);
    }
    return r;
  }
};

/// What the first rank sends back to every rank: the global numbers of its components and
/// chains, and the field data.
struct Resolved
{
  std::vector<std::vector<long long>> PerRank; ///< component numbers, then chain loop numbers
  std::vector<long long> Field;                ///< components (4 each), manifold, loops
  std::vector<double> Lengths;
  std::string Problems;
};

std::string Line(const char* level, const char* kind, const std::string& what)
{
  return std::string(level) + " " + kind + ": " + what;
}

/// The union-find over every rank's records (on the first rank).
Resolved Resolve(const std::vector<RankRecord>& records,
  const std::vector<double>& lengths,
  const std::vector<size_t>& lengthOffsets,
  int maxIds)
{
  const int ranks = static_cast<int>(records.size());
  std::vector<int> compAt(ranks + 1, 0), fanAt(ranks + 1, 0), vertexAt(ranks + 1, 0),
    chainAt(ranks + 1, 0);
  for (int r = 0; r < ranks; ++r)
  {
    compAt[r + 1] = compAt[r] + static_cast<int>(records[r].Components.size() / 5);
    fanAt[r + 1] = fanAt[r] + static_cast<int>(records[r].Fans.size() / 2);
    vertexAt[r + 1] = vertexAt[r] + static_cast<int>(records[r].VertexNodes);
    chainAt[r + 1] = chainAt[r] + static_cast<int>(records[r].Chains.size() / 2);
  }
  ParityUnionFind comps(compAt[ranks]), fans(fanAt[ranks]), vertices(vertexAt[ranks]),
    chains(chainAt[ranks]);
  std::vector<char> orientable(compAt[ranks], 1);
  for (int r = 0; r < ranks; ++r)
  {
    const std::vector<long long>& u = records[r].Unions;
    for (size_t i = 0; i + 4 < u.size(); i += 5)
    {
      const int other = static_cast<int>(u[i + 2]);
      const int a = static_cast<int>(u[i + 1]), b = static_cast<int>(u[i + 3]);
      switch (u[i])
      {
        case ComponentUnion:
          if (!comps.Union(compAt[r] + a, compAt[other] + b, static_cast<int>(u[i + 4])))
          {
            orientable[compAt[r] + a] = 0;
          }
          break;
        case FanUnion:
          fans.Union(fanAt[r] + a, fanAt[other] + b, 0);
          break;
        case VertexUnion:
          vertices.Union(vertexAt[r] + a, vertexAt[other] + b, 0);
          break;
        default:
          chains.Union(chainAt[r] + a, chainAt[other] + b, 0);
      }
    }
  }
  // Components numbered by their smallest global cell id.
  std::map<int, long long> rootMin;
  for (int r = 0; r < ranks; ++r)
  {
    for (int c = 0; c < compAt[r + 1] - compAt[r]; ++c)
    {
      const int root = comps.Find(compAt[r] + c);
      const long long gid = records[r].Components[5 * c];
      auto at = rootMin.emplace(root, gid).first;
      at->second = std::min(at->second, gid);
    }
  }
  std::vector<std::pair<long long, int>> byMin;
  for (const auto& rm : rootMin)
  {
    byMin.emplace_back(rm.second, rm.first);
  }
  std::sort(byMin.begin(), byMin.end());
  std::map<int, int> number;
  for (size_t i = 0; i < byMin.size(); ++i)
  {
    number[byMin[i].second] = static_cast<int>(i);
  }
  auto componentOf = [&](int r, long long c)
  { return c < 0 ? -1 : number[comps.Find(compAt[r] + static_cast<int>(c))]; };

  std::vector<ComponentTopology> topology(byMin.size());
  for (int r = 0; r < ranks; ++r)
  {
    for (int c = 0; c < compAt[r + 1] - compAt[r]; ++c)
    {
      ComponentTopology& t = topology[componentOf(r, c)];
      const long long* rec = &records[r].Components[5 * c];
      t.Triangles += static_cast<int>(rec[1]);
      t.Edges += static_cast<int>(rec[2]);
      t.Vertices += static_cast<int>(rec[3]);
      t.Orientable = t.Orientable && rec[4] && orientable[compAt[r] + c];
    }
  }
  // Vertex fans at shared points: one per group of joined fans; a point with several is a
  // non-manifold vertex.
  long long nonManifoldVertices = 0;
  std::map<int, std::set<int>> fansAtVertex;
  std::set<int> countedFans;
  for (int r = 0; r < ranks; ++r)
  {
    for (int f = 0; f < fanAt[r + 1] - fanAt[r]; ++f)
    {
      const int root = fans.Find(fanAt[r] + f);
      if (countedFans.insert(root).second)
      {
        ++topology[componentOf(r, records[r].Fans[2 * f])].Vertices;
      }
      fansAtVertex[vertices.Find(vertexAt[r] + static_cast<int>(records[r].Fans[2 * f + 1]))]
        .insert(root);
    }
    nonManifoldVertices += records[r].NonManifoldVertices;
  }
  for (const auto& v : fansAtVertex)
  {
    nonManifoldVertices += v.second.size() > 1 ? 1 : 0;
  }
  // Boundary loops numbered by their first half-edge (3 x global cell id + local edge).
  std::map<int, long long> chainMin;
  for (int r = 0; r < ranks; ++r)
  {
    for (int c = 0; c < chainAt[r + 1] - chainAt[r]; ++c)
    {
      const int root = chains.Find(chainAt[r] + c);
      const long long key = records[r].Chains[2 * c];
      auto at = chainMin.emplace(root, key).first;
      at->second = std::min(at->second, key);
    }
  }
  std::vector<std::pair<long long, int>> loopsByMin;
  for (const auto& cm : chainMin)
  {
    loopsByMin.emplace_back(cm.second, cm.first);
  }
  std::sort(loopsByMin.begin(), loopsByMin.end());
  std::map<int, int> loopNumber;
  for (size_t i = 0; i < loopsByMin.size(); ++i)
  {
    loopNumber[loopsByMin[i].second] = static_cast<int>(i);
  }
  Resolved out;
  out.Lengths.assign(loopsByMin.size(), 0.0);
  std::vector<int> loopComponent(loopsByMin.size(), -1);
  out.PerRank.resize(ranks);
  for (int r = 0; r < ranks; ++r)
  {
    for (int c = 0; c < compAt[r + 1] - compAt[r]; ++c)
    {
      out.PerRank[r].push_back(componentOf(r, c));
    }
    for (int c = 0; c < chainAt[r + 1] - chainAt[r]; ++c)
    {
      const int loop = loopNumber[chains.Find(chainAt[r] + c)];
      out.PerRank[r].push_back(loop);
      out.Lengths[loop] += lengths[lengthOffsets[r] + c];
      loopComponent[loop] = componentOf(r, records[r].Chains[2 * c + 1]);
    }
  }
  for (int component : loopComponent)
  {
    if (component >= 0)
    {
      ++topology[component].BoundaryLoops;
    }
  }
  for (ComponentTopology& c : topology)
  {
    c.EulerCharacteristic = c.Vertices - c.Edges + c.Triangles;
    c.Genus = c.Orientable ? (2 - c.BoundaryLoops - c.EulerCharacteristic) / 2 : -1;
    out.Field.insert(
      out.Field.end(), { c.Genus, c.BoundaryLoops, c.EulerCharacteristic, c.Orientable ? 1 : 0 });
  }

  // Problems, in the order one process reports them, named by global cell ids.
  std::vector<long long> nonFinite, repeated, degenerate, edges, misoriented;
  for (const RankRecord& r : records)
  {
    nonFinite.insert(nonFinite.end(), r.NonFinite.begin(), r.NonFinite.end());
    repeated.insert(repeated.end(), r.Repeated.begin(), r.Repeated.end());
    degenerate.insert(degenerate.end(), r.Degenerate.begin(), r.Degenerate.end());
    edges.insert(edges.end(), r.NonManifoldEdges.begin(), r.NonManifoldEdges.end());
    misoriented.insert(misoriented.end(), r.Misoriented.begin(), r.Misoriented.end());
  }
  for (auto* v : { &repeated, &degenerate, &edges })
  {
    std::sort(v->begin(), v->end());
  }
  std::vector<std::string> lines;
  auto sorted = [](std::vector<long long> v)
  {
    std::sort(v.begin(), v.end());
    return v;
  };
  if (!nonFinite.empty())
  {
    lines.push_back(Line("Error",
      "NonFiniteCoordinates",
      std::to_string(nonFinite.size()) +
        " triangle(s) have a point with NaN or infinite coordinates, global cell ids: " +
        FormatIds(sorted(nonFinite), maxIds)));
  }
  if (!repeated.empty())
  {
    lines.push_back(Line("Error",
      "RepeatedVertexIndex",
      std::to_string(repeated.size()) +
        " triangle(s) use the same point twice (topologically degenerate), global cell ids: " +
        FormatIds(repeated, maxIds)));
  }
  if (!degenerate.empty())
  {
    lines.push_back(Line("Error",
      "DegenerateTriangle",
      std::to_string(degenerate.size()) +
        " triangle(s) have zero area, global cell ids: " + FormatIds(degenerate, maxIds)));
  }
  if (!edges.empty())
  {
    lines.push_back(Line("Error",
      "NonManifoldEdge",
      std::to_string(edges.size()) +
        " non-manifold edge(s) shared by more than two triangles, by a global cell id on "
        "each: " +
        FormatIds(edges, maxIds)));
  }
  if (nonManifoldVertices > 0)
  {
    lines.push_back(Line("Error",
      "NonManifoldVertex",
      std::to_string(nonManifoldVertices) +
        " non-manifold vertex(es) where separate fans of triangles meet"));
  }
  if (!misoriented.empty())
  {
    std::string pairs;
    for (size_t i = 0; i + 1 < misoriented.size(); i += 2)
    {
      if (static_cast<int>(i / 2) == maxIds)
      {
        pairs += " ... and " + std::to_string(misoriented.size() / 2 - maxIds) + " more";
        break;
      }
      pairs +=
        (i ? ", " : "") + std::to_string(misoriented[i]) + "/" + std::to_string(misoriented[i + 1]);
    }
    lines.push_back(Line("Error",
      "InconsistentOrientation",
      std::to_string(misoriented.size() / 2) +
        " pair(s) of neighbouring triangles are oriented inconsistently (flip one of each), "
        "global cell id pairs: " +
        pairs));
  }
  for (size_t c = 0; c < topology.size(); ++c)
  {
    if (!topology[c].Orientable)
    {
      lines.push_back(Line("Error",
        "NonOrientable",
        "connected component " + std::to_string(c) + " is not orientable"));
    }
  }
  out.Field.push_back(edges.empty() && nonManifoldVertices == 0 ? 1 : 0);
  for (const std::string& line : lines)
  {
    out.Problems += line + '\n';
  }
  return out;
}

} // namespace

//------------------------------------------------------------------------------
void CheckDistributedSurface(const vtkBoolSurfSurfacePiece& piece, SurfaceCheckOutput& out)
{
  vtkMultiProcessController* controller = piece.GetController();
  const int rank = controller->GetLocalProcessId();
  const int ranks = controller->GetNumberOfProcesses();
  const vtkSurfaceInput& surface = piece.GetSurface();
  const TriangleMesh& mesh = *surface.Mesh;
  const MeshTopology& topo = *surface.Topology;
  const std::vector<long long>& gid = piece.GetGlobalCellIds();
  const std::vector<vtkBoolSurfSurfacePiece::Neighbour>& neighbours = piece.GetNeighbours();
  const int nt = mesh.GetNumberOfTriangles();
  const int nv = mesh.GetNumberOfVertices();
  const int nc = topo.GetNumberOfComponents();
  RankRecord record;

  // Shared points: their vertex node, and per neighbour each point's index in its list.
  std::map<int, int> vertexNode;
  std::vector<std::map<int, int>> sharedIndex(neighbours.size());
  for (size_t n = 0; n < neighbours.size(); ++n)
  {
    for (size_t i = 0; i < neighbours[n].Points.size(); ++i)
    {
      const int v = static_cast<int>(neighbours[n].Points[i]);
      sharedIndex[n][v] = static_cast<int>(i);
      vertexNode.emplace(v, static_cast<int>(vertexNode.size()));
    }
  }
  record.VertexNodes = static_cast<long long>(vertexNode.size());

  // Fans at shared points (corners joined through the edges at the point, as MeshTopology
  // counts them); the others are counted locally.
  std::map<int, int> cornerFan;
  std::vector<long long> sharedFans(nc, 0);
  for (const auto& vn : vertexNode)
  {
    const IntRange corners = mesh.GetVertexCorners(vn.first);
    std::vector<int> parent(corners.size());
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](int i)
    {
      while (parent[i] != i)
      {
        i = parent[i] = parent[parent[i]];
      }
      return i;
    };
    for (int i = 0; i < corners.size(); ++i)
    {
      const int t = corners[i] / 3, j = corners[i] % 3;
      for (int k : { j, (j + 2) % 3 })
      {
        const int n = mesh.GetNeighbor(t, k);
        for (int m = 0; n >= 0 && m < corners.size(); ++m)
        {
          if (corners[m] / 3 == n)
          {
            parent[find(i)] = find(m);
          }
        }
      }
    }
    std::map<int, int> fanOfRoot;
    for (int i = 0; i < corners.size(); ++i)
    {
      const int c = topo.TriangleComponent[corners[i] / 3];
      if (c < 0)
      {
        continue;
      }
      auto at = fanOfRoot.emplace(find(i), static_cast<int>(record.Fans.size() / 2));
      if (at.second)
      {
        record.Fans.insert(record.Fans.end(), { c, vn.second });
        ++sharedFans[c];
      }
      cornerFan[corners[i]] = at.first->second;
    }
  }
  for (int v : topo.NonManifoldVertices)
  {
    record.NonManifoldVertices += vertexNode.count(v) ? 0 : 1;
  }

  // Round 1: per neighbour, each shared point's vertex node, then the border half-edges whose
  // two points it shares: shared indices, global cell id, fans, component, flip, valence.
  const std::vector<int> flip = OrientationFlips(mesh);
  auto fanAt = [&](int t, int k)
  {
    auto at = cornerFan.find(3 * t + k);
    return at == cornerFan.end() ? -1 : at->second;
  };
  std::vector<std::vector<long long>> send(neighbours.size());
  for (size_t n = 0; n < neighbours.size(); ++n)
  {
    for (vtkIdType v : neighbours[n].Points)
    {
      send[n].push_back(vertexNode[static_cast<int>(v)]);
    }
    for (int t = 0; t < nt; ++t)
    {
      for (int k = 0; mesh.IsUsable(t) && k < 3; ++k)
      {
        const int u = mesh.GetTriangle(t)[k], w = mesh.GetTriangle(t)[(k + 1) % 3];
        auto iu = sharedIndex[n].find(u), iw = sharedIndex[n].find(w);
        if (mesh.GetTwin(3 * t + k) >= 0 || iu == sharedIndex[n].end() ||
          iw == sharedIndex[n].end())
        {
          continue;
        }
        send[n].insert(send[n].end(),
          { iu->second,
            iw->second,
            gid[t],
            fanAt(t, k),
            fanAt(t, (k + 1) % 3),
            topo.TriangleComponent[t],
            flip[t],
            mesh.GetEdgeValence(mesh.GetEdgeId(t, k)) });
      }
    }
  }
  const std::vector<std::vector<long long>> received = piece.Exchange(send);

  // The shared edges: each border half-edge's matches on the neighbours.
  std::vector<long long> edges(nc, 0);
  std::vector<int> boundary; // half-edges on the surface's boundary
  std::set<int> reportedEdges;
  for (int t = 0; t < nt; ++t)
  {
    for (int k = 0; mesh.IsUsable(t) && k < 3; ++k)
    {
      if (mesh.GetTwin(3 * t + k) >= 0)
      {
        continue;
      }
      const int u = mesh.GetTriangle(t)[k], w = mesh.GetTriangle(t)[(k + 1) % 3];
      const int valence = mesh.GetEdgeValence(mesh.GetEdgeId(t, k));
      struct Match
      {
        size_t Neighbour;
        const long long* Entry;
      };
      std::vector<Match> matches;
      for (size_t n = 0; n < neighbours.size(); ++n)
      {
        auto iu = sharedIndex[n].find(u), iw = sharedIndex[n].find(w);
        if (iu == sharedIndex[n].end() || iw == sharedIndex[n].end())
        {
          continue;
        }
        const std::vector<long long>& in = received[n];
        for (size_t e = neighbours[n].Points.size(); e + 7 < in.size(); e += 8)
        {
          if ((in[e] == iu->second && in[e + 1] == iw->second) ||
            (in[e] == iw->second && in[e + 1] == iu->second))
          {
            matches.push_back({ n, &in[e] });
          }
        }
      }
      if (matches.empty() && valence == 1)
      {
        boundary.push_back(3 * t + k);
        continue;
      }
      bool lowest = true;
      for (const Match& m : matches)
      {
        lowest = lowest && rank < neighbours[m.Neighbour].Rank;
      }
      if (!lowest)
      {
        --edges[topo.TriangleComponent[t]]; // counted by a lower rank
      }
      if (matches.size() != 1 || valence != 1 || matches[0].Entry[7] != 1)
      {
        // More than two triangles: no neighbours across it, as in one process.
        if (lowest && reportedEdges.insert(mesh.GetEdgeId(t, k)).second && valence <= 2)
        {
          record.NonManifoldEdges.push_back(gid[t]);
        }
        continue;
      }
      const Match& m = matches[0];
      const long long* e = m.Entry;
      const int other = neighbours[m.Neighbour].Rank;
      const bool same = e[0] == sharedIndex[m.Neighbour][u];
      if (same && rank < other)
      {
        record.Misoriented.insert(record.Misoriented.end(), { gid[t], e[2] });
      }
      if (rank < other)
      {
        const long long theirFanAtU = same ? e[3] : e[4];
        const long long theirFanAtW = same ? e[4] : e[3];
        record.Unions.insert(record.Unions.end(),
          { ComponentUnion,
            topo.TriangleComponent[t],
            other,
            e[5],
            flip[t] ^ e[6] ^ (same ? 1 : 0),
            FanUnion,
            fanAt(t, k),
            other,
            theirFanAtU,
            0,
            FanUnion,
            fanAt(t, (k + 1) % 3),
            other,
            theirFanAtW,
            0 });
      }
    }
  }
  for (const NonManifoldEdge& e : mesh.GetNonManifoldEdges())
  {
    record.NonManifoldEdges.push_back(gid[e.Triangles.front()]);
  }
  // Points shared with a neighbour are one vertex.
  for (size_t n = 0; n < neighbours.size(); ++n)
  {
    if (rank < neighbours[n].Rank)
    {
      for (size_t i = 0; i < neighbours[n].Points.size(); ++i)
      {
        record.Unions.insert(record.Unions.end(),
          { VertexUnion,
            vertexNode[static_cast<int>(neighbours[n].Points[i])],
            neighbours[n].Rank,
            received[n][i],
            0 });
      }
    }
  }

  // Boundary chains: the boundary half-edges joined at their points.
  std::vector<int> chainParent(boundary.size());
  std::iota(chainParent.begin(), chainParent.end(), 0);
  auto findChain = [&](int i)
  {
    while (chainParent[i] != i)
    {
      i = chainParent[i] = chainParent[chainParent[i]];
    }
    return i;
  };
  std::map<int, int> pointEdge; // a boundary half-edge at each boundary point
  for (size_t b = 0; b < boundary.size(); ++b)
  {
    const int t = boundary[b] / 3, k = boundary[b] % 3;
    for (int v : { mesh.GetTriangle(t)[k], mesh.GetTriangle(t)[(k + 1) % 3] })
    {
      auto at = pointEdge.emplace(v, static_cast<int>(b));
      chainParent[findChain(static_cast<int>(b))] = findChain(at.first->second);
    }
  }
  std::map<int, int> chainOfRoot;
  std::vector<int> chainOfEdge(boundary.size());
  for (size_t b = 0; b < boundary.size(); ++b)
  {
    const int t = boundary[b] / 3, k = boundary[b] % 3;
    auto at =
      chainOfRoot.emplace(findChain(static_cast<int>(b)), static_cast<int>(chainOfRoot.size()));
    const int chain = at.first->second;
    chainOfEdge[b] = chain;
    const long long key = 3 * gid[t] + k;
    if (at.second)
    {
      record.Chains.insert(record.Chains.end(), { key, topo.TriangleComponent[t] });
      record.ChainLengths.push_back(0.0);
    }
    record.Chains[2 * chain] = std::min(record.Chains[2 * chain], key);
    record.ChainLengths[chain] += Distance(
      mesh.GetPosition(mesh.GetTriangle(t)[k]), mesh.GetPosition(mesh.GetTriangle(t)[(k + 1) % 3]));
  }
  auto chainAtPoint = [&](int v)
  {
    auto at = pointEdge.find(v);
    return at == pointEdge.end() ? -1 : chainOfEdge[at->second];
  };

  // Round 2: the chain at each shared point; chains meeting at a point are one loop.
  for (size_t n = 0; n < neighbours.size(); ++n)
  {
    send[n].clear();
    for (vtkIdType v : neighbours[n].Points)
    {
      send[n].push_back(chainAtPoint(static_cast<int>(v)));
    }
  }
  const std::vector<std::vector<long long>> chainsThere = piece.Exchange(send);
  for (size_t n = 0; n < neighbours.size(); ++n)
  {
    for (size_t i = 0; rank < neighbours[n].Rank && i < neighbours[n].Points.size(); ++i)
    {
      const int mine = chainAtPoint(static_cast<int>(neighbours[n].Points[i]));
      if (mine >= 0 && chainsThere[n][i] >= 0)
      {
        record.Unions.insert(
          record.Unions.end(), { ChainUnion, mine, neighbours[n].Rank, chainsThere[n][i], 0 });
      }
    }
  }

  // Local problems, named by global cell ids.
  for (int c = 0; c < nc; ++c)
  {
    long long minGid = -1;
    for (int t = 0; t < nt; ++t)
    {
      if (topo.TriangleComponent[t] == c && (minGid < 0 || gid[t] < minGid))
      {
        minGid = gid[t];
      }
    }
    const ComponentTopology& ct = topo.Components[c];
    record.Components.insert(record.Components.end(),
      { minGid,
        ct.Triangles,
        ct.Edges + edges[c],
        ct.Vertices - sharedFans[c],
        ct.Orientable ? 1 : 0 });
  }
  for (const SurfaceProblem& p : surface.Check.Problems)
  {
    if (p.Kind == "RepeatedVertexIndex" || p.Kind == "DegenerateTriangle")
    {
      for (long long t : p.Ids)
      {
        (p.Kind == "DegenerateTriangle" ? record.Degenerate : record.Repeated).push_back(gid[t]);
      }
    }
    else if (p.Kind == "InconsistentOrientation")
    {
      for (long long t : p.Ids)
      {
        record.Misoriented.push_back(gid[t]);
      }
    }
  }
  for (int t = 0; t < nt; ++t)
  {
    for (int k = 0; mesh.IsUsable(t) && k < 3; ++k)
    {
      if (!IsFinite(mesh.GetCornerPosition(t, k)))
      {
        record.NonFinite.push_back(gid[t]);
        break;
      }
    }
  }

  // Every record to the first rank, which resolves the unions; each rank gets its numbers
  // back, every rank the field data.
  const std::vector<long long> flat = record.Flatten();
  long long size = static_cast<long long>(flat.size());
  long long lengthCount = static_cast<long long>(record.ChainLengths.size());
  std::vector<long long> sizes(ranks), offsets(ranks), lengthCounts(ranks), lengthOffsets(ranks);
  controller->Gather(&size, sizes.data(), 1, 0);
  controller->Gather(&lengthCount, lengthCounts.data(), 1, 0);
  long long total = 0, totalLengths = 0;
  for (int r = 0; r < ranks; ++r)
  {
    offsets[r] = total;
    total += sizes[r];
    lengthOffsets[r] = totalLengths;
    totalLengths += lengthCounts[r];
  }
  std::vector<long long> all(static_cast<size_t>(std::max<long long>(total, 1)));
  std::vector<double> allLengths(static_cast<size_t>(std::max<long long>(totalLengths, 1)));
  controller->GatherV(flat.data(), all.data(), size, sizes.data(), offsets.data(), 0);
  controller->GatherV(record.ChainLengths.data(),
    allLengths.data(),
    lengthCount,
    lengthCounts.data(),
    lengthOffsets.data(),
    0);
  Resolved resolved;
  std::vector<long long> back, backSizes(ranks), backOffsets(ranks);
  if (rank == 0)
  {
    std::vector<RankRecord> records;
    std::vector<size_t> at;
    for (int r = 0; r < ranks; ++r)
    {
      records.push_back(RankRecord::Read(&all[offsets[r]]));
      at.push_back(static_cast<size_t>(lengthOffsets[r]));
    }
    resolved = Resolve(records, allLengths, at, SurfaceCheckOptions().MaxIdsInMessage);
    long long sum = 0;
    for (int r = 0; r < ranks; ++r)
    {
      backOffsets[r] = sum;
      backSizes[r] = static_cast<long long>(resolved.PerRank[r].size());
      sum += backSizes[r];
      back.insert(back.end(), resolved.PerRank[r].begin(), resolved.PerRank[r].end());
    }
  }
  std::vector<long long> mine(static_cast<size_t>(nc + record.ChainLengths.size()) + 1);
  controller->ScatterV(back.data(),
    mine.data(),
    backSizes.data(),
    backOffsets.data(),
    static_cast<vtkIdType>(mine.size() - 1),
    0);
  long long header[3] = { static_cast<long long>(resolved.Field.size()),
    static_cast<long long>(resolved.Lengths.size()),
    static_cast<long long>(resolved.Problems.size()) };
  controller->Broadcast(header, 3, 0);
  resolved.Field.resize(static_cast<size_t>(header[0]));
  resolved.Lengths.resize(static_cast<size_t>(header[1]));
  resolved.Problems.resize(static_cast<size_t>(header[2]));
  controller->Broadcast(resolved.Field.data(), header[0], 0);
  if (header[1] > 0)
  {
    controller->Broadcast(resolved.Lengths.data(), header[1], 0);
  }
  if (header[2] > 0)
  {
    controller->Broadcast(&resolved.Problems[0], header[2], 0);
  }

  // This rank's piece: components and loops by their global numbers.
  out = SurfaceCheckOutput();
  out.ComponentId.assign(nt, -1);
  for (int t = 0; t < nt; ++t)
  {
    const int c = topo.TriangleComponent[t];
    out.ComponentId[t] = c < 0 ? -1 : static_cast<int>(mine[c]);
  }
  out.BoundaryLoopId.assign(nv, -1);
  for (int v = 0; v < nv; ++v)
  {
    const int chain = chainAtPoint(v);
    out.BoundaryLoopId[v] = chain < 0 ? -1 : static_cast<int>(mine[nc + chain]);
  }
  // Round 3: a point on the boundary of another rank's triangles only takes that loop.
  for (size_t n = 0; n < neighbours.size(); ++n)
  {
    send[n].clear();
    for (vtkIdType v : neighbours[n].Points)
    {
      send[n].push_back(out.BoundaryLoopId[v]);
    }
  }
  const std::vector<std::vector<long long>> loopsThere = piece.Exchange(send);
  for (size_t n = 0; n < neighbours.size(); ++n)
  {
    for (size_t i = 0; i < neighbours[n].Points.size(); ++i)
    {
      int& loop = out.BoundaryLoopId[neighbours[n].Points[i]];
      if (loopsThere[n][i] >= 0 && (loop < 0 || loopsThere[n][i] < loop))
      {
        loop = static_cast<int>(loopsThere[n][i]);
      }
    }
  }
  const size_t components = (resolved.Field.size() - 1) / 4;
  for (size_t c = 0; c < components; ++c)
  {
    ComponentTopology t;
    t.Genus = static_cast<int>(resolved.Field[4 * c]);
    t.BoundaryLoops = static_cast<int>(resolved.Field[4 * c + 1]);
    t.EulerCharacteristic = static_cast<int>(resolved.Field[4 * c + 2]);
    t.Orientable = resolved.Field[4 * c + 3] != 0;
    out.Components.push_back(t);
  }
  out.IsManifold = resolved.Field.back() != 0;
  out.BoundaryLoopLengths = resolved.Lengths;
  for (const std::string& w : surface.Warnings)
  {
    out.Problems.push_back("Warning Conversion: " + w);
  }
  size_t start = 0;
  for (size_t end; (end = resolved.Problems.find('\n', start)) != std::string::npos;
       start = end + 1)
  {
    out.Problems.push_back(resolved.Problems.substr(start, end - start));
  }
}

} // namespace boolsurf

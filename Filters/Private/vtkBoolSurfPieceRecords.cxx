#include "vtkBoolSurfPieceRecords.h"

#include "Mesh/SurfaceCheck.h"

#include <algorithm>
#include <map>
#include <memory>
#include <numeric>
#include <set>
#include <utility>

namespace boolsurf
{
namespace
{

/// Union-find with the parity of each element relative to its root (orientation).
class ParityUnionFind
{
public:
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

  /// False when a and b were already joined with the other parity.
  bool Union(int a, int b, int parity)
  {
    const int ra = this->Find(a), rb = this->Find(b);
    const int pa = this->ParityToRoot(a), pb = this->ParityToRoot(b);
    if (ra == rb)
    {
      return (pa ^ pb) == parity;
    }
    this->Parent[ra] = rb;
    this->Parity[ra] = pa ^ pb ^ parity;
    return true;
  }

private:
  int ParityToRoot(int i)
  {
    this->Find(i);
    return this->Parent[i] == i ? 0 : this->Parity[i];
  }

  std::vector<int> Parent;
  std::vector<int> Parity;
};

/// Roots numbered by increasing key (a root's key: the smallest of its members').
std::map<int, int> NumberByKey(const std::map<int, long long>& rootKey)
{
  std::vector<std::pair<long long, int>> byKey;
  for (const auto& rk : rootKey)
  {
    byKey.emplace_back(rk.second, rk.first);
  }
  std::sort(byKey.begin(), byKey.end());
  std::map<int, int> number;
  for (size_t i = 0; i < byKey.size(); ++i)
  {
    number[byKey[i].second] = static_cast<int>(i);
  }
  return number;
}

void KeepSmallest(std::map<int, long long>& rootKey, int root, long long key)
{
  auto at = rootKey.emplace(root, key).first;
  at->second = std::min(at->second, key);
}

std::string Line(const char* kind, const std::string& what)
{
  return std::string("Error ") + kind + ": " + what;
}

/// Every rank's nodes in one numbering, joined by the unions.
class PieceJoin
{
public:
  explicit PieceJoin(const std::vector<PieceRecord>& records)
    : Records(records)
    , Ranks(static_cast<int>(records.size()))
    , CompAt(Ranks + 1, 0)
    , FanAt(Ranks + 1, 0)
    , VertexAt(Ranks + 1, 0)
    , ChainAt(Ranks + 1, 0)
  {
    for (int r = 0; r < this->Ranks; ++r)
    {
      const PieceRecord& rec = records[r];
      this->CompAt[r + 1] = this->CompAt[r] + Count(rec.Components, ComponentEntry);
      this->FanAt[r + 1] = this->FanAt[r] + Count(rec.Fans, FanEntry);
      this->VertexAt[r + 1] = this->VertexAt[r] + static_cast<int>(rec.VertexNodes);
      this->ChainAt[r + 1] = this->ChainAt[r] + Count(rec.Chains, ChainEntry);
    }
    this->Comps = std::make_unique<ParityUnionFind>(this->CompAt[this->Ranks]);
    this->Fans = std::make_unique<ParityUnionFind>(this->FanAt[this->Ranks]);
    this->Vertices = std::make_unique<ParityUnionFind>(this->VertexAt[this->Ranks]);
    this->Chains = std::make_unique<ParityUnionFind>(this->ChainAt[this->Ranks]);
    this->Orientable.assign(this->CompAt[this->Ranks], 1);
    this->ApplyUnions();
    this->NumberComponents();
    this->NumberLoops();
  }

  /// Global component of rank r's local component c (-1 for none).
  int ComponentOf(int r, long long c)
  {
    return c < 0 ? -1 : this->Component[this->Comps->Find(this->CompAt[r] + static_cast<int>(c))];
  }
  int LoopOf(int r, int chain) { return this->Loop[this->Chains->Find(this->ChainAt[r] + chain)]; }
  int NumberOfComponents() const { return static_cast<int>(this->Component.size()); }
  int NumberOfLoops() const { return static_cast<int>(this->Loop.size()); }

  /// Triangles, edges, fans and orientability summed per component; boundary loops counted.
  std::vector<ComponentTopology> CountTopology(long long& nonManifoldVertices);

private:
  static int Count(const std::vector<long long>& list, int entry)
  {
    return static_cast<int>(list.size() / entry);
  }

  void ApplyUnions()
  {
    for (int r = 0; r < this->Ranks; ++r)
    {
      const std::vector<long long>& u = this->Records[r].Unions;
      for (size_t i = 0; i + UnionEntry <= u.size(); i += UnionEntry)
      {
        const int a = static_cast<int>(u[i + 1]), other = static_cast<int>(u[i + 2]),
                  b = static_cast<int>(u[i + 3]);
        switch (u[i])
        {
          case ComponentUnion:
            if (!this->Comps->Union(
                  this->CompAt[r] + a, this->CompAt[other] + b, static_cast<int>(u[i + 4])))
            {
              this->Orientable[this->CompAt[r] + a] = 0;
            }
            break;
          case FanUnion:
            this->Fans->Union(this->FanAt[r] + a, this->FanAt[other] + b, 0);
            break;
          case VertexUnion:
            this->Vertices->Union(this->VertexAt[r] + a, this->VertexAt[other] + b, 0);
            break;
          default:
            this->Chains->Union(this->ChainAt[r] + a, this->ChainAt[other] + b, 0);
        }
      }
    }
  }

  /// Components by their smallest global cell id, as one process numbers them by their first
  /// triangle.
  void NumberComponents()
  {
    std::map<int, long long> rootMin;
    for (int r = 0; r < this->Ranks; ++r)
    {
      for (int c = 0; c < this->CompAt[r + 1] - this->CompAt[r]; ++c)
      {
        KeepSmallest(rootMin,
          this->Comps->Find(this->CompAt[r] + c),
          this->Records[r].Components[ComponentEntry * c]);
      }
    }
    this->Component = NumberByKey(rootMin);
  }

  /// Boundary loops by their first half-edge (3 x global cell id + local edge), as one
  /// process finds them.
  void NumberLoops()
  {
    std::map<int, long long> rootMin;
    for (int r = 0; r < this->Ranks; ++r)
    {
      for (int c = 0; c < this->ChainAt[r + 1] - this->ChainAt[r]; ++c)
      {
        KeepSmallest(rootMin,
          this->Chains->Find(this->ChainAt[r] + c),
          this->Records[r].Chains[ChainEntry * c]);
      }
    }
    this->Loop = NumberByKey(rootMin);
  }

  const std::vector<PieceRecord>& Records;
  const int Ranks;
  std::vector<int> CompAt, FanAt, VertexAt, ChainAt; ///< first node of each rank, per kind
  std::unique_ptr<ParityUnionFind> Comps, Fans, Vertices, Chains;
  std::vector<char> Orientable;
  std::map<int, int> Component; ///< by component root
  std::map<int, int> Loop;      ///< by chain root
};

std::vector<ComponentTopology> PieceJoin::CountTopology(long long& nonManifoldVertices)
{
  std::vector<ComponentTopology> topology(this->Component.size());
  for (int r = 0; r < this->Ranks; ++r)
  {
    for (int c = 0; c < this->CompAt[r + 1] - this->CompAt[r]; ++c)
    {
      ComponentTopology& t = topology[this->ComponentOf(r, c)];
      const long long* rec = &this->Records[r].Components[ComponentEntry * c];
      t.Triangles += static_cast<int>(rec[1]);
      t.Edges += static_cast<int>(rec[2]);
      t.Vertices += static_cast<int>(rec[3]);
      t.Orientable = t.Orientable && rec[4] && this->Orientable[this->CompAt[r] + c];
    }
  }
  // Fans at shared points: one vertex per group of joined fans; a point with several groups
  // is a non-manifold vertex.
  nonManifoldVertices = 0;
  std::map<int, std::set<int>> fansAtVertex;
  std::set<int> counted;
  for (int r = 0; r < this->Ranks; ++r)
  {
    const std::vector<long long>& fans = this->Records[r].Fans;
    for (int f = 0; f < this->FanAt[r + 1] - this->FanAt[r]; ++f)
    {
      const int root = this->Fans->Find(this->FanAt[r] + f);
      if (counted.insert(root).second)
      {
        ++topology[this->ComponentOf(r, fans[FanEntry * f])].Vertices;
      }
      const int vertex = this->VertexAt[r] + static_cast<int>(fans[FanEntry * f + 1]);
      fansAtVertex[this->Vertices->Find(vertex)].insert(root);
    }
    nonManifoldVertices += this->Records[r].NonManifoldVertices;
  }
  for (const auto& v : fansAtVertex)
  {
    nonManifoldVertices += v.second.size() > 1 ? 1 : 0;
  }
  std::vector<int> loopComponent(this->Loop.size(), -1);
  for (int r = 0; r < this->Ranks; ++r)
  {
    for (int c = 0; c < this->ChainAt[r + 1] - this->ChainAt[r]; ++c)
    {
      loopComponent[this->LoopOf(r, c)] =
        this->ComponentOf(r, this->Records[r].Chains[ChainEntry * c + 1]);
    }
  }
  for (int component : loopComponent)
  {
    topology[component].BoundaryLoops += component >= 0 ? 1 : 0;
  }
  for (ComponentTopology& c : topology)
  {
    c.EulerCharacteristic = c.Vertices - c.Edges + c.Triangles;
    c.Genus = c.Orientable ? (2 - c.BoundaryLoops - c.EulerCharacteristic) / 2 : -1;
  }
  return topology;
}

std::vector<long long> Joined(const std::vector<PieceRecord>& records,
  std::vector<long long> PieceRecord::*list)
{
  std::vector<long long> all;
  for (const PieceRecord& r : records)
  {
    all.insert(all.end(), (r.*list).begin(), (r.*list).end());
  }
  return all;
}

/// The problems, in the order one process reports them, named by global cell ids.
std::vector<std::string> FormatProblems(const std::vector<PieceRecord>& records,
  const std::vector<ComponentTopology>& topology,
  long long nonManifoldVertices,
  int maxIds)
{
  std::vector<std::string> lines;
  auto sortedIds = [&](std::vector<long long> PieceRecord::*list)
  {
    std::vector<long long> ids = Joined(records, list);
    std::sort(ids.begin(), ids.end());
    return ids;
  };
  const std::vector<long long> nonFinite = sortedIds(&PieceRecord::NonFinite);
  const std::vector<long long> repeated = sortedIds(&PieceRecord::Repeated);
  const std::vector<long long> degenerate = sortedIds(&PieceRecord::Degenerate);
  const std::vector<long long> edges = sortedIds(&PieceRecord::NonManifoldEdges);
  const std::vector<long long> misoriented = Joined(records, &PieceRecord::Misoriented);
  auto counted = [&](const char* kind, const std::vector<long long>& ids, const char* what)
  {
    if (!ids.empty())
    {
      lines.push_back(Line(kind, std::to_string(ids.size()) + what + FormatIds(ids, maxIds)));
    }
  };
  counted("NonFiniteCoordinates",
    nonFinite,
    " triangle(s) have a point with NaN or infinite coordinates, global cell ids: ");
  counted("RepeatedVertexIndex",
    repeated,
    " triangle(s) use the same point twice (topologically degenerate), global cell ids: ");
  counted("DegenerateTriangle", degenerate, " triangle(s) have zero area, global cell ids: ");
  counted("NonManifoldEdge",
    edges,
    " non-manifold edge(s) shared by more than two triangles, by a global cell id on each: ");
  if (nonManifoldVertices > 0)
  {
    lines.push_back(Line("NonManifoldVertex",
      std::to_string(nonManifoldVertices) +
        " non-manifold vertex(es) where separate fans of triangles meet"));
  }
  if (!misoriented.empty())
  {
    std::string pairs;
    const int count = static_cast<int>(misoriented.size() / 2);
    for (int i = 0; i < count && i < maxIds; ++i)
    {
      pairs += (i ? ", " : "") + std::to_string(misoriented[2 * i]) + "/" +
        std::to_string(misoriented[2 * i + 1]);
    }
    pairs += count > maxIds ? " ... and " + std::to_string(count - maxIds) + " more" : "";
    lines.push_back(Line("InconsistentOrientation",
      std::to_string(count) +
        " pair(s) of neighbouring triangles are oriented inconsistently (flip one of each), "
        "global cell id pairs: " +
        pairs));
  }
  for (size_t c = 0; c < topology.size(); ++c)
  {
    if (!topology[c].Orientable)
    {
      lines.push_back(
        Line("NonOrientable", "connected component " + std::to_string(c) + " is not orientable"));
    }
  }
  return lines;
}

} // namespace

//------------------------------------------------------------------------------
std::vector<long long> PieceRecord::Flatten() const
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

//------------------------------------------------------------------------------
PieceRecord PieceRecord::Read(const long long* at)
{
  PieceRecord r;
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
  for (auto* v : { &r.NonFinite, &r.Repeated, &r.Degenerate, &r.NonManifoldEdges, &r.Misoriented })
  {
    list(*v);
  }
  return r;
}

//------------------------------------------------------------------------------
ResolvedPieces ResolvePieces(const std::vector<PieceRecord>& records,
  const std::vector<double>& lengths,
  const std::vector<long long>& lengthOffsets,
  int maxIds)
{
  PieceJoin join(records);
  ResolvedPieces out;
  long long nonManifoldVertices = 0;
  out.Components = join.CountTopology(nonManifoldVertices);
  out.LoopLengths.assign(join.NumberOfLoops(), 0.0);
  out.PerRank.resize(records.size());
  for (size_t r = 0; r < records.size(); ++r)
  {
    const int rank = static_cast<int>(r);
    const int components = static_cast<int>(records[r].Components.size() / ComponentEntry);
    const int chains = static_cast<int>(records[r].Chains.size() / ChainEntry);
    for (int c = 0; c < components; ++c)
    {
      out.PerRank[r].push_back(join.ComponentOf(rank, c));
    }
    for (int c = 0; c < chains; ++c)
    {
      const int loop = join.LoopOf(rank, c);
      out.PerRank[r].push_back(loop);
      // Summed per rank, then in rank order: the one-process length to rounding.
      out.LoopLengths[loop] += lengths[static_cast<size_t>(lengthOffsets[r]) + c];
    }
  }
  out.Problems = FormatProblems(records, out.Components, nonManifoldVertices, maxIds);
  out.IsManifold =
    Joined(records, &PieceRecord::NonManifoldEdges).empty() && nonManifoldVertices == 0;
  return out;
}

} // namespace boolsurf

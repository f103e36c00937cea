#include "vtkBoolSurfDistributedCheck.h"

#include "Mesh/SurfaceCheck.h"
#include "vtkBoolSurfPieceRecords.h"
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

using Buffers = std::vector<std::vector<long long>>;

/// Values per border half-edge sent to a neighbour: the shared indices of its two points,
/// its triangle's global id, the fans at its two points, the component, the orientation flip,
/// the edge's valence on the sending rank.
constexpr int EdgeEntry = 8;

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

/// The fans of triangles around vertex v (corners joined through the edges at v, as
/// MeshTopology counts them): a fan index per corner.
std::vector<int> FansAround(const TriangleMesh& mesh, int v)
{
  const IntRange corners = mesh.GetVertexCorners(v);
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
  std::vector<int> fan(corners.size());
  for (int i = 0; i < corners.size(); ++i)
  {
    fan[i] = find(i);
  }
  return fan;
}

/// One rank's side of the check: its piece's border turned into a record for the first rank,
/// through exchanges with its neighbours.
class PieceCheck
{
public:
  explicit PieceCheck(const vtkBoolSurfSurfacePiece& piece)
    : Piece(piece)
    , Mesh(*piece.GetSurface().Mesh)
    , Topo(*piece.GetSurface().Topology)
    , Gid(piece.GetGlobalCellIds())
    , Neighbours(piece.GetNeighbours())
    , Rank(piece.GetController()->GetLocalProcessId())
    , Flip(OrientationFlips(this->Mesh))
  {
  }

  /// Builds the record: three exchanges with the neighbours, no other communication.
  PieceRecord Run()
  {
    this->IndexSharedPoints();
    this->CountFansAtSharedPoints();
    const Buffers received = this->Piece.Exchange(this->BorderEdges());
    this->MatchSharedEdges(received);
    this->JoinSharedPoints(received);
    this->BuildBoundaryChains();
    this->JoinChains();
    this->AddLocalProblems();
    this->AddComponents();
    return std::move(this->Record);
  }

  int ChainAtPoint(int v) const
  {
    auto at = this->PointEdge.find(v);
    return at == this->PointEdge.end() ? -1 : this->ChainOfEdge[at->second];
  }

private:
  /// Shared points: their vertex node, and per neighbour each point's index in its list.
  void IndexSharedPoints()
  {
    this->SharedIndex.resize(this->Neighbours.size());
    for (size_t n = 0; n < this->Neighbours.size(); ++n)
    {
      for (size_t i = 0; i < this->Neighbours[n].Points.size(); ++i)
      {
        const int v = static_cast<int>(this->Neighbours[n].Points[i]);
        this->SharedIndex[n][v] = static_cast<int>(i);
        this->VertexNode.emplace(v, static_cast<int>(this->VertexNode.size()));
      }
    }
    this->Record.VertexNodes = static_cast<long long>(this->VertexNode.size());
  }

  /// Fans at shared points become nodes (joined across ranks); the others are counted here.
  void CountFansAtSharedPoints()
  {
    this->SharedFans.assign(this->Topo.GetNumberOfComponents(), 0);
    for (const auto& vn : this->VertexNode)
    {
      const IntRange corners = this->Mesh.GetVertexCorners(vn.first);
      const std::vector<int> fan = FansAround(this->Mesh, vn.first);
      std::map<int, int> node;
      for (int i = 0; i < corners.size(); ++i)
      {
        const int c = this->Topo.TriangleComponent[corners[i] / 3];
        if (c < 0)
        {
          continue;
        }
        auto at = node.emplace(fan[i], static_cast<int>(this->Record.Fans.size() / FanEntry));
        if (at.second)
        {
          this->Record.Fans.insert(this->Record.Fans.end(), { c, vn.second });
          ++this->SharedFans[c];
        }
        this->CornerFan[corners[i]] = at.first->second;
      }
    }
    for (int v : this->Topo.NonManifoldVertices)
    {
      this->Record.NonManifoldVertices += this->VertexNode.count(v) ? 0 : 1;
    }
  }

  int FanAt(int t, int k) const
  {
    auto at = this->CornerFan.find(3 * t + k);
    return at == this->CornerFan.end() ? -1 : at->second;
  }

  /// Calls visit(t, k) for every usable half-edge without a twin (boundary, cut or
  /// non-manifold edges).
  template <class Visit>
  void ForEachBorderHalfEdge(const Visit& visit) const
  {
    for (int t = 0; t < this->Mesh.GetNumberOfTriangles(); ++t)
    {
      for (int k = 0; this->Mesh.IsUsable(t) && k < 3; ++k)
      {
        if (this->Mesh.GetTwin(3 * t + k) < 0)
        {
          visit(t, k);
        }
      }
    }
  }

  /// Round 1: per neighbour, each shared point's vertex node, then the border half-edges
  /// whose two points it shares (EdgeEntry values each).
  Buffers BorderEdges() const
  {
    Buffers send(this->Neighbours.size());
    for (size_t n = 0; n < this->Neighbours.size(); ++n)
    {
      for (vtkIdType v : this->Neighbours[n].Points)
      {
        send[n].push_back(this->VertexNode.at(static_cast<int>(v)));
      }
    }
    this->ForEachBorderHalfEdge(
      [&](int t, int k)
      {
        const int u = this->Mesh.GetTriangle(t)[k], w = this->Mesh.GetTriangle(t)[(k + 1) % 3];
        for (size_t n = 0; n < this->Neighbours.size(); ++n)
        {
          auto iu = this->SharedIndex[n].find(u), iw = this->SharedIndex[n].find(w);
          if (iu != this->SharedIndex[n].end() && iw != this->SharedIndex[n].end())
          {
            send[n].insert(send[n].end(),
              { iu->second,
                iw->second,
                this->Gid[t],
                this->FanAt(t, k),
                this->FanAt(t, (k + 1) % 3),
                this->Topo.TriangleComponent[t],
                this->Flip[t],
                this->Mesh.GetEdgeValence(this->Mesh.GetEdgeId(t, k)) });
          }
        }
      });
    return send;
  }

  struct Match
  {
    size_t Neighbour;
    const long long* Entry;
  };

  /// The neighbours' border half-edges on the same two points as half-edge (t, k).
  std::vector<Match> MatchesOf(int t, int k, const Buffers& received) const
  {
    std::vector<Match> matches;
    const int u = this->Mesh.GetTriangle(t)[k], w = this->Mesh.GetTriangle(t)[(k + 1) % 3];
    for (size_t n = 0; n < this->Neighbours.size(); ++n)
    {
      auto iu = this->SharedIndex[n].find(u), iw = this->SharedIndex[n].find(w);
      if (iu == this->SharedIndex[n].end() || iw == this->SharedIndex[n].end())
      {
        continue;
      }
      const std::vector<long long>& in = received[n];
      for (size_t e = this->Neighbours[n].Points.size(); e + EdgeEntry <= in.size(); e += EdgeEntry)
      {
        if ((in[e] == iu->second && in[e + 1] == iw->second) ||
          (in[e] == iw->second && in[e + 1] == iu->second))
        {
          matches.push_back({ n, &in[e] });
        }
      }
    }
    return matches;
  }

  /// Each border half-edge: on the surface's boundary (no match), an edge shared with one
  /// neighbour (components, fans and orientation joined), or non-manifold.
  void MatchSharedEdges(const Buffers& received)
  {
    this->SharedEdges.assign(this->Topo.GetNumberOfComponents(), 0);
    std::set<int> reported;
    this->ForEachBorderHalfEdge(
      [&](int t, int k)
      {
        const int valence = this->Mesh.GetEdgeValence(this->Mesh.GetEdgeId(t, k));
        const std::vector<Match> matches = this->MatchesOf(t, k, received);
        if (matches.empty() && valence == 1)
        {
          this->Boundary.push_back(3 * t + k);
          return;
        }
        bool lowest = true;
        for (const Match& m : matches)
        {
          lowest = lowest && this->Rank < this->Neighbours[m.Neighbour].Rank;
        }
        if (!lowest)
        {
          --this->SharedEdges[this->Topo.TriangleComponent[t]]; // counted by a lower rank
        }
        if (matches.size() != 1 || valence != 1 || matches[0].Entry[7] != 1)
        {
          // More than two triangles: no neighbours across it, as in one process.
          if (lowest && valence <= 2 && reported.insert(this->Mesh.GetEdgeId(t, k)).second)
          {
            this->Record.NonManifoldEdges.push_back(this->Gid[t]);
          }
          return;
        }
        this->JoinAcross(t, k, matches[0]);
      });
    for (const NonManifoldEdge& e : this->Mesh.GetNonManifoldEdges())
    {
      this->Record.NonManifoldEdges.push_back(this->Gid[e.Triangles.front()]);
    }
  }

  /// Half-edge (t, k) and its one match on a neighbour: the same edge of the surface.
  void JoinAcross(int t, int k, const Match& m)
  {
    const long long* e = m.Entry;
    const int other = this->Neighbours[m.Neighbour].Rank;
    if (this->Rank > other)
    {
      return; // recorded by the lower rank
    }
    const int u = this->Mesh.GetTriangle(t)[k];
    const bool same = e[0] == this->SharedIndex[m.Neighbour].at(u);
    if (same)
    {
      this->Record.Misoriented.insert(this->Record.Misoriented.end(), { this->Gid[t], e[2] });
    }
    const long long theirFanAtU = same ? e[3] : e[4];
    const long long theirFanAtW = same ? e[4] : e[3];
    this->Record.Unions.insert(this->Record.Unions.end(),
      { ComponentUnion,
        this->Topo.TriangleComponent[t],
        other,
        e[5],
        this->Flip[t] ^ e[6] ^ (same ? 1 : 0),
        FanUnion,
        this->FanAt(t, k),
        other,
        theirFanAtU,
        0,
        FanUnion,
        this->FanAt(t, (k + 1) % 3),
        other,
        theirFanAtW,
        0 });
  }

  /// Points shared with a neighbour are one vertex.
  void JoinSharedPoints(const Buffers& received)
  {
    for (size_t n = 0; n < this->Neighbours.size(); ++n)
    {
      const std::vector<vtkIdType>& points = this->Neighbours[n].Points;
      for (size_t i = 0; this->Rank < this->Neighbours[n].Rank && i < points.size(); ++i)
      {
        this->Record.Unions.insert(this->Record.Unions.end(),
          { VertexUnion,
            this->VertexNode.at(static_cast<int>(points[i])),
            this->Neighbours[n].Rank,
            received[n][i],
            0 });
      }
    }
  }

  /// Boundary chains: the boundary half-edges joined at their points.
  void BuildBoundaryChains()
  {
    std::vector<int> parent(this->Boundary.size());
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](int i)
    {
      while (parent[i] != i)
      {
        i = parent[i] = parent[parent[i]];
      }
      return i;
    };
    for (size_t b = 0; b < this->Boundary.size(); ++b)
    {
      const int t = this->Boundary[b] / 3, k = this->Boundary[b] % 3;
      for (int v : { this->Mesh.GetTriangle(t)[k], this->Mesh.GetTriangle(t)[(k + 1) % 3] })
      {
        auto at = this->PointEdge.emplace(v, static_cast<int>(b));
        parent[find(static_cast<int>(b))] = find(at.first->second);
      }
    }
    std::map<int, int> chainOfRoot;
    this->ChainOfEdge.resize(this->Boundary.size());
    for (size_t b = 0; b < this->Boundary.size(); ++b)
    {
      const int t = this->Boundary[b] / 3, k = this->Boundary[b] % 3;
      auto at =
        chainOfRoot.emplace(find(static_cast<int>(b)), static_cast<int>(chainOfRoot.size()));
      const int chain = at.first->second;
      this->ChainOfEdge[b] = chain;
      const long long key = 3 * this->Gid[t] + k;
      if (at.second)
      {
        this->Record.Chains.insert(
          this->Record.Chains.end(), { key, this->Topo.TriangleComponent[t] });
        this->Record.ChainLengths.push_back(0.0);
      }
      long long& first = this->Record.Chains[ChainEntry * chain];
      first = std::min(first, key);
      this->Record.ChainLengths[chain] +=
        Distance(this->Mesh.GetCornerPosition(t, k), this->Mesh.GetCornerPosition(t, (k + 1) % 3));
    }
  }

  /// Round 2: the chain at each shared point; chains meeting at a point are one loop.
  void JoinChains()
  {
    Buffers send(this->Neighbours.size());
    for (size_t n = 0; n < this->Neighbours.size(); ++n)
    {
      for (vtkIdType v : this->Neighbours[n].Points)
      {
        send[n].push_back(this->ChainAtPoint(static_cast<int>(v)));
      }
    }
    const Buffers there = this->Piece.Exchange(send);
    for (size_t n = 0; n < this->Neighbours.size(); ++n)
    {
      const std::vector<vtkIdType>& points = this->Neighbours[n].Points;
      for (size_t i = 0; this->Rank < this->Neighbours[n].Rank && i < points.size(); ++i)
      {
        const int mine = this->ChainAtPoint(static_cast<int>(points[i]));
        if (mine >= 0 && there[n][i] >= 0)
        {
          this->Record.Unions.insert(this->Record.Unions.end(),
            { ChainUnion, mine, this->Neighbours[n].Rank, there[n][i], 0 });
        }
      }
    }
  }

  /// This piece's own problems, named by global cell ids.
  void AddLocalProblems()
  {
    for (const SurfaceProblem& p : this->Piece.GetSurface().Check.Problems)
    {
      std::vector<long long>* ids = p.Kind == "DegenerateTriangle" ? &this->Record.Degenerate
        : p.Kind == "RepeatedVertexIndex"                          ? &this->Record.Repeated
        : p.Kind == "InconsistentOrientation"                      ? &this->Record.Misoriented
                                                                   : nullptr;
      for (long long t : ids ? p.Ids : std::vector<long long>())
      {
        ids->push_back(this->Gid[t]);
      }
    }
    for (int t = 0; t < this->Mesh.GetNumberOfTriangles(); ++t)
    {
      for (int k = 0; this->Mesh.IsUsable(t) && k < 3; ++k)
      {
        if (!IsFinite(this->Mesh.GetCornerPosition(t, k)))
        {
          this->Record.NonFinite.push_back(this->Gid[t]);
          break;
        }
      }
    }
  }

  /// Per local component: smallest global id and counts (shared edges counted once, fans at
  /// shared points left to the first rank).
  void AddComponents()
  {
    const int nc = this->Topo.GetNumberOfComponents();
    std::vector<long long> minGid(nc, -1);
    for (int t = 0; t < this->Mesh.GetNumberOfTriangles(); ++t)
    {
      const int c = this->Topo.TriangleComponent[t];
      if (c >= 0 && (minGid[c] < 0 || this->Gid[t] < minGid[c]))
      {
        minGid[c] = this->Gid[t];
      }
    }
    for (int c = 0; c < nc; ++c)
    {
      const ComponentTopology& ct = this->Topo.Components[c];
      this->Record.Components.insert(this->Record.Components.end(),
        { minGid[c],
          ct.Triangles,
          ct.Edges + this->SharedEdges[c],
          ct.Vertices - this->SharedFans[c],
          ct.Orientable ? 1 : 0 });
    }
  }

  const vtkBoolSurfSurfacePiece& Piece;
  const TriangleMesh& Mesh;
  const MeshTopology& Topo;
  const std::vector<long long>& Gid;
  const std::vector<vtkBoolSurfSurfacePiece::Neighbour>& Neighbours;
  const int Rank;
  const std::vector<int> Flip;
  PieceRecord Record;
  std::map<int, int> VertexNode;               ///< by shared point
  std::vector<std::map<int, int>> SharedIndex; ///< per neighbour: point -> index in its list
  std::map<int, int> CornerFan;                ///< corners at shared points -> fan node
  std::vector<long long> SharedFans;           ///< per component: fan nodes
  std::vector<long long> SharedEdges;          ///< per component: edges a lower rank counts
  std::vector<int> Boundary;                   ///< half-edges on the surface's boundary
  std::map<int, int> PointEdge;                ///< a boundary half-edge at each boundary point
  std::vector<int> ChainOfEdge;                ///< per boundary half-edge
};

/// Every record to the first rank, which resolves them; each rank gets back its own numbers
/// (components then chains), every rank the field data in `resolved`.
std::vector<long long> ResolveOnFirstRank(vtkMultiProcessController* controller,
  const PieceRecord& record,
  ResolvedPieces& resolved)
{
  const int rank = controller->GetLocalProcessId();
  const int ranks = controller->GetNumberOfProcesses();
  const std::vector<long long> flat = record.Flatten();
  long long counts[2] = { static_cast<long long>(flat.size()),
    static_cast<long long>(record.ChainLengths.size()) };
  std::vector<long long> allCounts(2 * static_cast<size_t>(ranks));
  controller->Gather(counts, allCounts.data(), 2, 0);
  std::vector<long long> sizes(ranks), offsets(ranks), lengthCounts(ranks), lengthOffsets(ranks);
  long long total = 0, totalLengths = 0;
  for (int r = 0; r < ranks; ++r)
  {
    sizes[r] = allCounts[2 * r];
    lengthCounts[r] = allCounts[2 * r + 1];
    offsets[r] = total;
    lengthOffsets[r] = totalLengths;
    total += sizes[r];
    totalLengths += lengthCounts[r];
  }
  std::vector<long long> all(static_cast<size_t>(std::max<long long>(total, 1)));
  std::vector<double> lengths(static_cast<size_t>(std::max<long long>(totalLengths, 1)));
  controller->GatherV(flat.data(), all.data(), counts[0], sizes.data(), offsets.data(), 0);
  controller->GatherV(record.ChainLengths.data(),
    lengths.data(),
    counts[1],
    lengthCounts.data(),
    lengthOffsets.data(),
    0);
  std::vector<long long> back, backSizes(ranks), backOffsets(ranks);
  if (rank == 0)
  {
    std::vector<PieceRecord> records;
    for (int r = 0; r < ranks; ++r)
    {
      records.push_back(PieceRecord::Read(&all[offsets[r]]));
    }
    resolved =
      ResolvePieces(records, lengths, lengthOffsets, SurfaceCheckOptions().MaxIdsInMessage);
    for (int r = 0; r < ranks; ++r)
    {
      backOffsets[r] = static_cast<long long>(back.size());
      backSizes[r] = static_cast<long long>(resolved.PerRank[r].size());
      back.insert(back.end(), resolved.PerRank[r].begin(), resolved.PerRank[r].end());
    }
  }
  const size_t numbers = record.Components.size() / ComponentEntry + record.ChainLengths.size();
  std::vector<long long> mine(numbers + 1);
  controller->ScatterV(back.data(),
    mine.data(),
    backSizes.data(),
    backOffsets.data(),
    static_cast<vtkIdType>(numbers),
    0);
  mine.resize(numbers);
  return mine;
}

/// The first rank's field data to every rank.
void BroadcastField(vtkMultiProcessController* controller, ResolvedPieces& resolved)
{
  std::vector<long long> field;
  std::string problems;
  for (const ComponentTopology& c : resolved.Components)
  {
    field.insert(field.end(), { c.Genus, c.BoundaryLoops, c.EulerCharacteristic, c.Orientable });
  }
  field.push_back(resolved.IsManifold ? 1 : 0);
  for (const std::string& line : resolved.Problems)
  {
    problems += line + '\n';
  }
  long long header[3] = { static_cast<long long>(field.size()),
    static_cast<long long>(resolved.LoopLengths.size()),
    static_cast<long long>(problems.size()) };
  controller->Broadcast(header, 3, 0);
  field.resize(static_cast<size_t>(header[0]));
  resolved.LoopLengths.resize(static_cast<size_t>(header[1]));
  problems.resize(static_cast<size_t>(header[2]));
  controller->Broadcast(field.data(), header[0], 0);
  if (header[1] > 0)
  {
    controller->Broadcast(resolved.LoopLengths.data(), header[1], 0);
  }
  if (header[2] > 0)
  {
    controller->Broadcast(&problems[0], header[2], 0);
  }
  resolved.Components.assign((field.size() - 1) / 4, ComponentTopology());
  for (size_t c = 0; c < resolved.Components.size(); ++c)
  {
    ComponentTopology& t = resolved.Components[c];
    t.Genus = static_cast<int>(field[4 * c]);
    t.BoundaryLoops = static_cast<int>(field[4 * c + 1]);
    t.EulerCharacteristic = static_cast<int>(field[4 * c + 2]);
    t.Orientable = field[4 * c + 3] != 0;
  }
  resolved.IsManifold = field.back() != 0;
  resolved.Problems.clear();
  size_t start = 0;
  for (size_t end; (end = problems.find('\n', start)) != std::string::npos; start = end + 1)
  {
    resolved.Problems.push_back(problems.substr(start, end - start));
  }
}

} // namespace

//------------------------------------------------------------------------------
void CheckDistributedSurface(const vtkBoolSurfSurfacePiece& piece, SurfaceCheckOutput& out)
{
  vtkMultiProcessController* controller = piece.GetController();
  const vtkSurfaceInput& surface = piece.GetSurface();
  const int nt = surface.Mesh->GetNumberOfTriangles();
  const int nv = surface.Mesh->GetNumberOfVertices();
  const int nc = surface.Topology->GetNumberOfComponents();
  PieceCheck check(piece);
  const PieceRecord record = check.Run();
  ResolvedPieces resolved;
  const std::vector<long long> mine = ResolveOnFirstRank(controller, record, resolved);
  BroadcastField(controller, resolved);

  // This rank's piece: components and loops by their global numbers.
  out = SurfaceCheckOutput();
  out.ComponentId.assign(nt, -1);
  for (int t = 0; t < nt; ++t)
  {
    const int c = surface.Topology->TriangleComponent[t];
    out.ComponentId[t] = c < 0 ? -1 : static_cast<int>(mine[c]);
  }
  out.BoundaryLoopId.assign(nv, -1);
  for (int v = 0; v < nv; ++v)
  {
    const int chain = check.ChainAtPoint(v);
    out.BoundaryLoopId[v] = chain < 0 ? -1 : static_cast<int>(mine[nc + chain]);
  }
  // Round 3: a point on the boundary of another rank's triangles only takes that loop.
  const std::vector<vtkBoolSurfSurfacePiece::Neighbour>& neighbours = piece.GetNeighbours();
  Buffers send(neighbours.size());
  for (size_t n = 0; n < neighbours.size(); ++n)
  {
    for (vtkIdType v : neighbours[n].Points)
    {
      send[n].push_back(out.BoundaryLoopId[v]);
    }
  }
  const Buffers there = piece.Exchange(send);
  for (size_t n = 0; n < neighbours.size(); ++n)
  {
    for (size_t i = 0; i < neighbours[n].Points.size(); ++i)
    {
      int& loop = out.BoundaryLoopId[neighbours[n].Points[i]];
      if (there[n][i] >= 0 && (loop < 0 || there[n][i] < loop))
      {
        loop = static_cast<int>(there[n][i]);
      }
    }
  }
  out.Components = resolved.Components;
  out.IsManifold = resolved.IsManifold;
  out.BoundaryLoopLengths = resolved.LoopLengths;
  for (const std::string& w : surface.Warnings)
  {
    out.Problems.push_back("Warning Conversion: " + w);
  }
  out.Problems.insert(out.Problems.end(), resolved.Problems.begin(), resolved.Problems.end());
}

} // namespace boolsurf

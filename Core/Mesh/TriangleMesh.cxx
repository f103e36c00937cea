#include "Mesh/TriangleMesh.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <limits>
#include <utility>

#include <tbb/parallel_for.h>

namespace boolsurf
{

//------------------------------------------------------------------------------
TriangleMesh::TriangleMesh(std::vector<Vec3> positions, std::vector<Triangle> triangles)
  : Positions(std::move(positions))
  , Triangles(std::move(triangles))
{
  static std::atomic<std::uint64_t> lastSerial{ 0 };
  this->Serial = ++lastSerial;
  const int nv = this->GetNumberOfVertices();
  this->Usable.resize(this->Triangles.size());
  for (size_t t = 0; t < this->Triangles.size(); ++t)
  {
    const Triangle& tri = this->Triangles[t];
    bool inRange = true;
    for (int v : tri)
    {
      inRange = inRange && v >= 0 && v < nv;
    }
    const bool distinct = tri[0] != tri[1] && tri[1] != tri[2] && tri[2] != tri[0];
    this->Usable[t] = inRange && distinct;
  }
  this->BuildVertexCorners();
  this->BuildTwins();
}

//------------------------------------------------------------------------------
Vec3 TriangleMesh::Evaluate(int t, double u, double v) const
{
  const Triangle& tri = this->Triangles[t];
  return (1.0 - u - v) * this->Positions[tri[0]] + u * this->Positions[tri[1]] +
    v * this->Positions[tri[2]];
}

//------------------------------------------------------------------------------
// Counting sort of corners by vertex: linear, and corners come out sorted by corner id,
// which keeps every later traversal deterministic.
void TriangleMesh::BuildVertexCorners()
{
  const int nv = this->GetNumberOfVertices();
  const int nt = this->GetNumberOfTriangles();
  this->CornerOffset.assign(nv + 1, 0);
  for (int t = 0; t < nt; ++t)
  {
    if (this->Usable[t])
    {
      for (int v : this->Triangles[t])
      {
        ++this->CornerOffset[v + 1];
      }
    }
  }
  for (int v = 0; v < nv; ++v)
  {
    this->CornerOffset[v + 1] += this->CornerOffset[v];
  }
  this->CornerList.resize(this->CornerOffset[nv]);
  std::vector<int> fill(this->CornerOffset.begin(), this->CornerOffset.end() - 1);
  for (int t = 0; t < nt; ++t)
  {
    if (this->Usable[t])
    {
      for (int k = 0; k < 3; ++k)
      {
        this->CornerList[fill[this->Triangles[t][k]]++] = 3 * t + k;
      }
    }
  }
}

namespace
{
// BuildTwins' marks per half-edge.
enum : std::uint8_t
{
  Unmarked,
  Covered,
  Owned
};

// Triangles per block of BuildTwins' parallel passes.
constexpr int TwinBlockSize = 1 << 13;

struct Partner
{
  int HalfEdge;
  bool SameDirection;
};

// The other half-edges between the ends of half-edge h, whichever way they run.
void FindPartners(const TriangleMesh& mesh, int h, std::vector<Partner>& partners)
{
  partners.clear();
  const int t = h / 3, k = h % 3;
  const Triangle& tri = mesh.GetTriangle(t);
  const int a = tri[k];
  const int b = tri[(k + 1) % 3];
  for (int c : mesh.GetVertexCorners(a))
  {
    const int t2 = c / 3;
    if (t2 == t)
    {
      continue;
    }
    const int j = c % 3;
    const Triangle& tri2 = mesh.GetTriangle(t2);
    if (tri2[(j + 2) % 3] == b)
    {
      partners.push_back({ 3 * t2 + (j + 2) % 3, false }); // edge b->a: properly oriented
    }
    else if (tri2[(j + 1) % 3] == b)
    {
      partners.push_back({ c, true }); // edge a->b again: flipped neighbour
    }
  }
}

// visit(block, half-edge, partners scratch) for every half-edge of a usable triangle, blocks of
// TwinBlockSize triangles in parallel.
template <class Visit>
void ForEachUsableHalfEdge(const TriangleMesh& mesh, int blocks, const Visit& visit)
{
  const int nt = mesh.GetNumberOfTriangles();
  tbb::parallel_for(0,
    blocks,
    [&](int b)
    {
      std::vector<Partner> partners;
      const int end = 3 * std::min(nt, (b + 1) * TwinBlockSize);
      for (int h = 3 * b * TwinBlockSize; h < end; ++h)
      {
        if (mesh.IsUsable(h / 3))
        {
          visit(b, h, partners);
        }
      }
    });
}

// Passes 1 and 2 of BuildTwins (see there): every edge's owner half-edge marked Owned, its
// other half-edges Covered, and the twins of two-triangle edges set.
void MarkEdgeOwners(const TriangleMesh& mesh,
  int blocks,
  std::vector<int>& twin,
  std::vector<std::uint8_t>& mark)
{
  const auto setTwins = [&twin](int h, const std::vector<Partner>& partners)
  {
    if (partners.size() == 1)
    {
      twin[h] = partners[0].HalfEdge;
      twin[partners[0].HalfEdge] = h;
    }
  };
  const auto ascending = [&mesh](int h)
  {
    const Triangle& tri = mesh.GetTriangle(h / 3);
    return tri[h % 3] < tri[(h % 3 + 1) % 3];
  };
  ForEachUsableHalfEdge(mesh,
    blocks,
    [&](int, int h, std::vector<Partner>& partners)
    {
      if (!ascending(h))
      {
        return;
      }
      FindPartners(mesh, h, partners);
      int owner = h;
      for (const Partner& p : partners)
      {
        if (p.SameDirection && p.HalfEdge < h)
        {
          return; // a lower ascending half-edge finds this group
        }
        owner = std::min(owner, p.HalfEdge);
      }
      mark[h] = h == owner ? Owned : Covered;
      for (const Partner& p : partners)
      {
        mark[p.HalfEdge] = p.HalfEdge == owner ? Owned : Covered;
      }
      setTwins(h, partners);
    });
  ForEachUsableHalfEdge(mesh,
    blocks,
    [&](int, int h, std::vector<Partner>& partners)
    {
      if (mark[h] != Unmarked)
      {
        return;
      }
      FindPartners(mesh, h, partners); // all unmarked too: none is ascending
      for (const Partner& p : partners)
      {
        if (p.HalfEdge < h)
        {
          return;
        }
      }
      mark[h] = Owned;
      setTwins(h, partners);
    });
}
} // namespace

//------------------------------------------------------------------------------
// For half-edge a->b, the partners are the other triangles at a that also contain b: with
// h itself, the edge's half-edges. An edge belongs to its lowest half-edge (corner id) and
// edge ids follow that order, as a serial pass over the triangles would meet them, so the
// result is the same on any number of threads. The work runs over fixed blocks of
// triangles, each block independent, in passes:
// 1. the lowest ascending half-edge of each edge (a < b; a properly oriented edge has one)
//    finds the partners once, marks the group's half-edges (Covered, the owner Owned) and
//    sets the twins of a two-triangle edge;
// 2. half-edges left unmarked (edges with no ascending half-edge: boundary edges and flipped
//    pairs running from the higher vertex; rare) find their partners, and the owner marks
//    itself and sets the twins;
// 3. a prefix sum over the blocks' owner counts gives each block its first edge id, and each
//    owner numbers its edge and its partners; non-manifold and misoriented edges are merged
//    in owner order.
// Within a pass each entry is written by one thread, and nothing a pass writes is read in it.
void TriangleMesh::BuildTwins()
{
  const int nt = this->GetNumberOfTriangles();
  this->Twin.assign(3 * static_cast<size_t>(nt), -1);
  this->NonManifold.clear();
  this->Misoriented.clear();
  std::vector<std::uint8_t> mark(3 * static_cast<size_t>(nt), Unmarked);
  const int blocks = (nt + TwinBlockSize - 1) / TwinBlockSize;
  MarkEdgeOwners(*this, blocks, this->Twin, mark);
  constexpr int blockSize = TwinBlockSize;

  std::vector<int> blockFirstEdge(static_cast<size_t>(blocks) + 1, 0);
  tbb::parallel_for(0,
    blocks,
    [&](int b)
    {
      const int end = 3 * std::min(nt, (b + 1) * blockSize);
      blockFirstEdge[b + 1] =
        static_cast<int>(std::count(mark.begin() + 3 * b * blockSize, mark.begin() + end, Owned));
    });
  for (int b = 0; b < blocks; ++b)
  {
    blockFirstEdge[b + 1] += blockFirstEdge[b];
  }
  const int edgeCount = blockFirstEdge[blocks];
  this->EdgeHalfEdge.assign(static_cast<size_t>(edgeCount), -1);
  this->NonManifoldValence.clear();
  // Edge ids by rank: the owner bits of each 64 half-edges and the first edge id among them
  // (triangle blocks hold 3 * 2^13 half-edges, a multiple of 64, so each rank block lies in
  // one triangle block and is written by its thread).
  this->EdgeRank.assign((3 * static_cast<size_t>(nt) + 63) / 64, OwnerBlock());
  tbb::parallel_for(0,
    blocks,
    [&](int b)
    {
      const int begin = 3 * b * blockSize;
      const int end = 3 * std::min(nt, (b + 1) * blockSize);
      int edge = blockFirstEdge[b];
      for (int first = begin; first < end; first += 64)
      {
        OwnerBlock& block = this->EdgeRank[first >> 6];
        block.FirstEdge = edge;
        for (int h = first; h < std::min(end, first + 64); ++h)
        {
          if (mark[h] == Owned)
          {
            block.Owners |= std::uint64_t(1) << (h - first);
            ++edge;
          }
        }
      }
    });
  std::vector<std::vector<int>> blockSpecial(static_cast<size_t>(blocks)); // odd edges' owners
  std::vector<std::vector<std::pair<int, int>>> blockLoose(static_cast<size_t>(blocks));
  std::vector<int> nextEdge(blockFirstEdge.begin(), blockFirstEdge.end() - 1);
  ForEachUsableHalfEdge(*this,
    blocks,
    [&](int b, int h, std::vector<Partner>& partners)
    {
      if (mark[h] != Owned)
      {
        return;
      }
      const int twin = this->Twin[h];
      if (twin >= 0)
      {
        partners.assign(
          1, { twin, this->Triangles[twin / 3][twin % 3] == this->Triangles[h / 3][h % 3] });
      }
      else
      {
        FindPartners(*this, h, partners); // a boundary or non-manifold edge
      }
      const int e = nextEdge[b]++;
      this->EdgeHalfEdge[e] = h;
      if (twin < 0)
      {
        // The other half-edges of a non-manifold edge have no twin to find their owner by.
        for (const Partner& p : partners)
        {
          blockLoose[b].emplace_back(p.HalfEdge, e);
        }
      }
      if (partners.size() > 1 || (partners.size() == 1 && partners[0].SameDirection))
      {
        blockSpecial[b].push_back(h);
      }
    });

  this->NonManifoldHalfEdge.clear();
  for (const std::vector<std::pair<int, int>>& loose : blockLoose)
  {
    this->NonManifoldHalfEdge.insert(this->NonManifoldHalfEdge.end(), loose.begin(), loose.end());
  }
  std::sort(this->NonManifoldHalfEdge.begin(), this->NonManifoldHalfEdge.end());

  std::vector<Partner> partners;
  for (const std::vector<int>& special : blockSpecial)
  {
    for (const int h : special)
    {
      const int t = h / 3, k = h % 3;
      const int a = this->Triangles[t][k];
      const int b = this->Triangles[t][(k + 1) % 3];
      FindPartners(*this, h, partners);
      if (partners.size() == 1)
      {
        this->Misoriented.push_back({ a, b, t, partners[0].HalfEdge / 3 });
        continue;
      }
      this->NonManifoldValence.emplace_back(
        this->RankOfOwner(h), static_cast<int>(partners.size()) + 1); // in edge order
      NonManifoldEdge nm;
      nm.V0 = std::min(a, b);
      nm.V1 = std::max(a, b);
      nm.Triangles.push_back(t);
      for (const Partner& p : partners)
      {
        nm.Triangles.push_back(p.HalfEdge / 3);
      }
      this->NonManifold.push_back(std::move(nm));
    }
  }
}

//------------------------------------------------------------------------------
int TriangleMesh::GetLooseEdgeId(int h) const
{
  if (!this->Usable[h / 3])
  {
    return -1;
  }
  if (this->EdgeRank[h >> 6].Owners >> (h & 63) & 1)
  {
    return this->RankOfOwner(h); // a boundary edge, or the owner of a non-manifold one
  }
  const auto at = std::lower_bound(this->NonManifoldHalfEdge.begin(),
    this->NonManifoldHalfEdge.end(),
    std::make_pair(h, std::numeric_limits<int>::min()));
  return at != this->NonManifoldHalfEdge.end() && at->first == h ? at->second : -1;
}

//------------------------------------------------------------------------------
int TriangleMesh::GetEdgeValence(int e) const
{
  const int h = this->EdgeHalfEdge[e];
  if (this->Twin[h] >= 0)
  {
    return 2;
  }
  const auto at = std::lower_bound(
    this->NonManifoldValence.begin(), this->NonManifoldValence.end(), std::make_pair(e, 0));
  return at != this->NonManifoldValence.end() && at->first == e ? at->second : 1;
}

} // namespace boolsurf

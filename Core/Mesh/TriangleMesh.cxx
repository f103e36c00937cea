#include "Mesh/TriangleMesh.h"

#include <algorithm>
#include <atomic>
#include <utility>

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

//------------------------------------------------------------------------------
// For half-edge a->b, the partners are the other triangles at a that also contain b. The
// first half-edge of an edge (in corner-id order) finds all partners at once and assigns the
// edge id, the twins and any problem; the partners then skip the edge.
void TriangleMesh::BuildTwins()
{
  const int nt = this->GetNumberOfTriangles();
  this->Twin.assign(3 * static_cast<size_t>(nt), -1);
  this->HalfEdgeEdge.assign(3 * static_cast<size_t>(nt), -1);
  this->EdgeHalfEdge.clear();
  this->EdgeHalfEdge.reserve(3 * static_cast<size_t>(nt) / 2 + 1);
  this->EdgeValence.clear();
  this->EdgeValence.reserve(3 * static_cast<size_t>(nt) / 2 + 1);

  struct Partner
  {
    int HalfEdge;
    bool SameDirection;
  };
  std::vector<Partner> partners;
  for (int t = 0; t < nt; ++t)
  {
    if (!this->Usable[t])
    {
      continue;
    }
    const Triangle& tri = this->Triangles[t];
    for (int k = 0; k < 3; ++k)
    {
      const int h = 3 * t + k;
      if (this->HalfEdgeEdge[h] >= 0)
      {
        continue;
      }
      const int a = tri[k];
      const int b = tri[(k + 1) % 3];
      partners.clear();
      for (int c : this->GetVertexCorners(a))
      {
        const int t2 = c / 3;
        if (t2 == t)
        {
          continue;
        }
        const int j = c % 3;
        const Triangle& tri2 = this->Triangles[t2];
        if (tri2[(j + 2) % 3] == b)
        {
          partners.push_back({ 3 * t2 + (j + 2) % 3, false }); // edge b->a: properly oriented
        }
        else if (tri2[(j + 1) % 3] == b)
        {
          partners.push_back({ c, true }); // edge a->b again: flipped neighbour
        }
      }
      const int e = static_cast<int>(this->EdgeHalfEdge.size());
      this->EdgeHalfEdge.push_back(h);
      this->EdgeValence.push_back(static_cast<int>(partners.size()) + 1);
      this->HalfEdgeEdge[h] = e;
      for (const Partner& p : partners)
      {
        this->HalfEdgeEdge[p.HalfEdge] = e;
      }
      if (partners.size() == 1)
      {
        this->Twin[h] = partners[0].HalfEdge;
        this->Twin[partners[0].HalfEdge] = h;
        if (partners[0].SameDirection)
        {
          this->Misoriented.push_back({ a, b, t, partners[0].HalfEdge / 3 });
        }
      }
      else if (partners.size() > 1)
      {
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
}

} // namespace boolsurf

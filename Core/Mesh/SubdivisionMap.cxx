#include "Mesh/SubdivisionMap.h"

#include <algorithm>
#include <cstdint>
#include <unordered_map>

namespace boolsurf
{

namespace
{

std::uint64_t EdgeKey(int a, int b)
{
  const auto lo = static_cast<std::uint64_t>(std::min(a, b));
  const auto hi = static_cast<std::uint64_t>(std::max(a, b));
  return (hi << 32) | lo;
}

struct TripleHash
{
  std::size_t operator()(const std::array<int, 3>& t) const
  {
    std::uint64_t h = 1469598103934665603ull;
    for (int v : t)
    {
      h = (h ^ static_cast<std::uint64_t>(static_cast<unsigned>(v))) * 1099511628211ull;
    }
    return static_cast<std::size_t>(h);
  }
};

std::array<int, 3> Sorted(std::array<int, 3> t)
{
  std::sort(t.begin(), t.end());
  return t;
}

std::string Name(const Triangle& t)
{
  return "(" + std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]) +
    ")";
}

} // namespace

//------------------------------------------------------------------------------
bool SubdivisionMap::Build(const std::vector<Triangle>& parent,
  int parentVertices,
  const std::vector<Triangle>& child,
  std::string& error)
{
  this->Children.assign(parent.size(), { -1, -1, -1, -1 });
  this->Midpoints.assign(parent.size(), { -1, -1, -1 });
  this->ParentTriangles = parent;
  this->ChildTriangles = child;
  if (child.size() != 4 * parent.size())
  {
    error = "the subdivided surface has " + std::to_string(child.size()) + " triangles for " +
      std::to_string(parent.size()) + " (a 1-to-4 split has " + std::to_string(4 * parent.size()) +
      ")";
    return false;
  }
  // A new vertex is the midpoint of the edge joining the two old vertices whose corner
  // triangles contain it.
  int childVertices = 0;
  for (const Triangle& t : child)
  {
    for (int v : t)
    {
      childVertices = std::max(childVertices, v + 1);
    }
  }
  std::vector<std::array<int, 2>> ends(static_cast<std::size_t>(childVertices), { -1, -1 });
  std::unordered_map<std::array<int, 3>, int, TripleHash> childOf;
  childOf.reserve(child.size());
  for (std::size_t c = 0; c < child.size(); ++c)
  {
    const Triangle& t = child[c];
    childOf.emplace(Sorted(t), static_cast<int>(c));
    int old = -1, olds = 0;
    for (int v : t)
    {
      if (v < 0)
      {
        error = "subdivided triangle " + std::to_string(c) + " " + Name(t) + " has a negative id";
        return false;
      }
      if (v < parentVertices)
      {
        old = v;
        ++olds;
      }
    }
    if (olds > 1)
    {
      error = "subdivided triangle " + std::to_string(c) + " " + Name(t) + " has " +
        std::to_string(olds) + " vertices of the coarse surface (a 1-to-4 split has at most one)";
      return false;
    }
    if (olds == 0)
    {
      continue; // a middle triangle
    }
    for (int m : t)
    {
      if (m == old)
      {
        continue;
      }
      auto& e = ends[m];
      if (e[0] == old || e[1] == old)
      {
        continue;
      }
      if (e[1] >= 0)
      {
        error = "new vertex " + std::to_string(m) + " lies in corner triangles of three coarse " +
          "vertices (" + std::to_string(e[0]) + ", " + std::to_string(e[1]) + ", " +
          std::to_string(old) + "): it is no edge midpoint";
        return false;
      }
      (e[0] < 0 ? e[0] : e[1]) = old;
    }
  }
  for (int m = parentVertices; m < childVertices; ++m)
  {
    if (ends[m][1] < 0)
    {
      error = "new vertex " + std::to_string(m) + " is in the corner triangles of " +
        (ends[m][0] < 0 ? std::string("no coarse vertex") : "one coarse vertex only") +
        ": it is no edge midpoint";
      return false;
    }
  }
  std::unordered_multimap<std::uint64_t, int> midpointsOf;
  midpointsOf.reserve(ends.size());
  for (int m = parentVertices; m < childVertices; ++m)
  {
    if (ends[m][1] >= 0)
    {
      midpointsOf.emplace(EdgeKey(ends[m][0], ends[m][1]), m);
    }
  }
  auto childWith = [&](int a, int b, int c)
  {
    auto it = childOf.find(Sorted({ a, b, c }));
    return it == childOf.end() ? -1 : it->second;
  };
  for (std::size_t p = 0; p < parent.size(); ++p)
  {
    const Triangle& t = parent[p];
    bool found = false;
    // Usually one midpoint per edge; a coarse edge shared by non-adjacent triangles may have
    // several, and the one whose child triangles exist is this triangle's.
    auto r01 = midpointsOf.equal_range(EdgeKey(t[0], t[1]));
    for (auto i01 = r01.first; i01 != r01.second && !found; ++i01)
    {
      auto r12 = midpointsOf.equal_range(EdgeKey(t[1], t[2]));
      for (auto i12 = r12.first; i12 != r12.second && !found; ++i12)
      {
        auto r20 = midpointsOf.equal_range(EdgeKey(t[2], t[0]));
        for (auto i20 = r20.first; i20 != r20.second && !found; ++i20)
        {
          const int m01 = i01->second, m12 = i12->second, m20 = i20->second;
          const std::array<int, 4> kids = { childWith(t[0], m01, m20),
            childWith(t[1], m12, m01),
            childWith(t[2], m20, m12),
            childWith(m01, m12, m20) };
          if (std::find(kids.begin(), kids.end(), -1) == kids.end())
          {
            this->Children[p] = kids;
            this->Midpoints[p] = { m01, m12, m20 };
            found = true;
          }
        }
      }
    }
    if (!found)
    {
      error = "coarse triangle " + std::to_string(p) + " " + Name(t) +
        " has no four child triangles in the subdivided surface (is it a 1-to-4 split of this "
        "surface?)";
      return false;
    }
  }
  this->EdgeOfNewVertex.swap(ends);
  return true;
}

//------------------------------------------------------------------------------
SurfacePoint SubdivisionMap::Map(const SurfacePoint& p) const
{
  const Triangle& t = this->ParentTriangles[p.Triangle];
  const std::array<int, 3>& m = this->Midpoints[p.Triangle];
  const std::array<int, 4>& kids = this->Children[p.Triangle];
  const double w[3] = { 1 - p.U - p.V, p.U, p.V };
  // Child vertices and their weights: x = sum of weight * vertex, in the parent's parameters.
  int vertex[3];
  double weight[3];
  int child;
  if (w[0] >= 0.5 || w[1] >= 0.5 || w[2] >= 0.5)
  {
    // Corner k: (t[k], m(k,k+1), m(k-1,k)) with weights (2 w_k - 1, 2 w_{k+1}, 2 w_{k-1}).
    const int k = w[0] >= 0.5 ? 0 : (w[1] >= 0.5 ? 1 : 2);
    const int next = (k + 1) % 3, prev = (k + 2) % 3;
    child = kids[k];
    vertex[0] = t[k];
    vertex[1] = m[k];
    vertex[2] = m[prev];
    weight[1] = 2 * w[next];
    weight[2] = 2 * w[prev];
    weight[0] = 1 - weight[1] - weight[2];
  }
  else
  {
    // Middle: w_0 = (b01 + b20) / 2 and so on, so b01 = 1 - 2 w_2, b12 = 1 - 2 w_0, b20 = 1 - 2
    // w_1.
    child = kids[3];
    vertex[0] = m[0];
    vertex[1] = m[1];
    vertex[2] = m[2];
    weight[0] = 1 - 2 * w[2];
    weight[1] = 1 - 2 * w[0];
    weight[2] = 1 - 2 * w[1];
  }
  const Triangle& c = this->ChildTriangles[child];
  double u = 0, v = 0;
  for (int j = 0; j < 3; ++j)
  {
    if (c[1] == vertex[j])
    {
      u = weight[j];
    }
    else if (c[2] == vertex[j])
    {
      v = weight[j];
    }
  }
  // Rounding may leave a weight a few ulps below zero or the pair a few ulps above one.
  ClampBarycentric(u, v);
  return { child, u, v };
}

} // namespace boolsurf

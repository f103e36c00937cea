#include "Distributed/PieceMesh.h"

#include <algorithm>
#include <numeric>

namespace boolsurf
{
namespace
{

int FindSorted(const std::vector<int>& sorted, int g)
{
  const auto it = std::lower_bound(sorted.begin(), sorted.end(), g);
  return it != sorted.end() && *it == g ? static_cast<int>(it - sorted.begin()) : -1;
}

// The order that sorts `ids`, or false (with the repeated id in `repeated`) when one repeats.
bool SortedOrder(const std::vector<int>& ids, std::vector<int>& order, int& repeated)
{
  order.resize(ids.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return ids[a] < ids[b]; });
  for (size_t i = 1; i < order.size(); ++i)
  {
    if (ids[order[i]] == ids[order[i - 1]])
    {
      repeated = ids[order[i]];
      return false;
    }
  }
  return true;
}

// The owned triangles' sides on the piece border and on the surface's boundary (PieceMesh).
void ListOwnedSides(PieceMesh& piece)
{
  const TriangleMesh& mesh = piece.Mesh;
  piece.BorderHalfEdges.clear();
  piece.SurfaceBoundaryHalfEdges.clear();
  for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    for (int k = 0; k < 3 && piece.Owned[t]; ++k)
    {
      const int n = mesh.GetNeighbor(t, k);
      if (n >= 0 && !piece.Owned[n])
      {
        piece.BorderHalfEdges.push_back(3 * t + k);
      }
      const int e = mesh.GetEdgeId(t, k);
      if (e >= 0 && mesh.GetEdgeValence(e) == 1)
      {
        piece.SurfaceBoundaryHalfEdges.push_back(3 * t + k);
      }
    }
  }
}

} // namespace

//------------------------------------------------------------------------------
int PieceMesh::LocalTriangle(int g) const
{
  return FindSorted(this->GlobalTriangle, g);
}

//------------------------------------------------------------------------------
int PieceMesh::LocalVertex(int g) const
{
  return FindSorted(this->GlobalVertex, g);
}

//------------------------------------------------------------------------------
bool BuildPieceMesh(const PieceInput& input, PieceMesh& out, std::string& error)
{
  const int np = static_cast<int>(input.Positions.size());
  const int nt = static_cast<int>(input.Triangles.size());
  if (static_cast<int>(input.PointGlobalIds.size()) != np ||
    static_cast<int>(input.TriangleGlobalIds.size()) != nt ||
    static_cast<int>(input.Ghost.size()) != nt)
  {
    error = "piece: point or triangle global ids or ghost marks missing";
    return false;
  }
  std::vector<int> pointOrder, triangleOrder;
  int repeated = -1;
  if (!SortedOrder(input.PointGlobalIds, pointOrder, repeated))
  {
    error = "piece: point global id " + std::to_string(repeated) + " given twice";
    return false;
  }
  if (!SortedOrder(input.TriangleGlobalIds, triangleOrder, repeated))
  {
    error = "piece: triangle global id " + std::to_string(repeated) + " given twice";
    return false;
  }
  std::vector<int> localOfPoint(np);
  std::vector<Vec3> positions(np);
  out.GlobalVertex.resize(np);
  for (int i = 0; i < np; ++i)
  {
    localOfPoint[pointOrder[i]] = i;
    positions[i] = input.Positions[pointOrder[i]];
    out.GlobalVertex[i] = input.PointGlobalIds[pointOrder[i]];
  }
  std::vector<Triangle> triangles(nt);
  out.GlobalTriangle.resize(nt);
  out.Owned.resize(nt);
  out.NumberOfOwnedTriangles = 0;
  for (int i = 0; i < nt; ++i)
  {
    const int t = triangleOrder[i];
    for (int k = 0; k < 3; ++k)
    {
      const int p = input.Triangles[t][k];
      if (p < 0 || p >= np)
      {
        error = "piece: triangle " + std::to_string(input.TriangleGlobalIds[t]) + " names point " +
          std::to_string(p) + " of " + std::to_string(np);
        return false;
      }
      triangles[i][k] = localOfPoint[p];
    }
    out.GlobalTriangle[i] = input.TriangleGlobalIds[t];
    out.Owned[i] = input.Ghost[t] ? 0 : 1;
    out.NumberOfOwnedTriangles += out.Owned[i];
  }
  out.Mesh = TriangleMesh(std::move(positions), std::move(triangles));
  ListOwnedSides(out);
  return true;
}

} // namespace boolsurf

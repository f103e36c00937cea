#include "CellPartition.h"

#include <algorithm>

namespace boolsurf
{
namespace
{

// Bit k set when refined point id lies on (the closure of) local edge k of source triangle t.
int LocalEdgesOfPoint(const RefinedSurfaceView& s, int t, int id)
{
  const TriangleMesh& mesh = *s.Mesh;
  if (id < mesh.GetNumberOfVertices())
  {
    const Triangle& tri = mesh.GetTriangle(t);
    for (int k = 0; k < 3; ++k)
    {
      if (tri[k] == id)
      {
        return (1 << k) | (1 << ((k + 2) % 3)); // edges k and k-1 meet at corner k
      }
    }
    return 0;
  }
  if (id >= s.FirstInteriorPoint)
  {
    return 0;
  }
  const int e = (*s.EdgeOfEdgePoint)[id - mesh.GetNumberOfVertices()];
  for (int k = 0; k < 3; ++k)
  {
    if (mesh.GetEdgeId(t, k) == e)
    {
      return 1 << k;
    }
  }
  return 0;
}

} // namespace

//------------------------------------------------------------------------------
int RefinedSurfaceView::FindDirected(int t, int a, int b) const
{
  for (int r = (*this->Offset)[t]; r < (*this->Offset)[t + 1]; ++r)
  {
    const std::array<int, 3>& v = (*this->Triangles)[r];
    if ((v[0] == a && v[1] == b) || (v[1] == a && v[2] == b) || (v[2] == a && v[0] == b))
    {
      return r;
    }
  }
  return -1;
}

//------------------------------------------------------------------------------
int RefinedSurfaceView::Neighbor(int r, int j, bool& blocked) const
{
  const TriangleMesh& mesh = *this->Mesh;
  const int t = (*this->SourceTriangle)[r];
  const std::array<int, 3>& v = (*this->Triangles)[r];
  const int x = v[j], y = v[(j + 1) % 3];
  int k = j; // an unrefined triangle's edge j is the mesh edge j
  blocked = false;
  if (!(*this->Refined)[t])
  {
    // The common case, kept short: an unrefined triangle next to an unrefined triangle.
    const int n = mesh.GetNeighbor(t, j);
    if (n < 0)
    {
      return -1;
    }
    if ((*this->MeshEdgeHasBlocked)[mesh.GetEdgeId(t, j)])
    {
      blocked = this->BlockedMeshSubEdges->count(UndirectedPointPair(x, y)) > 0;
    }
    return (*this->Refined)[n] ? this->FindDirected(n, y, x) : (*this->Offset)[n];
  }
  else
  {
    const int common = LocalEdgesOfPoint(*this, t, x) & LocalEdgesOfPoint(*this, t, y);
    if (common == 0)
    {
      blocked = ((*this->Blocked)[r] >> j) & 1;
      return this->FindDirected(t, y, x);
    }
    k = common & 1 ? 0 : (common & 2 ? 1 : 2);
  }
  const int n = mesh.GetNeighbor(t, k);
  if (n < 0)
  {
    return -1;
  }
  if ((*this->MeshEdgeHasBlocked)[mesh.GetEdgeId(t, k)])
  {
    blocked = this->BlockedMeshSubEdges->count(UndirectedPointPair(x, y)) > 0;
  }
  return this->FindDirected(n, y, x);
}

//------------------------------------------------------------------------------
int FloodFillCells(const RefinedSurfaceView& surface, std::vector<int>& cellOfTriangle)
{
  const int count = static_cast<int>(surface.Triangles->size());
  cellOfTriangle.assign(count, -1);
  std::vector<int> queue;
  queue.reserve(count);
  int cells = 0;
  for (int seed = 0; seed < count; ++seed)
  {
    if (cellOfTriangle[seed] >= 0)
    {
      continue;
    }
    const int cell = cells++;
    queue.clear();
    queue.push_back(seed);
    cellOfTriangle[seed] = cell;
    for (size_t head = 0; head < queue.size(); ++head)
    {
      const int r = queue[head];
      for (int j = 0; j < 3; ++j)
      {
        bool blocked = false;
        const int n = surface.Neighbor(r, j, blocked);
        if (n >= 0 && !blocked && cellOfTriangle[n] < 0)
        {
          cellOfTriangle[n] = cell;
          queue.push_back(n);
        }
      }
    }
  }
  return cells;
}

//------------------------------------------------------------------------------
int BuildPatchesAndCellGraph(const RefinedSurfaceView& surface,
  const std::vector<TracedCurve>& curves,
  const std::vector<RefinedCurve>& refinedCurves,
  const std::vector<Vec3>& positions,
  const std::vector<SurfacePoint>& pointSurface,
  const std::vector<int>& cellOfTriangle,
  std::vector<ArrangementPatch>& patches,
  std::vector<CellGraphArc>& arcs)
{
  const TriangleMesh& mesh = *surface.Mesh;
  patches.clear();
  arcs.clear();

  // Visits per point over all curves: a point visited twice is where curves meet (crossing,
  // touching, overlap end, or a curve meeting itself).
  std::vector<int> visits(positions.size(), 0);
  for (const RefinedCurve& c : refinedCurves)
  {
    for (int p : c.Points)
    {
      ++visits[p];
    }
  }
  std::vector<char> isEnd(positions.size(), 0);
  int graphVertices = 0;
  auto markEnd = [&](int p)
  {
    if (!isEnd[p])
    {
      isEnd[p] = 1;
      ++graphVertices;
    }
  };

  // Cells on the left and right of sub-edge p -> q.
  auto sides = [&](int p, int q, int source, int& left, int& right)
  {
    int candidates[2] = { source, -1 };
    if (source < 0)
    {
      const int e = -source - 1;
      const int h = mesh.GetEdgeHalfEdge(e);
      candidates[0] = h / 3;
      candidates[1] = mesh.GetNeighbor(h / 3, h % 3);
    }
    left = right = -1;
    for (int t : candidates)
    {
      if (t < 0)
      {
        continue;
      }
      const int l = surface.FindDirected(t, p, q);
      const int r = surface.FindDirected(t, q, p);
      if (l >= 0)
        left = cellOfTriangle[l];
      if (r >= 0)
        right = cellOfTriangle[r];
    }
  };

  for (size_t ci = 0; ci < refinedCurves.size(); ++ci)
  {
    const RefinedCurve& rc = refinedCurves[ci];
    const TracedCurve& curve = curves[ci];
    const int n = static_cast<int>(rc.Points.size());
    if (n < 2)
    {
      continue;
    }
    const int edges = static_cast<int>(rc.SubEdgeSource.size());
    const bool cyclic = curve.Closed;
    // Where patches start: the first break point (closed), or the first point (open).
    int start = 0;
    bool anyBreak = !cyclic;
    if (cyclic)
    {
      for (int i = 0; i < n; ++i)
      {
        if (visits[rc.Points[i]] > 1)
        {
          start = i;
          anyBreak = true;
          break;
        }
      }
    }
    ArrangementPatch patch;
    auto begin = [&](int i)
    {
      patch = ArrangementPatch();
      patch.Curve = static_cast<int>(ci);
      patch.ShapeId = curve.ShapeId;
      patch.CurveId = curve.CurveId;
      patch.Closed = curve.Closed;
      patch.Points.push_back(rc.Points[i % n]);
      markEnd(rc.Points[i % n]);
      sides(rc.Points[i % n],
        rc.Points[(i + 1) % n],
        rc.SubEdgeSource[i % edges],
        patch.LeftCell,
        patch.RightCell);
    };
    auto finish = [&]()
    {
      markEnd(patch.Points.back());
      for (size_t k = 0; k + 1 < patch.Points.size(); ++k)
      {
        patch.Length += Distance(positions[patch.Points[k]], positions[patch.Points[k + 1]]);
      }
      for (int p : patch.Points)
      {
        patch.SurfacePoints.push_back(pointSurface[p]);
      }
      const int id = static_cast<int>(patches.size());
      if (patch.Closed && patch.LeftCell >= 0 && patch.RightCell >= 0)
      {
        arcs.push_back({ patch.RightCell, patch.LeftCell, patch.ShapeId, id });
      }
      patches.push_back(std::move(patch));
    };
    begin(start);
    for (int e = 0; e < edges; ++e)
    {
      const int i = start + e; // sub-edge from point i to i+1 (mod n)
      const int next = rc.Points[(i + 1) % n];
      patch.Points.push_back(next);
      const bool last = e + 1 == edges;
      if (!last && anyBreak && visits[next] > 1)
      {
        finish();
        begin(i + 1);
      }
    }
    finish();
  }
  return graphVertices;
}

} // namespace boolsurf

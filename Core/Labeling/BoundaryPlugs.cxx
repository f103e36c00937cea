#include "Labeling/BoundaryPlugs.h"

#include "Mesh/EdgeIndex.h"

#include <algorithm>

namespace boolsurf
{

//------------------------------------------------------------------------------
BoundaryPlugs FindBoundaryPlugs(const TriangleMesh& mesh,
  const MeshTopology& topo,
  const Arrangement& arr)
{
  BoundaryPlugs plugs;
  plugs.NumberOfCells = arr.NumberOfCells;
  plugs.NumberOfPlugs = static_cast<int>(topo.BoundaryLoops.size());
  plugs.ZeroNodes.assign(topo.GetNumberOfComponents(), -1);
  std::vector<int> longest(topo.GetNumberOfComponents(), -1);
  for (int l = 0; l < plugs.NumberOfPlugs; ++l)
  {
    const int c = topo.BoundaryLoops[l].Component;
    plugs.PlugComponent.push_back(c);
    if (longest[c] < 0 || topo.BoundaryLoops[l].Length > topo.BoundaryLoops[longest[c]].Length)
    {
      longest[c] = l;
    }
  }
  for (size_t c = 0; c < longest.size(); ++c)
  {
    plugs.ZeroNodes[c] = longest[c] < 0 ? -1 : plugs.PlugOf(longest[c]);
  }
  if (plugs.NumberOfPlugs == 0)
  {
    return plugs;
  }

  // The boundary sub-edges closed curves cover, with the patches covering them (overlapping
  // curves cover one sub-edge together).
  std::vector<std::pair<std::uint64_t, int>> covered;
  for (size_t p = 0; p < arr.Patches.size(); ++p)
  {
    const ArrangementPatch& patch = arr.Patches[p];
    if (patch.BoundaryHalfEdge < 0 || !patch.Closed)
    {
      continue;
    }
    for (size_t k = 0; k + 1 < patch.Points.size(); ++k)
    {
      covered.emplace_back(
        UndirectedPointPair(patch.Points[k], patch.Points[k + 1]), static_cast<int>(p));
    }
  }
  std::sort(covered.begin(), covered.end());

  // Walk every loop's sub-edges: a free one links its cell to the plug, a covered one tells
  // the covering patches which loop they run along.
  std::vector<int> patchLoop(arr.Patches.size(), -1);
  for (int l = 0; l < plugs.NumberOfPlugs; ++l)
  {
    const int plug = plugs.PlugOf(l);
    int lastLinked = -1;
    for (const int h : topo.BoundaryLoops[l].HalfEdges)
    {
      const int t = h / 3, k = h % 3;
      const Triangle& corners = mesh.GetTriangle(t);
      const int a = corners[k], b = corners[(k + 1) % 3];
      const int e = mesh.GetEdgeId(t, k);
      const auto onEdge = [&](int p)
      {
        if (p == a || p == b)
        {
          return true;
        }
        const CanonicalPoint q = arr.GetPointOnMesh(p);
        return q.Location == PointLocation::Edge && q.Id == e;
      };
      ForEachRefinedTriangle(mesh,
        arr,
        t,
        [&](int r)
        {
          const Triangle tri = arr.GetTriangle(mesh, r);
          for (int j = 0; j < 3; ++j)
          {
            const int x = tri[j], y = tri[(j + 1) % 3];
            if (!onEdge(x) || !onEdge(y))
            {
              continue;
            }
            const std::uint64_t key = UndirectedPointPair(x, y);
            auto it = std::lower_bound(covered.begin(),
              covered.end(),
              std::make_pair(key, -1),
              [](const auto& u, const auto& v) { return u.first < v.first; });
            if (it == covered.end() || it->first != key)
            {
              const int cell = arr.CellOfTriangle(r);
              if (cell >= 0 && cell != lastLinked)
              {
                plugs.Links.emplace_back(cell, plug);
                lastLinked = cell;
              }
              continue;
            }
            for (; it != covered.end() && it->first == key; ++it)
            {
              patchLoop[it->second] = l;
            }
          }
        });
    }
  }
  std::sort(plugs.Links.begin(), plugs.Links.end());
  plugs.Links.erase(std::unique(plugs.Links.begin(), plugs.Links.end()), plugs.Links.end());

  // One arc per covering patch, between the cell on its inner side and the plug.
  for (size_t p = 0; p < arr.Patches.size(); ++p)
  {
    const ArrangementPatch& patch = arr.Patches[p];
    if (patchLoop[p] < 0 || (patch.LeftCell < 0) == (patch.RightCell < 0))
    {
      continue;
    }
    const int plug = plugs.PlugOf(patchLoop[p]);
    plugs.Arcs.push_back({ patch.RightCell >= 0 ? patch.RightCell : plug,
      patch.LeftCell >= 0 ? patch.LeftCell : plug,
      patch.ShapeId,
      static_cast<int>(p) });
  }
  return plugs;
}

} // namespace boolsurf

#include "Labeling/ArrangementLabelingInput.h"

#include <algorithm>
#include <map>
#include <tuple>

namespace boolsurf
{

//------------------------------------------------------------------------------
std::vector<int> DistinctShapeIds(const std::vector<TracedCurve>& curves)
{
  std::vector<int> ids;
  ids.reserve(curves.size());
  for (const TracedCurve& c : curves)
  {
    ids.push_back(c.ShapeId);
  }
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

//------------------------------------------------------------------------------
int ShapeIndexOf(const std::vector<int>& shapeIds, int shapeId)
{
  const auto it = std::lower_bound(shapeIds.begin(), shapeIds.end(), shapeId);
  return it != shapeIds.end() && *it == shapeId ? static_cast<int>(it - shapeIds.begin()) : -1;
}

//------------------------------------------------------------------------------
std::vector<PatchPlace> PatchPlaces(const std::vector<ArrangementPatch>& patches)
{
  // Overlapping patches have the same point sequence, maybe reversed: the key is the ordered
  // end points and the points next to them. A patch runs along its place's orientation when
  // its first point is the key's first (for closed patches, when it leaves towards the lower
  // neighbour).
  std::map<std::tuple<int, int, int, int>, int> ids;
  std::vector<PatchPlace> places(patches.size());
  for (size_t p = 0; p < patches.size(); ++p)
  {
    const std::vector<int>& pts = patches[p].Points;
    if (pts.size() < 2)
    {
      // Degenerate patch: a place of its own.
      places[p].Location =
        ids
          .emplace(std::make_tuple(-1 - static_cast<int>(p), 0, 0, 0), static_cast<int>(ids.size()))
          .first->second;
      continue;
    }
    const int a = pts.front(), b = pts.back();
    const int c = pts[1], d = pts[pts.size() - 2];
    auto key = std::make_tuple(std::min(a, b), std::max(a, b), a <= b ? c : d, a <= b ? d : c);
    bool forward = a <= b;
    if (a == b) // a closed patch: its two directions give (c, d) and (d, c)
    {
      key = std::make_tuple(a, b, std::min(c, d), std::max(c, d));
      forward = c <= d;
    }
    places[p].Location = ids.emplace(key, static_cast<int>(ids.size())).first->second;
    places[p].Direction = forward ? 1 : -1;
  }
  return places;
}

//------------------------------------------------------------------------------
std::vector<int> CellComponents(const TriangleMesh& mesh,
  const MeshTopology& topology,
  const Arrangement& arr)
{
  std::vector<int> component(arr.NumberOfCells, 0);
  for (int c = 0; c < arr.NumberOfCells && c < static_cast<int>(arr.CellFirstTriangle.size()); ++c)
  {
    component[c] =
      topology.TriangleComponent[arr.GetSourceTriangle(mesh, arr.CellFirstTriangle[c])];
  }
  return component;
}

//------------------------------------------------------------------------------
LabelingInput MakeLabelingInput(const TriangleMesh& mesh,
  const MeshTopology& topology,
  const std::vector<TracedCurve>& curves,
  const Arrangement& arr)
{
  LabelingInput in;
  in.ShapeIds = DistinctShapeIds(curves);
  in.NumberOfCells = arr.NumberOfCells;
  in.NumberOfShapes = static_cast<int>(in.ShapeIds.size());
  const std::vector<PatchPlace> places = PatchPlaces(arr.Patches);
  const BoundaryPlugs plugs = FindBoundaryPlugs(mesh, topology, arr);
  in.Arcs.reserve(arr.CellGraph.size() + plugs.Arcs.size());
  for (const std::vector<CellGraphArc>* arcs : { &arr.CellGraph, &plugs.Arcs })
  {
    for (const CellGraphArc& a : *arcs)
    {
      const PatchPlace place = a.Patch >= 0 ? places[a.Patch] : PatchPlace{};
      in.Arcs.push_back({ a.RightCell,
        a.LeftCell,
        ShapeIndexOf(in.ShapeIds, a.Shape),
        place.Location,
        place.Direction });
    }
  }
  in.NumberOfPlugs = plugs.NumberOfPlugs;
  in.Links = plugs.Links;
  in.CellComponent = CellComponents(mesh, topology, arr);
  in.CellComponent.insert(
    in.CellComponent.end(), plugs.PlugComponent.begin(), plugs.PlugComponent.end());
  in.ZeroCells = plugs.ZeroNodes;
  return in;
}

//------------------------------------------------------------------------------
void AddShapesWithoutCurves(LabelingInput& in, const std::vector<int>& shapeIds)
{
  std::vector<int> ids = in.ShapeIds;
  ids.insert(ids.end(), shapeIds.begin(), shapeIds.end());
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  if (ids.size() == in.ShapeIds.size())
  {
    return;
  }
  for (CellArc& arc : in.Arcs)
  {
    if (arc.Shape >= 0 && arc.Shape < static_cast<int>(in.ShapeIds.size()))
    {
      arc.Shape = ShapeIndexOf(ids, in.ShapeIds[arc.Shape]);
    }
  }
  in.ShapeIds = ids;
  in.NumberOfShapes = static_cast<int>(ids.size());
}

//------------------------------------------------------------------------------
int CellAtSurfacePoint(const TriangleMesh& mesh, const Arrangement& arr, int t, double u, double v)
{
  if (t < 0 || t >= arr.NumberOfMeshTriangles)
  {
    return -1;
  }
  if (CountRefinedTriangles(mesh, arr, t) <= 1)
  {
    return arr.CellOfTriangle(t);
  }
  // The sub-triangle whose smallest barycentric coordinate of (u, v) is largest: the one that
  // contains the point, or the nearest one when rounding puts it just outside all.
  int best = -1;
  double bestScore = -1e300;
  ForEachRefinedTriangle(mesh,
    arr,
    t,
    [&](int r)
    {
      double x[3], y[3];
      for (int k = 0; k < 3; ++k)
      {
        const std::array<double, 3> w =
          WeightsInTriangle(mesh, arr.GetPointOnMesh(arr.GetTriangle(mesh, r)[k]), t);
        x[k] = w[1];
        y[k] = w[2];
      }
      const double area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
      if (area == 0)
      {
        return;
      }
      double score = 1e300;
      for (int k = 0; k < 3; ++k)
      {
        const int a = (k + 1) % 3, b = (k + 2) % 3;
        const double wk = ((x[b] - x[a]) * (v - y[a]) - (y[b] - y[a]) * (u - x[a])) / area;
        score = std::min(score, wk);
      }
      if (score > bestScore)
      {
        bestScore = score;
        best = r;
      }
    });
  return best >= 0 ? arr.CellOfTriangle(best) : -1;
}

} // namespace boolsurf

#include "Offset/OffsetRegionOfCells.h"

#include "Selection/RegionBoundary.h"

namespace boolsurf
{

//------------------------------------------------------------------------------
OffsetRegion MakeOffsetRegion(const TriangleMesh& mesh,
  const Arrangement& arrangement,
  const std::vector<char>& selected)
{
  OffsetRegion region;
  for (const BoundaryPolyline& line : ExtractRegionBoundary(arrangement.Patches, selected))
  {
    std::vector<CanonicalPoint> loop;
    loop.reserve(line.Points.size());
    for (int p : line.Points)
    {
      loop.push_back(arrangement.GetPointOnMesh(p));
    }
    region.Boundary.push_back(std::move(loop));
  }
  const TriangleMesh* m = &mesh;
  const Arrangement* arr = &arrangement;
  const std::vector<char>* cells = &selected;
  // Mesh vertices keep their ids in the refined surface: any refined triangle with v as a
  // corner, among those that replace a mesh triangle around v, tells its cell.
  region.InsideVertex = [m, arr, cells](int v)
  {
    for (int corner : m->GetVertexCorners(v))
    {
      const int t = corner / 3;
      int found = -1;
      ForEachRefinedTriangle(*m,
        *arr,
        t,
        [&](int r)
        {
          const Triangle tri = arr->GetTriangle(*m, r);
          if (found < 0 && (tri[0] == v || tri[1] == v || tri[2] == v))
          {
            found = r;
          }
        });
      if (found >= 0)
      {
        return (*cells)[arr->CellOfTriangle(found)] != 0;
      }
    }
    return false;
  };
  // Triangles left whole by the arrangement lie in one cell.
  region.TriangleSide = [m, arr, cells](int t)
  {
    if (CountRefinedTriangles(*m, *arr, t) != 1)
    {
      return 0;
    }
    return (*cells)[arr->CellOfTriangle(t)] != 0 ? 1 : -1;
  };
  return region;
}

} // namespace boolsurf

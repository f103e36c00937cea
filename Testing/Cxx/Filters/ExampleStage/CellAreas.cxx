#include "CellAreas.h"

#include <sstream>

namespace boolsurf
{

bool ComputeCellAreas(const TriangleMesh& mesh,
  const Arrangement& arrangement,
  std::vector<double>& areas,
  std::string& error)
{
  areas.assign(arrangement.NumberOfCells, 0.0);
  for (int c = 0; c < arrangement.NumberOfCells; ++c)
  {
    int triangles = 0;
    ForEachCellTriangle(arrangement,
      c,
      [&](int r)
      {
        const Triangle t = arrangement.GetTriangle(mesh, r);
        const Vec3 a = arrangement.GetPosition(mesh, t[0]);
        const Vec3 b = arrangement.GetPosition(mesh, t[1]);
        const Vec3 d = arrangement.GetPosition(mesh, t[2]);
        areas[c] += 0.5 * Length(Cross(b - a, d - a));
        ++triangles;
      });
    if (triangles == 0)
    {
      std::ostringstream message;
      message << "Arrangement cell " << c << " has no triangle: the arrangement was not computed "
              << "on this mesh.";
      error = message.str();
      return false;
    }
  }
  return true;
}

} // namespace boolsurf

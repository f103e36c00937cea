#include "Mesh/TriangleComponents.h"

namespace boolsurf
{

//------------------------------------------------------------------------------
TriangleComponents::TriangleComponents(const TriangleMesh& mesh)
{
  const int nt = mesh.GetNumberOfTriangles();
  this->Component.assign(nt, -1);
  std::vector<int> stack;
  for (int seed = 0; seed < nt; ++seed)
  {
    if (!mesh.IsUsable(seed) || this->Component[seed] >= 0)
    {
      continue;
    }
    const int id = this->NumberOfComponents++;
    this->Component[seed] = id;
    stack.push_back(seed);
    while (!stack.empty())
    {
      const int t = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k)
      {
        const int n = mesh.GetNeighbor(t, k);
        if (n >= 0 && this->Component[n] < 0)
        {
          this->Component[n] = id;
          stack.push_back(n);
        }
      }
    }
  }
}

} // namespace boolsurf

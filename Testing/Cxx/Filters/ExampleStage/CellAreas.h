// The Core half of the example stage of Docs/Architecture.md ("Adding a stage"): the area of
// every cell of an arrangement. In a real stage this file is Core/<Folder>/CellAreas.h: plain
// C++ on Core types, no VTK, tested directly.
#ifndef boolsurf_example_CellAreas_h
#define boolsurf_example_CellAreas_h

#include "Arrangement/Arrangement.h"
#include "Mesh/TriangleMesh.h"

#include <string>
#include <vector>

namespace boolsurf
{

/// The area of each cell of `arrangement` (computed on `mesh`), in cell order: the sum of its
/// refined triangles' areas. Fails, naming the cell, when a cell has no triangle (an
/// arrangement that was not computed on this mesh).
bool ComputeCellAreas(const TriangleMesh& mesh,
  const Arrangement& arrangement,
  std::vector<double>& areas,
  std::string& error);

} // namespace boolsurf

#endif

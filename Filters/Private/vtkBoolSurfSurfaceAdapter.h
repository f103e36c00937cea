// Conversion of a vtkPolyData surface into the Core triangle mesh, shared by every BoolSurf
// filter (not wrapped: a private header of the module).
//
// Non-triangle polygons and strips are triangulated (vtkTriangleFilter, which ear-cuts
// non-convex polygons); vertices and lines are dropped. Each conversion is reported as a
// warning naming how many cells were affected, so users know the output cells are not the
// input cells.
#ifndef vtkBoolSurfSurfaceAdapter_h
#define vtkBoolSurfSurfaceAdapter_h

#include "Mesh/MeshTopology.h"
#include "Mesh/SurfaceCheck.h"
#include "Mesh/TriangleMesh.h"

#include <vtkSmartPointer.h>

#include <memory>
#include <string>
#include <vector>

class vtkPolyData;

namespace boolsurf
{

struct vtkSurfaceInput
{
  /// The input reduced to triangles (same points; cell data follows the triangles).
  vtkSmartPointer<vtkPolyData> Triangles;
  std::shared_ptr<const TriangleMesh> Mesh;
  std::shared_ptr<const MeshTopology> Topology;
  SurfaceCheckResult Check;
  /// Conversion notes (triangulated polygons, dropped lines), one sentence each.
  std::vector<std::string> Warnings;
};

/// Lines joined into one message, each on its own line after `indent`.
inline std::string JoinLines(const std::vector<std::string>& lines, const char* indent = "  ")
{
  std::string all;
  for (const std::string& line : lines)
  {
    all += "\n" + std::string(indent) + line;
  }
  return all;
}

/// Fills `out` from `input` (which may be null: reported as EmptyInput). Never throws.
void ConvertSurface(vtkPolyData* input,
  vtkSurfaceInput& out,
  const SurfaceCheckOptions& options = SurfaceCheckOptions());

} // namespace boolsurf

#endif

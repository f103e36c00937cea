// Carries the input surface's own point and cell arrays onto a refined surface (a private
// header of the module): cell data is copied from each refined triangle's source triangle,
// point data is interpolated with each refined point's barycentric coordinates in its source
// triangle. Users keep their scalars (curvature, thickness, labels, ...) through BoolSurf.
#ifndef vtkBoolSurfAttributeTransfer_h
#define vtkBoolSurfAttributeTransfer_h

#include "Mesh/SurfacePoint.h"

#include <vtkAbstractArray.h>
#include <vtkCellData.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkType.h>
#include <vtkWeakPointer.h>

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

class vtkPolyData;

namespace boolsurf
{

/// `source` is the triangulated input surface (cell ids = mesh triangle ids); `target` gets
/// its point data (numberOfPoints tuples, point p interpolated at pointSurface(p)) and cell
/// data (one tuple per entry of sourceTriangle). Arrays whose names are in `skip` are not
/// carried (names BoolSurf writes). pointSurface is called only when the source has arrays to
/// carry.
void TransferSurfaceAttributes(vtkPolyData* source,
  const TriangleMesh& mesh,
  vtkIdType numberOfPoints,
  const std::function<SurfacePoint(vtkIdType)>& pointSurface,
  const std::vector<int>& sourceTriangle,
  vtkPolyData* target);

/// The input surface's arrays as last carried onto a refined surface, kept by their owner (a
/// Surface Arrangement result) from edit to edit, and what they were carried from.
struct CarriedAttributes
{
  vtkSmartPointer<vtkPointData> Points;
  vtkSmartPointer<vtkCellData> Cells;
  std::uint64_t MeshSerial = 0; ///< 0: nothing kept
  std::vector<vtkWeakPointer<vtkAbstractArray>> Inputs;
  std::vector<vtkMTimeType> InputTimes;
};

/// TransferSurfaceAttributes for a refined surface numbered as the arrangement numbers it: its
/// first `meshVertices` points are the mesh's vertices and its first `meshTriangles` triangles
/// have themselves as source (the first piece of a refined one keeps its index; 0 and 0 when
/// the numbering is another). Their values never change on one mesh with the same input
/// arrays, so the arrays in `kept` are written again only past them (the curves' points, the
/// pieces appended), in place when nothing but `kept` holds them; else written whole into new
/// arrays kept in their stead. The target gets the same arrays, values and attributes as from
/// TransferSurfaceAttributes.
void UpdateSurfaceAttributes(vtkPolyData* source,
  const TriangleMesh& mesh,
  vtkIdType numberOfPoints,
  vtkIdType meshVertices,
  vtkIdType meshTriangles,
  const std::function<SurfacePoint(vtkIdType)>& pointSurface,
  const std::vector<int>& sourceTriangle,
  CarriedAttributes& kept,
  vtkPolyData* target);

} // namespace boolsurf

#endif

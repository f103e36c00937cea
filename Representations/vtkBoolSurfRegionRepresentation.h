/**
 * @class   vtkBoolSurfRegionRepresentation
 * @brief   a surface representation drawn in front of the coincident surface it was cut from
 *
 * A BoolSurf region (the output of BoolSurf, Surface Boolean, Boundary Sampled Curves) lies
 * exactly on the input surface: drawn together, the two z-fight (speckles). This
 * representation is ParaView's Surface representation with its mappers' polygons pulled
 * toward the camera by a relative coincident-topology offset, so the region is always drawn
 * over the surface while the boundary lines (which VTK offsets further) stay over both. It is
 * the "BoolSurf Region" representation type of GeometryRepresentation, chosen by default for
 * the region ports by a RepresentationType hint in the filters' XML.
 */
#ifndef vtkBoolSurfRegionRepresentation_h
#define vtkBoolSurfRegionRepresentation_h

#include "BoolSurfRepresentationsModule.h" // for export macro
#include "vtkGeometryRepresentationWithFaces.h"

class BOOLSURFREPRESENTATIONS_EXPORT vtkBoolSurfRegionRepresentation
  : public vtkGeometryRepresentationWithFaces
{
public:
  static vtkBoolSurfRegionRepresentation* New();
  vtkTypeMacro(vtkBoolSurfRegionRepresentation, vtkGeometryRepresentationWithFaces);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// How far the region's polygons are pulled toward the camera, in the units of
  /// vtkMapper::SetRelativeCoincidentTopologyPolygonOffsetParameters (factor and units).
  static constexpr double Offset = -1.0;

protected:
  vtkBoolSurfRegionRepresentation();
  ~vtkBoolSurfRegionRepresentation() override;

private:
  vtkBoolSurfRegionRepresentation(const vtkBoolSurfRegionRepresentation&) = delete;
  void operator=(const vtkBoolSurfRegionRepresentation&) = delete;
};

#endif

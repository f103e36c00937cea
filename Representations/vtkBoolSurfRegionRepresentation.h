/**
 * @class   vtkBoolSurfRegionRepresentation
 * @brief   a surface representation drawn in front of the coincident surface it was cut from
 *
 * A BoolSurf region (the output of BoolSurf, Surface Boolean, Boundary Sampled Curves) lies
 * exactly on the input surface: drawn together, the two z-fight (speckles). Curves traced on
 * the surface do too: on a coarse mesh a line inside a steep facet comes out dashed. This
 * representation is ParaView's Surface representation with its mappers' polygons and lines
 * pulled toward the camera by relative coincident-topology offsets (lines further), so a
 * region is drawn over the surface and curves over both. It is the "BoolSurf Region" and
 * "BoolSurf Curves" representation types of GeometryRepresentation, chosen by default for the
 * region ports and the curve ports that lie on the surface by RepresentationType hints in the
 * filters' XML.
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
  /// The same for lines (factor and units). TestRenderDefaultDisplay.py, traced curves on
  /// Data/eight.ply: no offset loses 28 of their 64 pixels to the surface, -2 and -4 none
  /// (the factor matters: units alone, -8, still lose 17); -4 leaves a margin over regions.
  static constexpr double LineOffset = -4.0;

protected:
  vtkBoolSurfRegionRepresentation();
  ~vtkBoolSurfRegionRepresentation() override;

private:
  vtkBoolSurfRegionRepresentation(const vtkBoolSurfRegionRepresentation&) = delete;
  void operator=(const vtkBoolSurfRegionRepresentation&) = delete;
};

#endif

#include "vtkBoolSurfRegionRepresentation.h"

#include "vtkMapper.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkBoolSurfRegionRepresentation);

//------------------------------------------------------------------------------
vtkBoolSurfRegionRepresentation::vtkBoolSurfRegionRepresentation()
{
  // Relative to the global offsets (ParaView's "Resolve Coincident Topology" setting): the
  // region's faces win over the surface's faces at the same depth, lines still win over both.
  for (vtkMapper* mapper :
    { this->Mapper, this->LODMapper, this->BackfaceMapper, this->LODBackfaceMapper })
  {
    if (mapper)
    {
      mapper->SetRelativeCoincidentTopologyPolygonOffsetParameters(Offset, Offset);
    }
  }
}

//------------------------------------------------------------------------------
vtkBoolSurfRegionRepresentation::~vtkBoolSurfRegionRepresentation() = default;

//------------------------------------------------------------------------------
void vtkBoolSurfRegionRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Offset: " << Offset << "\n";
}

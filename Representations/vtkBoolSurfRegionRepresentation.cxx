#include "vtkBoolSurfRegionRepresentation.h"

#include "vtkMapper.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkBoolSurfRegionRepresentation);

//------------------------------------------------------------------------------
vtkBoolSurfRegionRepresentation::vtkBoolSurfRegionRepresentation()
{
  // Relative to the global offsets (ParaView's "Resolve Coincident Topology" setting): the
  // region's faces win over the surface's faces at the same depth; its lines (curves on the
  // surface) win over both, also where a steep facet would otherwise cut a line into dashes.
  for (vtkMapper* mapper :
    { this->Mapper, this->LODMapper, this->BackfaceMapper, this->LODBackfaceMapper })
  {
    if (mapper)
    {
      mapper->SetRelativeCoincidentTopologyPolygonOffsetParameters(Offset, Offset);
      mapper->SetRelativeCoincidentTopologyLineOffsetParameters(LineOffset, LineOffset);
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
  os << indent << "LineOffset: " << LineOffset << "\n";
}

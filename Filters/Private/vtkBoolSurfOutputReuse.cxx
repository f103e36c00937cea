#include "vtkBoolSurfOutputReuse.h"

#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

namespace boolsurf
{

//------------------------------------------------------------------------------
void EmptyPolyData(vtkPolyData* data)
{
  const bool empty = data->GetNumberOfPoints() == 0 && data->GetNumberOfCells() == 0 &&
    data->GetPointData()->GetNumberOfArrays() == 0 &&
    data->GetCellData()->GetNumberOfArrays() == 0 && data->GetFieldData()->GetNumberOfArrays() == 0;
  if (!empty)
  {
    data->Initialize();
  }
}

//------------------------------------------------------------------------------
std::array<int, 3> CountArrays(vtkPolyData* data)
{
  return { data->GetPointData()->GetNumberOfArrays(),
    data->GetCellData()->GetNumberOfArrays(),
    data->GetFieldData()->GetNumberOfArrays() };
}

//------------------------------------------------------------------------------
void ReserveArraySlots(vtkPolyData* data, const std::array<int, 3>& counts)
{
  // Only on empty attributes: after Initialize they have no slots, so AllocateArrays grows
  // the list (given fewer slots than it has, it would shrink it and drop arrays).
  vtkFieldData* attributes[3] = { data->GetPointData(), data->GetCellData(), data->GetFieldData() };
  for (int k = 0; k < 3; ++k)
  {
    if (attributes[k]->GetNumberOfArrays() == 0 && counts[k] > 0)
    {
      attributes[k]->AllocateArrays(counts[k]);
    }
  }
}

} // namespace boolsurf

#include "vtkBoolSurfExampleCellAreas.h"

#include "CellAreas.h"
#include "vtkBoolSurfStageHandoff.h"

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

#include <sstream>

vtkStandardNewMacro(vtkBoolSurfExampleCellAreas);

//------------------------------------------------------------------------------
vtkBoolSurfExampleCellAreas::vtkBoolSurfExampleCellAreas()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

//------------------------------------------------------------------------------
bool vtkBoolSurfExampleCellAreas::Execute(const std::vector<vtkPolyData*>& inputs,
  const std::vector<vtkPolyData*>& outputs,
  std::string& error)
{
  if (!(this->AreaScale > 0))
  {
    std::ostringstream message;
    message << "AreaScale must be positive; got " << this->AreaScale << ".";
    error = message.str();
    return false;
  }
  // The arrangement in Core form: attached upstream, or rebuilt from the input's arrays.
  const std::shared_ptr<const boolsurf::ArrangementResult> arranged =
    this->GetArrangement(inputs[0], error);
  if (!arranged)
  {
    return false;
  }
  std::vector<double> areas;
  if (!boolsurf::ComputeCellAreas(*arranged->Surface.Mesh, arranged->Arrangement, areas, error))
  {
    return false;
  }
  vtkPolyData* output = outputs[0];
  output->ShallowCopy(inputs[0]);
  vtkNew<vtkDoubleArray> cellArea;
  cellArea->SetName(boolsurf::names::CellArea);
  cellArea->SetNumberOfTuples(static_cast<vtkIdType>(areas.size()));
  for (std::size_t c = 0; c < areas.size(); ++c)
  {
    cellArea->SetValue(static_cast<vtkIdType>(c), this->AreaScale * areas[c]);
  }
  output->GetFieldData()->AddArray(cellArea);
  return true;
}

//------------------------------------------------------------------------------
void vtkBoolSurfExampleCellAreas::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "AreaScale: " << this->AreaScale << "\n";
}

#include "vtkBoolSurfPieceGlobalIds.h"

#include <vtkCellData.h>
#include <vtkCommunicator.h>
#include <vtkDataArray.h>
#include <vtkGenerateGlobalIds.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

//------------------------------------------------------------------------------
vtkPolyData* vtkBoolSurfPieceGlobalIds::Generate(vtkMultiProcessController* controller,
  vtkPolyData* local)
{
  int same =
    this->Generated && local == this->Source && local && local->GetMTime() == this->SourceTime ? 1
                                                                                               : 0;
  int allSame = 0;
  controller->AllReduce(&same, &allSame, 1, vtkCommunicator::MIN_OP);
  if (allSame)
  {
    return this->Generated;
  }
  vtkNew<vtkPolyData> input;
  if (local)
  {
    input->ShallowCopy(local);
  }
  vtkDataArray* cellIds = input->GetCellData()->GetGlobalIds();
  vtkNew<vtkGenerateGlobalIds> generate; // collective: every rank runs it
  generate->SetController(controller);
  generate->SetInputData(input);
  generate->Update();
  this->Generated = vtkSmartPointer<vtkPolyData>::New();
  this->Generated->ShallowCopy(generate->GetOutputDataObject(0));
  if (cellIds)
  {
    // The cells' own ids name the triangles (the gathered surface is ordered by them).
    vtkCellData* cells = this->Generated->GetCellData();
    if (vtkDataArray* generated = cells->GetGlobalIds())
    {
      cells->RemoveArray(generated->GetName());
    }
    cells->SetGlobalIds(cellIds);
  }
  this->Source = local;
  this->SourceTime = local ? local->GetMTime() : 0;
  return this->Generated;
}

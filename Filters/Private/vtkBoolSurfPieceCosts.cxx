#include "vtkBoolSurfPieceCosts.h"

#include "vtkBoolSurfArrayNames.h"

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>

namespace boolsurf
{

//------------------------------------------------------------------------------
void WritePieceCosts(const PieceCosts& costs, vtkPolyData* output)
{
  vtkFieldData* fd = output->GetFieldData();
  if (!costs.Times.empty())
  {
    vtkNew<vtkDoubleArray> times;
    times->SetName(names::StageTimes);
    times->SetNumberOfComponents(static_cast<int>(costs.Times.size()));
    times->SetNumberOfTuples(1);
    for (std::size_t k = 0; k < costs.Times.size(); ++k)
    {
      times->SetComponentName(static_cast<vtkIdType>(k), costs.Times[k].Name.c_str());
      times->SetComponent(0, static_cast<int>(k), costs.Times[k].Milliseconds);
    }
    fd->AddArray(times);
  }
  if (!costs.Bytes.empty())
  {
    // Doubles: exact to 2^53 bytes, and read as they are by Python and ParaView's panels.
    vtkNew<vtkDoubleArray> bytes;
    bytes->SetName(names::PieceBytes);
    bytes->SetNumberOfComponents(2 * static_cast<int>(costs.Bytes.size()));
    bytes->SetNumberOfTuples(1);
    for (std::size_t k = 0; k < costs.Bytes.size(); ++k)
    {
      const PieceCosts::Message& m = costs.Bytes[k];
      bytes->SetComponentName(static_cast<vtkIdType>(2 * k), (m.Name + "Sent").c_str());
      bytes->SetComponentName(static_cast<vtkIdType>(2 * k + 1), (m.Name + "Received").c_str());
      bytes->SetComponent(0, static_cast<int>(2 * k), static_cast<double>(m.Sent));
      bytes->SetComponent(0, static_cast<int>(2 * k + 1), static_cast<double>(m.Received));
    }
    fd->AddArray(bytes);
  }
}

//------------------------------------------------------------------------------
void WriteLocalStageCosts(double milliseconds, vtkPolyData* output)
{
  PieceCosts costs;
  costs.AddTime("Total", milliseconds);
  costs.AddBytes("Decision", 2 * sizeof(int), 2 * sizeof(int));
  WritePieceCosts(costs, output);
}

}

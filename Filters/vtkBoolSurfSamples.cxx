#include "vtkBoolSurfSamples.h"

#include "vtkBoolSurfRankGather.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <algorithm>

vtkStandardNewMacro(vtkBoolSurfSamples);

namespace
{
// Resizes a property vector; returns true when it changed (the caller then calls Modified).
bool Resize(std::vector<double>& values, size_t size)
{
  if (values.size() == size)
  {
    return false;
  }
  values.resize(size, 0.0);
  return true;
}

bool SetTriple(std::vector<double>& values, int i, double x, double y, double z)
{
  const size_t at = 3 * static_cast<size_t>(std::max(0, i));
  if (values.size() < at + 3)
  {
    values.resize(at + 3, 0.0);
  }
  if (values[at] == x && values[at + 1] == y && values[at + 2] == z)
  {
    return false;
  }
  values[at] = x;
  values[at + 1] = y;
  values[at + 2] = z;
  return true;
}
}

//------------------------------------------------------------------------------
vtkBoolSurfSamples::vtkBoolSurfSamples()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
vtkBoolSurfSamples::~vtkBoolSurfSamples() = default;

//------------------------------------------------------------------------------
void vtkBoolSurfSamples::SetNumberOfPoints(int n)
{
  if (Resize(this->Points, 3 * static_cast<size_t>(std::max(0, n))))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkBoolSurfSamples::SetPoint(int i, double x, double y, double z)
{
  if (SetTriple(this->Points, i, x, y, z))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkBoolSurfSamples::SetNumberOfDirections(int n)
{
  if (Resize(this->Directions, 3 * static_cast<size_t>(std::max(0, n))))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkBoolSurfSamples::SetDirection(int i, double x, double y, double z)
{
  if (SetTriple(this->Directions, i, x, y, z))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkBoolSurfSamples::RequestData(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(outInfo);
  output->Initialize();
  // One copy of the samples, in the first piece (the first MPI rank), as vtkBoolSurfRankGather
  // expects of BoolSurf's sources.
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) &&
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) > 0)
  {
    return 1;
  }
  const vtkIdType n = this->GetNumberOfPoints();
  if (this->Directions.size() != this->Points.size())
  {
    vtkErrorMacro("Each of the " << n << " sample Points needs a Direction; got "
                                 << this->Directions.size() / 3 << " Directions.");
    return vtkBoolSurfErrorReported;
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  vtkNew<vtkDoubleArray> direction;
  direction->SetName("Direction");
  direction->SetNumberOfComponents(3);
  direction->SetNumberOfTuples(n);
  vtkNew<vtkCellArray> vertices;
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->SetPoint(i, &this->Points[3 * i]);
    direction->SetTypedTuple(i, &this->Directions[3 * i]);
    vertices->InsertNextCell(1, &i);
  }
  output->SetPoints(points);
  output->SetVerts(vertices);
  output->GetPointData()->AddArray(direction);
  return 1;
}

//------------------------------------------------------------------------------
void vtkBoolSurfSamples::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Samples: " << this->GetNumberOfPoints() << "\n";
}

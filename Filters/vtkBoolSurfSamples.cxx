#include "vtkBoolSurfSamples.h"

#include "vtkBoolSurfArrayNames.h"

#include "vtkBoolSurfPropertyVector.h"
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
// Sets sample i's three values, growing the vector when a caller sets a sample past its end
// (ParaView sets the count first; a plain VTK user need not). True when anything changed.
bool SetSample(std::vector<double>& values, int i, double x, double y, double z)
{
  const size_t at = 3 * static_cast<size_t>(std::max(0, i));
  const bool grown = values.size() < at + 3 && boolsurf::ResizeProperty(values, at + 3, 0.0);
  return boolsurf::SetPropertyElements(values, at, { x, y, z }) || grown;
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
  if (boolsurf::ResizeProperty(this->Points, 3 * static_cast<size_t>(std::max(0, n)), 0.0))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkBoolSurfSamples::SetPoint(int i, double x, double y, double z)
{
  if (SetSample(this->Points, i, x, y, z))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkBoolSurfSamples::SetNumberOfDirections(int n)
{
  if (boolsurf::ResizeProperty(this->Directions, 3 * static_cast<size_t>(std::max(0, n)), 0.0))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkBoolSurfSamples::SetDirection(int i, double x, double y, double z)
{
  if (SetSample(this->Directions, i, x, y, z))
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
  direction->SetName(boolsurf::names::Direction);
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

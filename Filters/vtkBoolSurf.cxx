#include "vtkBoolSurf.h"

#include "vtkBoolSurfArrangementOutput.h"
#include "vtkBoolSurfBooleanStage.h"
#include "vtkBoolSurfLabelingStage.h"
#include "vtkBoolSurfTraceStage.h"

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkBoolSurf);

struct vtkBoolSurf::Internals
{
  boolsurf::vtkSurfaceCache Surface;
};

//------------------------------------------------------------------------------
vtkBoolSurf::vtkBoolSurf()
  : Internal(new Internals)
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
}

//------------------------------------------------------------------------------
vtkBoolSurf::~vtkBoolSurf() = default;

//------------------------------------------------------------------------------
int vtkBoolSurf::FillInputPortInformation(int vtkNotUsed(port), vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
int vtkBoolSurf::RequestData(vtkInformation* vtkNotUsed(request),
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkPolyData* surfaceInput = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* curvesInput = vtkPolyData::GetData(inputVector[1], 0);
  vtkPolyData* region = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* boundary = vtkPolyData::GetData(outputVector, 1);

  // 1. surface (cached)
  std::vector<std::string> warnings, problems;
  std::string error, warning;
  const boolsurf::vtkSurfaceInput* surface =
    this->Internal->Surface.GetUsable(surfaceInput, warnings, error);
  for (const std::string& w : warnings)
  {
    vtkWarningMacro(<< w);
  }
  if (!surface)
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  this->UpdateProgress(0.05);

  // 2. tracing
  std::vector<boolsurf::TracedCurve> traced;
  boolsurf::TraceOptions traceOptions;
  traceOptions.Resolution = this->Resolution;
  traceOptions.ProjectionTolerance = this->ProjectionTolerance;
  std::vector<std::string> notes;
  const bool ok = boolsurf::TraceControlCurves(
    this->Internal->Surface, curvesInput, traceOptions, nullptr, traced, nullptr, problems, notes);
  for (const std::string& n : notes)
  {
    vtkWarningMacro(<< n);
  }
  if (!ok)
  {
    vtkErrorMacro(<< "Cannot trace the curves:" << boolsurf::JoinLines(problems));
    return 0;
  }
  this->UpdateProgress(0.3);
  if (this->CheckAbort())
  {
    return 1;
  }

  // 3. arrangement
  vtkNew<vtkPolyData> refined;
  if (!boolsurf::ArrangeCurves(*surface, traced, this->NumberOfThreads, refined, nullptr, error))
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  this->UpdateProgress(0.7);
  if (this->CheckAbort())
  {
    return 1;
  }

  // 4. labeling
  vtkNew<vtkPolyData> labeled;
  boolsurf::ArrangementFields fields;
  boolsurf::LabelingResult labels;
  if (!boolsurf::LabelArrangement(refined,
        this->ZeroCellMode == 1 ? this->ZeroCellPoint : nullptr,
        labeled,
        fields,
        labels,
        error,
        warning))
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  if (!warning.empty())
  {
    vtkWarningMacro(<< warning);
  }
  this->UpdateProgress(0.8);

  // 5. Boolean
  const boolsurf::BooleanRequest request = boolsurf::MakeBooleanRequest(
    this->Operation, this->ShapeA, this->ShapeB, this->Expression, this->FillRule);
  if (!boolsurf::ComputeBoolean(labeled, fields, labels, request, region, boundary, error))
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkBoolSurf::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "Operation: " << this->Operation << "\n";
  os << indent << "ShapeA: " << this->ShapeA << " ShapeB: " << this->ShapeB << "\n";
  os << indent << "Expression: " << this->Expression << "\n";
  os << indent << "FillRule: " << this->FillRule << "\n";
}

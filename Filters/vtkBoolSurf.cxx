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
#include <vtkSmartPointer.h>

#include <array>
#include <tuple>

vtkStandardNewMacro(vtkBoolSurf);

struct vtkBoolSurf::Internals
{
  boolsurf::vtkSurfaceCache Surface;

  // The labeled arrangement of the last run, reused when only the Boolean properties
  // (operation, operands, expression, fill rule) change.
  vtkSmartPointer<vtkPolyData> Labeled;
  boolsurf::ArrangementFields Fields;
  boolsurf::LabelingResult Labels;
  /// What the labeled arrangement was computed from (the inputs by identity and time, and the
  /// tracing and labeling properties).
  struct Key
  {
    vtkPolyData* Surface = nullptr;
    vtkMTimeType SurfaceTime = 0;
    vtkPolyData* Curves = nullptr;
    vtkMTimeType CurvesTime = 0;
    int Resolution = 0;
    double ProjectionTolerance = 0;
    int ZeroCellMode = 0;
    std::array<double, 3> ZeroCellPoint{};
    int NumberOfThreads = 0;

    bool operator==(const Key& o) const
    {
      return std::tie(this->Surface,
               this->SurfaceTime,
               this->Curves,
               this->CurvesTime,
               this->Resolution,
               this->ProjectionTolerance,
               this->ZeroCellMode,
               this->ZeroCellPoint,
               this->NumberOfThreads) ==
        std::tie(o.Surface,
          o.SurfaceTime,
          o.Curves,
          o.CurvesTime,
          o.Resolution,
          o.ProjectionTolerance,
          o.ZeroCellMode,
          o.ZeroCellPoint,
          o.NumberOfThreads);
    }
  };
  Key LabeledKey;
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
  std::vector<std::string> warnings;
  std::string error;
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

  // 2-4. tracing, arrangement, labeling: reused while only the Boolean properties change.
  // Inputs and properties the labeled arrangement depends on; the surface's cached
  // conversion is keyed separately.
  const Internals::Key key{ surfaceInput,
    surfaceInput->GetMTime(),
    curvesInput,
    curvesInput ? curvesInput->GetMTime() : 0,
    this->Resolution,
    this->ProjectionTolerance,
    this->ZeroCellMode,
    { this->ZeroCellPoint[0], this->ZeroCellPoint[1], this->ZeroCellPoint[2] },
    this->NumberOfThreads };
  if (!this->Internal->Labeled || !(key == this->Internal->LabeledKey))
  {
    this->Internal->Labeled = nullptr;
    auto labeled = vtkSmartPointer<vtkPolyData>::New();
    if (!this->LabelCurves(*surface, curvesInput, labeled, error))
    {
      vtkErrorMacro(<< error);
      return 0;
    }
    this->Internal->Labeled = labeled;
    this->Internal->LabeledKey = key;
  }
  this->UpdateProgress(0.8);

  // 5. Boolean
  const boolsurf::BooleanRequest request = boolsurf::MakeBooleanRequest(
    this->Operation, this->ShapeA, this->ShapeB, this->Expression, this->FillRule);
  if (!boolsurf::ComputeBoolean(this->Internal->Labeled,
        this->Internal->Fields,
        this->Internal->Labels,
        request,
        region,
        boundary,
        error))
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkBoolSurf::LabelCurves(const boolsurf::vtkSurfaceInput& surface,
  vtkPolyData* curvesInput,
  vtkPolyData* labeled,
  std::string& error)
{
  std::vector<std::string> problems;
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
    error = "Cannot trace the curves:" + boolsurf::JoinLines(problems);
    return false;
  }
  this->UpdateProgress(0.3);
  if (this->CheckAbort())
  {
    error = "aborted";
    return false;
  }

  // 3. arrangement
  vtkNew<vtkPolyData> refined;
  if (!boolsurf::ArrangeCurves(surface, traced, this->NumberOfThreads, refined, nullptr, error))
  {
    return false;
  }
  this->UpdateProgress(0.7);
  if (this->CheckAbort())
  {
    error = "aborted";
    return false;
  }

  // 4. labeling
  std::string warning;
  if (!boolsurf::LabelArrangement(refined,
        this->ZeroCellMode == 1 ? this->ZeroCellPoint : nullptr,
        labeled,
        this->Internal->Fields,
        this->Internal->Labels,
        error,
        warning))
  {
    return false;
  }
  if (!warning.empty())
  {
    vtkWarningMacro(<< warning);
  }
  return true;
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

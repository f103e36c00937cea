#include "vtkBoolSurfArrangement.h"

#include "vtkBoolSurfRankGather.h"

#include "vtkBoolSurfArrangementOutput.h"
#include "vtkBoolSurfControlOutput.h"
#include "vtkBoolSurfHomologyOutput.h"
#include "vtkBoolSurfSurfaceCache.h"
#include "vtkBoolSurfTracedCurves.h"

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkBoolSurfArrangement);

struct vtkBoolSurfArrangement::Internals
{
  boolsurf::vtkSurfaceCache Surface;
  boolsurf::Arrangement Arrangement; ///< its buffers are reused by the next update
};

//------------------------------------------------------------------------------
vtkBoolSurfArrangement::vtkBoolSurfArrangement()
  : Internal(new Internals)
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
}

//------------------------------------------------------------------------------
vtkBoolSurfArrangement::~vtkBoolSurfArrangement() = default;

//------------------------------------------------------------------------------
vtkPolyData* vtkBoolSurfArrangement::GetPatchesOutput()
{
  return this->GetOutput(1);
}

//------------------------------------------------------------------------------
int vtkBoolSurfArrangement::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  (void)port;
  return 1;
}

//------------------------------------------------------------------------------
int vtkBoolSurfArrangement::RequestData(vtkInformation* vtkNotUsed(request),
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  // Every rank takes part in the gather first (see vtkBoolSurfRankGather); only rank 0 computes.
  vtkBoolSurfRankGather gather(this, inputVector, 2);
  vtkPolyData* surfaceInput = gather.Input(0);
  vtkPolyData* curvesInput = gather.Input(1);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* patches = vtkPolyData::GetData(outputVector, 1);
  // A failed update leaves empty outputs: downstream filters and views never show the last
  // successful result as if it were this one.
  output->Initialize();
  patches->Initialize();
  if (!gather.ComputesHere())
  {
    return 1; // other MPI ranks: empty outputs
  }

  this->UpdateProgress(0.0);
  std::vector<std::string> warnings, problems;
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
    return vtkBoolSurfErrorReported;
  }
  std::vector<boolsurf::TracedCurve> curves;
  if (!boolsurf::ReadTracedCurves(curvesInput, *surface->Mesh, curves, problems))
  {
    vtkErrorMacro(<< "Invalid traced curves:" << boolsurf::JoinLines(problems));
    return vtkBoolSurfErrorReported;
  }
  this->UpdateProgress(0.1);
  if (this->CheckAbort())
  {
    return 1;
  }
  if (!boolsurf::ArrangeCurves(*surface,
        curves,
        this->NumberOfThreads,
        this->Internal->Arrangement,
        output,
        patches,
        error))
  {
    vtkErrorMacro(<< error);
    return vtkBoolSurfErrorReported;
  }
  // Each patch as control points of its input curve (when the curves came from Trace Surface
  // Curves, which records them), for the Boolean's vector output.
  std::vector<boolsurf::CurveSource> sources;
  if (boolsurf::ReadCurveSources(curvesInput, curves, sources))
  {
    const boolsurf::Arrangement& arr = this->Internal->Arrangement;
    boolsurf::GeodesicPathSolver& solver = this->Internal->Surface.GetTracer().GetPathSolver();
    std::vector<boolsurf::ControlSubCurve> perPatch(arr.Patches.size());
    boolsurf::BezierPieces bezier(arr, sources); // each Bezier segment split once per cut
    for (std::size_t p = 0; p < perPatch.size(); ++p)
    {
      const boolsurf::TraceStatus status = boolsurf::PatchControlCurve(
        solver, arr, sources, static_cast<int>(p), perPatch[p], &bezier);
      if (!status)
      {
        vtkWarningMacro("patch " << p << " has no control points (" << status.Message << ")");
        perPatch[p] = boolsurf::ControlSubCurve();
      }
    }
    boolsurf::WritePatchControlCurves(perPatch, output->GetFieldData());
  }
  // Each curve's homology class and the surface's generators (computed once per surface), for
  // the labeling's explanation of inconsistent shapes.
  std::string homologyError;
  const boolsurf::HomologyBasis* basis = this->Internal->Surface.GetHomology(homologyError);
  if (!basis ||
    !boolsurf::AddHomologyFields(*surface->Mesh,
      *basis,
      curves,
      this->Internal->Surface.GetShortenedGenerators(),
      output->GetFieldData(),
      homologyError))
  {
    vtkWarningMacro(<< homologyError << " (no CurveHomology)");
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkBoolSurfArrangement::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
}

#include "vtkBoolSurfArrangement.h"

#include "vtkBoolSurfArrayNames.h"

#include "vtkBoolSurfArrangementOutput.h"
#include "vtkBoolSurfControlCurves.h"
#include "vtkBoolSurfControlOutput.h"
#include "vtkBoolSurfHomologyOutput.h"
#include "vtkBoolSurfPieceArrangementStage.h"
#include "vtkBoolSurfStageHandoff.h"
#include "vtkBoolSurfStageSettingsDefinitions.h"
#include "vtkBoolSurfSurfaceCache.h"
#include "vtkBoolSurfTraceStage.h"

#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMultiProcessController.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkBoolSurfArrangement);

struct vtkBoolSurfArrangement::Internals
{
  /// The homology generators' field arrays, written once per surface (its basis).
  const boolsurf::HomologyBasis* GeneratorBasis = nullptr;
  vtkNew<vtkFieldData> GeneratorArrays;
  /// Results handed downstream; an edit reuses the buffers of one no output holds any more.
  boolsurf::ResultPool<boolsurf::ArrangementResult> Results;
  /// The arrangement's work buffers, shared by the pool's results (only results need two).
  std::shared_ptr<boolsurf::Arrangement::WorkBuffers> Work;
  /// On pieces: the piece and its arrangements, kept while the surface is unchanged.
  boolsurf::PieceArrangementState Pieces;
};

//------------------------------------------------------------------------------
vtkBoolSurfArrangement::vtkBoolSurfArrangement()
  : ArrangementSettings(new boolsurf::ArrangementOptions)
  , Internal(new Internals)
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
}

//------------------------------------------------------------------------------
vtkBoolSurfArrangement::~vtkBoolSurfArrangement() = default;

//------------------------------------------------------------------------------
vtkBoolSurfThreadSettingsDefinitions(vtkBoolSurfArrangement, this->ArrangementSettings->Threads);

//------------------------------------------------------------------------------
vtkPolyData* vtkBoolSurfArrangement::GetPatchesOutput()
{
  return this->GetOutput(1);
}

//------------------------------------------------------------------------------
bool vtkBoolSurfArrangement::Execute(const std::vector<vtkPolyData*>& inputs,
  const std::vector<vtkPolyData*>& outputs,
  std::string& error)
{
  vtkPolyData* surfaceInput = inputs[0];
  vtkPolyData* curvesInput = inputs[1];
  vtkPolyData* output = outputs[0];
  vtkPolyData* patches = outputs[1];
  if (boolsurf::PassOnDrawingStart(curvesInput, outputs))
  {
    return true; // a drawing being started: no arrangement yet, and no message
  }
  const boolsurf::vtkSurfaceInput* surface = this->GetSurface(surfaceInput, error);
  if (!surface)
  {
    return false;
  }
  std::shared_ptr<boolsurf::ArrangementResult> result = this->Internal->Results.Acquire();
  if (this->Internal->Work)
  {
    result->Arrangement.Work = this->Internal->Work;
  }
  result->Surface = *surface;
  // The curves as Trace Surface Curves traced them when it handed them over (on this very
  // surface); else decoded from the arrays (a file, a script's curves).
  const auto traced = this->GetTracedCurves(curvesInput, surfaceInput, *surface, error);
  if (!traced)
  {
    return false;
  }
  std::vector<boolsurf::TracedCurve>& curves = result->Curves;
  std::vector<boolsurf::CurveSource>& sources = result->Sources;
  curves = traced->Curves;
  sources = traced->Sources;
  result->Method = traced->Method;
  this->UpdateProgress(0.1);
  if (this->CheckAbort())
  {
    return true;
  }
  if (!boolsurf::ArrangeResult(result, sources, *this->ArrangementSettings, output, patches, error))
  {
    this->Internal->Work = result->Arrangement.Work;
    return false;
  }
  this->Internal->Work = result->Arrangement.Work;
  // Each patch as control points of its input curve (when the curves came from Trace Surface
  // Curves, which records them), for the Boolean's vector output.
  if (!sources.empty())
  {
    const boolsurf::Arrangement& arr = result->Arrangement;
    // Traced as the curves were (the solver's method is set again by every user of the cache).
    boolsurf::GeodesicPathSolver& solver = this->GetSurfaceCache().GetTracer().GetPathSolver();
    boolsurf::GeodesicPathOptions pathOptions = solver.GetOptions();
    pathOptions.Method = result->Method;
    solver.SetOptions(pathOptions);
    std::vector<boolsurf::ControlSubCurve> perPatch(arr.Patches.size());
    boolsurf::BezierPieces bezier(arr, sources); // each Bezier segment split once per cut
    for (std::size_t p = 0; p < perPatch.size(); ++p)
    {
      std::string error;
      if (!boolsurf::PatchControlCurve(
            solver, arr, sources, static_cast<int>(p), perPatch[p], error, &bezier))
      {
        vtkWarningMacro("patch " << p << " has no control points (" << error << ")");
        perPatch[p] = boolsurf::ControlSubCurve();
      }
    }
    boolsurf::WritePatchControlCurves(perPatch, output->GetFieldData());
  }
  // Each curve's homology class and the surface's generators (computed once per surface), for
  // the labeling's explanation of inconsistent shapes.
  std::string homologyError;
  const boolsurf::HomologyBasis* basis = this->GetSurfaceCache().GetHomology(homologyError);
  if (basis != this->Internal->GeneratorBasis)
  {
    this->Internal->GeneratorArrays->Initialize();
    this->Internal->GeneratorBasis = basis;
  }
  if (!basis ||
    !boolsurf::AddHomologyFields(*surface->Mesh,
      *basis,
      curves,
      this->GetSurfaceCache().GetShortenedGenerators(),
      output->GetFieldData(),
      homologyError,
      this->Internal->GeneratorArrays))
  {
    vtkWarningMacro(<< homologyError << " (no CurveHomology)");
  }
  // The arrangement in Core form for the labeling and selections (vtkBoolSurfStageHandoff.h).
  boolsurf::AttachStageResult<boolsurf::ArrangementResult>(
    output->GetCellData()->GetArray(boolsurf::names::ArrangementCell), std::move(result));
  return true;
}

//------------------------------------------------------------------------------
bool vtkBoolSurfArrangement::ExecutePiece(const std::vector<vtkPolyData*>& locals,
  const std::vector<vtkPolyData*>& outputs,
  std::string& error)
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  std::shared_ptr<boolsurf::PieceArrangementResult> result;
  bool drawingStart = false;
  std::vector<std::string> warnings;
  const bool ok = boolsurf::ArrangeOnPiece(controller,
    locals[0],
    locals[1],
    *this->ArrangementSettings,
    this->Internal->Pieces,
    outputs[0],
    result,
    drawingStart,
    error,
    warnings);
  this->ReportWarnings(warnings);
  if (!ok)
  {
    return false;
  }
  if (drawingStart)
  {
    boolsurf::MarkDrawingStart(outputs);
    return true;
  }
  if (controller->GetLocalProcessId() == 0)
  {
    vtkWarningMacro("ran on each rank's piece of the surface: its output is one rank's part of "
                    "the refined surface, without "
      << boolsurf::ArraysNotOnPieces << " (not yet computed on pieces)");
  }
  // The piece and its arrangement for the labeling and the Boolean on this rank.
  boolsurf::AttachStageResult<boolsurf::PieceArrangementResult>(
    outputs[0]->GetCellData()->GetArray(boolsurf::names::ArrangementCell), std::move(result));
  return true;
}

//------------------------------------------------------------------------------
void vtkBoolSurfArrangement::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfThreads: " << this->GetNumberOfThreads() << "\n";
}

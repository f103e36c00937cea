#include "vtkBoolSurfBSC.h"

#include "vtkBoolSurfControlCurves.h"

#include "vtkBoolSurfBSCStage.h"
#include "vtkBoolSurfLabelingStage.h"
#include "vtkBoolSurfSelectionOutput.h"
#include "vtkBoolSurfStageHandoff.h"
#include "vtkBoolSurfStageSettingsDefinitions.h"

#include <vtkCellData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkBoolSurfBSC);

struct vtkBoolSurfBSC::Internals
{
  std::vector<boolsurf::PatchSnap> Snaps;
  boolsurf::BscResult Result;
  boolsurf::SelectionOutputBuffers Output;
  boolsurf::ResultPathSolver Solver;
};

//------------------------------------------------------------------------------
vtkBoolSurfBSC::~vtkBoolSurfBSC() = default;

//------------------------------------------------------------------------------
vtkBoolSurfBSC::vtkBoolSurfBSC()
  : Internal(new Internals)
{
  this->BscSettings.reset(new boolsurf::BscOptions);
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(4);
}

//------------------------------------------------------------------------------
vtkBoolSurfBSCSettingsDefinitions(vtkBoolSurfBSC);

//------------------------------------------------------------------------------
bool vtkBoolSurfBSC::Execute(const std::vector<vtkPolyData*>& inputs,
  const std::vector<vtkPolyData*>& outputs,
  std::string& error)
{
  vtkPolyData* input = inputs[0];
  vtkPolyData* samples = inputs[1];
  vtkPolyData* region = outputs[0];
  vtkPolyData* boundary = outputs[1];
  vtkPolyData* controls = outputs[2];
  vtkPolyData* clipped = outputs[3];
  if (boolsurf::PassOnDrawingStart(input, outputs))
  {
    return true; // a drawing being started: no region yet, and no message
  }
  Internals& in = *this->Internal;
  // The labeled arrangement in Core form (handed over, or computed again for a file): selected
  // and written as the one-step filter does.
  const auto labeled = this->GetLabeledArrangement(input, error);
  if (!labeled)
  {
    return false;
  }
  const boolsurf::ArrangementResult& arranged = *labeled->Arranged;
  std::vector<boolsurf::SampleQuery> queries;
  if (!boolsurf::ReadSampleQueries(samples, arranged.Surface.Mesh.get(), queries, error))
  {
    return false;
  }
  const auto abort = [this] { return this->CheckAbort(); };
  if (!boolsurf::SelectBySamples(*arranged.Surface.Mesh,
        arranged.Arrangement,
        queries,
        *this->BscSettings,
        arranged.Surface.Triangles->GetLength(),
        in.Snaps,
        in.Result,
        error,
        abort))
  {
    return false;
  }
  this->UpdateProgress(0.5);
  std::string note;
  if (!boolsurf::WriteHandedOverSelection(arranged,
        in.Result.Selected,
        in.Solver,
        in.Output,
        region,
        boundary,
        controls,
        clipped,
        error,
        note))
  {
    return false;
  }
  if (!note.empty())
  {
    vtkWarningMacro(<< note);
  }
  boolsurf::AddSampleFields(in.Snaps, in.Result, region);
  boolsurf::AddSampleFields(in.Snaps, in.Result, boundary);
  // The labels of the arrangement's cells, as the one-step filter gives them.
  boolsurf::AddLabelTable(labeled->Labels, region->GetFieldData());
  return true;
}

//------------------------------------------------------------------------------
void vtkBoolSurfBSC::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SnapTolerance: " << this->GetSnapTolerance() << "\n";
  os << indent << "MaxSearchStates: " << this->GetMaxSearchStates() << "\n";
}

#include "vtkBoolSurfBSC.h"

#include "vtkBoolSurfControlCurves.h"

#include "vtkBoolSurfBSCStage.h"
#include "vtkBoolSurfBooleanStage.h"
#include "vtkBoolSurfLabelingStage.h"
#include "vtkBoolSurfSelectionOutput.h"
#include "vtkBoolSurfStageHandoff.h"

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
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(4);
}

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
  std::string note;
  if (boolsurf::PassOnDrawingStart(input, outputs))
  {
    return true; // a drawing being started: no region yet, and no message
  }
  // The arrangement in Core form when Surface Arrangement handed it over: selected and written
  // as the one-step filter does.
  if (const auto labeled = boolsurf::FindLabeledArrangement(input))
  {
    if (!this->SelectFromCore(
          *labeled->Arranged, samples, region, boundary, controls, clipped, error))
    {
      return false;
    }
    // The labels of the arrangement's cells, as the one-step filter gives them.
    boolsurf::AddLabelTable(labeled->Labels, region->GetFieldData());
    return true;
  }
  boolsurf::ArrangementFields fields;
  if (!boolsurf::ReadArrangementFields(input, fields, error))
  {
    return false;
  }
  std::vector<boolsurf::SampleQuery> queries;
  if (!boolsurf::ReadSampleQueries(samples, nullptr, queries, error))
  {
    return false;
  }
  std::vector<boolsurf::PatchSnap> snaps;
  boolsurf::BscResult result;
  if (!boolsurf::SelectSampledCells(input,
        fields,
        queries,
        boolsurf::SnapDistance(input, this->SnapTolerance),
        this->MaxSearchStates,
        snaps,
        result,
        error,
        [this] { return this->CheckAbort(); }))
  {
    return false;
  }
  this->UpdateProgress(0.5);
  boolsurf::WriteSelection(
    input, fields, result.Selected, region, boundary, controls, clipped, &note);
  if (!note.empty())
  {
    vtkWarningMacro(<< note);
  }
  boolsurf::AddSampleFields(snaps, result, region);
  boolsurf::AddSampleFields(snaps, result, boundary);
  return true;
}

//------------------------------------------------------------------------------
bool vtkBoolSurfBSC::SelectFromCore(const boolsurf::ArrangementResult& arranged,
  vtkPolyData* samples,
  vtkPolyData* region,
  vtkPolyData* boundary,
  vtkPolyData* controls,
  vtkPolyData* clipped,
  std::string& error)
{
  Internals& in = *this->Internal;
  std::vector<boolsurf::SampleQuery> queries;
  if (!boolsurf::ReadSampleQueries(samples, arranged.Surface.Mesh.get(), queries, error) ||
    !boolsurf::SelectBySamples(*arranged.Surface.Mesh,
      arranged.Arrangement,
      queries,
      boolsurf::SnapDistance(arranged.Surface.Triangles, this->SnapTolerance),
      this->MaxSearchStates,
      in.Snaps,
      in.Result,
      error,
      [this] { return this->CheckAbort(); }))
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
  return true;
}

//------------------------------------------------------------------------------
void vtkBoolSurfBSC::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SnapTolerance: " << this->SnapTolerance << "\n";
  os << indent << "MaxSearchStates: " << this->MaxSearchStates << "\n";
}

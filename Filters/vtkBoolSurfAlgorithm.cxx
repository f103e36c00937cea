#include "vtkBoolSurfAlgorithm.h"

#include "Geodesic/GeodesicPath.h"
#include "Labeling/ArrangementLabelingInput.h"

#include "vtkBoolSurfArrangementRebuild.h"
#include "vtkBoolSurfArrayNames.h"
#include "vtkBoolSurfArrayRanges.h"
#include "vtkBoolSurfControlOutput.h"
#include "vtkBoolSurfOutputReuse.h"
#include "vtkBoolSurfPieceGlobalIds.h"
#include "vtkBoolSurfRankGather.h"
#include "vtkBoolSurfStageHandoff.h"
#include "vtkBoolSurfSurfaceCache.h"
#include "vtkBoolSurfSurfacePiece.h"
#include "vtkBoolSurfTracedCurves.h"

#include <vtkAbstractArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMultiProcessController.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <algorithm>

namespace
{
/// The field data of a BoolSurf filter's output. VTK's executive passes every field array of
/// the first input to every output before each RequestData (vtkDemandDrivenPipeline::
/// ExecuteDataStart); BoolSurf's outputs are written whole, starting empty, so those copies
/// were thrown away at once, and on an arrangement (about 40 field arrays, each added by name)
/// they cost more than a small scene's whole arrangement. The output keeps this field data
/// across updates (Initialize empties it, it does not replace it), so it never takes them.
/// Shallow and deep copies of the output get a plain vtkFieldData with the same arrays.
class vtkBoolSurfOutputFieldData : public vtkFieldData
{
public:
  static vtkBoolSurfOutputFieldData* New();
  vtkTypeMacro(vtkBoolSurfOutputFieldData, vtkFieldData);
  void PassData(vtkFieldData*) override {}

protected:
  vtkBoolSurfOutputFieldData() = default;
  ~vtkBoolSurfOutputFieldData() override = default;

private:
  vtkBoolSurfOutputFieldData(const vtkBoolSurfOutputFieldData&) = delete;
  void operator=(const vtkBoolSurfOutputFieldData&) = delete;
};
vtkStandardNewMacro(vtkBoolSurfOutputFieldData);
} // namespace

//------------------------------------------------------------------------------
vtkBoolSurfAlgorithm::vtkBoolSurfAlgorithm() = default;

//------------------------------------------------------------------------------
vtkBoolSurfAlgorithm::~vtkBoolSurfAlgorithm() = default;

//------------------------------------------------------------------------------
void vtkBoolSurfAlgorithm::RecordFailure(const std::string&, const std::vector<vtkPolyData*>&) {}

//------------------------------------------------------------------------------
bool vtkBoolSurfAlgorithm::ExecutePiece(const std::vector<vtkPolyData*>&,
  const std::vector<vtkPolyData*>&,
  std::string&)
{
  return false;
}

//------------------------------------------------------------------------------
boolsurf::vtkSurfaceCache& vtkBoolSurfAlgorithm::GetSurfaceCache()
{
  if (!this->Surface)
  {
    this->Surface = std::make_unique<boolsurf::vtkSurfaceCache>();
  }
  return *this->Surface;
}

//------------------------------------------------------------------------------
const boolsurf::vtkSurfaceInput* vtkBoolSurfAlgorithm::GetSurface(vtkPolyData* input,
  std::string& error)
{
  std::vector<std::string> warnings;
  const boolsurf::vtkSurfaceInput* surface =
    this->GetSurfaceCache().GetUsable(input, warnings, error);
  this->ReportWarnings(warnings);
  return surface;
}

//------------------------------------------------------------------------------
std::shared_ptr<const boolsurf::TracedCurvesResult> vtkBoolSurfAlgorithm::GetTracedCurves(
  vtkPolyData* curves,
  vtkPolyData* surfaceInput,
  const boolsurf::vtkSurfaceInput& surface,
  std::string& error)
{
  auto traced = boolsurf::FindStageResult<boolsurf::TracedCurvesResult>(
    curves ? curves->GetPointData()->GetArray(boolsurf::names::TriangleId) : nullptr);
  if (traced && traced->Surface.Matches(surfaceInput))
  {
    return traced;
  }
  // No result attached, or one traced on another surface: the arrays say what the curves are.
  auto decoded = std::make_shared<boolsurf::TracedCurvesResult>();
  std::vector<std::string> problems;
  if (!boolsurf::ReadTracedCurves(curves, *surface.Mesh, decoded->Curves, problems))
  {
    error = "Invalid traced curves:" + boolsurf::JoinLines(problems);
    return nullptr;
  }
  if (!boolsurf::ReadCurveSources(curves, decoded->Curves, decoded->Sources))
  {
    decoded->Sources.clear();
  }
  decoded->Method = boolsurf::GeodesicMethod::Bounded; // the method is not in the arrays
  return decoded;
}

//------------------------------------------------------------------------------
std::shared_ptr<const boolsurf::ArrangementResult> vtkBoolSurfAlgorithm::GetArrangement(
  vtkPolyData* input,
  std::string& error)
{
  auto arranged = boolsurf::FindStageResult<boolsurf::ArrangementResult>(
    input ? input->GetCellData()->GetArray(boolsurf::names::ArrangementCell) : nullptr);
  if (arranged)
  {
    return arranged;
  }
  // Read from a file, deep-copied or edited since: computed again from what the refined
  // surface records of its mesh and curves.
  if (!this->Rebuilt)
  {
    this->Rebuilt = std::make_unique<boolsurf::RebuiltArrangement>();
  }
  return this->Rebuilt->Get(input, error);
}

//------------------------------------------------------------------------------
std::shared_ptr<const boolsurf::LabeledArrangementResult>
vtkBoolSurfAlgorithm::GetLabeledArrangement(vtkPolyData* input, std::string& error)
{
  vtkAbstractArray* cellLabels =
    input ? input->GetFieldData()->GetAbstractArray(boolsurf::names::CellLabels) : nullptr;
  if (auto attached = boolsurf::FindStageResult<boolsurf::LabeledArrangementResult>(cellLabels))
  {
    return attached;
  }
  auto arranged = this->GetArrangement(input, error);
  if (!arranged)
  {
    return nullptr;
  }
  auto labeled = std::make_shared<boolsurf::LabeledArrangementResult>();
  if (cellLabels)
  {
    // Labeled by Label Arrangement Cells (with the zero cell it was given): its table.
    if (!boolsurf::ReadLabelTable(input, *arranged, labeled->Labels, error))
    {
      return nullptr;
    }
  }
  else
  {
    // Not labeled: with the automatic zero cell, as the one-step filter labels.
    labeled->Labels = boolsurf::LabelCells(boolsurf::MakeLabelingInput(*arranged->Surface.Mesh,
      *arranged->Surface.Topology,
      arranged->Curves,
      arranged->Arrangement));
  }
  labeled->Arranged = std::move(arranged);
  return labeled;
}

//------------------------------------------------------------------------------
void vtkBoolSurfAlgorithm::ReportWarnings(const std::vector<std::string>& lines)
{
  for (const std::string& line : lines)
  {
    vtkWarningMacro(<< line);
  }
}

//------------------------------------------------------------------------------
void vtkBoolSurfAlgorithm::SetInputPortOptional(int port)
{
  this->OptionalPorts.push_back(port);
}

//------------------------------------------------------------------------------
void vtkBoolSurfAlgorithm::SetSurfacePorts(const std::vector<int>& ports)
{
  this->SurfacePorts = ports;
}

//------------------------------------------------------------------------------
int vtkBoolSurfAlgorithm::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  if (std::find(this->OptionalPorts.begin(), this->OptionalPorts.end(), port) !=
    this->OptionalPorts.end())
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

//------------------------------------------------------------------------------
// Every BoolSurf port takes and makes vtkPolyData, so the composite executive VTK uses by
// default only adds its checks for composite inputs: about a tenth of a small scene's chain of
// stage filters. ParaView sets its own executive on every filter it creates.
vtkExecutive* vtkBoolSurfAlgorithm::CreateDefaultExecutive()
{
  return vtkStreamingDemandDrivenPipeline::New();
}

//------------------------------------------------------------------------------
int vtkBoolSurfAlgorithm::RequestData(vtkInformation* vtkNotUsed(request),
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  const int ports = this->GetNumberOfInputPorts();
  // A surface split across ranks stays where it is for the filters that work on pieces: every
  // rank decides the same way (one all-reduce), then runs the filter on its piece.
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  vtkPolyData* local = ports > 0 && inputVector[0]->GetNumberOfInformationObjects() > 0
    ? vtkPolyData::GetData(inputVector[0], 0)
    : nullptr;
  bool onPieces =
    this->ExecutesOnPieces() && vtkBoolSurfSurfacePiece::IsDistributed(controller, local);
  vtkPolyData* withIds = local;
  if (onPieces && this->PiecesNeedGlobalIds() &&
    !vtkBoolSurfSurfacePiece::HasGlobalIds(controller, local))
  {
    if (!this->PieceIds)
    {
      this->PieceIds = std::make_unique<vtkBoolSurfPieceGlobalIds>();
    }
    withIds = this->PieceIds->Generate(controller, local);
    if (controller->GetLocalProcessId() == 0)
    {
      vtkWarningMacro("the surface is split across ranks, but its pieces carry no point and cell "
                      "GlobalIds: generated them (vtkGenerateGlobalIds; the triangles numbered "
                      "rank by rank, as the surface gathered to rank 0 numbers them)");
    }
  }
  if (onPieces)
  {
    std::vector<vtkPolyData*> locals(static_cast<std::size_t>(ports), nullptr);
    for (int p = 0; p < ports; ++p)
    {
      if (inputVector[p]->GetNumberOfInformationObjects() > 0)
      {
        locals[p] = p == 0 ? withIds : vtkPolyData::GetData(inputVector[p], 0);
      }
    }
    this->PiecesGatherInstead = false;
    const int done = this->RunOnPiece(locals, outputVector);
    if (!this->PiecesGatherInstead)
    {
      return done;
    }
    this->PiecesGatherInstead = false; // every rank gathers, as for a surface on one rank
  }
  // Every rank takes part in the gather first, before anything that may fail or return early
  // (see vtkBoolSurfRankGather); only the computing rank runs the filter.
  vtkBoolSurfRankGather gather(this, inputVector, ports, this->SurfacePorts);
  std::vector<vtkPolyData*> inputs(static_cast<std::size_t>(ports));
  for (int p = 0; p < ports; ++p)
  {
    inputs[p] = gather.Input(p);
  }
  std::vector<vtkPolyData*> outputs(static_cast<std::size_t>(this->GetNumberOfOutputPorts()));
  for (std::size_t p = 0; p < outputs.size(); ++p)
  {
    outputs[p] = vtkPolyData::GetData(outputVector, static_cast<int>(p));
    // Other ranks, and a failure: empty outputs. The executive has normally emptied them
    // already (PrepareForNewData); initializing an empty output again costs a few
    // microseconds per port, which a chain of stage filters pays on every edit.
    boolsurf::EmptyPolyData(outputs[p]);
    if (!vtkBoolSurfOutputFieldData::SafeDownCast(outputs[p]->GetFieldData()))
    {
      outputs[p]->SetFieldData(vtkSmartPointer<vtkBoolSurfOutputFieldData>::New());
    }
  }
  if (!gather.ComputesHere())
  {
    return 1;
  }
  // VTK's field data grows its list of arrays one slot at a time, each step a reallocation and
  // a Modified event the dataset observes (about 4,000 instructions an array, more than most
  // of the arrays' own writing on a small edit); an update writes the arrays the last one did,
  // so the slots are reserved at once.
  this->ArrayCounts.resize(outputs.size());
  for (std::size_t p = 0; p < outputs.size(); ++p)
  {
    boolsurf::ReserveArraySlots(outputs[p], this->ArrayCounts[p]);
  }
  // An input from Surface Arrangement on pieces is one rank's part, or the parts appended: no
  // whole arrangement to compute from (Docs/Parallel.md, "What still gathers").
  for (int p = 0; p < ports; ++p)
  {
    if (inputs[p] &&
      inputs[p]->GetFieldData()->GetAbstractArray(boolsurf::names::ArrangementOnPieces))
    {
      vtkErrorMacro(
        "input " << p
                 << " comes from Surface Arrangement run on each rank's piece "
                    "of a split surface; "
                 << this->GetClassName()
                 << " gathers its inputs to rank 0 and cannot use pieces yet (Label "
                    "Arrangement Cells and Surface Boolean run on them, and the one-step BoolSurf "
                    "filter runs on the surface's pieces itself)");
      return vtkBoolSurfErrorReported;
    }
  }
  // No UpdateProgress(0) here nor (1) at the end: the executive reports both around
  // RequestData (vtkDemandDrivenPipeline::ExecuteDataStart/End), and each report is an event.
  std::string error;
  if (!this->Execute(inputs, outputs, error))
  {
    return this->Fail(error, outputs);
  }
  for (std::size_t p = 0; p < outputs.size(); ++p)
  {
    this->ArrayCounts[p] = boolsurf::CountArrays(outputs[p]);
    // The ranges ParaView's data information reads after every update, one pass per array
    // (vtkBoolSurfArrayRanges.h); arrays kept unchanged from the last update, and those the
    // filter stored already, hold theirs.
    boolsurf::CacheDataRanges(outputs[p]);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkBoolSurfAlgorithm::RunOnPiece(const std::vector<vtkPolyData*>& locals,
  vtkInformationVector* outputVector)
{
  std::vector<vtkPolyData*> outputs(static_cast<std::size_t>(this->GetNumberOfOutputPorts()));
  for (std::size_t p = 0; p < outputs.size(); ++p)
  {
    outputs[p] = vtkPolyData::GetData(outputVector, static_cast<int>(p));
    boolsurf::EmptyPolyData(outputs[p]);
  }
  std::string error;
  if (!this->ExecutePiece(locals, outputs, error))
  {
    return this->Fail(error, outputs);
  }
  for (vtkPolyData* output : outputs)
  {
    boolsurf::CacheDataRanges(output);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkBoolSurfAlgorithm::Fail(const std::string& error, const std::vector<vtkPolyData*>& outputs)
{
  for (vtkPolyData* output : outputs)
  {
    output->Initialize();
  }
  this->RecordFailure(error, outputs);
  if (!error.empty())
  {
    vtkErrorMacro(<< error);
  }
  return vtkBoolSurfErrorReported;
}

//------------------------------------------------------------------------------
void vtkBoolSurfAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

//------------------------------------------------------------------------------
// The property's values are those of Core's enumeration.
static_assert(
  vtkBoolSurfAlgorithm::GEODESIC_BOUNDED == static_cast<int>(boolsurf::GeodesicMethod::Bounded),
  "GeodesicMethod values");
static_assert(
  vtkBoolSurfAlgorithm::GEODESIC_EXACT == static_cast<int>(boolsurf::GeodesicMethod::Exact),
  "GeodesicMethod values");
static_assert(vtkBoolSurfAlgorithm::GEODESIC_LOCALLY_SHORTEST ==
    static_cast<int>(boolsurf::GeodesicMethod::LocallyShortest),
  "GeodesicMethod values");

const char* vtkBoolSurfAlgorithm::GetGeodesicMethodName(int method)
{
  if (method < GEODESIC_BOUNDED || method > GEODESIC_LOCALLY_SHORTEST)
  {
    return "Unknown";
  }
  return boolsurf::GeodesicMethodName(static_cast<boolsurf::GeodesicMethod>(method));
}

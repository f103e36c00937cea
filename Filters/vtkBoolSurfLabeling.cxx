#include "vtkBoolSurfLabeling.h"

#include "vtkBoolSurfControlCurves.h"

#include "vtkBoolSurfArrayNames.h"

#include "vtkBoolSurfHomologyOutput.h"
#include "vtkBoolSurfLabelingStage.h"
#include "vtkBoolSurfPieceCosts.h"
#include "vtkBoolSurfPieceLabels.h"
#include "vtkBoolSurfStageHandoff.h"
#include "vtkBoolSurfStageSettingsDefinitions.h"
#include "vtkBoolSurfTriangleLabels.h"

#include <vtkAbstractArray.h>
#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMultiProcessController.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkWeakPointer.h>

vtkStandardNewMacro(vtkBoolSurfLabeling);

struct vtkBoolSurfLabeling::Internals
{
  /// On the arrangement's input surface, for ZeroCellPoint.
  boolsurf::SurfaceLocator Locator;
  /// Port 1 as last drawn, and the generator array it was drawn from.
  vtkNew<vtkPolyData> Generators;
  vtkWeakPointer<vtkAbstractArray> GeneratorKey;
  vtkMTimeType GeneratorTime = 0;
  bool GeneratorsHadKey = false;
  bool GeneratorsDrawn = false;
  /// ShapeLabel and Labels, kept so that an edit writes only the triangles whose labels change.
  boolsurf::KeptTriangleLabels ShapeLabel, Labels;
};

//------------------------------------------------------------------------------
vtkBoolSurfLabeling::vtkBoolSurfLabeling()
  : Internal(new Internals)
{
  this->ZeroCellSettings.reset(new boolsurf::ZeroCellOptions);
  this->SetNumberOfOutputPorts(2);
}

//------------------------------------------------------------------------------
vtkBoolSurfLabeling::~vtkBoolSurfLabeling() = default;

//------------------------------------------------------------------------------
vtkBoolSurfZeroCellSettingsDefinitions(vtkBoolSurfLabeling);

//------------------------------------------------------------------------------
bool vtkBoolSurfLabeling::Execute(const std::vector<vtkPolyData*>& inputs,
  const std::vector<vtkPolyData*>& outputs,
  std::string& error)
{
  vtkPolyData* input = inputs[0];
  vtkPolyData* output = outputs[0];
  vtkPolyData* generators = outputs[1];
  if (boolsurf::PassOnDrawingStart(input, outputs))
  {
    return true; // a drawing being started: no labels yet, and no message
  }
  boolsurf::LabelingResult labels;
  std::string warning;
  boolsurf::LabelingOutputOptions options;
  options.ZeroCell = *this->ZeroCellSettings;
  options.ColorShape = this->ColorShape;
  options.PerTriangleLabels = this->PerTriangleLabels;
  options.KeptShapeLabel = &this->Internal->ShapeLabel;
  options.KeptLabels = &this->Internal->Labels;
  // The arrangement in Core form (handed over, or computed again for a file): labeled as the
  // one-step filter labels it.
  const auto arranged = this->GetArrangement(input, error);
  if (!arranged)
  {
    return false;
  }
  if (options.ZeroCell.Mode == boolsurf::ZeroCellMode::Point)
  {
    options.SurfaceLocator = this->Internal->Locator.Get(arranged->Surface.Triangles);
  }
  if (!boolsurf::LabelArrangement(input, *arranged, options, output, labels, error, warning))
  {
    return false;
  }
  auto result = std::make_shared<boolsurf::LabeledArrangementResult>();
  result->Arranged = arranged;
  result->Labels = std::move(labels);
  boolsurf::AttachStageResult<boolsurf::LabeledArrangementResult>(
    output->GetFieldData()->GetArray(boolsurf::names::CellLabels), std::move(result));
  if (!warning.empty())
  {
    vtkWarningMacro(<< warning);
  }
  // Port 1: the homology generators the arrangement found on the surface.
  // Port 1 depends only on the generators' arrays, which the arrangement writes once per
  // surface: drawn again only when they are other arrays.
  vtkAbstractArray* key =
    input->GetFieldData()->GetAbstractArray(boolsurf::names::HomologyGeneratorPoints);
  Internals& in = *this->Internal;
  // Without generator arrays (a genus-0 surface) the empty drawing is kept as well.
  const bool unchanged = in.GeneratorsDrawn &&
    (key ? key == in.GeneratorKey.GetPointer() && key->GetMTime() == in.GeneratorTime
         : !in.GeneratorsHadKey);
  if (!unchanged)
  {
    in.Generators->Initialize();
    boolsurf::WriteGeneratorPolylines(
      boolsurf::ReadHomologyFields(input->GetFieldData()), in.Generators);
    in.GeneratorKey = key;
    in.GeneratorTime = key ? key->GetMTime() : 0;
    in.GeneratorsHadKey = key != nullptr;
    in.GeneratorsDrawn = true;
  }
  generators->ShallowCopy(in.Generators);
  return true;
}

//------------------------------------------------------------------------------
bool vtkBoolSurfLabeling::ExecutePiece(const std::vector<vtkPolyData*>& locals,
  const std::vector<vtkPolyData*>& outputs,
  std::string& error)
{
  if (boolsurf::PassOnDrawingStart(locals[0], outputs))
  {
    return true; // a drawing being started (on every rank: the arrangement marked each piece)
  }
  boolsurf::PieceStopwatch watch; // this rank's time, written with the output (mpi_scale.py)
  boolsurf::LabelingOutputOptions options;
  options.ZeroCell = *this->ZeroCellSettings;
  options.ColorShape = this->ColorShape;
  options.PerTriangleLabels = this->PerTriangleLabels;
  std::shared_ptr<boolsurf::PieceLabeledResult> result;
  std::string warning;
  if (!boolsurf::LabelPiece(vtkMultiProcessController::GetGlobalController(),
        this->Internal->Locator,
        locals[0],
        options,
        outputs[0],
        result,
        error,
        warning))
  {
    return false;
  }
  boolsurf::AttachStageResult<boolsurf::PieceLabeledResult>(
    outputs[0]->GetFieldData()->GetArray(boolsurf::names::CellLabels), std::move(result));
  boolsurf::WriteLocalStageCosts(watch.Lap(), outputs[0]);
  // Port 1: the homology generators need the homology basis of the whole surface, which no
  // rank has: empty, marked as coming from pieces, and said so below.
  outputs[1]->Initialize();
  if (vtkAbstractArray* onPieces =
        outputs[0]->GetFieldData()->GetAbstractArray(boolsurf::names::ArrangementOnPieces))
  {
    outputs[1]->GetFieldData()->AddArray(onPieces);
  }
  // The labels are the same on every rank: one rank says what they mean.
  if (vtkMultiProcessController::GetGlobalController()->GetLocalProcessId() == 0)
  {
    if (!warning.empty())
    {
      vtkWarningMacro(<< warning);
    }
    vtkWarningMacro("ran on each rank's piece of the surface: homology generators are not "
                    "computed on pieces (they need the homology basis of the whole surface): "
                    "port 1 (the generators) stays empty and the labels carry no "
                    "HomologyExcess; the labels, consistency verdicts and the zero cell (given "
                    "by a point or automatic) are the one-rank ones");
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkBoolSurfLabeling::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const double* zeroCellPoint = this->GetZeroCellPoint();
  os << indent << "ZeroCellMode: " << this->GetZeroCellMode() << "\n";
  os << indent << "ZeroCellPoint: " << zeroCellPoint[0] << " " << zeroCellPoint[1] << " "
     << zeroCellPoint[2] << "\n";
  os << indent << "ColorShape: " << this->ColorShape << "\n";
  os << indent << "PerTriangleLabels: " << this->PerTriangleLabels << "\n";
}

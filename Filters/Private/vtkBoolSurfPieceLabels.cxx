#include "vtkBoolSurfPieceLabels.h"

#include "vtkBoolSurfArrayNames.h"
#include "vtkBoolSurfBooleanStage.h"
#include "vtkBoolSurfPieceArrangementOutput.h"
#include "vtkBoolSurfPieceZeroCell.h"
#include "vtkBoolSurfStageHandoff.h"

#include "Distributed/MergedLabeling.h"
#include "Distributed/PieceSelection.h"

#include <vtkAbstractArray.h>
#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

namespace boolsurf
{

//------------------------------------------------------------------------------
bool LabelPieceCells(vtkMultiProcessController* controller,
  SurfaceLocator& locator,
  const std::shared_ptr<const PieceArrangementResult>& arranged,
  const ZeroCellOptions& zeroCellOptions,
  const std::vector<int>& shapeIds,
  PieceLabeledResult& result,
  std::string& error)
{
  int zeroCell = -1;
  if (zeroCellOptions.Mode == ZeroCellMode::Point)
  {
    zeroCell = PieceZeroCellAt(controller,
      *arranged,
      arranged->Surface && arranged->Surface->GetNumberOfCells() > 0
        ? locator.Get(arranged->Surface)
        : nullptr,
      zeroCellOptions.Point.data(),
      error);
    if (zeroCell < 0)
    {
      return false; // on every rank: the all-gather gave each the same answer
    }
  }
  result.Arranged = arranged;
  result.Labels = LabelMergedArrangement(arranged->Run.GetMerged(), shapeIds, zeroCell);
  return true;
}

//------------------------------------------------------------------------------
bool LabelPiece(vtkMultiProcessController* controller,
  SurfaceLocator& locator,
  vtkPolyData* input,
  const LabelingOutputOptions& options,
  vtkPolyData* output,
  std::shared_ptr<PieceLabeledResult>& result,
  std::string& error,
  std::string& warning)
{
  auto arranged = FindStageResult<PieceArrangementResult>(
    input ? input->GetCellData()->GetArray(names::ArrangementCell) : nullptr);
  if (!arranged)
  {
    error = "Label Arrangement Cells on each rank's piece needs Surface Arrangement's result on "
            "the rank (its output on pieces, unchanged); this input has none";
    return false;
  }
  result = std::make_shared<PieceLabeledResult>();
  if (!LabelPieceCells(
        controller, locator, arranged, options.ZeroCell, arranged->ShapeIds, *result, error))
  {
    return false; // on every rank: the all-gather gave each the same answer
  }
  WriteLabelingOutput(input, nullptr, result->Labels, options, output, warning);
  return true;
}

//------------------------------------------------------------------------------
std::shared_ptr<const PieceLabeledResult> FindPieceLabels(vtkPolyData* input, std::string& error)
{
  auto labeled = FindStageResult<PieceLabeledResult>(
    input ? input->GetFieldData()->GetAbstractArray(names::CellLabels) : nullptr);
  if (!labeled)
  {
    error = "Surface Boolean on each rank's piece needs Label Arrangement Cells' result on the "
            "rank (its output on pieces, unchanged); this input has none";
  }
  return labeled;
}

//------------------------------------------------------------------------------
bool WritePieceRegion(const PieceLabeledResult& labeled,
  const BooleanOptions& options,
  vtkPolyData* region,
  std::string& text,
  std::vector<char>& cells,
  std::string& error)
{
  const PieceArrangementResult& arranged = *labeled.Arranged;
  const vtkBoolSurfPieceArrangement& run = arranged.Run;
  PieceRegion selected;
  if (!SelectPieceBoolean(*arranged.Piece,
        run.GetArrangement(),
        run.GetMerged().GlobalCellOfLocal[0],
        labeled.Labels,
        options,
        selected,
        cells,
        text,
        error))
  {
    return false;
  }
  WritePieceTriangles(
    *arranged.Piece, run, selected.Triangles, selected.SourceTriangles, selected.Cells, region);
  // The surface's own cell arrays, from each triangle's source triangle on this rank.
  vtkPolyData* surface = arranged.Surface;
  if (surface && surface->GetCellData()->GetNumberOfArrays() > 0)
  {
    vtkCellData* from = surface->GetCellData();
    vtkNew<vtkCellData> carried;
    carried->CopyAllocate(from, static_cast<vtkIdType>(selected.Triangles.size()));
    for (std::size_t i = 0; i < selected.Triangles.size(); ++i)
    {
      const int local = arranged.Piece->LocalTriangle(selected.SourceTriangles[i]);
      const vtkIdType cell = local >= 0 ? (*arranged.SurfaceCell)[local] : -1;
      if (cell >= 0)
      {
        carried->CopyData(from, cell, static_cast<vtkIdType>(i));
      }
    }
    for (int a = 0; a < carried->GetNumberOfArrays(); ++a)
    {
      vtkAbstractArray* array = carried->GetAbstractArray(a);
      if (array->GetName() && !region->GetCellData()->GetAbstractArray(array->GetName()))
      {
        region->GetCellData()->AddArray(array);
      }
    }
  }
  vtkNew<vtkUnsignedCharArray> mark;
  mark->SetName(names::Region);
  mark->SetNumberOfTuples(region->GetNumberOfCells());
  mark->FillValue(1);
  region->GetCellData()->AddArray(mark);
  region->GetCellData()->SetActiveScalars(names::Region);
  AddExpressionField(region, text);
  AddLabelTable(labeled.Labels, region->GetFieldData());
  return true;
}

}

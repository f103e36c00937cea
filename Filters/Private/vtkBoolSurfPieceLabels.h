/**
 * @brief   Label Arrangement Cells and Surface Boolean on each rank's piece, after Surface
 *          Arrangement ran on the pieces (vtkBoolSurfPieceArrangementStage.h)
 *
 * Nothing is gathered and nothing is sent: every rank has the merged cell graph (message 3 of
 * the distributed arrangement), which is small, so each labels it whole (replicated; the same
 * labels and consistency verdicts on every rank, equal to the labeling stage's on the whole
 * arrangement: Core/Distributed/MergedLabeling.h), and each selects the Boolean's cells from
 * those labels and keeps its owned refined triangles in them (Core/Distributed/PieceSelection.h).
 * The union over ranks of the regions is the one-rank region, triangle for triangle.
 *
 * Each stage reads the result the stage before it attached on the same rank; an input without
 * one (a piece output read from a file, or edited) is refused, naming the stage.
 */
#ifndef vtkBoolSurfPieceLabels_h
#define vtkBoolSurfPieceLabels_h

#include "vtkBoolSurfLabelingStage.h"
#include "vtkBoolSurfPieceArrangementStage.h"
#include "vtkBoolSurfStageHandoff.h"

#include "Labeling/CellLabeling.h"
#include "Selection/BooleanOptions.h"

#include <memory>
#include <string>
#include <vector>

class vtkMultiProcessController;
class vtkPolyData;

namespace boolsurf
{

/// Label Arrangement Cells on a piece -> Surface Boolean on that piece.
struct PieceLabeledResult
{
  std::shared_ptr<const PieceArrangementResult> Arranged;
  LabelingResult Labels;
};

/// Labels the merged cell graph of the piece arrangement attached to `input` and writes
/// `output` as LabelArrangement does (WriteLabelingOutput); `result` is the hand-off to the
/// Boolean. False with `error` when `input` carries no piece arrangement. Collective for a zero
/// cell given by a point (ZeroCellMode Point: vtkBoolSurfPieceZeroCell.h, with `locator` on
/// the rank's surface piece).
bool LabelPiece(vtkMultiProcessController* controller,
  SurfaceLocator& locator,
  vtkPolyData* input,
  const LabelingOutputOptions& options,
  vtkPolyData* output,
  std::shared_ptr<PieceLabeledResult>& result,
  std::string& error,
  std::string& warning);

/// The result Label Arrangement Cells on a piece attached to `input`, or null with `error`
/// naming Surface Boolean (an input read from a file, or edited, has none).
std::shared_ptr<const PieceLabeledResult> FindPieceLabels(vtkPolyData* input, std::string& error);

/// The labels of the merged cell graph of `arranged` for the shapes `shapeIds` (the drawing's,
/// with any shape without curves yet; sorted, distinct), into `result`: LabelPiece's labeling,
/// without an output. Collective for a zero cell given by a point.
bool LabelPieceCells(vtkMultiProcessController* controller,
  SurfaceLocator& locator,
  const std::shared_ptr<const PieceArrangementResult>& arranged,
  const ZeroCellOptions& zeroCell,
  const std::vector<int>& shapeIds,
  PieceLabeledResult& result,
  std::string& error);

/// The Boolean's region on the labeled piece `labeled`: its owned refined triangles in the
/// selected cells, with ArrangementCell, SourceTriangle, TriangleId, Barycentric, Region, the
/// surface's own cell arrays, the expression and the label table. `text` is the expression
/// evaluated, `selected` the selection per global cell.
bool WritePieceRegion(const PieceLabeledResult& labeled,
  const BooleanOptions& options,
  vtkPolyData* region,
  std::string& text,
  std::vector<char>& selected,
  std::string& error);

}

#endif

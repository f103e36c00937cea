// The labeling stage on VTK data, shared by vtkBoolSurfLabeling and vtkBoolSurfBoolean (a
// private header of the module).
#ifndef vtkBoolSurfLabelingStage_h
#define vtkBoolSurfLabelingStage_h

#include "Labeling/CellLabeling.h"
#include "Labeling/ZeroCellOptions.h"
#include "vtkBoolSurfArrangementOutput.h"

#include <vtkSmartPointer.h>

#include <string>

class vtkFieldData;
class vtkPolyData;
class vtkStaticCellLocator;

namespace boolsurf
{

struct ArrangementResult;
class KeptTriangleLabels;

/// The arrangement cell holding the point of the surface closest to `point` (the one-step
/// filter's and the labeling's ZeroCellPoint): `locator` is built on the surface's triangles.
/// -1 with a message when there is none.
int ZeroCellAt(vtkStaticCellLocator* locator,
  const TriangleMesh& mesh,
  const Arrangement& arrangement,
  const double point[3],
  std::string& error);

/// What the labeling writes besides the per-cell table.
struct LabelingOutputOptions
{
  /// How the zero cell is chosen (the filters' ZeroCellMode and ZeroCellPoint).
  ZeroCellOptions ZeroCell;
  /// ShapeId whose label is written per triangle as the 1-component cell array `ShapeLabel`
  /// (for coloring); -1: none.
  int ColorShape = -1;
  /// Every shape's label per triangle as the cell array `Labels` (one component per shape):
  /// memory triangles x shapes, so off unless asked for.
  bool PerTriangleLabels = false;
  /// For ZeroCellMode Point: a locator on the arrangement's input surface.
  vtkStaticCellLocator* SurfaceLocator = nullptr;
  /// Where the per-triangle arrays are kept from update to update (a filter's, so that an edit
  /// writes only what changed: vtkBoolSurfTriangleLabels.h); null: written whole.
  KeptTriangleLabels* KeptShapeLabel = nullptr;
  KeptTriangleLabels* KeptLabels = nullptr;
};

/// Labels the cells of `arranged`, the arrangement of the refined surface `input`, the way the
/// one-step filter labels. Adds field data `CellLabels` (cells x shapes, components named
/// S<id>) and `ShapeConsistent` (per shape index, in the order of `ShapeIds`) to `output` (a
/// shallow copy of the input), plus the per-triangle arrays asked for. `warning` names
/// inconsistent shapes and unknown ColorShape ids (empty when none).
bool LabelArrangement(vtkPolyData* input,
  const ArrangementResult& arranged,
  const LabelingOutputOptions& options,
  vtkPolyData* output,
  LabelingResult& labels,
  std::string& error,
  std::string& warning);

/// LabelArrangement's output for labels computed elsewhere (on the merged cell graph of a
/// distributed arrangement, vtkBoolSurfPieceLabels.h): `output` a shallow copy of `input` with
/// the label table and the per-triangle arrays asked for (read through ArrangementCell; kept
/// from update to update per tile of `arrangement`, written whole when it is null).
void WriteLabelingOutput(vtkPolyData* input,
  const Arrangement* arrangement,
  const LabelingResult& labels,
  const LabelingOutputOptions& options,
  vtkPolyData* output,
  std::string& warning);

/// Field data `ShapeIds`, `ShapeConsistent` (per shape) and `CellLabels` (cells x shapes,
/// components named S<id>): the labels as a table, written by the labeling and the one-step
/// filters alike.
void AddLabelTable(const LabelingResult& labels, vtkFieldData* fd);

/// "shape S7 is inconsistent: cell 3 is reached with labels 0 and 1; ..." for the conflicts
/// of `labels` (empty when every shape is consistent).
std::string InconsistencyWarning(const LabelingResult& labels);

} // namespace boolsurf

#endif

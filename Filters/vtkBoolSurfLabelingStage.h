// The labeling stage on VTK data, shared by vtkBoolSurfLabeling and the one-step vtkBoolSurf
// filter (a private header of the module).
#ifndef vtkBoolSurfLabelingStage_h
#define vtkBoolSurfLabelingStage_h

#include "Labeling/CellLabeling.h"
#include "vtkBoolSurfArrangementOutput.h"

#include <string>

class vtkPolyData;

namespace boolsurf
{

/// Labels the cells of a refined surface. zeroCellPoint is null in automatic mode. Adds
/// `Labels`, `ShapeConsistent` and `CellLabels` to `output` (a shallow copy of the
/// input). `warning` names inconsistent shapes (empty when all are consistent).
bool LabelArrangement(vtkPolyData* input,
  const double* zeroCellPoint,
  vtkPolyData* output,
  ArrangementFields& fields,
  LabelingResult& labels,
  std::string& error,
  std::string& warning);

} // namespace boolsurf

#endif

#include "vtkBoolSurfPieceBoolean.h"

#include "vtkBoolSurfBooleanStage.h"
#include "vtkBoolSurfPieceRegionBoundary.h"

#include <vtkFieldData.h>
#include <vtkMultiProcessController.h>
#include <vtkPolyData.h>

namespace boolsurf
{

const char* const PieceBooleanPortsNote =
  "each rank's port 0 is its part of the region; ports 1, 2 and 3 (the region's boundary loops, "
  "the boundary's control points and the clipped open curves) are whole on rank 0 and empty on "
  "the others";

//------------------------------------------------------------------------------
bool WritePieceBoolean(vtkMultiProcessController* controller,
  const PieceLabeledResult& labeled,
  const BooleanOptions& options,
  const std::vector<vtkPolyData*>& outputs,
  std::string& error,
  std::size_t* sent,
  std::size_t* received,
  std::string* vectorNote,
  bool controlCurves)
{
  std::string text;
  std::vector<char> selected;
  if (!WritePieceRegion(labeled, options, outputs[0], text, selected, error))
  {
    return false;
  }
  // Ports 1 to 3: the whole region's boundary loops, chained on rank 0 from every rank's
  // runs, and their control curves and the clipped open curves, written there too.
  PieceVectorPorts vector;
  vector.Controls = outputs[2];
  vector.Clipped = outputs[3];
  outputs[2]->Initialize();
  outputs[3]->Initialize();
  if (!WritePieceRegionBoundary(controller,
        *labeled.Arranged,
        selected,
        outputs[1],
        error,
        sent,
        received,
        controlCurves ? &vector : nullptr))
  {
    outputs[0]->Initialize();
    return false;
  }
  AddExpressionField(outputs[1], text);
  if (vectorNote)
  {
    *vectorNote = vector.Note;
  }
  // Every port is marked as coming from pieces.
  const auto onPieces = OnPiecesField(controller);
  for (vtkPolyData* output : outputs)
  {
    output->GetFieldData()->AddArray(onPieces);
  }
  return true;
}

} // namespace boolsurf

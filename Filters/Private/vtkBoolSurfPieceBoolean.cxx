#include "vtkBoolSurfPieceBoolean.h"

#include "vtkBoolSurfBooleanStage.h"
#include "vtkBoolSurfPieceRegionBoundary.h"

#include <vtkFieldData.h>
#include <vtkMultiProcessController.h>
#include <vtkPolyData.h>

namespace boolsurf
{

const char* const PieceBooleanPortsNote =
  "each rank's port 0 is its part of the region, port 1 (the region's boundary loops) is whole "
  "on rank 0 and empty on the others; ports 2 and 3 (the boundary's control points and the "
  "clipped curves) are not computed on pieces (they need the control points and geodesics on "
  "the whole surface) and stay empty";

//------------------------------------------------------------------------------
bool WritePieceBoolean(vtkMultiProcessController* controller,
  const PieceLabeledResult& labeled,
  const BooleanOptions& options,
  const std::vector<vtkPolyData*>& outputs,
  std::string& error,
  std::size_t* sent,
  std::size_t* received)
{
  std::string text;
  std::vector<char> selected;
  if (!WritePieceRegion(labeled, options, outputs[0], text, selected, error))
  {
    return false;
  }
  // Port 1: the whole region's boundary loops, chained on rank 0 from every rank's runs.
  if (!WritePieceRegionBoundary(
        controller, *labeled.Arranged, selected, outputs[1], error, sent, received))
  {
    outputs[0]->Initialize();
    return false;
  }
  AddExpressionField(outputs[1], text);
  // Ports 2 and 3 stay empty. Every port is marked as coming from pieces.
  const auto onPieces = OnPiecesField(controller);
  for (vtkPolyData* output : outputs)
  {
    output->GetFieldData()->AddArray(onPieces);
  }
  return true;
}

} // namespace boolsurf

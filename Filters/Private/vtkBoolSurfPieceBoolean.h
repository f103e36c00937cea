/**
 * @brief   Surface Boolean's four outputs on each rank's piece, from the piece's labels: the
 *          same writing for Surface Boolean and the one-step BoolSurf filter on pieces
 *
 * Port 0 is the rank's part of the region (vtkBoolSurfPieceLabels.h, WritePieceRegion), ports
 * 1 to 3 the region's boundary loops, their control curves and the clipped open curves, whole
 * on rank 0 (vtkBoolSurfPieceRegionBoundary.h; ports 2 and 3 empty, with a note, for curves
 * without control points or cubic Beziers). Every port carries ArrangementOnPieces, so that the
 * filters that gather refuse them.
 */
#ifndef vtkBoolSurfPieceBoolean_h
#define vtkBoolSurfPieceBoolean_h

#include "vtkBoolSurfPieceLabels.h"

#include <cstddef>
#include <string>
#include <vector>

class vtkMultiProcessController;
class vtkPolyData;

namespace boolsurf
{

/// What rank 0 says of the outputs on pieces (where each port is), for the warning of the
/// filter that wrote them.
extern const char* const PieceBooleanPortsNote;

/// Collective: the Boolean `options` on the labeled piece `labeled` into `outputs` (four
/// ports). The selection fails alike on every rank (the labels are replicated), so no rank is
/// left waiting in the boundary's exchange; a failure leaves port 0 empty. `sent` and
/// `received` get the bytes of the boundary's message on this rank; `vectorNote` on rank 0 why
/// ports 2 and 3 are empty (empty when they are written); `controlCurves` false leaves them
/// empty without a note.
bool WritePieceBoolean(vtkMultiProcessController* controller,
  const PieceLabeledResult& labeled,
  const BooleanOptions& options,
  const std::vector<vtkPolyData*>& outputs,
  std::string& error,
  std::size_t* sent = nullptr,
  std::size_t* received = nullptr,
  std::string* vectorNote = nullptr,
  bool controlCurves = true);

} // namespace boolsurf

#endif

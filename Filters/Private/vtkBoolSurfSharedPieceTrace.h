/**
 * @brief   one ringed piece and one tracing per rank's piece of a split surface, shared by the
 *          filters that trace on it
 *
 * Surface Curves (its port 1) and Trace Surface Curves both trace on the same piece of the
 * same surface, one after the other in a chain. Each used to keep its own ringed piece and
 * tracer (vtkBoolSurfPieceTraceStage.h), so a rank held its piece, its ring, its directory and
 * its tracer's partial surface twice: about a third of a rank's memory above an idle pvbatch
 * (igea_1m on 4 ranks: 113 of 367 MB per rank). On one rank the filters already share the
 * surface's adjacency and tracer (vtkBoolSurfSurfaceCache.h); this is the same on pieces: one
 * PieceTraceState per piece, held by the filters tracing on it and gone with the last of them.
 *
 * What a filter gets is a state another filter may have traced on: a traced curve does not
 * depend on what the tracer fetched before (an edit of the curves reuses the tracer the same
 * way), and UpdateRingedPiece builds the ring again on every rank unless every rank's state was
 * built from its piece as it is, so the ranks stay in step.
 */
#ifndef vtkBoolSurfSharedPieceTrace_h
#define vtkBoolSurfSharedPieceTrace_h

#include "vtkBoolSurfPieceTraceStage.h"

#include <memory>

class vtkPolyData;

namespace boolsurf
{
/// The tracing state for this rank's piece `local`: `current` when it was built from `local`,
/// else the one a filter holds for `local`, else a new one, which later callers with `local`
/// then share. Not collective (UpdateRingedPiece decides collectively whether it is
/// usable as it is).
std::shared_ptr<PieceTraceState> SharedPieceTraceState(vtkPolyData* local,
  std::shared_ptr<PieceTraceState> current);
}

#endif

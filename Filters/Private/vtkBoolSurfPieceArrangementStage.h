/**
 * @brief   Surface Arrangement on each rank's piece of a surface split across MPI ranks
 *
 * The filter side of the distributed arrangement (Docs/Parallel.md, "What runs on each rank's
 * piece"): rank 0 broadcasts the traced curves as Trace Surface Curves packed them
 * (vtkBoolSurfCurvesMessage.h); every rank builds its piece (vtkBoolSurfSurfacePiece: owned
 * triangles, the neighbour ranks, overlapping pieces refused) and its ring of ghosts
 * (vtkBoolSurfRingedPiece.h), restricts the curves to it and runs the distributed arrangement
 * (vtkBoolSurfPieceArrangement.h); port 0 is the rank's part of the refined surface
 * (vtkBoolSurfPieceArrangementOutput.h) with the field array ArrangementOnPieces, and the piece
 * with its arrangement and the merged cell graph is handed to Label Arrangement Cells and Surface
 * Boolean on the same rank (attached to ArrangementCell, vtkBoolSurfStageHandoff.h).
 *
 * Nothing proportional to the surface travels: the curves from rank 0, the ring and the
 * boundary records between neighbours, the cells and the cell graph to and from rank 0.
 *
 * Edits reuse (PieceArrangementState): while every rank's piece of the surface is the same
 * object, unmodified (decided by one all-reduce), the piece, its neighbours, its ring and its
 * mesh are kept, and the piece's arrangement is computed again into one computed on the same
 * mesh, so Core's edit path refines and refills only what the curves touch, now or before
 * (Docs/Decisions.md, "Edits reuse"). The field array PieceArrangementReuse says what was kept.
 */
#ifndef vtkBoolSurfPieceArrangementStage_h
#define vtkBoolSurfPieceArrangementStage_h

#include "vtkBoolSurfPieceArrangement.h"
#include "vtkBoolSurfPieceCosts.h"
#include "vtkBoolSurfStageHandoff.h"

#include "Arrangement/Arrangement.h"
#include "Distributed/PieceMesh.h"
#include "Distributed/PieceRegionBoundary.h"
#include "Distributed/PieceTileSums.h"
#include "Selection/BoundaryControlPoints.h"

#include <vtkIntArray.h> // for OnPiecesField
#include <vtkSmartPointer.h>
#include <vtkType.h>

#include <memory>
#include <string>
#include <vector>

class vtkMultiProcessController;
class vtkPolyData;

namespace boolsurf
{

/// Surface Arrangement on a piece -> Label Arrangement Cells and Surface Boolean on that piece.
struct PieceArrangementResult
{
  /// The piece's mesh, shared by the results of the updates that kept it.
  std::shared_ptr<const PieceMesh> Piece;
  vtkBoolSurfPieceArrangement Run;
  /// The curves' distinct ShapeIds (the whole drawing's, the same on every rank).
  std::vector<int> ShapeIds;
  /// The rank's piece as it arrived, and per local triangle of Piece its cell there (-1 for a
  /// ghost): the surface's own cell arrays, carried to the owned triangles' regions.
  vtkSmartPointer<vtkPolyData> Surface;
  std::shared_ptr<const std::vector<vtkIdType>> SurfaceCell;
  /// Of each curve of the piece: the global curve it is a run of and where the run starts, for
  /// the stations of the result's vector output (Distributed/PieceVectorOutput.h).
  PieceCurveRuns CurveRuns;
  /// Rank 0 only: the curves' control points and parameters, read from the traced curves
  /// (empty when they do not carry them, and on the other ranks).
  std::vector<CurveSource> Sources;
};

/// What Surface Arrangement keeps between updates on pieces while this rank's piece of the
/// surface is the same object, unmodified, on every rank: what the piece's build found (the
/// neighbour ranks, its notes, its bytes), the ringed piece's mesh and the cells of the
/// surface per local triangle, and the results of the last updates, whose arrangements an edit
/// computes again in place (pooled: one that no output holds any more).
struct PieceArrangementState
{
  vtkPolyData* Surface = nullptr; ///< compared, never dereferenced
  vtkMTimeType SurfaceTime = 0;
  bool HasPiece = false;
  std::vector<int> Neighbours;
  std::vector<std::string> BuildWarnings;
  std::size_t BorderSent = 0, BorderReceived = 0, RingReceived = 0;
  std::shared_ptr<const PieceMesh> Piece;
  std::shared_ptr<const std::vector<vtkIdType>> SurfaceCell;
  ResultPool<PieceArrangementResult> Results;
  /// The arrangement's work buffers, shared by the pooled results.
  std::shared_ptr<Arrangement::WorkBuffers> Work;
  /// What the piece's clean tiles add to the summary, kept for the piece's mesh.
  PieceTileSums TileSums;

  /// Forgets the piece and the results (the surface changed, or a build failed).
  void Clear();
};

/// The arrays of the one-rank port 0 that a piece's output does not have yet, named for the
/// warning that says so (Docs/Parallel.md).
extern const char* const ArraysNotOnPieces;

/// Collective: Surface Arrangement on this rank's piece `local` with the curves `curves` (Trace
/// Surface Curves' output; read on rank 0 only), keeping in `state` what the next update may
/// reuse. Fills `output` and `result`. Returns false on
/// every rank, with `error`, when any rank fails; true with `drawingStart` when rank 0's curves
/// are a drawing being started (no arrangement, and no message). `warnings` gets the piece's
/// notes (generated global ids).
bool ArrangeOnPiece(vtkMultiProcessController* controller,
  vtkPolyData* local,
  vtkPolyData* curves,
  const ArrangementOptions& options,
  PieceArrangementState& state,
  vtkPolyData* output,
  std::shared_ptr<PieceArrangementResult>& result,
  bool& drawingStart,
  std::string& error,
  std::vector<std::string>& warnings);

/// Collective: ArrangeOnPiece after the broadcast, for a rank that has message 0 already
/// (`message`, the same on every rank: the one-step filter, whose tracing on pieces gave it to
/// every rank). `output`, when given, is written as ArrangeOnPiece writes port 0, without the
/// costs; `costs` gets this rank's steps and messages (without a Total). `traced`: on rank 0,
/// the traced curves the result's Sources are read from (null: none).
bool ArrangeMessageOnPiece(vtkMultiProcessController* controller,
  vtkPolyData* local,
  vtkPolyData* traced,
  const std::vector<long long>& message,
  const ArrangementOptions& options,
  PieceArrangementState& state,
  vtkPolyData* output,
  std::shared_ptr<PieceArrangementResult>& result,
  PieceCosts& costs,
  std::string& error,
  std::vector<std::string>& warnings);

/// The field array ArrangementOnPieces (the number of ranks) that marks an output as one rank's
/// part, so that the filters that gather refuse it.
vtkSmartPointer<vtkIntArray> OnPiecesField(vtkMultiProcessController* controller);

}

#endif

/**
 * @class   vtkBoolSurfPieceArrangement
 * @brief   the arrangement of curves on a surface split across MPI ranks, each rank on its piece
 *
 * The processes' side of Core's distributed arrangement (Core/Distributed, Docs/Parallel.md):
 * each rank arranges its piece (its owned triangles and their ring of ghosts, with the curves
 * restricted to it), sends its boundary records to its neighbours only and matches theirs with
 * its own, sends its cells, crossings and joins to rank 0, which merges the cell graph and
 * numbers the cells as the whole surface's arrangement numbers them, and gets back the global
 * cell of each of its local cells and the cell graph with the plugs of the surface's boundary
 * loops: what each rank labels itself (Core's LabelMergedArrangement on GetMerged(), the
 * labeling stage's labels) and selects a Boolean's owned triangles from (SelectPieceBoolean
 * with GetArrangement() and GetMerged().GlobalCellOfLocal[0]). The messages are Core's
 * (Distributed/PieceWire.h); what travels grows with the pieces' shared boundary (to the
 * neighbours) and with the curves (to and from rank 0), never with the surface.
 *
 * Run() is collective: every rank calls it, with its own (possibly empty) piece, and every rank
 * learns of a failure on any rank (one all-reduce after each step that can fail), so no rank
 * is left waiting.
 */
#ifndef vtkBoolSurfPieceArrangement_h
#define vtkBoolSurfPieceArrangement_h

#include "Arrangement/Arrangement.h"
#include "Distributed/MergedArrangement.h"
#include "Distributed/PieceCurves.h"
#include "Distributed/PieceMesh.h"
#include "Distributed/PieceTileSums.h"

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

class vtkMultiProcessController;

class vtkBoolSurfPieceArrangement
{
public:
  /// Bytes this rank sent and received, per message.
  struct Traffic
  {
    std::size_t BoundarySent = 0, BoundaryReceived = 0; ///< boundary records, neighbours
    std::size_t MergeSent = 0, MergeReceived = 0;       ///< cells, crossings, joins to rank 0
    std::size_t BackSent = 0, BackReceived = 0;         ///< merged cells from rank 0
  };
  /// This rank's wall time per step, in milliseconds: its piece's arrangement (Core's stage
  /// times are the arrangement's own, GetArrangement().Times), the boundary records with the
  /// neighbours and their joins, the merge on rank 0 with the cells back.
  struct StepTimes
  {
    double Arrange = 0, Boundary = 0, Merge = 0;
  };

  /// Collective. `neighbours`: the ranks owning this piece's ghost triangles (symmetric: the
  /// ranks sharing points with it), ascending. False on every rank, with `error` naming the
  /// rank and its problem, when any rank fails. `tileSums`: the piece's clean-tile figures
  /// kept between runs on its mesh (PieceSummary.h), null to read every owned triangle.
  bool Run(vtkMultiProcessController* controller,
    const boolsurf::PieceMesh& piece,
    const boolsurf::PieceCurves& curves,
    const std::vector<int>& neighbours,
    const boolsurf::ArrangementOptions& options,
    std::string& error,
    boolsurf::PieceTileSums* tileSums = nullptr);

  /// Collective: true when `ok` on every rank; else false on every rank, `error` naming the
  /// first failing rank (its own message on that rank). What each step of a distributed run
  /// that can fail on one rank ends with, so that no rank goes on to wait for the others.
  static bool AllSucceeded(vtkMultiProcessController* controller, bool ok, std::string& error);

  /// The piece's own arrangement (on piece.Mesh; cells are local).
  const boolsurf::Arrangement& GetArrangement() const { return this->Local; }
  /// The piece arrangement's work buffers (shared with other runs: nothing of a result is in
  /// them, Arrangement::Work).
  std::shared_ptr<boolsurf::Arrangement::WorkBuffers>& WorkBuffers() { return this->Local.Work; }
  /// True when the next Run on `piece` computes again into an arrangement computed on its
  /// mesh: Core's edit path, which refines and refills only what the curves touch.
  bool KeepsArrangementOf(const boolsurf::PieceMesh& piece) const
  {
    return this->Local.LayoutMeshSerial != 0 &&
      this->Local.LayoutMeshSerial == piece.Mesh.GetSerial();
  }
  /// The merged arrangement as this rank has it: GlobalCellOfLocal holds this rank's row only
  /// (GetGlobalCell), CellLowestTriangle is empty; the cell graph, plugs, components and zero
  /// nodes are whole (the same on every rank).
  const boolsurf::MergedArrangement& GetMerged() const { return this->Merged; }
  /// Global cell of local cell c (-1 for a cell of ghost triangles only).
  int GetGlobalCell(int c) const { return this->Merged.GlobalCellOfLocal[0][c]; }
  const Traffic& GetTraffic() const { return this->Bytes; }
  const StepTimes& GetTimes() const { return this->Times; }

private:
  boolsurf::Arrangement Local;
  boolsurf::MergedArrangement Merged;
  Traffic Bytes;
  StepTimes Times;
};

#endif

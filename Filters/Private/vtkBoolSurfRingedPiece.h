/**
 * @brief   a rank's piece of a split surface with the ring of ghost triangles Core's
 *          distributed arrangement needs (Core/Distributed/PieceMesh.h)
 *
 * The distributed arrangement refines each owned triangle exactly as on the whole surface, which
 * needs every triangle sharing a point with an owned one: one layer of ghost cells as VTK
 * defines them. VTK's own vtkGhostCellsGenerator builds it (collective, on the controller's
 * ranks; ghost cells the input already carries are dropped and built again, so a piece with
 * more layers or none gives the same ring), and the result is read as a Core PieceInput: every
 * triangle with its global cell id, every point with its global point id, the ghost mark of
 * each triangle.
 *
 * Global ids are the undistributed surface's: the pieces' cell and point `GlobalIds` arrays
 * (vtkGenerateGlobalIds gives both when the pieces have none). Cost: the ghost generator's (the
 * ring is exchanged between neighbouring ranks only) and one pass over the ringed piece.
 */
#ifndef vtkBoolSurfRingedPiece_h
#define vtkBoolSurfRingedPiece_h

#include "Distributed/PieceMesh.h"

#include <string>

class vtkMultiProcessController;
class vtkPolyData;

namespace boolsurf
{
/// Collective: `local` (this rank's piece, possibly empty or null) with its ring of ghosts, as
/// a PieceInput. False, with `error` naming what is missing (global ids of cells or points) or
/// the first cell that is not a triangle; every rank still takes part in the ghost exchange
/// first, so no rank waits.
bool BuildRingedPiece(vtkMultiProcessController* controller,
  vtkPolyData* local,
  PieceInput& out,
  std::string& error);
}

#endif

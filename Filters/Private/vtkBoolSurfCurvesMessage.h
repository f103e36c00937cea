// The traced curves as the pieces of a surface split across MPI ranks need them: message 0 of
// Core/Distributed/PieceWire.h (a private header of the module).
//
// Trace Surface Curves traces on the surface gathered to rank 0 and is the only filter that has
// the traced mesh, which packing needs (an edge point is named by its edge's two vertices). So it
// packs the message itself, its points named by the undistributed surface's ids: the gathered
// surface's point GlobalIds (the gather's point merge keeps them) and cell GlobalIds (whose order
// the gather restores). It hands the buffer over with its result (TracedCurvesResult) and writes
// it as the field array PieceCurvesMessage, for a pipeline read from a file; Surface Arrangement
// on pieces broadcasts it from rank 0 (Docs/Parallel.md).
//
// The pieces' arrangement breaks ties by global vertex id, the one-rank arrangement by the
// surface's own point order: the two agree when the point GlobalIds are the undistributed file's
// point order (Generate Global Ids on the undistributed surface). Ids that are not one per point,
// 0 to n - 1, cannot be that order, and packing says so.
#ifndef vtkBoolSurfCurvesMessage_h
#define vtkBoolSurfCurvesMessage_h

#include "Geodesic/TracedCurve.h"

#include <string>
#include <vector>

class vtkFieldData;
class vtkPolyData;

namespace boolsurf
{
struct vtkSurfaceInput;

/// Message 0 of `curves`, traced on `surface`. False (no message) when the surface's triangles
/// carry no point or cell GlobalIds; `note` then says why, or, on success, warns when the ids
/// cannot be the undistributed surface's order (see above).
bool PackPieceCurvesMessage(const vtkSurfaceInput& surface,
  const std::vector<TracedCurve>& curves,
  std::vector<long long>& out,
  std::string& note);

/// `message` as the field array PieceCurvesMessage of `fields`.
void AddPieceCurvesField(const std::vector<long long>& message, vtkFieldData* fields);

/// The message of Trace Surface Curves' output `curves`: the buffer it handed over, else its
/// PieceCurvesMessage field array. False when it has neither.
bool ReadPieceCurvesMessage(vtkPolyData* curves, std::vector<long long>& out);
}

#endif

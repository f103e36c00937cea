/**
 * @class   vtkBoolSurfPieceGlobalIds
 * @brief   GlobalIds generated for the pieces of a split surface that carry none
 *
 * The filters that run on each rank's piece name the surface by global ids (control points by
 * global cell id; the distributed arrangement by global point and cell ids). When the pieces
 * carry no point or cell GlobalIds (a .pvtp's pieces, RedistributeDataSet of a surface without
 * them), VTK's vtkGenerateGlobalIds gives them, collectively, on every rank:
 *
 * - cell ids number each rank's own cells in rank order (rank 0's first, each rank's in its
 *   order): the numbering of the surface gathered to rank 0, which appends the pieces in rank
 *   order (vtkBoolSurfRankGather), so a triangle id means the same on pieces and gathered;
 * - point ids number the distinct positions (coincident points of neighbouring pieces share
 *   one id), as the pieces' common border needs.
 *
 * Cell GlobalIds the pieces already carry are kept when only the points' are missing (the
 * gathered surface is put back in their order), only the points' are generated then. The result is
 * kept, the same object, while every rank's piece is unchanged, so the filters' own caches (the
 * ringed piece, the tracer) stay valid between edits.
 */
#ifndef vtkBoolSurfPieceGlobalIds_h
#define vtkBoolSurfPieceGlobalIds_h

#include <vtkSmartPointer.h>
#include <vtkType.h>

class vtkMultiProcessController;
class vtkPolyData;

class vtkBoolSurfPieceGlobalIds
{
public:
  /// Collective: `local` (this rank's piece, possibly null) with point and cell GlobalIds.
  vtkPolyData* Generate(vtkMultiProcessController* controller, vtkPolyData* local);

private:
  vtkSmartPointer<vtkPolyData> Generated;
  vtkPolyData* Source = nullptr; ///< compared, never dereferenced
  vtkMTimeType SourceTime = 0;
};

#endif

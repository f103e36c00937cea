/**
 * @class   vtkBoolSurfRankGather
 * @brief   the inputs of a BoolSurf filter gathered to the first MPI rank
 *
 * BoolSurf's stages need the whole surface and every curve at once (tracing crosses any
 * triangle, the arrangement's cells and their labels are global). Under pvbatch or pvserver
 * with several MPI ranks, a filter therefore gathers its inputs to rank 0, computes there,
 * and leaves empty outputs on the other ranks; ParaView shows and saves rank 0's result as
 * the whole. With one process (plain VTK, the GUI's builtin server, pvpython) this class does
 * nothing: Input() is the filter's own input object.
 *
 * Use: construct it first thing in RequestData, on every rank, before anything that may fail
 * or return early (every rank must take part in the gather, or the others wait forever);
 * then `if (!gather.ComputesHere()) return 1;` after emptying the outputs.
 *
 * Merging: when only one rank holds data on a port (serial readers and sources fill piece
 * 0 only), that piece is used as it is. When several do (a surface split across ranks by
 * RedistributeDataSet/D3 or a parallel reader), the pieces are appended, ghost cells dropped,
 * coincident points of surface ports merged (exact positions), and cells put back in the
 * order of their global ids when the pieces carry them (so TriangleId of exact surface points
 * keep meaning the input's triangles), the pieces' point and cell GlobalIds kept; field data is
 * that of the first non-empty piece.
 *
 * The gathered data is kept from one update to the next (per filter and port) while no rank's
 * input changed, so the filters' caches, keyed by input object and modification time, still
 * hit under MPI.
 *
 * A rank whose input is absent (an optional port) sends an empty piece. Every rank must run
 * the filter's RequestData: an input of the wrong type on one rank stops VTK's executive
 * before RequestData there, so sources feeding BoolSurf must give every rank a vtkPolyData
 * (possibly empty), as BoolSurf's own sources and ParaView's readers do.
 */
#ifndef vtkBoolSurfRankGather_h
#define vtkBoolSurfRankGather_h

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkAlgorithm;
class vtkInformationVector;
class vtkPolyData;

/// What a filter's RequestData returns after reporting an error: success, with its outputs
/// empty. A failure (0) would stop the pipeline there, and a ParaView representation
/// downstream that did not update would then ignore every later change upstream (it asks to
/// re-execute again only once it has updated), so the view would stop following the drawing.
constexpr int vtkBoolSurfErrorReported = 1;

class vtkBoolSurfRankGather
{
public:
  /// Gathers the first connection of each of `ports` input ports. `surfacePorts` lists the
  /// ports whose pieces are parts of one surface (coincident points merged); other ports
  /// (curves, samples) are appended as they are.
  vtkBoolSurfRankGather(vtkAlgorithm* filter,
    vtkInformationVector** inputVector,
    int ports,
    std::vector<int> surfacePorts = { 0 });

  /// True on rank 0 and in a single process: the filter computes here.
  bool ComputesHere() const { return this->Here; }

  /// The (gathered) input of a port on the computing rank; nullptr for a missing optional
  /// input or a port not gathered.
  vtkPolyData* Input(int port) const;

  /// The number of processes of the global controller (1 without MPI).
  int NumberOfProcesses() const { return this->Processes; }

private:
  bool Here = true;
  int Processes = 1;
  /// Not owned: the pipeline holds a single process's inputs, and the kept gathers hold rank
  /// 0's merged ones, for as long as the filter executes. A smart pointer here cost a garbage
  /// collection pass per input and update (a data object released while others still hold it),
  /// a few percent of a small scene's whole chain of stage filters.
  std::vector<vtkPolyData*> Inputs;
};

#endif

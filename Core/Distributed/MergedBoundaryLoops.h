// The plugs of the surface's boundary loops in the merged cell graph (MergedArrangement.h):
// the pieces' loop fragments (PieceBoundaryLoops.h) chained into loops, numbered and measured
// as MeshTopology does on the whole surface, the cells along them on global cells, and the
// surface components of cells and plugs. Part of MergeCellGraph, after the cells are numbered.
//
// Cost: O(F log F + E) for F fragments and E boundary edges of the surface, on the merging
// process.
#ifndef boolsurf_MergedBoundaryLoops_h
#define boolsurf_MergedBoundaryLoops_h

#include "Distributed/MergedArrangement.h"
#include "Distributed/PieceSummary.h"

#include <string>
#include <vector>

namespace boolsurf
{

/// Fills out.NumberOfPlugs, PlugCrossings, NodeComponent and ZeroNodes from the pieces'
/// LoopFragments and PlugCrossings; out.NumberOfCells, GlobalCellOfLocal and Crossings must be
/// set. Fails, naming the half-edge by its global vertices, when fragments do not chain into
/// loops (a broken or non-manifold boundary, or a piece without its ghost ring).
bool MergeBoundaryLoops(const std::vector<PieceSummary>& pieces,
  MergedArrangement& out,
  std::string& error);

} // namespace boolsurf

#endif

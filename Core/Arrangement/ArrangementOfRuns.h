// The arrangement of curves some of which are runs of closed curves: open (their ends are not
// joined) but bounding cells like the closed curves they are part of. A piece of a surface
// split across processes keeps such runs where a closed curve leaves it (Core/Distributed);
// its flood fill must stop at them as the whole surface's stops at the closed curve.
//
// Kept apart from Arrangement.h (included by every stage and filter) so that the distributed
// arrangement adds a declaration only where it is used.
#ifndef boolsurf_ArrangementOfRuns_h
#define boolsurf_ArrangementOfRuns_h

#include "Arrangement/Arrangement.h"

#include <string>
#include <vector>

namespace boolsurf
{

/// ComputeArrangement where each open curve c with cutFromClosed[c] != 0 separates cells
/// (its segments block the flood fill) while staying open for the patches and the cell graph
/// (its patches are not closed: no cell graph arc). Costs a copy of the curves more.
bool ComputeArrangementOfRuns(const TriangleMesh& mesh,
  const std::vector<TracedCurve>& curves,
  const std::vector<char>& cutFromClosed,
  const ArrangementOptions& options,
  Arrangement& out,
  std::string& error);

} // namespace boolsurf

#endif

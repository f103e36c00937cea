// The cells of a surface's site graph: every mesh vertex's nearest site along mesh edges, its
// distance and the next vertex towards it (a multi-source Dijkstra over the vertex adjacency).
//
// On several threads the same three arrays are computed in two passes: the distances by rounds
// of edge relaxations until nothing improves (the distances Dijkstra gives: each is the
// smallest rounded sum along an edge path from a site, which any order of relaxations that
// stops only when no edge improves reaches), then each vertex's parent as the one Dijkstra
// picks: of the neighbours u with d(u) + |uw| == d(w), the first Dijkstra settles, the least
// (d(u), u). That is Dijkstra's choice whenever every relaxation strictly increases the
// distance it relaxes from (settling order is then (d, vertex id)); an edge that does not
// (a zero-length edge, or one below the rounding of the distance) sends the build back to
// the serial search, so the result is the serial one bit for bit in every case.
#ifndef boolsurf_SiteCells_h
#define boolsurf_SiteCells_h

#include "Mesh/TriangleMesh.h"

#include <vector>

namespace boolsurf
{

struct SiteCells
{
  std::vector<int> Cell;            ///< mesh vertex -> site index (-1: unused vertex)
  std::vector<int> Parent;          ///< mesh vertex -> next vertex towards its site (-1 at sites)
  std::vector<double> SiteDistance; ///< mesh vertex -> edge-path distance to its site
};

/// Grows the cells of `sites` (mesh vertices) over the vertex adjacency (compressed rows:
/// neighbors[offsets[v] .. offsets[v + 1]) of v), on the calling thread's arena when
/// `parallel`, else by the serial Dijkstra search; the same cells either way. Returns whether
/// the parallel passes gave them (false: the serial search did).
bool GrowSiteCells(const TriangleMesh& mesh,
  const std::vector<int>& offsets,
  const std::vector<int>& neighbors,
  const std::vector<int>& sites,
  bool parallel,
  SiteCells& out);

} // namespace boolsurf

#endif

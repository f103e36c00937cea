// The traced curves restricted to one piece of a distributed surface (see PieceMesh.h).
//
// A piece keeps every segment of a curve that lies in one of its triangles (owned or ghost):
// all the segments of its owned triangles and of their neighbours, which is what refining an
// owned triangle exactly as on the whole surface needs (its own segments and the points its
// neighbours put on its edges). Runs of kept segments become curves of the piece, renumbered
// to local ids; a run of a closed curve is open there but still separates cells
// (PieceCurves::CutFromClosed, arranged by ComputeArrangementOfRuns). A closed curve the piece
// keeps whole stays closed.
//
// Runs keep the order of the global curve's segments (a closed curve's run through its first
// point is cut there into two runs), so inside every triangle the segments come in the same
// order as on the whole surface and the triangle is refined bit for bit the same way.
//
// Cost: O(curve points x triangles around a point) per piece, no whole-surface table. Points
// name the global surface (the tracer's output); an edge point names its edge by id, and
// `edgeVertices` gives that edge's global vertices in the direction its parameter runs (in a
// distributed run, the traced point carries them).
#ifndef boolsurf_PieceCurves_h
#define boolsurf_PieceCurves_h

#include "Distributed/PieceMesh.h"
#include "Geodesic/TracedCurve.h"

#include <array>
#include <functional>
#include <vector>

namespace boolsurf
{

/// Global vertices of a global edge, from the end where its parameter is 0.
using GlobalEdgeVertices = std::function<std::array<int, 2>(int globalEdge)>;

struct PieceCurves
{
  std::vector<TracedCurve> Curves; ///< on the piece's local ids
  std::vector<int> SourceCurve;    ///< per curve: index of the global curve it is a run of
  std::vector<int> FirstPoint;     ///< per curve: index of its first point in the global curve
  /// Per curve: 1 for an open run of a closed curve, which bounds cells all the same.
  std::vector<char> CutFromClosed;
  /// Whether curve c separates cells: closed, or a run of a closed curve.
  bool BoundsCells(int c) const { return this->Curves[c].Closed || this->CutFromClosed[c] != 0; }
};

/// Restricts `curves` (on global ids) to the piece. Points the piece does not have drop out
/// with the segments they end, so it cannot fail: a segment is kept only when the piece has a
/// triangle holding both its points, and then it has their vertices and edges too.
void RestrictCurvesToPiece(const PieceMesh& piece,
  const std::vector<TracedCurve>& curves,
  const GlobalEdgeVertices& edgeVertices,
  PieceCurves& out);

} // namespace boolsurf

#endif

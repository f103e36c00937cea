// Cutting Bezier segments at given parameters by halving (split at the middle cut, then each
// half at its own middle cut), with the halves on several threads: every split of one level,
// over all segments, is a task, since the two halves of a split are cut independently.
#ifndef boolsurf_BezierCutLevels_h
#define boolsurf_BezierCutLevels_h

#include "Geodesic/GeodesicPath.h"

#include <array>
#include <string>
#include <vector>

namespace boolsurf
{

/// The part [A, B] of a segment's parameters and its control polygon.
struct BezierCutPiece
{
  double A, B;
  std::array<CanonicalPoint, 4> Controls;
};

/// One segment to cut: its control polygon and its cuts (sorted, distinct, inside (0, 1)).
struct BezierCutJob
{
  const std::array<CanonicalPoint, 4>* Whole = nullptr;
  const std::vector<double>* At = nullptr;
};

/// The part [from, to] of a segment, given as `polygon`, cut at `first`..`last` (sorted,
/// strictly inside) by recursive halving on one thread: split at the middle cut, then each
/// half at its own middle cut. Appends the pieces in order; false with the failing split's
/// message.
bool CutSegmentRecursively(GeodesicPathSolver& solver,
  const std::array<CanonicalPoint, 4>& polygon,
  double from,
  double to,
  const double* first,
  const double* last,
  std::vector<BezierCutPiece>& pieces,
  std::string& error);

/// For every job, its pieces in order (pieces[j], the ones the recursive halving on one thread
/// gives, bit for bit: a split depends only on its polygon and parameter) and ok[j]; a job
/// whose split failed has ok[j] 0 and errors[j] the message of the split that recursion
/// would have failed at first. `solvers`: one per thread (the arena slot's), as
/// BezierPieces::CutCurves takes them.
void CutSegmentsByLevels(const std::vector<GeodesicPathSolver*>& solvers,
  const std::vector<BezierCutJob>& jobs,
  std::vector<std::vector<BezierCutPiece>>& pieces,
  std::vector<std::string>& errors,
  std::vector<char>& ok);

} // namespace boolsurf

#endif

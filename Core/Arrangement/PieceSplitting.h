// The fallback of a crowded triangle's refinement: curve pieces split until no two of them
// cross and no point lies inside a piece, so the constrained triangulation only has to connect
// points along pieces that never block each other.
//
// Stage 2 (SegmentIntersection) computes each crossing once, rounded to doubles; between
// rounded crossings two sub-pieces can still cross, and on a triangle crowded with a few
// hundred pieces the triangulation's detours around such crossings need not end
// (TriangleRefinement's step budget turns that into an error). Here every pair of sub-pieces
// is tested with exact orientation predicates, round after round: a crossing found is a new
// point of both pieces (or, within rounding of an end of either, that end), a point strictly
// inside a piece becomes one of its points; each round's new points can only create crossings
// within rounding of themselves, which the next round snaps, so the rounds end in practice
// (they are capped).
//
// Cost: quadratic in the pieces of the triangle per round. It runs only for a triangle whose
// refinement failed, after that failure.
#ifndef boolsurf_PieceSplitting_h
#define boolsurf_PieceSplitting_h

#include "Arrangement/SegmentIntersection.h"

#include <string>

namespace boolsurf
{

/// Splits the chains of `arr` (points and chains as stage 2 left them, no triangulation yet)
/// until no two pieces cross properly and no point lies strictly inside a piece, adding the
/// crossings as interior points. False, with `problem` set, when that takes more than the
/// allowed rounds or points.
bool SplitPiecesAtCrossings(LocalArrangement& arr, double snapDistance, std::string& problem);

} // namespace boolsurf

#endif

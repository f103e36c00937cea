// Property test hunting degeneracies: random polygons on a small integer lattice, so that
// touching vertices, vertices on segments, shared and overlapping edges (same or opposite
// direction, same or different shapes), repeated points, spikes and keyhole bridges are the
// common case. Each drawing is answered on an irregular mesh and on a mesh aligned with the
// lattice (curves through mesh vertices and along mesh edges) and compared with Clipper, exact
// on integers, for every operation and fill rule; plus S + ~S = total and inclusion-exclusion.
//
// BOOLSURF_LATTICE_CASES=N runs N drawings instead of the CI default (a long hunt).
#include "LatticeDrawingChecks.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>

using namespace boolsurf;
using namespace boolsurf::testing;

namespace
{

ClipperTally Tally;

int CaseCount(int ciDefault)
{
  const char* env = std::getenv("BOOLSURF_LATTICE_CASES");
  return env ? std::max(1, std::atoi(env)) : ciDefault;
}

void RunLatticeCases(int cases, int lattice, std::uint32_t seed)
{
  std::mt19937 rng(seed);
  int failures = 0;
  for (int k = 0; k < cases && failures < 5; ++k)
  {
    const std::vector<LatticePolygon> drawing = RandomLatticeDrawing(rng, lattice);
    const int cells = lattice + 2 + static_cast<int>(rng() % 5);
    const std::uint32_t meshSeed = rng();
    const TriangleMesh irregular = FlatMeshFor(-1, lattice + 1, cells, false, meshSeed);
    const TriangleMesh aligned = FlatMeshFor(-1, lattice + 1, lattice + 2, true, 0);
    CheckDrawing(irregular,
      drawing,
      "irregular mesh (" + std::to_string(cells) + " cells, seed " + std::to_string(meshSeed) + ")",
      failures,
      Tally);
    CheckDrawing(aligned, drawing, "aligned mesh", failures, Tally);
  }
}

} // namespace

/// Runs the drawings and reports how often Clipper disagreed with the exact areas.
void RunAndCountClipperDisagreements(int cases, int lattice, std::uint32_t seed)
{
  Tally = ClipperTally();
  RunLatticeCases(cases, lattice, seed);
  std::cout << "Clipper disagreed with the exact areas in " << Tally.Disagreements << " of "
            << Tally.Comparisons << " comparisons\n";
  EXPECT_LT(Tally.Disagreements * 20, Tally.Comparisons);
}

TEST(LatticeDrawingsProperty, SmallLatticeMatchesExactAreasAndClipper)
{
  RunAndCountClipperDisagreements(CaseCount(1500), 4, 7);
}

TEST(LatticeDrawingsProperty, LargerLatticeMatchesExactAreasAndClipper)
{
  RunAndCountClipperDisagreements(CaseCount(1000), 10, 8);
}

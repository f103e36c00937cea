"""Edits on each rank's piece of a split surface (MpiPiecesEdits.py, pvbatch on 1, 2 and 3
ranks): after every edit the union over ranks of Surface Arrangement's, Label Arrangement
Cells' and Surface Boolean's outputs equals the one-rank output per source triangle (the same
refined triangles in the same cells with the same labels, areas to 1e-12), and each rank's
Surface Arrangement says what it kept (PieceArrangementReuse): the first update and the update
after the surface changed build the piece, every edit of the curves alone keeps it, and once
an earlier result is free the arrangement is computed again in place (Core's edit path). One
edit moves a small circle across rank boundaries (the ranks holding its triangles change).
The curves are traced on the pieces once per update: the Surface Curves source (its port 1)
traces the moved circle alone and recalls the others (PieceTracingTraffic), every curve on a new
piece, and Trace Surface Curves, sharing its tracing of the piece, recalls them all.
Each run has a time limit: a rank left waiting fails the test.
"""
import os
import shutil
import sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mpi_pieces_compare import PvbatchRuns, same_by_source  # noqa: E402

runs = PvbatchRuns("MpiPiecesEdits.py", "boolsurf-pieces-edits-")
out = runs.out


def run(ranks):
    return runs.run(ranks, seconds=300)[0]


serial = run(1)["steps"]
names = [s["name"] for s in serial]
for earlier, later in zip(serial, serial[1:]):
    assert earlier["boolean"]["by_source"] != later["boolean"]["by_source"], (
        "one rank: the edit changed nothing", later["name"])
rebuilt = {"first", "the surface scaled"}  # the steps whose pieces are built
for ranks in (2, 3):
    steps = run(ranks)["steps"]
    assert [s["name"] for s in steps] == names, names
    for i, (got, expected) in enumerate(zip(steps, serial)):
        for stage in ("arrangement", "labels", "boolean"):
            where = "%s, %s on %d ranks" % (got["name"], stage, ranks)
            assert got[stage]["pieces"], (where, "did not run on the pieces")
            assert got[stage]["triangles"] == expected[stage]["triangles"], where
            same_by_source(got[stage]["by_source"], expected[stage]["by_source"], where,
                           stage != "boolean")
            assert got[stage]["NumberOfCells"] == expected[stage]["NumberOfCells"], where
        assert got["labels"]["CellLabels"] == expected["labels"]["CellLabels"], got["name"]
        reuse = got["reuse"]
        assert sorted(reuse) == [str(r) for r in range(ranks)], (got["name"], reuse)
        for rank, row in reuse.items():
            where = "%s, rank %s of %d" % (got["name"], rank, ranks)
            kept = got["name"] not in rebuilt
            assert row["KeptPiece"] == (1 if kept else 0), (where, row)
            assert row["OwnedTriangles"] < row["RingedTriangles"], (where, row)
            if not kept:
                assert row["KeptArrangement"] == 0, (where, "a new piece has no arrangement", row)
            elif i >= 2 and steps[i - 1]["name"] not in rebuilt:
                # Two updates on the kept piece: a result is free again, computed in place.
                assert row["KeptArrangement"] == 1, (where, row)
        # Each edit moves one of the three circles: traced alone on a kept piece, by the
        # source; Trace Surface Curves then traces none.
        display, tracing = got["display"], got["tracing"]
        assert sorted(display) == sorted(tracing) == [str(r) for r in range(ranks)], (
            got["name"], display, tracing)
        traced = sum(int(row["TracedCurves"]) for row in display.values())
        kept = got["name"] not in rebuilt
        assert traced == (1 if kept else 3), (got["name"], "curves traced", display)
        for rank, row in display.items():
            assert row["ReusedPiece"] == (1 if kept else 0), (got["name"], rank, row)
            assert row["RecalledCurves"] == (2 if kept else 0), (got["name"], rank, row)
        for rank, row in tracing.items():
            assert (row["TracedCurves"], row["RecalledCurves"]) == (0, 3), (
                got["name"], "Trace Surface Curves traced again", rank, row)
        print("%s on %d ranks: the one-rank outputs; kept piece %s, kept arrangement %s, "
              "curves traced %d" % (
                  got["name"], ranks, [int(r["KeptPiece"]) for _, r in sorted(reuse.items())],
                  [int(r["KeptArrangement"]) for _, r in sorted(reuse.items())], traced))
    # The small circle moved across rank boundaries: other ranks hold its triangles.
    before, after = steps[1]["small_circle_ranks"], steps[2]["small_circle_ranks"]
    assert before and after and before != after, ("the small circle stayed on its ranks",
                                                   before, after)
shutil.rmtree(out, ignore_errors=True)

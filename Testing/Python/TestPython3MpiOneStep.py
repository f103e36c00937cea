"""The one-step BoolSurf filter on each rank's piece of a split surface (MpiOneStep.py, pvbatch
on 1, 2 and 3 ranks, and on 3 ranks with the surface split in 2, one rank holding none): for
several Booleans, a zero cell given by a point and an edit of the curves, the union over ranks
of the region equals the one-rank region per source triangle (the same triangles in the same
cells, areas to 1e-12), with the same labels, consistency verdicts, shapes and expression; the
boundary loops are whole on rank 0 and equal to the one-rank loops and to the stage chain's on
the same pieces; ports 2 and 3 (the boundary's control points, an open polyline clipped by the
region) are whole on rank 0 and equal to the one-rank ones; no rank holds the whole region.
Selection BSC runs on the gathered surface with a warning naming it, and answers as one rank
does; the filter runs on the pieces again once switched back. Each run has a time limit: a rank left
waiting fails the test.
"""
import os
import shutil
import sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mpi_pieces_compare import (PvbatchRuns, same_by_source, same_control_curves,  # noqa: E402
                                 same_loops)

runs = PvbatchRuns("MpiOneStep.py", "boolsurf-one-step-")


def area(outputs):
    return sum(row[0] for rows in outputs["by_source"].values() for row in rows)


ON_PIECES = ("union", "intersection", "difference", "expression", "pointed", "edited", "back",
             "open", "whole", "whole_reversed")
# Regions large enough to cross pieces on every split tested.
SPREAD = ("union", "pointed", "edited", "back")

serial, _ = runs.run(1)
for name in ON_PIECES + ("bsc",):
    assert not serial[name]["pieces"], (name, "one rank: the surface is whole")
    assert serial[name]["triangles"] > 0, (name, "one rank: an empty region")
assert serial["union"]["ports23"][0], "one rank: the boundary as control points"
assert serial["open"]["ports23"][1], "one rank: the open polyline clipped"
for name, pieces in (("whole", 1), ("whole_reversed", 2)):
    # One loop, the whole first circle (walked against it outside); the polyline in pieces.
    loops = serial[name]["ports23"][0]
    assert len(loops) == 1 and loops[0][0]["SourceCurveId"] == [0.0], (name, loops)
    assert len(serial[name]["ports23"][1]) == pieces, (name, serial[name]["ports23"][1])
# The point's zero cell changes the labels: the automatic zero cell is elsewhere.
assert serial["pointed"]["fields"]["CellLabels"] != serial["union"]["fields"]["CellLabels"]
same_loops(serial["chain"]["lines"], serial["union"]["lines"], "one rank: stage chain")
same_control_curves(serial["chain"]["ports23"][0], serial["union"]["ports23"][0], "BoundaryLoop",
                    "one rank: stage chain")
assert serial["edited"]["by_source"] != serial["union"]["by_source"], "the edit changed nothing"
# Traced, arranged and labeled on the pieces when the curves or the labeling change; only the
# selection when only the Boolean does.
LABELED = ("union", "pointed", "edited", "open")
for ranks, partitions in ((2, None), (3, None), (3, 2)):
    result, output = runs.run(ranks, partitions)
    assert result["ranks"] == ranks, result["ranks"]
    holding = partitions or ranks
    for name in ON_PIECES:
        where = "%s on %d ranks, %d holding triangles" % (name, ranks, holding)
        got, expected = result[name], serial[name]
        assert got["pieces"], (where, "did not run on the pieces")
        assert got["triangles"] == expected["triangles"], (where, got["triangles"],
                                                           expected["triangles"])
        same_by_source(got["by_source"], expected["by_source"], where, False)
        assert got["fields"] == expected["fields"], (where, got["fields"], expected["fields"])
        steps = got["StageTimes"]
        assert steps and "Selection" in steps and "Total" in steps, (where, steps)
        assert ("Trace" in steps and "Labeling" in steps) == (name in LABELED), (where, steps)
        # Ports 2 and 3: whole on rank 0, the one-rank control curves.
        assert got["held23"] in ([], [0]), (where, "ports 2 and 3 off rank 0", got["held23"])
        same_control_curves(got["ports23"][0], expected["ports23"][0], "BoundaryLoop", where)
        same_control_curves(got["ports23"][1], expected["ports23"][1], "ClippedPiece", where)
        # The boundary loops: whole, on rank 0 only, the one-rank loops.
        assert all(held == 0 for _, held, _ in got["lines"]), (where, "loops off rank 0")
        same_loops(got["lines"], expected["lines"], where)
        assert got["expression"] == expected["expression"], where
        if name in SPREAD:
            held = got["held"]
            assert len(held) >= 2 and max(held.values()) < got["triangles"], (where, held)
        print("%s: region of %d triangles held per rank %s" % (where, got["triangles"],
                                                                got["held"]))
    where = "%d ranks, %d holding triangles" % (ranks, holding)
    # The stage chain on the same pieces draws the same loops.
    same_loops(result["union"]["lines"], result["chain"]["lines"], where + ": stage chain")
    same_control_curves(result["chain"]["ports23"][0], serial["union"]["ports23"][0],
                        "BoundaryLoop", where + ": stage chain")
    assert "ran on each rank's piece of the surface" in output, output
    # Selection BSC: gathered, with a warning saying why, and the one-rank answer.
    bsc = result["bsc"]
    assert not bsc["pieces"], (where, "BSC ran on pieces")
    assert "not on each rank's piece: Selection BSC" in output, output
    assert bsc["triangles"] == serial["bsc"]["triangles"], (where, bsc["triangles"])
    # The gathered surface numbers its triangles in rank order (SourceTriangle and the cells
    # follow it): the region's area and boundary are compared whole.
    assert abs(area(bsc) - area(serial["bsc"])) <= 1e-12, (where, area(bsc), area(serial["bsc"]))
    assert len(bsc["lines"]) == len(serial["bsc"]["lines"]), (where, "BSC loops")
    print("%s: the one-step filter on the pieces gives the one-rank answers" % where)
shutil.rmtree(runs.out, ignore_errors=True)

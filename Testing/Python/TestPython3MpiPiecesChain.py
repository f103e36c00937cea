"""Trace Surface Curves, Surface Arrangement, Label Arrangement Cells and Surface Boolean on
each rank's piece of a split surface (MpiPiecesChain.py, pvbatch on 1, 2 and 3 ranks, and on 3
ranks with the surface split in 2, one rank holding none): the union over ranks of each output
equals the one-rank output per source triangle (the same refined triangles in the same cells
with the same labels, areas to 1e-12), the Boolean's boundary loops are the one-rank loops,
whole on rank 0 (the same points in the same order, started at their lowest point), every rank
holds only its part (no rank holds the whole region), the piece outputs say so, and a filter
that gathers its input refuses them with an error instead of answering wrongly. Trace Surface
Curves traces on the pieces: rank 0's polylines equal one rank's exactly, every rank's message
0 equals the gathered path's byte for byte, no rank holds the whole surface, an edit of the
curves keeps the ringed piece, the LocallyShortest method is traced on the gathered surface
(warning), and a curve naming a triangle no rank holds fails on every rank with an error naming
it. Each run has a time limit: a rank left waiting fails the test.
"""
import os
import shutil
import sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mpi_pieces_compare import PvbatchRuns, same_by_source, same_loops  # noqa: E402

runs = PvbatchRuns("MpiPiecesChain.py", "boolsurf-pieces-chain-")
run = runs.run

serial, _ = run(1)
assert serial["boundary"]["lines"], "one rank: the union has a boundary"
# The point's zero cell changes the labels: the automatic zero cell is elsewhere.
assert serial["pointed"]["CellLabels"] != serial["labels"]["CellLabels"], serial["pointed"]
assert not serial["arrangement"]["pieces"], "one rank: the surface is whole"
assert serial["boolean"]["triangles"] > 0 and serial["bsc"]["triangles"] > 0, serial["bsc"]
assert serial["traced"]["cells"], "one rank traces the curves"
assert serial["bad"] and "curve 0" in serial["bad"][0], serial["bad"]
cells = int(serial["arrangement"]["NumberOfCells"][0])
assert cells > 4, cells  # three crossing circles
for ranks, partitions in ((2, None), (3, None), (3, 2)):
    result, output = run(ranks, partitions)
    assert result["ranks"] == ranks, result["ranks"]
    holding = partitions or ranks  # ranks holding triangles (the others hold none)
    for stage in ("arrangement", "labels", "boolean"):
        where = "%s on %d ranks, %d holding triangles" % (stage, ranks, holding)
        got, expected = result[stage], serial[stage]
        assert got["pieces"], (where, "did not run on the pieces")
        assert got["triangles"] == expected["triangles"], (where, got["triangles"],
                                                           expected["triangles"])
        same_by_source(got["by_source"], expected["by_source"], where, stage != "boolean")
        assert got["NumberOfCells"] == expected["NumberOfCells"], where
        # Each rank holds only its part: every rank holds refined triangles (the region may miss
        # a rank's piece), at least two hold parts, none holds them all.
        held = got["held"]
        assert len(held) == holding or (stage == "boolean" and len(held) >= 2), (where, held)
        assert max(held.values()) < got["triangles"], (where, held)
    # Trace Surface Curves on the pieces: rank 0's polylines are the one-rank output exactly,
    # every rank has message 0, byte for byte the gathered path's, and no rank held the surface.
    assert result["traced"] == serial["traced"], "traced polylines differ from one rank's"
    for stage, tracing in (("traced", result["tracing"]), ("edited", result["edited"]["tracing"])):
        assert sorted(tracing) == [str(r) for r in range(ranks)], (stage, tracing)
        reference = tracing["0"]["Reference"]
        assert reference >= 0, (stage, "the gathered path packed no message")
        for rank, row in tracing.items():
            where = "%s, rank %s of %d" % (stage, rank, ranks)
            assert row["Message"] == reference, (where, "message 0 differs", row)
            assert "HeldTriangles" in row, (where, "not traced on pieces", row)
            assert row["HeldTriangles"] < result["surface_triangles"], (where, row)
            assert row["Lines"] == (len(serial["traced"]["cells"]) if rank == "0" else 0), row
            assert row["ReusedPiece"] == (1 if stage == "edited" else 0), (where, row)
        print("%s on %d ranks: held triangles per rank %s of %d, rounds %d" % (
            stage, ranks, [int(r["HeldTriangles"]) for _, r in sorted(tracing.items())],
            result["surface_triangles"], int(tracing["0"]["Rounds"])))
    # LocallyShortest: gathered, the one-rank polylines on rank 0, message 0 there only.
    shortest = result["shortest"]
    assert shortest["traced"] == serial["shortest"]["traced"], "LocallyShortest differs"
    assert shortest["tracing"]["0"]["Message"] == shortest["tracing"]["0"]["Reference"] >= 0
    assert all("HeldTriangles" not in row for row in shortest["tracing"].values()), shortest
    assert "not on each rank's piece: the LocallyShortest geodesic method" in output, output
    same_by_source(result["edited"]["boolean"], serial["edited"]["boolean"], "edited", False)
    assert result["bad"] and "which no rank holds" in result["bad"][0], result["bad"]
    assert "curve 0" in result["bad"][0], result["bad"]
    assert output.count("which no rank holds") >= ranks, "the error is not on every rank"
    # The Boolean's boundary loops: whole, on rank 0 only, the one-rank loops.
    where = "boundary on %d ranks, %d holding triangles" % (ranks, holding)
    assert result["boundary"]["pieces"], where
    assert result["boundary"]["Expression"] == serial["boundary"]["Expression"], where
    assert all(held == 0 for _, held, _ in result["boundary"]["lines"]), where
    same_loops(result["boundary"]["lines"], serial["boundary"]["lines"], where)
    # Port 0's plug fields, from the merged graph.
    assert result["arrangement"]["plugs"] == serial["arrangement"]["plugs"], (
        ranks, result["arrangement"]["plugs"], serial["arrangement"]["plugs"])
    for table in ("CellLabels", "ShapeConsistent"):
        assert result["labels"][table] == serial["labels"][table], (ranks, table)
        # The zero cell given by a point, located on the rank owning its triangle.
        assert result["pointed"][table] == serial["pointed"][table], (ranks, "pointed", table)
    assert "ran on each rank's piece of the surface" in output, output
    # Boundary Sampled Curves gathers its input: it refuses the labeled pieces, naming them.
    assert result["bsc"]["triangles"] == 0, result["bsc"]
    assert "comes from Surface Arrangement run on each rank's piece" in output, output
    print("%d ranks, %d holding triangles: Surface Arrangement, labels and Boolean on the "
          "pieces give the one-rank answers" % (ranks, holding))
shutil.rmtree(runs.out, ignore_errors=True)

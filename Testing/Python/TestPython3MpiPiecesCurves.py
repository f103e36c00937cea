"""The Surface Curves source on each rank's piece of a split surface (MpiPiecesCurves.py, pvbatch
on 1, 2 and 3 ranks): with points given by position (snapped) and by TriangleId/Barycentric,
rank 0's control curves (port 0) and their trace (port 1) equal one rank's exactly (global
triangle ids, barycentric weights, positions, facet normals), the other ranks' are empty, no
rank searched or held the whole surface (PieceSnapping, PieceTracingTraffic), an edit of the
points keeps the ringed piece, and a point naming a triangle no rank has fails on every rank with
an error naming its curve and point; the LocallyShortest method gathers (warning) and
gives the one-rank ports. Pieces without GlobalIds: the filters generate them (a
warning says so) and Surface Curves, Trace Surface Curves and the chain to Surface Boolean give
the one-rank answer on the surface those pieces form (the triangles numbered rank by rank, as
the gathered surface numbers them). Each run has a time limit: a rank left waiting fails the
test.
"""
import os
import sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mpi_pieces_compare import PvbatchRuns  # noqa: E402

runs = PvbatchRuns("MpiPiecesCurves.py", "boolsurf-pieces-curves-")
out = runs.out


def run(ranks, extra=(), name=None):
    return runs.run(ranks, extra=extra, name=name)


def same_ports(got, expected, where):
    for port in ("curves", "traced"):
        a, b = got[port], expected[port]
        assert a["cells"], (where, port, "no curves")
        for key in sorted(set(a) | set(b)):
            assert a.get(key) == b.get(key), (where, port, key, "differs from one rank's")


def pieces_ran(rows, ranks, total, where, reused=None):
    """Every rank placed the points and traced port 1 on its piece, holding part of it only."""
    assert sorted(rows) == [str(r) for r in range(ranks)], (where, rows)
    for rank, row in rows.items():
        here = "%s, rank %s of %d" % (where, rank, ranks)
        assert "PieceSnapping:OwnedTriangles" in row, (here, "not on pieces", row)
        assert 0 < row["PieceSnapping:OwnedTriangles"] < total, (here, row)
        assert 0 < row["PieceTracingTraffic:HeldTriangles"] < total, (here, row)
        # Placing the points costs per point and rank, not per triangle: rank 0 receives every
        # other rank's answers (16 words a point, and its number of triangles), and every rank
        # the smallest distance of each point (one all-reduce).
        if rank == "0":
            points = row["PieceSnapping:Points"]
            assert row["PieceSnapping:Received"] == 8 * (ranks - 1) * (1 + 16 * points) + \
                8 * points, (here, row)
        if rank != "0":
            assert row["Lines0"] == 0 and row["Lines1"] == 0, (here, "curves on another rank")
        if reused is not None:
            assert row["PieceTracingTraffic:ReusedPiece"] == reused, (here, row)


serial, _ = run(1)
assert serial["bad"]["lines"] == 0, serial["bad"]
assert serial["snapped"]["curves"] == serial["exact"]["curves"], "exact points differ"
for ranks in (2, 3):
    appended = os.path.join(out, "appended%d.vtp" % ranks)
    result, output = run(ranks, ["--appended", appended])
    assert result["ranks"] == ranks, result["ranks"]
    total = result["surface_triangles"]
    for stage, reused in (("snapped", 0), ("exact", 0), ("edited", 1)):
        where = "%s on %d ranks" % (stage, ranks)
        same_ports(result[stage], serial[stage], where)
        pieces_ran(result[stage + "_ranks"], ranks, total, where, reused)
    print("%d ranks: triangles searched per rank %s of %d" % (
        ranks, [int(r["PieceSnapping:OwnedTriangles"])
                for _, r in sorted(result["snapped_ranks"].items())], total))
    # The LocallyShortest method does not trace on pieces: the update gathers (a warning says
    # why) and gives the one-rank ports.
    same_ports(result["shortest"], serial["shortest"], "LocallyShortest on %d ranks" % ranks)
    assert "curves were drawn on the surface gathered to rank 0, not on each rank's piece: " \
        "the LocallyShortest" in output, output
    # The bad point: every rank fails (no rank waits), the error names the curve and point.
    assert result["bad"]["lines"] == 0, result["bad"]
    assert "Curve 1, point 5: TriangleId 1000000 is not a triangle of the surface" in output, \
        output
    # Pieces without GlobalIds: generated, warned, the one-rank answer on the appended surface.
    assert "carry no point and cell GlobalIds: generated them" in output, output
    whole, _ = run(1, ["--whole", appended], name="whole%d" % ranks)
    where = "pieces without GlobalIds on %d ranks" % ranks
    same_ports(result["plain"]["curves"], whole["plain"]["curves"], where)
    pieces_ran(result["plain"]["ranks"], ranks, total, where)
    assert result["plain"]["traced"] == whole["plain"]["traced"], (where, "traced curves")
    a, b = result["plain"]["region"], whole["plain"]["region"]
    assert a and a.keys() == b.keys(), (where, sorted(set(a) ^ set(b))[:10])
    for source in a:
        assert len(a[source]) == len(b[source]), (where, source)
        assert all(abs(x - y) <= 1e-12 for x, y in zip(a[source], b[source])), (where, source)
print("Surface Curves on pieces: the one-rank curves on 2 and 3 ranks")

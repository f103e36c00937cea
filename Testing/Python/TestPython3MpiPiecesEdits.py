"""Edits on each rank's piece of a split surface (MpiPiecesEdits.py, pvbatch on 1, 2 and 3
ranks): after every edit the union over ranks of Surface Arrangement's, Label Arrangement
Cells' and Surface Boolean's outputs equals the one-rank output per source triangle (the same
refined triangles in the same cells with the same labels, areas to 1e-12), and each rank's
Surface Arrangement says what it kept (PieceArrangementReuse): the first update and the update
after the surface changed build the piece, every edit of the curves alone keeps it, and once
an earlier result is free the arrangement is computed again in place (Core's edit path). One
edit moves a small circle across rank boundaries (the ranks holding its triangles change).
Each run has a time limit: a rank left waiting fails the test.
"""
import json
import os
import shutil
import subprocess
import sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scratch  # noqa: E402

source_dir = os.environ.get("BOOLSURF_SOURCE_DIR",
                            os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
script = os.path.join(source_dir, "Testing", "Python", "MpiPiecesEdits.py")
mpiexec = shutil.which("mpiexec")
pvbatch = shutil.which("pvbatch")
if not mpiexec or not pvbatch:
    print("mpiexec or pvbatch not found: nothing to test")
    sys.exit(0)
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")
out = scratch.folder("boolsurf-pieces-edits-")


def run(ranks):
    path = os.path.join(out, "r%d.json" % ranks)
    command = [mpiexec, "-np", str(ranks), pvbatch, script, "--json", path]
    # Its own process group, so a hung run's ranks can all be stopped.
    process = subprocess.Popen(command, env=env, stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, text=True, start_new_session=True)
    try:
        output, _ = process.communicate(timeout=300)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, 9)
        process.communicate()
        raise SystemExit("%d ranks: no answer within 300 s (a rank waits for another)" % ranks)
    if process.returncode != 0 or not os.path.exists(path):
        print(output)
        raise SystemExit("%d ranks: pvbatch failed (exit code %d)" % (ranks, process.returncode))
    with open(path) as f:
        return json.load(f)


def same_by_source(a, b, where, ordered):
    """Per source triangle: the same rows (area to 1e-12, every other value exactly), in the
    same order when `ordered` (the refined surface), else as sets (the one-rank region lists a
    source triangle's triangles in its extractor's order)."""
    assert a.keys() == b.keys(), (where, sorted(set(a) ^ set(b))[:10])
    for source in a:
        rows_a, rows_b = a[source], b[source]
        if not ordered:
            rows_a = sorted(rows_a, key=lambda row: (row[1:], row[0]))
            rows_b = sorted(rows_b, key=lambda row: (row[1:], row[0]))
        assert len(rows_a) == len(rows_b), (where, source, rows_a, rows_b)
        for x, y in zip(rows_a, rows_b):
            assert abs(x[0] - y[0]) <= 1e-12, (where, source, x, y)
            assert x[1:] == y[1:], (where, source, x, y)


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
        print("%s on %d ranks: the one-rank outputs; kept piece %s, kept arrangement %s" % (
            got["name"], ranks, [int(r["KeptPiece"]) for _, r in sorted(reuse.items())],
            [int(r["KeptArrangement"]) for _, r in sorted(reuse.items())]))
    # The small circle moved across rank boundaries: other ranks hold its triangles.
    before, after = steps[1]["small_circle_ranks"], steps[2]["small_circle_ranks"]
    assert before and after and before != after, ("the small circle stayed on its ranks",
                                                   before, after)
shutil.rmtree(out, ignore_errors=True)

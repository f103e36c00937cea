"""A surface split across MPI ranks stays split: Check Surface on 1, 2, 3 and 4 ranks
(MpiPieces.py) gives, per global cell id and per point, the one-rank answers, with the same
field data on every rank; pieces with ghost cells, a rank with no triangles, pieces without global ids (generated, with
a warning) and overlapping pieces (a clear error on every rank, no hang) are handled; and the
pieces of a .pvtp written on 3 ranks, read back in one process, give the undistributed
surface's answers through every filter of the one-step pipeline (PvtpSerialPipeline.py).

The shared scans (../shared/data, or BOOLSURF_SHARED_DATA) add one scan when present.
"""
import json
import os
import shutil
import sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scratch  # noqa: E402
from mpi_pieces_compare import run_limited  # noqa: E402

source_dir = os.environ.get("BOOLSURF_SOURCE_DIR",
                            os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
python_dir = os.path.join(source_dir, "Testing", "Python")
mpiexec = shutil.which("mpiexec")
pvbatch = shutil.which("pvbatch")
if not mpiexec or not pvbatch:
    print("mpiexec or pvbatch not found: nothing to test")
    sys.exit(0)
out = scratch.folder("boolsurf-pieces-")
shared = os.environ.get("BOOLSURF_SHARED_DATA") or os.path.join(source_dir, "..", "shared", "data")
scan = os.path.join(shared, "meshes", "fertility.ply")
if not os.path.exists(scan):
    print("shared data not found (%s): the shared scan is skipped" % shared)
    scan = None


def run(command, what):
    return run_limited(command, what, 300)


def pieces(ranks):
    path = os.path.join(out, "r%d.json" % ranks)
    command = [mpiexec, "-np", str(ranks), pvbatch, os.path.join(python_dir, "MpiPieces.py"),
               "--json", path]
    if scan:
        command += ["--scan", scan]
    if ranks == 3:
        command += ["--pvtp", os.path.join(out, "eight.pvtp")]
    output = run(command, "%d ranks" % ranks)
    with open(path) as f:
        return json.load(f), output


def same_field(a, b, where):
    assert a.keys() == b.keys(), (where, a, b)
    for k in a:
        if k == "BoundaryLoopLength":
            # Summed per rank, then across ranks: the same to rounding.
            assert len(a[k]) == len(b[k]), (where, a[k], b[k])
            for x, y in zip(a[k], b[k]):
                assert abs(x - y) <= 1e-9 * max(1.0, abs(x)), (where, x, y)
        else:
            assert a[k] == b[k], (where, k, a[k], b[k])


serial, _ = pieces(1)
assert serial["eight"]["field"]["Genus"] == ["2"], serial["eight"]["field"]
assert serial["torus"]["field"]["Genus"] == ["1"], serial["torus"]["field"]
assert serial["open_sphere"]["field"]["BoundaryLoops"] == ["1"], serial["open_sphere"]["field"]
surfaces = [k for k in ("sphere", "open_sphere", "torus", "eight", "scan") if k in serial]
for ranks in (2, 3, 4):
    result, output = pieces(ranks)
    assert result["ranks"] == ranks, result
    for name in surfaces:
        where = "%s on %d ranks" % (name, ranks)
        got, expected = result[name], serial[name]
        assert got["digests"] == 1, (where, "field data differs between ranks")
        same_field(got["field"], expected["field"], where)
        assert got["components"] == expected["components"], where
        assert got["loops"] == expected["loops"], where
    # Pieces holding copies of their neighbours' cells, marked as ghosts: each cell counted once.
    assert result["ghosts"]["ghost_cells"] > 0, "no ghost cells generated"
    assert result["ghosts"]["components"] == serial["eight"]["components"], "ghosts"
    same_field(result["ghosts"]["field"], serial["eight"]["field"], "ghosts, %d ranks" % ranks)
    # Without global ids: generated, with a warning; the same topology.
    same_field(result["no_ids"]["field"], serial["no_ids"]["field"], "no ids, %d ranks" % ranks)
    assert "carry no global cell ids: generated them" in output, output
    # Overlapping pieces: an error naming the ids and ranks, on every rank; empty outputs.
    assert "pieces overlap without ghost marks" in output, output
    assert "0 (ranks 0 1" in output, output
    assert result["overlap"]["triangles"] == 0, result["overlap"]["triangles"]
    if ranks >= 3:
        assert result["empty_rank"]["holding"] < ranks, result["empty_rank"]["holding"]
        same_field(result["empty_rank"]["field"], serial["eight"]["field"], "rank with no triangles")
        assert result["empty_rank"]["components"] == serial["eight"]["components"]
        same_field(result["empty_rank_no_ids"]["field"], serial["eight"]["field"],
                   "rank with no triangles, no ids")
    print("%d ranks: Check Surface on the pieces gives the one-rank answers" % ranks)

print(run([pvbatch, os.path.join(python_dir, "PvtpSerialPipeline.py"),
           os.path.join(out, "eight.pvtp")], "pieces read serially").splitlines()[-1])
shutil.rmtree(out, ignore_errors=True)

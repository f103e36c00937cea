"""BoolSurf under MPI: pvbatch on 2 and 3 ranks gives the answers of 1 rank, for every filter
(MpiPipeline.py), with the surface as one serial reader's output and split across the ranks;
and no run hangs (each has a time limit, a hang fails the test).

Runs `mpiexec -np N pvbatch Testing/Python/MpiPipeline.py`; mpiexec is told to oversubscribe
(3 ranks on a 2-core machine) and, when run as root (CI), to allow it.
"""
import json
import os
import shutil
import subprocess
import sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scratch  # noqa: E402
from mpi_pieces_compare import MPI_ENV, run_limited  # noqa: E402

source_dir = os.environ.get("BOOLSURF_SOURCE_DIR",
                            os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
script = os.path.join(source_dir, "Testing", "Python", "MpiPipeline.py")
mpiexec = shutil.which("mpiexec")
pvbatch = shutil.which("pvbatch")
if not mpiexec or not pvbatch:
    print("mpiexec or pvbatch not found: nothing to test")
    sys.exit(0)
out = scratch.folder("boolsurf-mpi-")


def run(ranks, distribute):
    path = os.path.join(out, "r%d%s.json" % (ranks, "d" if distribute else ""))
    command = [mpiexec, "-np", str(ranks), pvbatch, script, "--json", path]
    if distribute:
        command.append("--distribute")
    what = "%d ranks%s" % (ranks, " (distributed)" if distribute else "")
    output = run_limited(command, what)
    if not os.path.exists(path):
        print(output)
        raise SystemExit("%s: pvbatch wrote no JSON" % what)
    with open(path) as f:
        return json.load(f)


def same(a, b, where=""):
    """Equal structures; floats to 1e-9 relative (rank 0 computes the same way either way,
    but the summed areas come back through a gather)."""
    if isinstance(a, dict):
        assert a.keys() - {"surface_pieces"} == b.keys() - {"surface_pieces"}, (where, a, b)
        for k in a:
            if k not in ("ranks", "surface_pieces"):
                same(a[k], b[k], where + "/" + k)
    elif isinstance(a, float):
        assert abs(a - b) <= 1e-9 * max(1.0, abs(a)), (where, a, b)
    else:
        assert a == b, (where, a, b)


serial = run(1, False)
assert serial["one_step"]["triangles"] > 0 and serial["svg"]["area"] > 0, serial
assert serial["arrangement"]["cells"] == 4, serial  # two crossing discs: 4 cells
assert serial["samples"]["points"] == 2 and serial["bsc"]["triangles"] > 0, serial
assert serial["resolve"]["curves"] == 2, serial  # consistent discs: kept as they are
for ranks in (2, 3):
    for distribute in (False, True):
        result = run(ranks, distribute)
        assert result["ranks"] == ranks, result
        if distribute:
            assert result["surface_pieces"] == ranks, result  # the surface really was split
        # Distributed, the surface's pieces get generated GlobalIds and the one-step filter
        # runs on them, its vector output (port 2) included: the same answers.
        same(serial, result, "np %d%s" % (ranks, " distributed" if distribute else ""))
        print("%d ranks%s: same answers as 1 rank" % (ranks, " (distributed surface)"
                                                     if distribute else ""))

# The main example (it renders: under Xvfb) prints the same region on 1, 2 and 3 ranks and
# writes the same .vtp.
def demo(ranks):
    folder = os.path.join(out, "demo%d" % ranks)
    command = [os.path.join(source_dir, "Testing", "run-with-xvfb.sh"), mpiexec, "-np",
               str(ranks), pvbatch, os.path.join(source_dir, "Examples", "demo.py"),
               "--output", folder]
    done = subprocess.run(command, env=MPI_ENV, timeout=240, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True)
    lines = [line for line in done.stdout.splitlines() if "triangles, area" in line]
    assert done.returncode == 0 and lines, done.stdout
    assert os.path.getsize(os.path.join(folder, "eight_boolean.png")) > 10000
    return lines[0]


one = demo(1)
for ranks in (2, 3):
    assert demo(ranks) == one, (ranks, one)
    print("%d ranks: demo.py prints %r, as on 1 rank" % (ranks, one))
shutil.rmtree(out, ignore_errors=True)

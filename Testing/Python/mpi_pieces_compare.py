"""The driver side of the pvbatch runs under MPI (TestPython3MpiPiecesChain.py,
TestPython3MpiOneStep.py, TestPython3MpiPieces.py, TestPython3MpiPiecesCurves.py,
TestPython3MpiPiecesEdits.py, TestPython3MpiRanks.py, TestPython3MpiScaleScript.py): a command run under a time limit (a rank left waiting fails the
test), a script run by mpiexec on N ranks, and the comparisons of a union over ranks with one
rank's output.
"""
import json
import os
import shutil
import subprocess
import sys

import scratch


# Open MPI as root, and more ranks than cores.
MPI_ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")


def run_limited(command, what, seconds=240):
    """Runs `command` (mpiexec, pvbatch, pvpython) under MPI_ENV and a time limit, and returns
    its output; a run that fails, or gives no answer in time (a rank waiting for another),
    stops the test naming `what`."""
    # Its own process group, so a hung run's ranks can all be stopped.
    process = subprocess.Popen(command, env=MPI_ENV, stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, text=True, start_new_session=True)
    try:
        output, _ = process.communicate(timeout=seconds)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, 9)
        process.communicate()
        raise SystemExit("%s: no answer within %d s (a rank waits for another)" % (what, seconds))
    if process.returncode != 0:
        print(output)
        raise SystemExit("%s failed (exit code %d)" % (what, process.returncode))
    return output


class PvbatchRuns:
    """Runs `script` (in Testing/Python) with mpiexec and pvbatch, its JSON written to a scratch
    folder named from `prefix`; the test passes at once, saying so, when mpiexec or pvbatch is
    missing."""

    def __init__(self, script, prefix):
        self.mpiexec = shutil.which("mpiexec")
        self.pvbatch = shutil.which("pvbatch")
        if not self.mpiexec or not self.pvbatch:
            print("mpiexec or pvbatch not found: nothing to test")
            sys.exit(0)
        here = os.path.dirname(os.path.abspath(__file__))
        source_dir = os.environ.get("BOOLSURF_SOURCE_DIR", os.path.join(here, "..", ".."))
        self.script = os.path.join(source_dir, "Testing", "Python", script)
        self.out = scratch.folder(prefix)

    def run(self, ranks, partitions=None, extra=(), name=None, seconds=240):
        """The script's JSON and its output on `ranks` ranks (the surface split into
        `partitions` parts when given; `extra` more arguments, `name` the JSON's name when
        several runs have the same number of ranks), under a limit of `seconds`."""
        name = (name or "r%d%s" % (ranks, "p%d" % partitions if partitions else "")) + ".json"
        path = os.path.join(self.out, name)
        command = [self.mpiexec, "-np", str(ranks), self.pvbatch, self.script, "--json", path]
        if partitions:
            command += ["--partitions", str(partitions)]
        command += list(extra)
        output = run_limited(command, "%d ranks" % ranks, seconds)
        if not os.path.exists(path):
            print(output)
            raise SystemExit("%d ranks: pvbatch wrote no %s" % (ranks, name))
        with open(path) as f:
            return json.load(f), output


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


def canonical_loops(lines):
    """The loops as point sequences, each closed one started at its lowest point (then the
    lowest after it), sorted: the pieces' port 1 starts loops there and orders them so; the
    one-rank port 1 starts each where its first patch starts."""
    out = []
    for closed, _, points in lines:
        points = [tuple(p) for p in points]
        if closed:
            m = len(points)
            best = min(range(m), key=lambda k: (points[k][:3], points[(k + 1) % m][:3]))
            points = points[best:] + points[:best]
        out.append((closed, points))
    return sorted(out)


def same_loops(got, expected, where):
    """The same loops: the same points in the same order (positions to 1e-12; the triangle
    named may be the other one of an edge a point lies on)."""
    a, b = canonical_loops(got), canonical_loops(expected)
    assert len(a) == len(b), (where, len(a), len(b))
    for (closed_a, points_a), (closed_b, points_b) in zip(a, b):
        assert closed_a == closed_b and len(points_a) == len(points_b), (where, len(points_a),
                                                                         len(points_b))
        for x, y in zip(points_a, points_b):
            assert max(abs(u - v) for u, v in zip(x[:3], y[:3])) <= 1e-12, (where, x, y)


def canonical_control_curves(curves, group):
    """The sub-curves of a control-curves output (mpi_pieces_fetch.control_curves) grouped by
    their cell array `group` (BoundaryLoop: a loop's sub-curves, cyclic, started at the lowest
    one, the loops sorted; ClippedPiece: one piece each, in order)."""
    groups = {}
    for values, points in curves:
        groups.setdefault(int(values[group][0]), []).append((values, points))
    out = [groups[g] for g in sorted(groups)]
    if group == "BoundaryLoop":
        def key(sub):
            values, points = sub
            return (values["SourceCurveId"], [round(x, 9) for x in points[0][:3]])
        out = [loop[min(range(len(loop)), key=lambda k: key(loop[k])):] +
               loop[:min(range(len(loop)), key=lambda k: key(loop[k]))] for loop in out]
        out.sort(key=lambda loop: [key(sub) for sub in loop])
    return out


def same_control_curves(got, expected, group, where):
    """The same sub-curves (control_curves of a port 2 or 3): the same groups, cell arrays
    (ParameterRange to 1e-9, every other exactly, the group's number left out for loops, whose
    order differs), points to 1e-12; a point's TriangleId and Barycentric exactly where it is
    one of the user's control points (the same triangle), else only its position (a point on
    an edge may name either triangle)."""
    a = canonical_control_curves(got, group)
    b = canonical_control_curves(expected, group)
    assert len(a) == len(b), (where, group, len(a), len(b))
    for loop_a, loop_b in zip(a, b):
        assert len(loop_a) == len(loop_b), (where, group, len(loop_a), len(loop_b))
        for (values_a, points_a), (values_b, points_b) in zip(loop_a, loop_b):
            assert values_a.keys() == values_b.keys(), (where, values_a.keys(), values_b.keys())
            for name in values_a:
                if name == group and group == "BoundaryLoop":
                    continue
                tolerance = 1e-9 if name == "ParameterRange" else 0
                assert all(abs(x - y) <= tolerance
                           for x, y in zip(values_a[name], values_b[name])), (
                    where, group, name, values_a, values_b)
            assert len(points_a) == len(points_b), (where, group, points_a, points_b)
            for x, y in zip(points_a, points_b):
                assert max(abs(u - v) for u, v in zip(x[:3], y[:3])) <= 1e-12, (where, x, y)
                if x[3] == y[3]:
                    assert max(abs(x[4] - y[4]), abs(x[5] - y[5])) <= 1e-12, (where, x, y)

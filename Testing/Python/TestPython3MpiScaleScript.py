"""The MPI scale benchmark's scripts run (Benchmarks/ParaView/mpi_scale*.py; not a timing): on
Data/bunny_npm.ply with ten circles, the inputs are prepared (one file, two pieces), one and
two ranks of pvbatch run the stage chain with one edit, and the summary reads both. Each rank's
record must carry what the benchmark reports: its memory, each stage's wall time, and on two
ranks the stages' per-rank arrays (StageTimes with the arrangement's steps, PieceBytes with
the messages), each rank holding part of the surface.
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
bench = os.path.join(source_dir, "Benchmarks", "ParaView")
mpiexec, pvbatch, pvpython = (shutil.which(p) for p in ("mpiexec", "pvbatch", "pvpython"))
if not mpiexec or not pvbatch or not pvpython:
    print("mpiexec, pvbatch or pvpython not found: nothing to test")
    sys.exit(0)
out = scratch.folder("boolsurf-mpi-scale-")
name = os.path.join(out, "bunny")


def run(command, what):
    return run_limited(command, what)


run([pvpython, os.path.join(bench, "mpi_scale_prepare.py"), "--mesh",
     os.path.join(source_dir, "Data", "bunny_npm.ply"), "--out", name, "--whole", "--scene",
     "ten"], "preparing the surface")
run([mpiexec, "-np", "2", pvbatch, os.path.join(bench, "mpi_scale_prepare.py"), "--out", name,
     "--pieces"], "splitting it in 2")
runs = []
for ranks, surface in ((1, name + ".vtp"), (2, name + "-2.pvtp")):
    path = os.path.join(out, "run%d.json" % ranks)
    run([mpiexec, "-np", str(ranks), pvbatch, "--symmetric", os.path.join(bench, "mpi_scale.py"),
         "--surface", surface, "--scene-cache", name + "-ten.json", "--json", path, "--edits",
         "1"], "%d rank(s)" % ranks)
    with open(path) as f:
        result = json.load(f)
    assert result["ranks"] == ranks and len(result["records"]) == ranks, result["ranks"]
    for record in result["records"]:
        assert record["memory"]["idle"]["hwm"] > 0, record["memory"]
        assert len(record["updates"]) == 2, len(record["updates"])
        for update in record["updates"]:
            stages = update["stages"]
            assert set(stages) == {"curves", "trace", "arrangement", "labels", "boolean"}
            times = stages["arrangement"]["arrays"].get("StageTimes", {})
            assert "Refinement" in times and "FloodFill" in times, times
            if ranks > 1:
                # Each rank's own figures, its own part of the surface.
                messages = stages["arrangement"]["arrays"]["PieceBytes"]
                for message in ("Curves", "Border", "Boundary", "Merge", "Back"):
                    assert message + "Sent" in messages and message + "Received" in messages
                assert messages["BoundarySent"] > 0 and messages["BoundaryReceived"] > 0
                assert "Total" in stages["boolean"]["arrays"]["StageTimes"]
                assert 0 < record["piece"]["triangles"] < 3674, record["piece"]
                assert stages["arrangement"]["cells"] > 0, stages["arrangement"]
    runs.append(path)
summary = run([pvpython, os.path.join(bench, "mpi_scale.py"), "--summarize"] + runs,
              "the summary")
assert "bytes per edit" in summary and "refinement + flood fill + output" in summary, summary
print(summary)

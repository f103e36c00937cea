"""A 3-rank pvserver session on pieces, driven from pvpython (PvserverSessionPipeline.py):
`mpiexec -np 3 pvserver`, the plugin loaded on the server, Data/eight.ply with global ids
redistributed, three circles drawn with Surface Curves, Trace, Surface Arrangement, Label
Arrangement Cells and Surface Boolean on the ranks' pieces, the region rendered on the server
and saved with Save Data as a .pvtp in pieces; then the one-step BoolSurf filter's region of the
same Boolean, on the pieces, rendered in its place.

Checks (pvserver_session.check_session): the region was computed on the pieces, every rank
holding a part and none all of it; per SourceTriangle the same triangles and area (1e-12) as a
builtin one-rank session; the screenshot shows it; the .pvtp has a piece per rank and reads
back to the same region, in the same session on the ranks and in a fresh one-process pvpython;
the one-step filter's region is that region too, on the pieces and on one rank, held in parts,
and covers the chain's pixels (1 %, another color). Renders through X: runs itself under Testing/run-with-xvfb.sh when no display is set.
"""
import json
import os
import shutil
import subprocess
import sys
here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
import pvserver_session as session  # noqa: E402
import scratch  # noqa: E402

RANKS = 3
missing = session.missing_tools(("mpiexec", "pvserver", "pvpython", "Xvfb"))
if missing:
    print("SKIPPED: %s not found: no pvserver session to test" % ", ".join(missing))
    sys.exit(0)
if not os.environ.get("DISPLAY"):
    # pvserver and pvpython render through X: one private X server for all of them.
    xvfb = os.path.join(here, "..", "run-with-xvfb.sh")
    sys.exit(subprocess.call([xvfb, sys.executable, os.path.abspath(__file__)] + sys.argv[1:]))

pvpython = shutil.which("pvpython")
pipeline = os.path.join(here, "PvserverSessionPipeline.py")
out = scratch.folder("boolsurf-pvserver-")


def client(name, *arguments, timeout=300):
    path = os.path.join(out, name + ".json")
    folder = os.path.join(out, name)
    os.makedirs(folder)
    session.run_client([pvpython, pipeline, "--json", path, "--folder", folder] +
                       list(arguments), timeout, "pvpython (%s)" % name)
    with open(path) as f:
        return json.load(f)


serial = client("builtin")
with session.PvServer(RANKS) as server:
    remote = client("pvserver", "--server", "localhost:%d" % server.port, timeout=400)
# The pieces the ranks wrote, read in a fresh one-process session.
fresh = client("fresh", "--read", remote["pvtp"])

failures = []
session.check_session(remote, serial, RANKS, failures)
session.same_region(fresh["read_back"], serial["region"],
                    "the .pvtp read back in one process", failures)
if fresh["ranks"] != 1:
    failures.append("the fresh session has %d ranks" % fresh["ranks"])
print("one rank: region of %d triangles on %d source triangles"
      % (serial["region"]["triangles"], len(serial["region"]["by_source"])))
print("pvserver on %d ranks: surface per rank %s, region per rank %s, %d region pixels "
      "(one-step filter: %s, %d pixels), pieces written %s"
      % (RANKS, remote["surface"]["held"], remote["region"]["held"], remote["region_pixels"],
         remote["one_step"]["held"], remote["one_step_pixels"], remote["pvtp_pieces"]))
if failures:
    sys.exit("FAILED:\n  " + "\n  ".join(failures))
print("pvserver session on %d ranks: the region on the pieces is the one-rank region; its "
      ".pvtp reads back the same on the ranks and in one process" % RANKS)

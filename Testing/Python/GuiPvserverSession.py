"""The 3-rank pvserver session from the GUI client, under Xvfb:

    run-with-xvfb.sh python3 GuiPvserverSession.py <paraview>

Starts `mpiexec -np 3 pvserver` (pvserver_session.PvServer), then `paraview --dr
--server-url=cs://localhost:PORT --script=GuiPvserverSessionScript.py`, which builds the session
of PvserverSessionPipeline.py through the GUI's proxies (Data/eight.ply with global ids,
redistributed; three circles in a Surface Curves source, set as the curve editor sets them;
Trace, Surface Arrangement, Label Arrangement Cells, Surface Boolean), shows the region in the
GUI's render view (rendered on the server), saves a screenshot and the region as a .pvtp in
pieces, then shows the one-step BoolSurf filter's region of the same Boolean in its place, and
exits. Checks the same as TestPython3PvserverSession.py against a builtin
one-rank pvpython session, and reads the GUI's .pvtp in a fresh one-process pvpython.
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
paraview = sys.argv[1] if len(sys.argv) > 1 else shutil.which("paraview")
missing = session.missing_tools(("mpiexec", "pvserver", "pvpython", "Xvfb"))
if not paraview or not shutil.which(paraview):
    missing.append("paraview")
if missing:
    print("SKIPPED: %s not found: no GUI pvserver session to test" % ", ".join(missing))
    sys.exit(0)
if not os.environ.get("DISPLAY"):
    # The GUI and pvserver render through X: one private X server for all of them.
    xvfb = os.path.join(here, "..", "run-with-xvfb.sh")
    sys.exit(subprocess.call([xvfb, sys.executable, os.path.abspath(__file__)] + sys.argv[1:]))

pvpython = shutil.which("pvpython")
pipeline = os.path.join(here, "PvserverSessionPipeline.py")
source_dir = os.environ.get("BOOLSURF_SOURCE_DIR", os.path.join(here, "..", ".."))
out = scratch.folder("boolsurf-gui-pvserver-")


def client(name, *arguments):
    path = os.path.join(out, name + ".json")
    folder = os.path.join(out, name)
    os.makedirs(folder)
    session.run_client([pvpython, pipeline, "--json", path, "--folder", folder] +
                       list(arguments), 300, "pvpython (%s)" % name)
    with open(path) as f:
        return json.load(f)


serial = client("builtin")
result_path = os.path.join(out, "gui.json")
os.environ.update(BOOLSURF_GUI_RESULT=result_path, BOOLSURF_SOURCE_DIR=source_dir)
with session.PvServer(RANKS) as server:
    output = session.run_client(
        [paraview, "--dr", "--server-url=" + server.url,
         "--script=" + os.path.join(here, "GuiPvserverSessionScript.py")],
        400, "paraview connected to %d pvserver ranks" % RANKS)
if not os.path.exists(result_path):
    print(output[-4000:])
    sys.exit("the GUI wrote no result: " + result_path)
with open(result_path) as f:
    remote = json.load(f)
fresh = client("fresh", "--read", remote["pvtp"])

failures = []
session.check_session(remote, serial, RANKS, failures)
session.same_region(fresh["read_back"], serial["region"],
                    "the GUI's .pvtp read back in one process", failures)
print("GUI client on %d pvserver ranks: surface per rank %s, region per rank %s, %d region "
      "pixels in the GUI's view (one-step filter: %s, %d pixels), pieces written %s"
      % (RANKS, remote["surface"]["held"], remote["region"]["held"], remote["region_pixels"],
         remote["one_step"]["held"], remote["one_step_pixels"], remote["pvtp_pieces"]))
if failures:
    print(output[-4000:])
    sys.exit("FAILED:\n  " + "\n  ".join(failures))
print("GUI pvserver session on %d ranks: the region on the pieces is the one-rank region" % RANKS)

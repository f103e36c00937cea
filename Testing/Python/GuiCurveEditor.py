"""GUI test of the curve editor, driven by ParaView's test player with synthetic mouse events.

    run-with-xvfb.sh pvpython GuiCurveEditor.py <paraview> [--server-ranks N]

Runs `paraview --script=GuiCurveEditorSetup.py --test-script=GuiCurveEditor.xml` (with
--server-ranks, connected to `mpiexec -np N pvserver` on localhost, in the same X server): the
setup builds a flat triangulated square, an empty Surface Curves source (its panel, the curve
editor, active) and BoolSurf of shape 0; the recorded events click four points on the square in
the render view, click the first point again (closing the curve), drag the third point, undo
and redo the drag (Edit menu), Shift+click the fourth point (deleting it) and save the state
(File > Save State). The player compares the
final view with Testing/Data/Baseline/curve_editor.png (BOOLSURF_UPDATE_BASELINE=1 rewrites
it: look at the new picture first).

Then, from the saved state loaded here: one closed polygon of three points of shape 0, each
stored exactly (a triangle and barycentric weights), on the square, the third moved by the
drag, and BoolSurf's region of exactly the polygon's area (shoelace formula: on a flat mesh
geodesics are straight lines) to 1e-9. Without a server, the results BoolSurf produced in the
GUI (recorded by the setup) must show the drag undone and redone, then the deletion, ending
with that area.
"""
import argparse
import json
import os
import re
import shutil
import signal
import socket
import subprocess
import sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scratch  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("paraview")
parser.add_argument("--server-ranks", type=int, default=0)
args = parser.parse_args()
here = os.path.dirname(os.path.abspath(__file__))
source_dir = os.environ.get("BOOLSURF_SOURCE_DIR", os.path.join(here, "..", ".."))
baseline = os.path.join(source_dir, "Testing", "Data", "Baseline", "curve_editor.png")
update = os.environ.get("BOOLSURF_UPDATE_BASELINE") == "1"
out = scratch.folder("boolsurf-editor-")
result_path = os.path.join(out, "result.json")
# pvpython started MPI as a singleton: its OMPI_/PMIX_ variables would mislead mpiexec.
env = {k: v for k, v in os.environ.items() if not re.match(r"(OMPI_|PMIX_|OPAL_)", k)}
env.update(BOOLSURF_GUI_RESULT=result_path, BOOLSURF_SOURCE_DIR=source_dir,
           OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")
test_baseline = os.path.join(out, "curve_editor.png") if update else baseline
command = [args.paraview, "--dr", "--script=" + os.path.join(here, "GuiCurveEditorSetup.py"),
           "--test-script=" + os.path.join(here, "GuiCurveEditor.xml"),
           "--test-directory=" + out, "--test-baseline=" + test_baseline, "--exit"]

server = None
if args.server_ranks:
    tools = {name: shutil.which(name) for name in ("mpiexec", "pvserver")}
    if not all(tools.values()):
        print("missing %s: nothing to test" % [k for k, v in tools.items() if not v])
        sys.exit(0)
    # Port 0 is not allowed by pvserver: take a free one from the system.
    with socket.socket() as s:
        s.bind(("localhost", 0))
        port = s.getsockname()[1]
    server = subprocess.Popen([tools["mpiexec"], "-np", str(args.server_ranks), tools["pvserver"],
                               "--server-port=%d" % port], env=env, stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT, universal_newlines=True,
                              start_new_session=True)
    for line in server.stdout:
        if re.search(r"Accepting connection", line):
            break
    else:
        sys.exit("pvserver stopped before accepting connections")
    command.append("--url=cs://localhost:%d" % port)
try:
    run = subprocess.run(command, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         timeout=600, universal_newlines=True)
finally:
    if server:
        os.killpg(server.pid, signal.SIGKILL)
        server.wait()

failures = []


def expect(condition, what):
    if not condition:
        failures.append(what)


if update:
    shutil.copyfile(test_baseline, baseline)
    print("baseline written: %s" % baseline)
else:
    expect(run.returncode == 0, "the test player failed (events or image comparison), exit %d;"
           " images in %s" % (run.returncode, out))
state = os.path.join(out, "drawing.pvsm")
if not os.path.exists(state):
    print(run.stdout[-4000:])
    sys.exit("no state saved by the GUI: " + state)

# The drawing and its region, from the saved state, in a builtin session.
from paraview.simple import GetSources, LoadPlugin, LoadState  # noqa: E402
from paraview import servermanager as sm  # noqa: E402
from vtkmodules.vtkFiltersVerdict import vtkCellSizeFilter  # noqa: E402

LoadPlugin(os.environ["BOOLSURF_PLUGIN"], remote=False, ns=globals())
LoadState(state)
sources = {s.GetXMLName(): s for s in GetSources().values()}
curves, region = sources["BoolSurfSurfaceCurves"], sources["BoolSurf"]
result = {name: list(curves.GetPropertyValue(name)) for name in (
    "Points", "TriangleIds", "Barycentrics", "CurveSizes", "ShapeIds", "CurveTypes",
    "ClosedCurves")}
sizes = vtkCellSizeFilter()
sizes.SetInputData(sm.Fetch(region))
sizes.Update()
areas = sizes.GetOutput().GetCellData().GetArray("Area")
area = sum(areas.GetValue(i) for i in range(areas.GetNumberOfTuples()))
print("saved drawing:", json.dumps(result))

expect(result["CurveSizes"] == [3], "one curve of three points: %s" % result["CurveSizes"])
expect(result["ClosedCurves"] == [1], "the curve is closed: %s" % result["ClosedCurves"])
expect(result["ShapeIds"] == [0] and result["CurveTypes"] == [0],
       "a polygon of shape 0: %s %s" % (result["ShapeIds"], result["CurveTypes"]))
points = [result["Points"][3 * i:3 * i + 3] for i in range(len(result["Points"]) // 3)]
triangles, weights = result["TriangleIds"], result["Barycentrics"]
expect(len(triangles) == len(points) and all(t >= 0 for t in triangles),
       "every point stored exactly (a triangle each): %s" % triangles)
for i in range(len(weights) // 2):
    u, v = weights[2 * i], weights[2 * i + 1]
    expect(u >= 0 and v >= 0 and u + v <= 1 + 1e-12, "point %d inside its triangle" % i)
for i, p in enumerate(points):
    expect(p[2] == 0 and abs(p[0]) < 0.5 and abs(p[1]) < 0.5, "point %d on the square: %s"
           % (i, p))
shoelace = None
if len(points) == 3:
    # Clicked at the corners of a rectangle (the fourth deleted), the third point dragged right
    # and up from the corner mirroring the first.
    expect(points[2][0] > points[1][0] + 0.03 and points[2][1] > -points[0][1] + 0.02,
           "the dragged point moved: %s" % points)
    shoelace = 0.5 * abs(sum(points[i][0] * points[(i + 1) % 3][1]
                             - points[(i + 1) % 3][0] * points[i][1] for i in range(3)))
    expect(abs(area - shoelace) <= 1e-9 * shoelace,
           "region area %.15g equals the polygon's %.15g" % (area, shoelace))

if not args.server_ranks:
    # What BoolSurf produced in the GUI, update after update: the drag, its undo, its redo.
    with open(result_path) as f:
        history = json.load(f)
    seen = []
    for h in history:
        if h["region_triangles"] and (not seen or h["region_area"] != seen[-1]):
            seen.append(h["region_area"])
    expect(len(seen) >= 4 and seen[-2] == seen[-4] and seen[-3] != seen[-2]
           and seen[-1] < seen[-2], "drag, undo, redo, then deletion: areas %s" % seen)
    expect(shoelace is not None and abs(history[-1]["region_area"] - shoelace) <= 1e-9 * shoelace,
           "the GUI's last region has the polygon's area: %s" % history[-1]["region_area"])
    # The Python trace recorded the edits as property changes of the Surface Curves source.
    trace = history[-1]["trace"]
    expect(re.search(r"\.Points = \[", trace) and re.search(r"\.CurveSizes = \[3\]", trace),
           "the Python trace holds the edits:\n" + trace[-2000:])
if failures:
    print(run.stdout[-4000:])
    sys.exit("FAILED:\n  " + "\n  ".join(failures))
print("curve editor OK%s: area %.12g" % (
    " (client connected to %d pvserver ranks)" % args.server_ranks if args.server_ranks else "",
    area))

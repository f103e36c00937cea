"""A new user's first drawing in the ParaView GUI, by a person's path, with the Output Messages
window left to its default settings.

    run-with-xvfb.sh pvpython GuiFirstDrawing.py <paraview>

Runs `paraview --script=GuiFirstDrawingSetup.py --test-script=GuiFirstDrawing.xml`: Data/eight.ply
open; the recorded events run Filters > BoolSurf > Surface Curves, click a polygon (four points,
then the first again to close it), select the mesh and run Filters > BoolSurf > BoolSurf as the
README says (the input dialog: Curves = the Surface Curves' Control Curves), Apply, go back to
the drawing, press New Curve, choose a cubic Bezier spline and click six points clockwise (one
about 5 pixels from a marker of the polygon) and the first again, press Reverse, select the
Traced Curves output (its display section widens the panel) and zoom in with a right-button
drag. After every click the player checks that the Output Messages window is closed (ParaView
opens it on any error or warning).

Then: nothing reported an error or a warning; from the saved state, the drawing is the
polygon and the closed 6-point Bezier spline (the click near the polygon's marker went to the
spline), both enclosing the small regions they were drawn around (the spline reversed), and the
BoolSurf made from the menus gives their union; its Difference is the polygon minus the spline;
every edit is one named undo step (no "Changed 'vtkSMProxy'"); the markers, in the frames the
view rendered before and after the zoom, have the same size in pixels while the surface grew on
the screen. Last, the saved state opened in a new session (GuiFirstDrawingLoaded.xml: the
drawing's panel, then the camera turned around the surface): its markers show from the front and
hide once on the far side, although a state holds no normals.
"""
import argparse
import json
import os
import re
import sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scratch  # noqa: E402
from gui_player import play  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("paraview")
args = parser.parse_args()
here = os.path.dirname(os.path.abspath(__file__))
source_dir = os.environ.get("BOOLSURF_SOURCE_DIR", os.path.join(here, "..", ".."))
out = scratch.folder("boolsurf-first-drawing-")
result = os.path.join(out, "result")
env = dict(os.environ, BOOLSURF_GUI_RESULT=result, BOOLSURF_SOURCE_DIR=source_dir)
run = play(args.paraview, "GuiFirstDrawingSetup.py", "GuiFirstDrawing.xml", out, env)
failures = []


def expect(condition, what):
    if not condition:
        failures.append(what)


expect(run.returncode == 0, "the test player failed (a menu path, a widget, or the Output "
       "Messages window opened), exit %d" % run.returncode)
# VTK's messages, as ParaView also prints them: errors and warnings both open the window.
messages = [line for line in run.stdout.splitlines() if re.search(r"\b(ERR|WARN)\|", line)]
expect(not messages, "messages while drawing:\n    " + "\n    ".join(messages[:10]))
state = os.path.join(out, "first_drawing.pvsm")
if not os.path.exists(state):
    print(run.stdout[-6000:])
    sys.exit("no state saved by the GUI: " + state)

from paraview.simple import GetSources, LoadPlugin, LoadState  # noqa: E402
from vtkmodules.vtkIOImage import vtkPNGReader  # noqa: E402
from proxy_area import area  # noqa: E402

LoadPlugin(os.environ["BOOLSURF_PLUGIN"], remote=False, ns=globals())
LoadState(state)
sources = {s.GetXMLName(): s for s in GetSources().values()}
curves, region, mesh = (sources["BoolSurfSurfaceCurves"], sources["BoolSurf"],
                        sources["PLYReader"])


drawing = {name: list(curves.GetPropertyValue(name)) for name in (
    "CurveSizes", "ShapeIds", "CurveTypes", "ClosedCurves")}
print("drawing:", json.dumps(drawing))
expect(drawing["CurveSizes"] == [4, 6], "a polygon of 4 points and a spline of 6 (the click near "
       "the polygon's marker added to the spline): %s" % drawing["CurveSizes"])
expect(drawing["CurveTypes"] == [0, 1] and drawing["ClosedCurves"] == [1, 1],
       "a closed polygon and a closed Bezier spline: %s" % drawing)
expect(drawing["ShapeIds"] == [0, 1], "shapes 0 and 1: %s" % drawing["ShapeIds"])
expect(region.Surface.GetXMLName() == "PLYReader" and region.Curves.GetXMLName()
       == "BoolSurfSurfaceCurves", "BoolSurf from the menus: Surface = the mesh, Curves = the "
       "drawing: %s, %s" % (region.Surface.GetXMLName(), region.Curves.GetXMLName()))

total = area(mesh)
union = area(region)  # as the GUI made it: Union of shapes 0 and 1
print("surface %.6f, union from the GUI %.6f" % (total, union))
BoolSurf = globals()["BoolSurf"]
parts = {}
for name, expression in (("S0", "S0"), ("S1", "S1"), ("both", "S0 & S1")):
    parts[name] = area(BoolSurf(Surface=mesh, Curves=curves, Operation="Expression",
                                Expression=expression))
print("areas:", parts)
# Both curves enclose the small regions they were drawn around, not the rest of the surface.
expect(0 < parts["S0"] < 0.05 * total and 0 < parts["S1"] < 0.05 * total,
       "each shape is the small region drawn (not its complement): %s of %.4f" % (parts, total))
expect(parts["both"] > 0, "the spline overlaps the polygon: %s" % parts)
expect(abs(union - (parts["S0"] + parts["S1"] - parts["both"])) <= 1e-9 * total,
       "the union from the GUI is S0 + S1 - S0&S1: %.9f" % union)
region.Operation = "Difference"
difference = area(region)
expect(abs(difference - (parts["S0"] - parts["both"])) <= 1e-9 * total,
       "Difference is S0 - S0&S1: %.9f against %.9f" % (difference, parts["S0"] - parts["both"]))


# Every edit one named undo step (an entry read "Undo Changed 'vtkSMProxy'": the pick's and the
# read-back's helper proxies).
with open(result + "-undo.json") as f:
    undo = json.load(f)
print("undo stack, newest first:", undo)
expect(undo[:2] == ["Reverse curve", "Close curve"] and "Add control point" in undo,
       "the last edits named: %s" % undo)
expect(not any(label.startswith("Changed 'vtk") for label in undo),
       "no unnamed undo step: %s" % undo)


# The markers at two zoom levels: the frames the view rendered (saved by the setup).
def pixels(png):
    reader = vtkPNGReader()
    reader.SetFileName(png)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    scalars = image.GetPointData().GetScalars()
    return width, height, [scalars.GetTuple3(i) for i in range(scalars.GetNumberOfTuples())]


def measure(png):
    """Pixel areas of the yellow markers (the polygon's points while the spline is current),
    and the number of pixels that are not background (how large the surface shows)."""
    width, height, rgb = pixels(png)
    background = rgb[0]
    yellow = set(i for i, (r, g, b) in enumerate(rgb) if r > 150 and g > 120 and b < 110
                 and r - g < 60)
    blobs = []
    while yellow:
        stack = [yellow.pop()]
        size = 0
        while stack:
            i = stack.pop()
            size += 1
            x, y = i % width, i // width
            for j in ((i - 1) if x > 0 else -1, (i + 1) if x + 1 < width else -1,
                      i - width, i + width):
                if j in yellow:
                    yellow.remove(j)
                    stack.append(j)
        if size >= 20:  # not a stray anti-aliased pixel
            blobs.append(size)
    covered = sum(1 for c in rgb if max(abs(a - b) for a, b in zip(c, background)) > 30)
    return sorted(blobs), covered


with open(result + "-frames/frames.json") as f:
    frames = json.load(f)
measured = [measure(frame["png"]) for frame in frames[-40:]]
# The last frame before the zoom and the last one: four markers each, the surface larger.
before = None
for blobs, covered in measured:
    if covered < 0.6 * measured[-1][1] and len(blobs) == 4:
        before = (blobs, covered)
after = measured[-1]
print("markers before the zoom %s (surface %s pixels), after %s (surface %s pixels)"
      % (before[0] if before else None, before[1] if before else None, after[0], after[1]))
expect(before is not None and len(after[0]) == 4,
       "four yellow markers before and after the zoom: %s, %s" % (before, after[0]))
if before is not None and len(after[0]) == 4:
    expect(after[1] > 1.6 * before[1], "the zoom made the surface larger on the screen")
    ratio = sorted(after[0])[2] / float(sorted(before[0])[2])
    expect(0.8 < ratio < 1.25, "the markers keep their size in pixels: %s -> %s"
           % (before[0], after[0]))

# The drawing loaded from its state file in a new session (its points come without normals):
# the panel opened, the camera turned around; the markers now on the far side must hide.
loaded = os.path.join(out, "loaded")
second = play(args.paraview, "GuiFirstDrawingSetup.py", "GuiFirstDrawingLoaded.xml", out,
              dict(env, BOOLSURF_GUI_RESULT=loaded, BOOLSURF_GUI_STATE=state))
expect(second.returncode == 0, "the loaded-state run failed, exit %d" % second.returncode)
with open(loaded + "-frames/frames.json") as f:
    frames = json.load(f)
counts = [(len(measure(frame["png"])[0]), frame["png"]) for frame in frames]
print("yellow markers per frame of the loaded drawing:", [c for c, _ in counts])
expect(any(c >= 4 for c, _ in counts), "the loaded drawing's markers show from the front")
expect(counts and counts[-1][0] == 0,
       "no marker shows through the surface once it is turned around: %s" % counts[-1:])

if failures:
    print(run.stdout[-4000:])
    sys.exit("FAILED:\n  " + "\n  ".join(failures))
print("first drawing OK: union %.6f, difference %.6f of %.6f" % (union, difference, total))

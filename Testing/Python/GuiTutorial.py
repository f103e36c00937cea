"""The README tutorial (steps 1 to 3) replayed in the ParaView GUI by its test player.

    run-with-xvfb.sh pvpython GuiTutorial.py <paraview>

Runs `paraview --script=GuiTutorialSetup.py --test-script=GuiTutorial.xml`: Data/eight.ply
open and shown; the recorded events run Filters > BoolSurf > Check Surface and Filters >
BoolSurf > Surface Curves from the menus (the paths the README gives), check the properties
dock's width and font (those the panel layout test assumes), draw two overlapping closed curves
counter-clockwise by clicking on the surface, press New Curve between them and check that its
fields show the next curve's values (shape 1, polygon, open, enabled), run Filters > BoolSurf >
BoolSurf with the checked mesh selected (README step 3: the input dialog asks for the Curves),
open Sources > BoolSurf > BSC Samples, and save the state. The player fails on any menu path or
widget that does not exist and on any check that does not hold.

Then, from the saved state: two closed curves of four exact points, shapes 0 and 1; the
surface still shown (the filters keep their input visible); the traced curves shown as
"BoolSurf Curves", with none of their pixels lost to the surface; and the BoolSurf made from the
menus is the union of the two curves, the small region they enclose (not the rest of the
surface), shown with ParaView's defaults in one color over the surface (one chromaticity over
all its pixels, lit flat).
"""
import argparse
import os
import sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scratch  # noqa: E402
from gui_player import play  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("paraview")
args = parser.parse_args()
here = os.path.dirname(os.path.abspath(__file__))
source_dir = os.environ.get("BOOLSURF_SOURCE_DIR", os.path.join(here, "..", ".."))
out = scratch.folder("boolsurf-tutorial-")
env = dict(os.environ, BOOLSURF_GUI_RESULT=os.path.join(out, "result"),
           BOOLSURF_SOURCE_DIR=source_dir)
run = play(args.paraview, "GuiTutorialSetup.py", "GuiTutorial.xml", out, env)
if run.returncode != 0:
    print(run.stdout[-6000:])
    sys.exit("the test player failed (a menu path, a widget or a check), exit %d" % run.returncode)
state = os.path.join(out, "tutorial.pvsm")
if not os.path.exists(state):
    sys.exit("no state saved by the GUI: " + state)

from paraview.simple import (GetActiveView, GetDisplayProperties, GetSources, Hide,  # noqa: E402
                             LoadPlugin, LoadState, ResetCamera, Show)
from paraview import servermanager as sm  # noqa: E402
sys.path.insert(0, here)
from render_pixels import chromaticity_spread, paint_unlit, view_pixels  # noqa: E402

LoadPlugin(os.environ["BOOLSURF_PLUGIN"], remote=False, ns=globals())
LoadState(state)
sources = {s.GetXMLName(): s for s in GetSources().values()}
curves, surface = sources["BoolSurfSurfaceCurves"], sources["CheckSurface"]
failures = []


def expect(condition, what):
    if not condition:
        failures.append(what)


sizes = list(curves.CurveSizes)
expect(sizes == [4, 4], "two curves of four points: %s" % sizes)
expect(list(curves.ShapeIds) == [0, 1], "shapes 0 and 1: %s" % list(curves.ShapeIds))
expect(list(curves.ClosedCurves) == [1, 1], "both closed: %s" % list(curves.ClosedCurves))
expect(all(t >= 0 for t in curves.TriangleIds), "exact points: %s" % list(curves.TriangleIds))
view = GetActiveView()
expect(GetDisplayProperties(surface, view).Visibility == 1, "the surface is still shown")
traced = sm.OutputPort(curves, 1)
lines = GetDisplayProperties(traced, view)
expect(lines.Visibility == 1 and lines.Representation == "BoolSurf Curves",
       "traced curves shown as BoolSurf Curves: %s" % lines.Representation)
if "PLYReader" in sources:  # Check Surface shows the mesh in its place
    Hide(sources["PLYReader"], view)
# What the GUI showed of BoolSurf (every output port) and of the samples is looked at below, or
# not at all.
for port in range(sources["BoolSurf"].GetNumberOfOutputPorts()):
    Hide(sm.OutputPort(sources["BoolSurf"], port), view)
if "BSCSamples" in sources:
    Hide(sources["BSCSamples"], view)

png = os.path.join(out, "view.png")


def pixels():
    return view_pixels(view, png, (500, 400))


view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0, 0, 0]  # black: edge pixels blend the region's color with no other hue
# The traced curves, flat red: every pixel they have alone they keep over the surface.
paint_unlit(lines, [1, 0, 0])


def reddish(c):
    return c[0] > 120 and c[1] < 40 and c[2] < 40


# A curve pixel is lost where the surface hides it: there the view with the curves is the view
# of the surface alone (a pixel the curve only partly covers blends with the surface).
Hide(surface, view)
alone = [i for i, c in enumerate(pixels()) if reddish(c)]
Show(surface, view)
Hide(traced, view)
bare = pixels()
Show(traced, view)
together = pixels()
lost = sum(1 for i in alone if max(abs(a - b) for a, b in zip(together[i], bare[i])) <= 2)
print("curve pixels %d, lost to the surface %d" % (len(alone), lost))
expect(len(alone) > 40 and lost == 0, "curve pixels %d, lost %d" % (len(alone), lost))

# The union as the user applied it from the menus (README step 3), with ParaView's default
# display: one color; and the region the two curves enclose, not the rest of the surface.
union = sources["BoolSurf"]
expect(union.Surface.GetXMLName() == "CheckSurface" and
       union.Curves.GetXMLName() == "BoolSurfSurfaceCurves",
       "BoolSurf from the menus: Surface = the checked mesh, Curves = the drawing")
expect(union.Operation == "Union" and union.ShapeA == 0 and union.ShapeB == 1,
       "BoolSurf's default operation: the union of shapes 0 and 1")
union.UpdatePipeline()
covered, whole = sm.Fetch(union).GetNumberOfCells(), sm.Fetch(surface).GetNumberOfCells()
print("union triangles %d of the surface's %d" % (covered, whole))
expect(0 < covered < 0.1 * whole, "the union is the small region drawn, not its complement")
region = Show(union, view)
Hide(traced, view)
expect(region.ColorArrayName[1] == "Region", "colored by Region: %s" % region.ColorArrayName)
region.Ambient, region.Diffuse = 1.0, 0.0
Hide(surface, view)
ResetCamera(view)
image = pixels()
colors = [c for c in image if c != (0.0, 0.0, 0.0)]
spread = chromaticity_spread(colors)
print("union pixels %d, chromaticity spread %.4f" % (len(colors), spread))
expect(len(colors) > 200 and spread < 0.02,
       "the union is one color: %d pixels, spread %.4f" % (len(colors), spread))
if failures:
    sys.exit("FAILED:\n  " + "\n  ".join(failures))
print("GUI tutorial OK")

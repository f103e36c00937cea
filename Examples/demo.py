"""BoolSurf main example (the README's main job).

Runs the BoolSurf pipeline on a mesh shipped in Data/ and writes the result as a .vtp file
and a .png rendering. At this stage of the project the pipeline is the surface check: it
validates the mesh and reports its topology (components, genus, boundary loops).

    xvfb-run -a pvbatch Examples/demo.py --output out [--mesh Data/eight.ply]

The plugin is found through $BOOLSURF_PLUGIN, else in build/ next to this script's folder.
"""
import argparse
import os
import sys

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager as sm

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(here)
parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--mesh", default=os.path.join(root, "Data", "eight.ply"))
parser.add_argument("--output", default=os.path.join(root, "out"))
args = parser.parse_args()

plugin = os.environ.get("BOOLSURF_PLUGIN") or os.path.join(
    root, "build", "lib", "paraview-5.11", "plugins", "BoolSurf", "BoolSurf.so")
LoadPlugin(plugin, remote=False, ns=globals())
os.makedirs(args.output, exist_ok=True)

mesh = PLYReader(FileNames=[args.mesh])
check = CheckSurface(Input=mesh)
check.UpdatePipeline()
data = sm.Fetch(check)
fd = data.GetFieldData()


def values(name):
    a = fd.GetAbstractArray(name)
    return [a.GetValue(i) for i in range(a.GetNumberOfValues())]


name = os.path.splitext(os.path.basename(args.mesh))[0]
if data.GetNumberOfCells() == 0:
    sys.exit("error: no triangles read from %s" % args.mesh)
print("mesh: %s (%d points, %d triangles)" % (args.mesh, data.GetNumberOfPoints(),
                                              data.GetNumberOfCells()))
print("components: %d, genus per component: %s, boundary loops per component: %s, "
      "Euler characteristic: %s, manifold: %s" % (
          values("Components")[0], values("Genus"), values("BoundaryLoops"),
          values("EulerCharacteristic"), bool(values("IsManifold")[0])))
problems = values("Problems")
print("problems: %s" % ("none" if not problems else "\n  " + "\n  ".join(problems)))

vtp = os.path.join(args.output, name + "_check.vtp")
# Inline binary, not appended: with Debian 12's current expat, VTK 9.2 cannot read back
# appended-mode XML files ("not well-formed (invalid token)").
SaveData(vtp, proxy=check, DataMode="Binary")
print("wrote %s" % vtp)

view = CreateView("RenderView")
view.ViewSize = [1024, 768]
view.OrientationAxesVisibility = 0
view.Background = [1, 1, 1]
try:  # ParaView 5.11 keeps a palette background unless told to use its own
    view.UseColorPaletteForBackground = 0
except AttributeError:
    pass
display = Show(check, view)
display.SetRepresentationType("Surface With Edges")
display.EdgeColor = [0.2, 0.2, 0.3]
if sum(values("BoundaryLoops")) > 0:  # show the boundary loops; else a plain surface
    ColorBy(display, ("POINTS", "BoundaryLoopId"))
    display.RescaleTransferFunctionToDataRange(True, False)
else:
    display.ColorArrayName = ["POINTS", ""]
    display.DiffuseColor = [0.85, 0.75, 0.55]
view.ResetCamera()
view.CameraPosition = [1, -1, 1.5]
view.CameraFocalPoint = [0, 0, 0]
view.CameraViewUp = [0, 0, 1]
view.ResetCamera()
Render(view)
png = os.path.join(args.output, name + "_check.png")
SaveScreenshot(png, view, ImageResolution=[1024, 768])
print("wrote %s" % png)

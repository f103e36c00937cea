"""How BoolSurf's output looks with ParaView's defaults, as a GUI user sees it after Apply.

Draws two overlapping discs on a mesh (rays cast along its thinnest axis), runs the one-step
BoolSurf filter (union) and shows the surface and the region with no display setting changed:
the region uses its default "BoolSurf Region" representation (drawn over the coincident
surface, no z-fighting) and is colored by its active scalars, Region, in one color (the union
reads as one region); the boundary (port 1) is drawn as lines over it ("BoolSurf Curves").

    xvfb-run -a pvbatch Examples/default_display.py --mesh ../shared/data/meshes/bimba.ply \\
        --png out/default_display.png
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from boolsurf_example_utils import (ROOT, SurfaceRays, curves_source,  # noqa: E402
                                    load_plugin, surface_circle)
from paraview.simple import *  # noqa: E402,F401,F403

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--mesh", default=os.path.join(ROOT, "Data", "eight.ply"))
parser.add_argument("--png", default=os.path.join(ROOT, "out", "default_display.png"))
args = parser.parse_args()
load_plugin(globals())
os.makedirs(os.path.dirname(os.path.abspath(args.png)), exist_ok=True)

mesh = PLYReader(FileNames=[args.mesh])
mesh.UpdatePipeline()
b = mesh.GetDataInformation().GetBounds()
extent = [b[1] - b[0], b[3] - b[2], b[5] - b[4]]
axis = extent.index(min(extent))  # look along the thinnest axis
rays = SurfaceRays(mesh, axis=axis)
u, v = (axis + 1) % 3, (axis + 2) % 3
cu, cv = (b[2 * u] + b[2 * u + 1]) / 2, (b[2 * v] + b[2 * v + 1]) / 2
radius = 0.08 * min(extent[u], extent[v])
# The first place near the middle where both discs lie on the surface seen along the axis.
for du, dv in [(0, 0), (0, 0.15), (0, -0.15), (0.15, 0), (-0.15, 0), (0, 0.3), (0, -0.3)]:
    center = (cu + du * extent[u], cv + dv * extent[v])
    try:
        discs = [(surface_circle(rays, (center[0] - 0.6 * radius, center[1]), radius), 0),
                 (surface_circle(rays, (center[0] + 0.6 * radius, center[1]), radius), 1)]
        break
    except RuntimeError:
        continue
else:
    sys.exit("error: found no place for the discs on %s" % args.mesh)
control = curves_source(discs, mesh)
one = BoolSurf(Surface=mesh, Curves=control, Operation="Union")

view = CreateView("RenderView")
view.ViewSize = [1024, 768]
view.OrientationAxesVisibility = 0
Show(mesh, view)
region = Show(one, view)  # port 0, every display property at its default
boundary = Show(OutputPort(one, 1), view)
print("region representation: %s, colored by %s" % (region.Representation,
                                                     region.ColorArrayName[1] or "solid color"))
position = [0.0, 0.0, 0.0]
position[axis] = 1.0
camera = view.GetActiveCamera()
camera.SetFocalPoint(0, 0, 0)
camera.SetPosition(*position)
camera.SetViewUp(*[1.0 if k == v else 0.0 for k in range(3)])
view.ResetCamera(False)
Render(view)
SaveScreenshot(args.png, view, ImageResolution=[1024, 768])
print("wrote %s" % args.png)

"""BoolSurf main example (the README's main job).

Draws two overlapping discs on a mesh shipped in Data/ (by casting rays onto it along its
thinnest axis), runs the whole pipeline (Trace Surface Curves -> Surface Arrangement ->
Label Arrangement Cells -> Surface Boolean), writes the selected region as a .vtp file and
renders it (orange, on the gray surface) to a .png.

    xvfb-run -a pvbatch Examples/demo.py --output out [--mesh Data/eight.ply]
                                         [--operation Union|Intersection|Difference|SymmetricDifference]

Writes <output>/<mesh>_boolean.vtp and <output>/<mesh>_boolean.png. The plugin is found
through $BOOLSURF_PLUGIN, else in build/ next to this script's folder.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from boolsurf_example_utils import (ROOT, SurfaceRays, area, curves_source,  # noqa: E402
                                    load_plugin, render_result, save_result, surface_circle)
from paraview.simple import *  # noqa: E402,F401,F403
from paraview import servermanager as sm  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--mesh", default=os.path.join(ROOT, "Data", "eight.ply"))
parser.add_argument("--output", default=os.path.join(ROOT, "out"))
parser.add_argument("--operation", default="Union",
                    choices=["Union", "Intersection", "Difference", "SymmetricDifference"])
args = parser.parse_args()
load_plugin(globals())
os.makedirs(args.output, exist_ok=True)

mesh = PLYReader(FileNames=[args.mesh])
check = CheckSurface(Input=mesh)
check.UpdatePipeline()
data = sm.Fetch(check)
if data.GetNumberOfCells() == 0:
    sys.exit("error: no triangles read from %s" % args.mesh)
genus = data.GetFieldData().GetArray("Genus")
print("mesh: %s (%d points, %d triangles, genus %s)" % (
    args.mesh, data.GetNumberOfPoints(), data.GetNumberOfCells(),
    [genus.GetValue(i) for i in range(genus.GetNumberOfTuples())] if genus else "?"))

# Draw along the thinnest axis of the bounding box, from its positive side.
b = data.GetBounds()
extent = [b[1] - b[0], b[3] - b[2], b[5] - b[4]]
axis = extent.index(min(extent))
rays = SurfaceRays(mesh, axis)
a_axis, b_axis = (axis + 1) % 3, (axis + 2) % 3
center = (0.5 * (b[2 * a_axis] + b[2 * a_axis + 1]), 0.5 * (b[2 * b_axis] + b[2 * b_axis + 1]))
size = min(extent[a_axis], extent[b_axis])
radius, shift = 0.12 * size, 0.07 * size
shift_along_b = extent[b_axis] <= extent[a_axis]  # shift the discs along the shorter side
offsets = [(0, -shift), (0, shift)] if shift_along_b else [(-shift, 0), (shift, 0)]
discs = [surface_circle(rays, (center[0] + da, center[1] + db), radius) for da, db in offsets]
control = curves_source([(discs[0], 0), (discs[1], 1)], mesh)

traced = TraceSurfaceCurves(Surface=mesh, Curves=control)
arrangement = SurfaceArrangement(Surface=mesh, Curves=traced)
labels = LabelArrangementCells(Input=arrangement)
result = SurfaceBoolean(Input=labels, Operation=args.operation, ShapeA=0, ShapeB=1)
result.UpdatePipeline()
fd = sm.Fetch(labels).GetFieldData()
print("arrangement: %d cells; S0 %s S1: %d triangles, area %.6f" % (
    fd.GetArray("NumberOfCells").GetValue(0), args.operation,
    sm.Fetch(result).GetNumberOfCells(), area(result)))

name = os.path.splitext(os.path.basename(args.mesh))[0]
save_result(result, os.path.join(args.output, name + "_boolean.vtp"))
up = [0, 0, 0]
up[a_axis if extent[a_axis] >= extent[b_axis] else b_axis] = 1
render_result(os.path.join(args.output, name + "_boolean.png"), mesh, result,
              boundary=OutputPort(result, 1), curves=traced, view_axis=axis, view_up=up)

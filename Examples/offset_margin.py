"""A margin along the surface: a region drawn on a scan grown by 2 mm, minus another shape.

Annotators ask for "the region within 2 mm of this lesion, outside that structure". The
Stanford bunny (Data/bunny_npm.ply, about 10 cm tall; its units are taken as centimetres)
gets a drawn region S0 and a second shape S1 that overlaps where the margin will be. Offset
Shapes grows S0 by 0.2 cm along the surface (the exact geodesic distance, not a distance in
space) into a new shape S2; BoolSurf then takes S2 - S1. The one-step BoolSurf does the same
with OffsetShape=0, OffsetDistance=0.2 and the expression S0 - S1.

    xvfb-run -a pvbatch Examples/offset_margin.py --output out [--margin 0.2]
writes out/offset_margin.vtp (the region) and out/offset_margin.png, and prints the areas.
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
parser.add_argument("--mesh", default=os.path.join(ROOT, "Data", "bunny_npm.ply"))
parser.add_argument("--output", default=os.path.join(ROOT, "out"))
parser.add_argument("--margin", type=float, default=0.2, help="in mesh units (cm here)")
args = parser.parse_args()
load_plugin(globals())
os.makedirs(args.output, exist_ok=True)

mesh = PLYReader(FileNames=[args.mesh])
rays = SurfaceRays(mesh, axis=2)  # drawn on the flank seen from +z
b = rays.bounds
size = min(b[1] - b[0], b[3] - b[2])
center = (0.5 * (b[0] + b[1]) + 0.05 * (b[1] - b[0]), b[2] + 0.35 * (b[3] - b[2]))
lesion = surface_circle(rays, center, 0.08 * size, n=16)
other = surface_circle(rays, (center[0] + 0.12 * size, center[1]), 0.07 * size, n=16)
control = curves_source([(lesion, 0), (other, 1)], mesh)

# S2: S0 grown by the margin; the input curves are kept, so S1 is still there.
margin = OffsetShapes(Surface=mesh, Curves=control, Distance=args.margin, Shapes="0",
                      OutputShapeId=2)
margin.UpdatePipeline()
stats = sm.Fetch(margin).GetFieldData().GetArray("OffsetStatistics")
result = BoolSurf(Surface=mesh, Curves=margin, Operation="Expression", Expression="S2 - S1")
result.UpdatePipeline()
shape = BoolSurf(Surface=mesh, Curves=control, Operation="Expression", Expression="S0")
grown = BoolSurf(Surface=mesh, Curves=margin, Operation="Expression", Expression="S2")
# The same in one filter: the offset of S0 takes S0's place.
one_step = BoolSurf(Surface=mesh, Curves=control, Operation="Expression", Expression="S0 - S1",
                    OffsetShape=0, OffsetDistance=args.margin)
print("S0: area %.4f cm^2; grown by %.2f cm: %.4f cm^2; minus S1: %.4f cm^2 "
      "(one-step: %.4f cm^2)" % (area(shape), args.margin, area(grown), area(result),
                                 area(one_step)))
print("offset: %d boundary points, %d windows, %d triangles crossed, %.1f ms" % (
    stats.GetComponent(0, 0), stats.GetComponent(0, 1), stats.GetComponent(0, 3),
    stats.GetComponent(0, 7)))

save_result(result, os.path.join(args.output, "offset_margin.vtp"))
traced = TraceSurfaceCurves(Surface=mesh, Curves=control)
render_result(os.path.join(args.output, "offset_margin.png"), mesh, result,
              boundary=OutputPort(result, 1), curves=traced, view_axis=2, view_up=(0, 1, 0))

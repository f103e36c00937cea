"""An SVG drawing on the bunny, combined with a hand-placed shape by a Boolean.

The drawing (by default the maple leaf of the BoolSurf authors' SVGs when ../shared is beside
the project, else Data/star.svg) is placed on the bunny's flank by Map SVG Onto Surface (the
discrete exponential map: straightest geodesics from the center), as cubic geodesic Bezier
curves. A disc drawn by hand overlaps it; BoolSurf takes the drawing minus the disc.

    xvfb-run -a pvbatch Examples/svg_on_bunny.py --output out
writes out/svg_on_bunny.vtp (the region) and out/svg_on_bunny.png.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from boolsurf_example_utils import (ROOT, SurfaceRays, area, curves_source,  # noqa: E402
                                    load_plugin, render_result, save_result, surface_circle)
from paraview.simple import *  # noqa: E402,F401,F403
from paraview import servermanager as sm  # noqa: E402

shared_svg = os.path.join(ROOT, "..", "shared", "data", "boolsurf-scenes", "svgs", "leaves", "maple_leaf.svg")
parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--mesh", default=os.path.join(ROOT, "Data", "bunny_npm.ply"))
parser.add_argument("--svg", default=shared_svg if os.path.exists(shared_svg)
                    else os.path.join(ROOT, "Data", "star.svg"))
parser.add_argument("--output", default=os.path.join(ROOT, "out"))
args = parser.parse_args()
load_plugin(globals())
os.makedirs(args.output, exist_ok=True)

mesh = PLYReader(FileNames=[args.mesh])
rays = SurfaceRays(mesh, axis=2)  # in-plane coordinates (x, y), seen from +z
b = rays.bounds
size = min(b[1] - b[0], b[3] - b[2])
center = (0.5 * (b[0] + b[1]) + 0.05 * (b[1] - b[0]), b[2] + 0.35 * (b[3] - b[2]))

# The drawing, 0.25 of the bunny's size across, on the flank facing +z; its shapes are 0, 1, ...
drawing = MapSVGOntoSurface(Input=mesh, FileName=args.svg, Center=rays.hit(*center),
                            Radius=0.18 * size, Rotation=0)
drawing.UpdatePipeline()
shapes = sorted({int(v) for v in sm.Fetch(drawing).GetCellData().GetArray("ShapeId")
                 .GetValueRange()})
# A disc drawn by hand (projected control points of a geodesic polygon), shape 100.
disc = curves_source([(surface_circle(rays, (center[0] + 0.12 * size, center[1]),
                                      0.09 * size, n=24), 100)], mesh)
traced_drawing = TraceSurfaceCurves(Surface=mesh, Curves=drawing)
both = AppendDatasets(Input=[drawing, disc])
both = ExtractSurface(Input=both)

drawing_shapes = " | ".join("S%d" % s for s in range(shapes[0], shapes[-1] + 1))
result = BoolSurf(Surface=mesh, Curves=both, Operation="Expression",
                  Expression="(%s) - S100" % drawing_shapes, FillRule="EvenOdd")
result.UpdatePipeline()
region = sm.Fetch(result)
print("drawing %s: shapes %s; (drawing) - disc: %d triangles, area %.5f of %.5f" % (
    os.path.basename(args.svg), shapes, region.GetNumberOfCells(), area(result), area(mesh)))
save_result(result, os.path.join(args.output, "svg_on_bunny.vtp"))
render_result(os.path.join(args.output, "svg_on_bunny.png"), mesh, result,
              boundary=OutputPort(result, 1), curves=traced_drawing, view_axis=2,
              view_up=(0, 1, 0))

"""Variadic symmetric difference (xor) of many shapes on the Stanford bunny (Data/bunny_npm.ply).

Six overlapping discs are drawn on the bunny's flank (rays cast along -z, so each circle is
counter-clockwise seen from outside and encloses its disc). The result is the region covered
by an odd number of discs: S0 ^ S1 ^ ... ^ S5, computed in one pass over the arrangement
cells (Operation SymmetricDifference with ShapeA = ShapeB = -1: all shapes).

    xvfb-run -a pvbatch Examples/variadic_xor.py --output out
writes out/bunny_xor.vtp (inline binary) and out/bunny_xor.png.
"""
import argparse
import math
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
parser.add_argument("--shapes", type=int, default=6)
args = parser.parse_args()
load_plugin(globals())
os.makedirs(args.output, exist_ok=True)

mesh = PLYReader(FileNames=[args.mesh])
rays = SurfaceRays(mesh, axis=2)  # in-plane coordinates (x, y)
b = rays.bounds
center = (0.5 * (b[0] + b[1]) + 0.05 * (b[1] - b[0]), b[2] + 0.35 * (b[3] - b[2]))
size = min(b[1] - b[0], b[3] - b[2])
curves = []
for k in range(args.shapes):
    angle = 2 * math.pi * k / args.shapes
    c = (center[0] + 0.08 * size * math.cos(angle), center[1] + 0.08 * size * math.sin(angle))
    curves.append((surface_circle(rays, c, 0.11 * size, n=32), k))
control = curves_source(curves, mesh)

# The one-step filter: trace, arrange, label and select in one go.
xor = BoolSurf(Surface=mesh, Curves=control, Operation="SymmetricDifference", ShapeA=-1,
               ShapeB=-1, FillRule="NonZero")
xor.UpdatePipeline()
region = sm.Fetch(xor)
labels = region.GetFieldData().GetArray("CellLabels")  # one row per arrangement cell
print("%d shapes, xor region: %d triangles, area %.4f of %.4f; %d cells x %d shapes" % (
    args.shapes, region.GetNumberOfCells(), area(xor), area(mesh),
    labels.GetNumberOfTuples() if labels else 0, labels.GetNumberOfComponents() if labels else 0))

save_result(xor, os.path.join(args.output, "bunny_xor.vtp"))
traced = TraceSurfaceCurves(Surface=mesh, Curves=control)
render_result(os.path.join(args.output, "bunny_xor.png"), mesh, xor,
              boundary=OutputPort(xor, 1), curves=None, view_axis=2, view_up=(0, 1, 0))

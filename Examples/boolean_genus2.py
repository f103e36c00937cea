"""Boolean operations between three shapes on a genus-2 surface (Data/eight.ply).

Shapes (drawn by casting rays onto the front face, the side whose normals point to +y):
  S0, S1: two overlapping discs on the waist between the two holes;
  S2:     a band around the left arm of the upper ring, bounded by two loops that go around
          the tube in opposite directions (each loop alone is not null-homologous: it would
          make an inconsistent shape; together they bound the band).
The result is (S0 ^ S1) | S2 by default (any expression or operation on the command line).

    xvfb-run -a pvbatch Examples/boolean_genus2.py --output out
writes out/genus2_boolean.vtp (the selected region, inline binary) and out/genus2_boolean.png.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from boolsurf_example_utils import (ROOT, SurfaceRays, area, curves_source, first_hit,  # noqa: E402
                                    load_plugin, render_result, save_result, surface_circle)
from paraview.simple import *  # noqa: E402,F401,F403
from paraview import servermanager as sm  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--mesh", default=os.path.join(ROOT, "Data", "eight.ply"))
parser.add_argument("--output", default=os.path.join(ROOT, "out"))
parser.add_argument("--expression", default="(S0 ^ S1) | S2")
args = parser.parse_args()
load_plugin(globals())
os.makedirs(args.output, exist_ok=True)

mesh = PLYReader(FileNames=[args.mesh])
front = SurfaceRays(mesh, axis=1)  # rays along -y; in-plane coordinates (z, x)


def tube_loop(z, reverse):
    """A loop around the tube of the upper ring's left arm (x in [-0.23, -0.12]) at height z,
    through four surface points: front, outer side, back, inner side (seen from the hole)."""
    far = front.far
    points = [
        first_hit(front, (-0.175, far, z), (-0.175, -far, z)),  # front
        first_hit(front, (-far, 0, z), (far, 0, z)),  # outer side
        first_hit(front, (-0.175, -far, z), (-0.175, far, z)),  # back
        first_hit(front, (0, 0, z), (-far, 0, z)),  # inner side, from inside the hole
    ]
    return points[::-1] if reverse else points


curves = [
    (surface_circle(front, (0.0, -0.035), 0.06), 0),
    (surface_circle(front, (0.0, 0.035), 0.06), 1),
    (tube_loop(0.22, False), 2),
    (tube_loop(0.30, True), 2),
]
control = curves_source(curves, mesh)
traced = TraceSurfaceCurves(Surface=mesh, Curves=control)
arrangement = SurfaceArrangement(Surface=mesh, Curves=traced)
labels = LabelArrangementCells(Input=arrangement)
labels.UpdatePipeline()
fd = sm.Fetch(labels).GetFieldData()
consistent = fd.GetArray("ShapeConsistent")
print("arrangement cells: %d, shapes consistent: %s" % (
    fd.GetArray("NumberOfCells").GetValue(0),
    [consistent.GetValue(i) for i in range(consistent.GetNumberOfTuples())]))

result = SurfaceBoolean(Input=labels, Operation="Expression", Expression=args.expression)
for op in ("Union", "Intersection", "Difference", "SymmetricDifference"):
    check = SurfaceBoolean(Input=labels, Operation=op, ShapeA=0, ShapeB=1)
    check.UpdatePipeline()
    print("S0 %s S1: area %.5f" % (op, area(check)))
    Delete(check)
result.UpdatePipeline()
print("%s: area %.5f of %.5f" % (args.expression, area(result), area(mesh)))

save_result(result, os.path.join(args.output, "genus2_boolean.vtp"))
render_result(os.path.join(args.output, "genus2_boolean.png"), mesh, result,
              boundary=OutputPort(result, 1), curves=traced, view_axis=1, view_up=(0, 0, 1))

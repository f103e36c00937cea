"""pvpython: Offset Shapes by its ParaView name on a torus.

A meridian does not bound a region (it winds around the tube): in Region mode Offset Shapes
refuses it with the labeling's reason, in Bands mode it becomes a band, an annulus of two
loops whose area is about 2 d times the meridian's length; a disc grown and shrunk by the same
distance gets back its area; the one-step BoolSurf's OffsetShape step gives the chain's answer.
"""
import math
import os
import sys

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager as sm

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import torus_mesh  # noqa: E402
from proxy_area import area  # noqa: E402

LoadPlugin(os.environ["BOOLSURF_PLUGIN"], remote=False, ns=globals())

R, r = 1.0, 0.4
NU, NV = 96, 48


def torus_polydata():
    return torus_mesh.torus_polydata(R, r, NU, NV)


torus = PVTrivialProducer()
torus.GetClientSideObject().SetOutput(torus_polydata())
# The meridian at u = 0 through mesh vertices (a geodesic of the torus).
meridian = []
for k in range(NV):
    v = 2 * math.pi * k / NV
    meridian += [R + r * math.cos(v), 0.0, r * math.sin(v)]
curves = PolyLineSource(Points=meridian, Closed=1)  # shape 0

offset = OffsetShapes(Surface=torus, Curves=curves, Distance=0.1)
assert offset.Mode == "Region" and offset.EndStyle == "Round" and offset.OutputShapeId == -1
offset.UpdatePipeline()
assert sm.Fetch(offset).GetNumberOfCells() == 0  # refused: the meridian bounds no region

offset.Mode = "Bands"
offset.KeepInputCurves = 0
offset.UpdatePipeline()
out = sm.Fetch(offset)
assert out.GetNumberOfCells() == 2, out.GetNumberOfCells()  # the annulus' two boundaries
assert out.GetFieldData().GetArray("OffsetShapeId").GetValue(0) == 1
band = BoolSurf(Surface=torus, Curves=offset, Operation="Union", ShapeA=1, ShapeB=1)
expected = 2 * 0.1 * 2 * math.pi * r
assert abs(area(band) - expected) < 0.03 * expected, (area(band), expected)
print("band around the meridian: area %.4f (2 d L = %.4f)" % (area(band), expected))

# A disc on the outer equator: grown then shrunk by the same distance it keeps its area.
disc = []
for k in range(16):
    t = 2 * math.pi * k / 16
    a, b = 0.25 * math.cos(t), 0.25 * math.sin(t) / r  # angles around z and around the tube
    disc += [(R + r * math.cos(b)) * math.cos(a), (R + r * math.cos(b)) * math.sin(a),
             r * math.sin(b)]
disc_source = PolyLineSource(Points=disc, Closed=1)
grown = OffsetShapes(Surface=torus, Curves=disc_source, Distance=0.05, KeepInputCurves=0,
                     OutputShapeId=0)
shrunk = OffsetShapes(Surface=torus, Curves=grown, Distance=-0.05, KeepInputCurves=0,
                      OutputShapeId=0)
original = BoolSurf(Surface=torus, Curves=disc_source, Operation="Union", ShapeA=0, ShapeB=0)
closing = BoolSurf(Surface=torus, Curves=shrunk, Operation="Union", ShapeA=0, ShapeB=0)
bigger = BoolSurf(Surface=torus, Curves=grown, Operation="Union", ShapeA=0, ShapeB=0)
assert area(bigger) > area(original) * 1.2, (area(bigger), area(original))
assert abs(area(closing) - area(original)) < 0.01 * area(original), (area(closing),
                                                                      area(original))
one_step = BoolSurf(Surface=torus, Curves=disc_source, Operation="Union", ShapeA=0, ShapeB=0,
                    OffsetShape=0, OffsetDistance=0.05)
assert abs(area(one_step) - area(bigger)) < 1e-12, (area(one_step), area(bigger))
print("disc %.4f, grown %.4f, closing %.4f" % (area(original), area(bigger), area(closing)))
print("OFFSET_OK")

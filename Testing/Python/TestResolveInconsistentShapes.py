"""pvpython: homology and Resolve Inconsistent Shapes by their ParaView names on a torus.

A single meridian is inconsistent (it winds once around the tube): Label Arrangement Cells
reports its generators in excess and draws the two generators; Resolve Inconsistent Shapes
with each strategy makes it consistent; the one-step BoolSurf resolves it when asked.
"""
import math
import os
import sys

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager as sm

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import torus_mesh  # noqa: E402

LoadPlugin(os.environ["BOOLSURF_PLUGIN"], remote=False, ns=globals())

R, r = 1.0, 0.5
NU, NV = 48, 24


def torus_polydata():
    return torus_mesh.torus_polydata(R, r, NU, NV)


torus = PVTrivialProducer()
torus.GetClientSideObject().SetOutput(torus_polydata())

u = 0.3
meridian = []
for k in range(12):
    v = 0.1 + 2 * math.pi * k / 12
    meridian += [(R + r * math.cos(v)) * math.cos(u), (R + r * math.cos(v)) * math.sin(u),
                 r * math.sin(v)]
curves = PolyLineSource(Points=meridian, Closed=1)  # shape 0


def labeled(curve_source):
    traced = TraceSurfaceCurves(Surface=torus, Curves=curve_source)
    arrangement = SurfaceArrangement(Surface=torus, Curves=traced)
    labels = LabelArrangementCells(Input=arrangement)
    labels.UpdatePipeline()
    return labels


labels = labeled(curves)
fd = sm.Fetch(labels).GetFieldData()
assert fd.GetArray("NumberOfHomologyGenerators").GetValue(0) == 2
assert fd.GetArray("ShapeConsistent").GetValue(0) == 0
excess = fd.GetArray("HomologyExcess")
assert excess.GetNumberOfComponents() == 2
assert any(excess.GetComponent(0, g) != 0 for g in range(2))
generators = sm.Fetch(labels, idx=1)
shortened = generators.GetCellData().GetArray("Shortened")
flags = [shortened.GetValue(c) for c in range(generators.GetNumberOfCells())]
assert flags.count(0) == 2, flags  # the two generators, then their shortened loops
assert flags.count(1) <= 2, flags
assert generators.GetCellData().GetArray("GeneratorId") is not None

for strategy in ("AddGenerators", "DuplicateReversed", "RemoveCurves"):
    resolved = ResolveInconsistentShapes(Surface=torus, Curves=curves, Strategy=strategy)
    resolved.UpdatePipeline()
    out = sm.Fetch(resolved)
    if strategy == "RemoveCurves":
        assert out.GetNumberOfCells() == 0  # the only curve winds: removed
        assert out.GetFieldData().GetArray("RemovedCurves").GetValue(0) == 0
        continue
    assert out.GetNumberOfCells() == 2, (strategy, out.GetNumberOfCells())
    assert out.GetCellData().GetArray("Resolution").GetValue(1) in (1, 2)
    fixed = sm.Fetch(labeled(resolved)).GetFieldData()
    assert fixed.GetArray("ShapeConsistent").GetValue(0) == 1, strategy
    print("%s: consistent" % strategy)

one = BoolSurf(Surface=torus, Curves=curves, Operation="Union", ShapeA=0, ShapeB=0,
               ResolveStrategy="DuplicateReversed")
one.UpdatePipeline()
region = sm.Fetch(one)
assert region.GetNumberOfCells() > 0
notes = region.GetFieldData().GetAbstractArray("ResolutionNotes")
assert notes is not None and "DuplicateReversed" in notes.GetValue(0), notes
print("RESOLVE_OK")

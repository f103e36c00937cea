"""pvpython: a Boolean region carries the same arrays from a labeled file as from the chain.

Label Arrangement Cells writes per-triangle label arrays on request (ColorShape: `ShapeLabel`,
PerTriangleLabels: `Labels`). They are the labeling's output, not the surface's own arrays, so
a region never carries them (Docs/Filters/SurfaceBoolean.md): its labels are field data
CellLabels, row ArrangementCell. The handed-over chain writes the region from the Core result;
a labeled output saved as .vtp and read back has the arrays in its cell data, and the region
computed from that file must still be the chain's region, array for array, bit for bit.
"""
import os
import random
import sys
import tempfile

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager as sm
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from stage_chain_helpers import producer, random_curves, same_data, triangles  # noqa: E402

LoadPlugin(os.environ["BOOLSURF_PLUGIN"], remote=False, ns=globals())
rng = random.Random(58)

sphere = vtkSphereSource()
sphere.SetThetaResolution(24)
sphere.SetPhiResolution(16)
plane = vtkPlaneSource()
plane.SetResolution(10, 10)
folder = tempfile.mkdtemp()
checked = 0
for name, surface_pd in (("sphere", triangles(sphere)), ("plane", triangles(plane))):
    surface = producer(surface_pd)
    for trial in range(3):
        curves = producer(random_curves(surface_pd, rng))
        traced = TraceSurfaceCurves(Surface=surface, Curves=curves)
        arrangement = SurfaceArrangement(Surface=surface, Curves=traced)
        labels = LabelArrangementCells(Input=arrangement, ColorShape=0, PerTriangleLabels=1)
        labels.UpdatePipeline()
        labeled = sm.Fetch(labels)
        for array in ("ShapeLabel", "Labels"):
            assert labeled.GetCellData().GetArray(array) is not None, (name, trial, array)
        chain = SurfaceBoolean(Input=labels, Operation="Union", ShapeA=-1, ShapeB=-1)
        chain.UpdatePipeline()
        region = sm.Fetch(chain)
        if region.GetFieldData().GetAbstractArray("Expression") is None:
            continue  # refused (an inconsistent shape): the one-step test covers refusals
        path = os.path.join(folder, "%s-%d-labeled.vtp" % (name, trial))
        SaveData(path, proxy=OutputPort(labels, 0))
        reader = XMLPolyDataReader(FileName=[path])
        again = SurfaceBoolean(Input=reader, Operation="Union", ShapeA=-1, ShapeB=-1)
        again.UpdatePipeline()
        from_file = sm.Fetch(again)
        what = "%s, trial %d" % (name, trial)
        for array in ("ShapeLabel", "Labels"):
            assert region.GetCellData().GetArray(array) is None, (what, "chain", array)
            assert from_file.GetCellData().GetArray(array) is None, (what, "file", array)
        same_data(region, from_file, what)
        checked += 1
print("regions from %d labeled files with label arrays == the chain's regions" % checked)
assert checked >= 3, checked

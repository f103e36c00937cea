"""pvpython: stages below Surface Arrangement read from .vtp files give the handed-over answer.

Surface Arrangement's refined surface and Label Arrangement Cells' output are saved as .vtp
and read back (no Core result travels with a file): Label Arrangement Cells and Surface Boolean
on them compute the arrangement again from the field data Surface Arrangement writes for it,
and give the outputs of the chain that handed its results over, bit for bit, on every port.

A labeled output with the per-triangle label arrays (ColorShape: `ShapeLabel`,
PerTriangleLabels: `Labels`) has them in its file's cell data, while the chain hands over a
Core result without them: the region from that file is still the chain's region, array for
array. Neither carries the arrays: a region's labels are field data CellLabels, row
ArrangementCell (Docs/Filters/SurfaceBoolean.md).
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
checked_label_arrays = 0
for name, surface_pd in (("sphere", triangles(sphere)), ("plane", triangles(plane))):
    surface = producer(surface_pd)
    for trial in range(3):
        curves = producer(random_curves(surface_pd, rng))
        traced = TraceSurfaceCurves(Surface=surface, Curves=curves)
        arrangement = SurfaceArrangement(Surface=surface, Curves=traced)
        labels = LabelArrangementCells(Input=arrangement)
        boolean = SurfaceBoolean(Input=labels, Operation="Union", ShapeA=-1, ShapeB=-1)
        boolean.UpdatePipeline()
        if sm.Fetch(boolean).GetFieldData().GetAbstractArray("Expression") is None:
            continue  # refused (an inconsistent shape): the one-step test covers refusals
        for which, proxy in (("refined", arrangement), ("labeled", labels)):
            path = os.path.join(folder, "%s-%d-%s.vtp" % (name, trial, which))
            SaveData(path, proxy=OutputPort(proxy, 0))
            reader = XMLPolyDataReader(FileName=[path])
            read = LabelArrangementCells(Input=reader) if which == "refined" else reader
            again = SurfaceBoolean(Input=read, Operation="Union", ShapeA=-1, ShapeB=-1)
            again.UpdatePipeline()
            for port in range(4):
                same_data(sm.Fetch(boolean, idx=port), sm.Fetch(again, idx=port),
                          "%s, trial %d, %s file, port %d" % (name, trial, which, port))
            checked += 1
        # The labeled file with per-triangle label arrays against its own chain.
        arrays = LabelArrangementCells(Input=arrangement, ColorShape=0, PerTriangleLabels=1)
        chain = SurfaceBoolean(Input=arrays, Operation="Union", ShapeA=-1, ShapeB=-1)
        chain.UpdatePipeline()
        labeled = sm.Fetch(arrays)
        path = os.path.join(folder, "%s-%d-label-arrays.vtp" % (name, trial))
        SaveData(path, proxy=OutputPort(arrays, 0))
        again = SurfaceBoolean(Input=XMLPolyDataReader(FileName=[path]), Operation="Union",
                               ShapeA=-1, ShapeB=-1)
        again.UpdatePipeline()
        what = "%s, trial %d, labeled file with label arrays" % (name, trial)
        for array in ("ShapeLabel", "Labels"):
            assert labeled.GetCellData().GetArray(array) is not None, (what, array)
            for region in (sm.Fetch(chain), sm.Fetch(again)):
                assert region.GetCellData().GetArray(array) is None, (what, array)
        same_data(sm.Fetch(chain), sm.Fetch(again), what)
        checked_label_arrays += 1
print("stages on %d files == the handed-over chain" % checked)
print("regions from %d labeled files with label arrays == the chain's" % checked_label_arrays)
assert checked >= 4, checked
assert checked_label_arrays >= 3, checked_label_arrays

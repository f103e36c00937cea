"""pvbatch under Xvfb: the README's main job (Examples/demo.py) runs the whole pipeline on
Data/eight.ply and writes the Boolean's region as .vtp and a .png rendering."""
import os
import sys
import shutil
import subprocess

from paraview.simple import *  # noqa: F401,F403
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scratch  # noqa: E402

source_dir = os.environ["BOOLSURF_SOURCE_DIR"]
out = scratch.folder("boolsurf-demo-")
demo = os.path.join(source_dir, "Examples", "demo.py")
# A separate pvbatch process, as Scripts/run-demo.sh runs it (same DISPLAY and environment).
subprocess.check_call([shutil.which("pvbatch") or "pvbatch", demo, "--output", out])

vtp = os.path.join(out, "eight_boolean.vtp")
png = os.path.join(out, "eight_boolean.png")
assert os.path.getsize(vtp) > 1000, vtp
assert os.path.getsize(png) > 10000, png
reader = XMLPolyDataReader(FileName=[vtp])
reader.UpdatePipeline()
info = reader.GetDataInformation()
assert info.GetNumberOfCells() > 20, info.GetNumberOfCells()
assert reader.CellData["ArrangementCell"] is not None
# Labels belong to cells: the region carries the cells x shapes table, no per-triangle labels.
assert reader.FieldData["CellLabels"] is not None
assert reader.CellData["Labels"] is None
# The union of two discs of radius 0.12 * 0.49 on the front face: a small part of the surface.
from paraview import servermanager as sm  # noqa: E402
from vtkmodules.vtkFiltersVerdict import vtkCellSizeFilter  # noqa: E402
sizes = vtkCellSizeFilter()
sizes.SetInputData(sm.Fetch(reader))
sizes.Update()
a = sizes.GetOutput().GetCellData().GetArray("Area")
total = sum(a.GetValue(i) for i in range(a.GetNumberOfTuples()))
assert 0.005 < total < 0.05, total
print("DEMO_OK area %.5f" % total)

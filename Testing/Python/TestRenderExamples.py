"""pvbatch under Xvfb: the examples a new user runs first (Examples/boolean_genus2.py,
Examples/variadic_xor.py, Examples/bsc_flower.py, Examples/svg_on_bunny.py and
Examples/offset_margin.py) write a
readable .vtp region and a non-trivial .png."""
import os
import shutil
import sys
import subprocess

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager as sm
from vtkmodules.vtkIOImage import vtkPNGReader
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scratch  # noqa: E402

source_dir = os.environ["BOOLSURF_SOURCE_DIR"]
out = scratch.folder("boolsurf-examples-")
pvbatch = shutil.which("pvbatch") or "pvbatch"
expected = {
    "boolean_genus2.py": ("genus2_boolean", 0.03, 0.08),  # (S0 ^ S1) | band: 0.0516
    "variadic_xor.py": ("bunny_xor", 3.0, 10.0),  # odd coverage of six discs: 6.23
    "bsc_flower.py": ("bsc_flower", 8.3, 9.5),  # BSC: half the torus (7.89) + 3 petals: 8.88
    # Data/star.svg (a star with a hole) mapped on the bunny, minus a disc: 1.152
    "svg_on_bunny.py": ("svg_on_bunny", 0.9, 1.4),
    # S0 (2.02 cm^2) grown by 0.2 cm along the surface (3.09), minus S1: 2.72
    "offset_margin.py": ("offset_margin", 2.5, 2.95),
}
extra = {"svg_on_bunny.py": ["--svg", os.path.join(source_dir, "Data", "star.svg")]}
for script, (name, low, high) in expected.items():
    subprocess.check_call([pvbatch, os.path.join(source_dir, "Examples", script), "--output", out]
                          + extra.get(script, []))
    vtp, png = os.path.join(out, name + ".vtp"), os.path.join(out, name + ".png")
    reader = XMLPolyDataReader(FileName=[vtp])
    reader.UpdatePipeline()
    region = sm.Fetch(reader)
    assert region.GetNumberOfCells() > 50, (script, region.GetNumberOfCells())
    assert region.GetFieldData().GetArray("CellLabels") is not None
    from vtkmodules.vtkFiltersVerdict import vtkCellSizeFilter
    sizes = vtkCellSizeFilter()
    sizes.SetInputData(region)
    sizes.Update()
    a = sizes.GetOutput().GetCellData().GetArray("Area")
    total = sum(a.GetValue(i) for i in range(a.GetNumberOfTuples()))
    assert low < total < high, (script, total)
    image = vtkPNGReader()
    image.SetFileName(png)
    image.Update()
    dims = image.GetOutput().GetDimensions()
    assert dims[0] == 1024 and dims[1] == 768, dims
    scalars = image.GetOutput().GetPointData().GetScalars()
    # Non-trivial: more than a blank background (orange region and gray surface present).
    colors = set(scalars.GetTuple(i)[:3] for i in range(0, scalars.GetNumberOfTuples(), 97))
    assert len(colors) > 20, (png, len(colors))
    print("%s: %d triangles, area %.4f, %s" % (script, region.GetNumberOfCells(), total, png))
print("EXAMPLES_OK")

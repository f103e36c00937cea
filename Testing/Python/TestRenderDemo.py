"""pvbatch under Xvfb: the README's main job (Examples/demo.py) writes its .vtp and .png."""
import os
import sys
import tempfile

from paraview.simple import *  # noqa: F401,F403

source_dir = os.environ["BOOLSURF_SOURCE_DIR"]
out = tempfile.mkdtemp(prefix="boolsurf-demo-")
demo = os.path.join(source_dir, "Examples", "demo.py")
sys.argv = [demo, "--output", out]
exec(compile(open(demo).read(), demo, "exec"), {"__file__": demo, "__name__": "__main__"})

vtp = os.path.join(out, "eight_check.vtp")
png = os.path.join(out, "eight_check.png")
assert os.path.getsize(vtp) > 1000, vtp
assert os.path.getsize(png) > 10000, png
reader = XMLPolyDataReader(FileName=[vtp])
reader.UpdatePipeline()
info = reader.GetDataInformation()
assert info.GetNumberOfCells() == 634, info.GetNumberOfCells()
print("DEMO_OK")

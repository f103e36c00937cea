"""pvbatch under Xvfb: a rendering of a Boolean result (the union of two discs on the genus-2
Data/eight.ply, as Examples/demo.py draws them) compared with the checked-in baseline
Testing/Data/Baseline/eight_union.png by VTK's image comparison (vtkTesting).

Regenerate the baseline (after checking the new picture!) with BOOLSURF_UPDATE_BASELINE=1.
"""
import os
import shutil
import subprocess
import sys

from vtkmodules.vtkTestingRendering import vtkTesting
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scratch  # noqa: E402

source_dir = os.environ["BOOLSURF_SOURCE_DIR"]
baseline = os.path.join(source_dir, "Testing", "Data", "Baseline", "eight_union.png")
out = scratch.folder("boolsurf-baseline-")
pvbatch = shutil.which("pvbatch") or "pvbatch"
subprocess.check_call([pvbatch, os.path.join(source_dir, "Examples", "demo.py"), "--output", out,
                       "--operation", "Union"])
image = os.path.join(out, "eight_boolean.png")
if os.environ.get("BOOLSURF_UPDATE_BASELINE"):
    shutil.copyfile(image, baseline)
    print("baseline updated: %s" % baseline)
    sys.exit(0)

testing = vtkTesting()
testing.AddArgument("-T")
testing.AddArgument(out)
testing.AddArgument("-V")
testing.AddArgument(baseline)
# vtkTesting's own metric (summed per-pixel error after its smoothing); 15 is VTK's default.
result = testing.RegressionTest(image, 15.0)
print("image comparison of %s against %s: %s (error %g)" % (
    image, baseline, "passed" if result == vtkTesting.PASSED else "FAILED",
    testing.GetImageDifference()))
assert result == vtkTesting.PASSED, "see the difference image in %s" % out
print("BASELINE_OK")

"""GUI test of the curve editor, driven by ParaView's test player with synthetic mouse events.

    python3 GuiCurveEditor.py <run-with-xvfb.sh> <paraview>

Runs `paraview --script=GuiCurveEditorSetup.py --test-script=GuiCurveEditor.xml` under Xvfb:
the setup builds a flat triangulated square, an empty Surface Curves source (its panel, the
curve editor, active) and BoolSurf of shape 0; the recorded events click four points on the
square in the render view, click the first point again (closing the curve), drag the third
point, then undo and redo the drag (Edit menu). The player compares the final view with Testing/Data/Baseline/curve_editor.png
(BOOLSURF_UPDATE_BASELINE=1 rewrites it: look at the new picture first). Then the drawing and
BoolSurf's last result, recorded by the setup, must be: one closed polygon of four points of
shape 0, each stored exactly (a triangle and barycentric weights), on the square, the third
moved by the drag, and a region whose area is the polygon's (shoelace formula: on a flat mesh
geodesics are straight lines) to 1e-9.
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

runner, paraview = sys.argv[1], sys.argv[2]
here = os.path.dirname(os.path.abspath(__file__))
source_dir = os.environ.get("BOOLSURF_SOURCE_DIR", os.path.join(here, "..", ".."))
baseline = os.path.join(source_dir, "Testing", "Data", "Baseline", "curve_editor.png")
update = os.environ.get("BOOLSURF_UPDATE_BASELINE") == "1"
out = tempfile.mkdtemp(prefix="boolsurf-editor-")
result_path = os.path.join(out, "result.json")
env = dict(os.environ, BOOLSURF_GUI_RESULT=result_path, BOOLSURF_SOURCE_DIR=source_dir)
test_baseline = os.path.join(out, "curve_editor.png") if update else baseline
command = [runner, paraview, "--dr", "--script=" + os.path.join(here, "GuiCurveEditorSetup.py"),
           "--test-script=" + os.path.join(here, "GuiCurveEditor.xml"),
           "--test-directory=" + out, "--test-baseline=" + test_baseline, "--exit"]
run = subprocess.run(command, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                     timeout=600, universal_newlines=True)
failures = []
if update:
    shutil.copyfile(test_baseline, baseline)
    print("baseline written: %s" % baseline)
elif run.returncode != 0:
    failures.append("the test player failed (events or image comparison), exit %d; images in %s"
                    % (run.returncode, out))
if not os.path.exists(result_path):
    print(run.stdout[-4000:])
    sys.exit("BoolSurf never produced a result in the GUI: " + result_path)
with open(result_path) as f:
    history = json.load(f)
result = history[-1]
print(json.dumps(result))


def expect(condition, what):
    if not condition:
        failures.append(what)


expect(result["CurveSizes"] == [4], "one curve of four points: %s" % result["CurveSizes"])
expect(result["ClosedCurves"] == [1], "the curve is closed: %s" % result["ClosedCurves"])
expect(result["ShapeIds"] == [0] and result["CurveTypes"] == [0],
       "a polygon of shape 0: %s %s" % (result["ShapeIds"], result["CurveTypes"]))
points = [result["Points"][3 * i:3 * i + 3] for i in range(len(result["Points"]) // 3)]
triangles, weights = result["TriangleIds"], result["Barycentrics"]
expect(len(triangles) == len(points) and all(t >= 0 for t in triangles),
       "every point stored exactly (a triangle each): %s" % triangles)
for i in range(len(weights) // 2):
    u, v = weights[2 * i], weights[2 * i + 1]
    expect(u >= 0 and v >= 0 and u + v <= 1 + 1e-12, "point %d inside its triangle" % i)
for i, p in enumerate(points):
    expect(p[2] == 0 and abs(p[0]) < 0.5 and abs(p[1]) < 0.5, "point %d on the square: %s"
           % (i, p))
if len(points) == 4:
    # Clicked at symmetric places (a rectangle), then the third point dragged right and up.
    expect(points[2][0] > points[1][0] + 0.03 and points[2][1] > points[3][1] + 0.02,
           "the dragged point moved: %s" % points)
    shoelace = 0.5 * abs(sum(points[i][0] * points[(i + 1) % 4][1]
                             - points[(i + 1) % 4][0] * points[i][1] for i in range(4)))
    expect(abs(result["region_area"] - shoelace) <= 1e-9 * shoelace,
           "region area %.15g equals the polygon's %.15g" % (result["region_area"], shoelace))
# Undo (Edit > Undo) put the dragged point back, redo moved it again: the areas BoolSurf
# produced end with moved, not moved, moved.
areas = []
for h in history:
    if h["region_triangles"] and (not areas or h["region_area"] != areas[-1]):
        areas.append(h["region_area"])
expect(len(areas) >= 3 and areas[-1] == areas[-3] and areas[-2] != areas[-1],
       "undo and redo of the drag: areas %s" % areas)
if failures:
    print(run.stdout[-4000:])
    sys.exit("FAILED:\n  " + "\n  ".join(failures))
print("curve editor OK: area %.12g; areas over the session %s" % (result["region_area"], areas))

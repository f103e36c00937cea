"""pvpython: File > Save Data of a curve output picks BoolSurfSceneWriter for .json; the saved
scene opens again with the same surface points, curves, shapes and operations, and gives the
same one-step Boolean region, also after Subdivide Surface With Curves. Bad input (curves without surface points) writes nothing."""
import json
import os
import sys

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager as sm
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scratch  # noqa: E402

LoadPlugin(os.environ["BOOLSURF_PLUGIN"], remote=False, ns=globals())
source_dir = os.environ["BOOLSURF_SOURCE_DIR"]
folder = scratch.folder("boolsurf-scene-writer-")
scene = {
    "model": "./data/models/eight.ply",
    # Two overlapping triangles inside triangle 10 (null-homologous on the genus-2 eight), uv
    # values that are not short decimals so that their round trip is tested.
    "points": [{"face": 10, "uv": uv} for uv in
               ([0.1, 0.1], [0.8, 0.1], [0.1, 0.8], [0.3, 1 / 3.0], [0.7, 0.2 / 7.0],
                [0.6, 0.3], [0.2, 0.61])],
    "polygons": [[], [0, 1, 2], [], [2, 3, 4, 5, 6]],
    "shapes": [[0], [1], [3]],
    "operations": [{"a": 1, "b": 2, "type": 0}],
}
path = os.path.join(folder, "scene.json")
json.dump(scene, open(path, "w"))
reader = BoolSurfSceneReader(FileName=path, MeshSearchPath=os.path.join(source_dir, "Data"))
reader.UpdatePipeline()

# Save Data chooses the writer by extension, as the GUI's File > Save Data does.
saved = os.path.join(folder, "saved.json")
SaveData(saved, proxy=OutputPort(reader, 1))
written = json.load(open(saved))
# The reader gives each curve points of its own: scene point 2, in both polygons, is saved twice.
assert written["polygons"] == [[], [0, 1, 2], [], [3, 4, 5, 6, 7]], written["polygons"]
assert written["shapes"] == [[], [1], [3]], written["shapes"]
assert written["operations"] == scene["operations"], written["operations"]
as_read = [scene["points"][i] for i in (0, 1, 2, 2, 3, 4, 5, 6)]
assert [p["face"] for p in written["points"]] == [p["face"] for p in as_read]
assert [p["uv"] for p in written["points"]] == [p["uv"] for p in as_read]
assert written["model"].endswith("eight.ply"), written["model"]

again = BoolSurfSceneReader(FileName=saved)
again.UpdatePipeline()
a, b = sm.Fetch(reader, idx=1), sm.Fetch(again, idx=1)
for name in ("TriangleId", "Barycentric"):
    x, y = a.GetPointData().GetArray(name), b.GetPointData().GetArray(name)
    assert x.GetNumberOfTuples() == y.GetNumberOfTuples() == 8
    for i in range(8):
        assert x.GetTuple(i) == y.GetTuple(i), (name, i, x.GetTuple(i), y.GetTuple(i))

areas = []
for src in (reader, again):
    one_step = BoolSurf(Surface=OutputPort(src, 0), Curves=OutputPort(src, 1))
    one_step.Operation = "Union"
    one_step.ShapeA = 1
    one_step.ShapeB = 2
    one_step.UpdatePipeline()
    region = sm.Fetch(one_step, idx=0)
    integrated = IntegrateVariables(Input=one_step)
    integrated.UpdatePipeline()
    areas.append((sm.Fetch(integrated).GetCellData().GetArray("Area").GetValue(0),
                  region.GetNumberOfCells()))
assert areas[0][1] > 0 and areas[0] == areas[1], areas

# Subdivide Surface With Curves: the curves moved onto a linear subdivision give the same area
# (the surface does not move; the region's triangles are finer).
sub = SubdivideSurfaceWithCurves(Surface=OutputPort(reader, 0), Curves=OutputPort(reader, 1))
sub.Scheme = "Linear"
sub.NumberOfSubdivisions = 1
sub.UpdatePipeline()
assert sm.Fetch(sub, idx=0).GetNumberOfCells() == 4 * 634
fine = BoolSurf(Surface=OutputPort(sub, 0), Curves=OutputPort(sub, 1))
fine.Operation = "Union"
fine.ShapeA = 1
fine.ShapeB = 2
integrated = IntegrateVariables(Input=fine)
integrated.UpdatePipeline()
fine_area = sm.Fetch(integrated).GetCellData().GetArray("Area").GetValue(0)
assert abs(fine_area - areas[0][0]) <= 1e-6 * areas[0][0], (fine_area, areas[0][0])

# A polydata without surface points: a named error, no file.
sphere = Sphere()
bad = os.path.join(folder, "bad.json")
writer = BoolSurfSceneWriter(Input=sphere, FileName=bad)
writer.UpdatePipeline()
assert not os.path.exists(bad), "a refused write left a file"
print("SCENE_WRITER_PROXY_OK")

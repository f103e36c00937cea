"""pvpython: BoolSurfSceneReader by its ParaView name, a scene on Data/eight.ply written here
(two triangles-worth of control points around a vertex region), then the one-step filter."""
import json
import os
import sys

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager as sm
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scratch  # noqa: E402

LoadPlugin(os.environ["BOOLSURF_PLUGIN"], remote=False, ns=globals())
source_dir = os.environ["BOOLSURF_SOURCE_DIR"]
folder = scratch.folder("boolsurf-scene-")
scene = {
    "model": "./data/models/eight.ply",
    "points": [{"face": f, "uv": [0.3, 0.3]} for f in (10, 12, 30, 31, 50)],
    "polygons": [[], [0, 1, 2], [], [2, 3, 4]],
    "shapes": [[0], [1], [3]],
    "operations": [{"a": 1, "b": 2, "type": 0}],
}
path = os.path.join(folder, "scene.json")
json.dump(scene, open(path, "w"))
reader = BoolSurfSceneReader(FileName=path, MeshSearchPath=os.path.join(source_dir, "Data"))
reader.UpdatePipeline()
mesh, curves = sm.Fetch(reader, idx=0), sm.Fetch(reader, idx=1)
assert mesh.GetNumberOfCells() == 634, mesh.GetNumberOfCells()
assert curves.GetNumberOfCells() == 2, curves.GetNumberOfCells()
cd = curves.GetCellData()
assert [cd.GetArray("CurveId").GetValue(i) for i in range(2)] == [1, 3]
assert [cd.GetArray("ShapeId").GetValue(i) for i in range(2)] == [1, 2]
assert curves.GetFieldData().GetArray("OperationType").GetValue(0) == 0
# Each curve has points of its own (scene point 2 is written in both): scene point 4, the last
# point of polygon 3, is output point 5.
assert curves.GetNumberOfPoints() == 6, curves.GetNumberOfPoints()
assert int(curves.GetPointData().GetArray("TriangleId").GetValue(5)) == 50
# The mesh path is resolved by base name through MeshSearchPath.
assert curves.GetFieldData().GetAbstractArray("MeshFileName").GetValue(0).endswith("Data/eight.ply")
traced = TraceSurfaceCurves(Surface=reader, Curves=OutputPort(reader, 1))
traced.UpdatePipeline()
assert sm.Fetch(traced).GetNumberOfCells() == 2
print("SCENE_READER_PROXY_OK")

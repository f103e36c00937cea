"""pvpython: LoadPlugin + CheckSurface on shipped meshes gives the exact topology."""
import os
import sys

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager as sm

plugin = os.environ["BOOLSURF_PLUGIN"]
source_dir = os.environ["BOOLSURF_SOURCE_DIR"]
LoadPlugin(plugin, remote=False, ns=globals())


def field(data, name):
    array = data.GetFieldData().GetAbstractArray(name)
    assert array is not None, "missing field array %s" % name
    return [array.GetValue(i) for i in range(array.GetNumberOfValues())]


expected = {
    # file: (components, genus per component, boundary loops per component, Euler)
    "eight.ply": (1, [2], [0], [-2]),
    "bunny_npm.ply": (1, [0], [0], [2]),
    "nefertiti_small.ply": (1, [0], [1], [1]),
}
for name, (components, genus, loops, euler) in expected.items():
    mesh = PLYReader(FileNames=[os.path.join(source_dir, "Data", name)])
    check = CheckSurface(Input=mesh)
    check.UpdatePipeline()
    data = sm.Fetch(check)
    assert field(data, "Components") == [components], (name, field(data, "Components"))
    assert field(data, "Genus") == genus, (name, field(data, "Genus"))
    assert field(data, "BoundaryLoops") == loops, (name, field(data, "BoundaryLoops"))
    assert field(data, "EulerCharacteristic") == euler, name
    assert field(data, "IsManifold") == [1], name
    assert not [p for p in field(data, "Problems") if p.startswith("Error")], name
    assert data.GetCellData().GetArray("ComponentId") is not None
    assert data.GetPointData().GetArray("BoundaryLoopId") is not None
    print("%s: genus %s, loops %s: OK" % (name, genus, loops))

# A bad surface is reported, not crashed on: a sphere with one triangle's points repeated.
sphere = Sphere(ThetaResolution=16, PhiResolution=8)
programmable = ProgrammableFilter(Input=sphere)
programmable.Script = """
pd = self.GetPolyDataInput()
out = self.GetPolyDataOutput()
out.DeepCopy(pd)
out.GetPoints().SetPoint(0, float('nan'), 0.0, 0.0)
"""
check = CheckSurface(Input=programmable)
check.WarnOnProblems = 0
check.UpdatePipeline()
problems = field(sm.Fetch(check), "Problems")
assert any(p.startswith("Error NonFiniteCoordinates") and "point ids: 0" in p for p in problems), problems
print("PLUGIN_OK")

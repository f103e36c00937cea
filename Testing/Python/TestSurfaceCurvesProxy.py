"""pvpython: Surface Curves holds a drawing as properties. Points set by property are snapped
to the closest surface point (checked against VTK's own cell locator) and given as exact
surface points; exact TriangleIds/Barycentrics are kept bit for bit (TriangleId -1 snaps
that one point, as the curve editor stores a dragged point); curve sizes, shapes,
types and closure reach the output; a state file saved and loaded again gives the same
curves; port 1 holds the curves traced on the surface (Trace Surface Curves' output); bad
properties give an empty output and an error naming the problem."""
import os
import sys

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager as sm
from vtkmodules.vtkCommonDataModel import vtkStaticCellLocator
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_STRING
from vtkmodules.vtkCommonCore import mutable, reference
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scratch  # noqa: E402

LoadPlugin(os.environ["BOOLSURF_PLUGIN"], remote=False, ns=globals())
source_dir = os.environ["BOOLSURF_SOURCE_DIR"]
mesh = PLYReader(FileNames=[os.path.join(source_dir, "Data", "eight.ply")])
surface = sm.Fetch(mesh)
locator = vtkStaticCellLocator()
locator.SetDataSet(surface)
locator.BuildLocator()

# Two curves: a closed polygon (shape 5) and an open Bezier (shape 7, 4 points), off the
# surface by a little, as points picked in a view are.
b = surface.GetBounds()
center = [(b[0] + b[1]) / 2, b[3] + 0.01, (b[4] + b[5]) / 2]
points = [[center[0] + dx, center[1], center[2] + dz]
          for dx, dz in [(-0.05, -0.1), (0.05, -0.1), (0.0, -0.02),
                         (-0.05, 0.1), (-0.02, 0.12), (0.02, 0.12), (0.05, 0.1)]]
curves = SurfaceCurves(Surface=mesh, Points=[x for p in points for x in p], CurveSizes=[3, 4],
                       ShapeIds=[5, 7], CurveTypes=[0, 1], ClosedCurves=[1, 0])
out = sm.Fetch(curves)
assert out.GetNumberOfCells() == 2, out.GetNumberOfCells()
tri = out.GetPointData().GetArray("TriangleId")
bary = out.GetPointData().GetArray("Barycentric")
assert out.GetNumberOfPoints() == 7 and tri and bary
for i, p in enumerate(points):
    closest, cell, sub, dist2 = [0.0, 0.0, 0.0], reference(0), reference(0), mutable(0.0)
    locator.FindClosestPoint(p, closest, cell, sub, dist2)
    assert tri.GetValue(i) == cell.get(), (i, tri.GetValue(i), cell.get())
    q = out.GetPoint(i)
    assert sum((q[k] - closest[k]) ** 2 for k in range(3)) < 1e-20, (i, q, closest)
    # The output point is the barycentric combination of its triangle's corners.
    ids = surface.GetCell(tri.GetValue(i)).GetPointIds()
    u, v = bary.GetTuple2(i)
    corners = [surface.GetPoint(ids.GetId(k)) for k in range(3)]
    x = [(1 - u - v) * corners[0][k] + u * corners[1][k] + v * corners[2][k] for k in range(3)]
    assert x == list(q), (i, x, q)
cd = out.GetCellData()
assert [cd.GetArray("ShapeId").GetValue(c) for c in range(2)] == [5, 7]
assert [cd.GetArray("CurveType").GetValue(c) for c in range(2)] == [0, 1]
assert [cd.GetArray("Closed").GetValue(c) for c in range(2)] == [1, 0]
lines = out.GetLines()
assert lines.GetCellSize(0) == 4 and lines.GetCellSize(1) == 4  # closed: first point repeated

# Port 1 shows the curves traced on the surface: Trace Surface Curves' output, point for point.
shown = sm.Fetch(curves, idx=1)
traced = sm.Fetch(TraceSurfaceCurves(Surface=mesh, Curves=curves))
assert shown.GetNumberOfCells() == 2 and shown.GetNumberOfPoints() > 7, shown.GetNumberOfPoints()
assert shown.GetNumberOfPoints() == traced.GetNumberOfPoints()
assert all(shown.GetPoint(i) == traced.GetPoint(i) for i in range(traced.GetNumberOfPoints()))

# Exact surface points are kept bit for bit.
exact_tris = [tri.GetValue(i) for i in range(7)]
exact_bary = [x for i in range(7) for x in bary.GetTuple2(i)]
exact = SurfaceCurves(Surface=mesh, Points=[0.0] * 21, TriangleIds=exact_tris,
                      Barycentrics=exact_bary, CurveSizes=[3, 4], ShapeIds=[5, 7],
                      CurveTypes=[0, 1], ClosedCurves=[1, 0])
again = sm.Fetch(exact)
for i in range(7):
    assert again.GetPointData().GetArray("TriangleId").GetValue(i) == exact_tris[i]
    assert list(again.GetPointData().GetArray("Barycentric").GetTuple2(i)) == \
        exact_bary[2 * i:2 * i + 2]
    assert again.GetPoint(i) == out.GetPoint(i)

# Mixed, as the curve editor stores a drawing while a point is dragged: TriangleId -1 snaps
# that point's position, the other points stay exact bit for bit.
dragged = [center[0] + 0.01, center[1], center[2] - 0.05]
mixed = SurfaceCurves(Surface=mesh, Points=[x for p in points for x in p],
                      TriangleIds=exact_tris[:2] + [-1] + exact_tris[3:],
                      Barycentrics=exact_bary, CurveSizes=[3, 4], ShapeIds=[5, 7],
                      CurveTypes=[0, 1], ClosedCurves=[1, 0])
mixed.Points = [x for i, p in enumerate(points) for x in (dragged if i == 2 else p)]
moved = sm.Fetch(mixed)
closest, cell, sub, dist2 = [0.0, 0.0, 0.0], reference(0), reference(0), mutable(0.0)
locator.FindClosestPoint(dragged, closest, cell, sub, dist2)
assert moved.GetPointData().GetArray("TriangleId").GetValue(2) == cell.get()
assert sum((moved.GetPoint(2)[k] - closest[k]) ** 2 for k in range(3)) < 1e-20
for i in (0, 1, 3, 4, 5, 6):
    assert moved.GetPointData().GetArray("TriangleId").GetValue(i) == exact_tris[i]
    assert moved.GetPoint(i) == out.GetPoint(i), i

# The drawing feeds BoolSurf: the polygon alone (shape 5) encloses a region.
region = BoolSurf(Surface=mesh, Curves=curves, Operation="Expression", Expression="S5")
assert sm.Fetch(region).GetNumberOfCells() > 0

# A state file keeps the drawing.
state = os.path.join(scratch.folder("boolsurf-curves-"), "drawing.pvsm")
SaveState(state)
ResetSession()
LoadPlugin(os.environ["BOOLSURF_PLUGIN"], remote=False, ns=globals())
LoadState(state)
reloaded = [s for s in GetSources().values() if s.GetXMLName() == "BoolSurfSurfaceCurves"]
assert len(reloaded) == 3, reloaded  # the snapped, the exact and the mixed drawing
for proxy in reloaded:
    data = sm.Fetch(proxy)
    assert data.GetNumberOfPoints() == 7
    expected = moved if -1 in list(proxy.TriangleIds) else out
    for i in range(7):
        assert data.GetPoint(i) == expected.GetPoint(i), (i, data.GetPoint(i))

# Bad properties: sizes that do not add up, a triangle that is not one.
mesh = PLYReader(FileNames=[os.path.join(source_dir, "Data", "eight.ply")])
for props, expected in [
        (dict(Points=[x for p in points for x in p], CurveSizes=[3, 3]), "add up to 6"),
        (dict(Points=[0.0] * 6, TriangleIds=[0, 99999], Barycentrics=[0.2] * 4),
         "TriangleId 99999"),
]:
    bad = SurfaceCurves(Surface=mesh, **props)
    messages = []

    @calldata_type(VTK_STRING)
    def caught(caller, event, text):
        messages.append(text)
    bad.GetClientSideObject().AddObserver("ErrorEvent", caught)
    bad.UpdatePipeline()
    assert sm.Fetch(bad).GetNumberOfPoints() == 0, (props, expected)
    assert any(expected in m for m in messages), (expected, messages)
    Delete(bad)
# A Bezier curve of 5 points is one being drawn, not bad input: no message, the curve in the
# output marked incomplete, and what it needs said in the field data.
drawn = SurfaceCurves(Surface=mesh, Points=[x for p in points[:5] for x in p], CurveTypes=[1],
                      ClosedCurves=[0])
messages = []


@calldata_type(VTK_STRING)
def caught_any(caller, event, text):
    messages.append(text)


drawn.GetClientSideObject().AddObserver("ErrorEvent", caught_any)
drawn.GetClientSideObject().AddObserver("WarningEvent", caught_any)
drawn.UpdatePipeline()
data = sm.Fetch(drawn)
assert not messages, messages
assert data.GetNumberOfPoints() == 5
assert data.GetCellData().GetArray("Complete").GetValue(0) == 0
needs = data.GetFieldData().GetAbstractArray("IncompleteCurves").GetValue(0)
assert "3n+1" in needs and "it has 5: 2 more complete it" in needs, needs
print("Surface Curves: snapped and exact points, curves, state file, bad input, curves being drawn")

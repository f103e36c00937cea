"""pvpython: the pipeline by its ParaView names, on a flat plane with two overlapping squares.

On a flat mesh geodesics are straight, so the areas are known exactly: A = [0.2,0.6]^2,
B = [0.4,0.8]^2: union 0.28, intersection 0.04, A - B 0.12, xor 0.24.
"""
import os

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager as sm
from vtkmodules.vtkFiltersVerdict import vtkCellSizeFilter

LoadPlugin(os.environ["BOOLSURF_PLUGIN"], remote=False, ns=globals())

plane = Plane(Origin=[0, 0, 0], Point1=[1, 0, 0], Point2=[0, 1, 0], XResolution=25,
              YResolution=25)
square_a = PolyLineSource(Points=[0.2, 0.2, 0, 0.6, 0.2, 0, 0.6, 0.6, 0, 0.2, 0.6, 0], Closed=1)
square_b = PolyLineSource(Points=[0.4, 0.4, 0, 0.8, 0.4, 0, 0.8, 0.8, 0, 0.4, 0.8, 0], Closed=1)
curves = AppendGeometry(Input=[square_a, square_b])  # no ShapeId: shape = cell index


def area(proxy, port=0):
    data = sm.Fetch(proxy, idx=port)
    sizes = vtkCellSizeFilter()
    sizes.SetInputData(data)
    sizes.Update()
    a = sizes.GetOutput().GetCellData().GetArray("Area")
    return sum(a.GetValue(i) for i in range(a.GetNumberOfTuples()))


traced = TraceSurfaceCurves(Surface=plane, Curves=curves)
traced.UpdatePipeline()
assert sm.Fetch(traced).GetNumberOfCells() == 2
arrangement = SurfaceArrangement(Surface=plane, Curves=traced)
arrangement.UpdatePipeline()
refined = sm.Fetch(arrangement)
assert refined.GetFieldData().GetArray("NumberOfCells").GetValue(0) == 4
assert abs(area(arrangement) - 1.0) < 1e-12
patches = sm.Fetch(arrangement, idx=1)
assert patches.GetNumberOfLines() == 4, patches.GetNumberOfLines()  # two crossings, 4 patches

labels = LabelArrangementCells(Input=arrangement)
labels.UpdatePipeline()
consistent = sm.Fetch(labels).GetFieldData().GetArray("ShapeConsistent")
assert [consistent.GetValue(i) for i in range(2)] == [1, 1]

expected = {"Union": 0.28, "Intersection": 0.04, "Difference": 0.12, "SymmetricDifference": 0.24}
boolean = SurfaceBoolean(Input=labels, ShapeA=0, ShapeB=1, FillRule="NonZero")
for operation, value in expected.items():
    boolean.Operation = operation
    boolean.UpdatePipeline()
    got = area(boolean)
    assert abs(got - value) < 1e-12, (operation, got, value)
    print("%s: %.12f" % (operation, got))

boolean.Operation = "Expression"
boolean.Expression = "S1 - S0"
boolean.UpdatePipeline()
assert abs(area(boolean) - 0.12) < 1e-12
boundary = sm.Fetch(boolean, idx=1)
assert boundary.GetNumberOfLines() == 1
assert boundary.GetPointData().GetArray("TriangleId") is not None

one = BoolSurf(Surface=plane, Curves=curves, Operation="Intersection")
one.UpdatePipeline()
assert abs(area(one) - 0.04) < 1e-12
one.Operation = "Union"
one.UpdatePipeline()
assert abs(area(one) - 0.28) < 1e-12

# Boundary Sampled Curves: samples on A's and B's outer edges pointing inside give the union; a
# lone sample on A's edge inside B gives A (the lens is not sample-connected).
def samples(points_and_directions):
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    pd, pts, d = vtkPolyData(), vtkPoints(), vtkDoubleArray()
    d.SetName("Direction")
    d.SetNumberOfComponents(3)
    for p, v in points_and_directions:
        pts.InsertNextPoint(p)
        d.InsertNextTuple3(*v)
    pd.SetPoints(pts)
    pd.GetPointData().AddArray(d)
    source = PVTrivialProducer()
    source.GetClientSideObject().SetOutput(pd)
    return source


union_samples = samples([((0.2, 0.4, 0), (1, 0, 0)), ((0.8, 0.6, 0), (-1, 0, 0))])
bsc = BoundarySampledCurves(Input=arrangement, Samples=union_samples)
bsc.UpdatePipeline()
assert abs(area(bsc) - 0.28) < 1e-12, area(bsc)
assert sm.Fetch(bsc).GetFieldData().GetArray("DroppedSamples").GetNumberOfTuples() == 0
bsc.Samples = samples([((0.6, 0.5, 0), (-1, 0, 0))])
bsc.UpdatePipeline()
assert abs(area(bsc) - 0.16) < 1e-12, area(bsc)
one.Selection = "BSC"
one.Samples = union_samples
one.UpdatePipeline()
assert abs(area(one) - 0.28) < 1e-12, area(one)
# The GUI way (Docs/Filters/BoundarySampledCurves.md): a Line source's end points on A's left
# edge, a Calculator making the Direction array.
line = Line(Point1=[0.2, 0.3, 0], Point2=[0.2, 0.5, 0], Resolution=1)
directions = Calculator(Input=line, ResultArrayName="Direction", Function="iHat")
bsc.Samples = directions
bsc.UpdatePipeline()
assert abs(area(bsc) - 0.16) < 1e-12, area(bsc)
print("BSC_OK")
print("PIPELINE_OK")

"""pvpython: stages below Surface Arrangement read from .vtp files give the handed-over answer.

Surface Arrangement's refined surface and Label Arrangement Cells' output are saved as .vtp
and read back (no Core result travels with a file): Label Arrangement Cells and Surface Boolean
on them compute the arrangement again from the field data Surface Arrangement writes for it,
and give the outputs of the chain that handed its results over, bit for bit, on every port.
"""
import os
import random
import tempfile

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager as sm
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkIdTypeArray, vtkIntArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkTriangleFilter
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource

LoadPlugin(os.environ["BOOLSURF_PLUGIN"], remote=False, ns=globals())
rng = random.Random(58)


def triangles(algorithm):
    tri = vtkTriangleFilter()
    tri.SetInputConnection(algorithm.GetOutputPort())
    tri.Update()
    out = vtkPolyData()
    out.ShallowCopy(tri.GetOutput())
    return out


def random_curves(surface):
    """Two or three closed control polygons given as exact surface points."""
    pd = vtkPolyData()
    points = vtkPoints()
    points.SetDataTypeToDouble()
    polys = vtkCellArray()
    shape = vtkIntArray()
    shape.SetName("ShapeId")
    tri = vtkIdTypeArray()
    tri.SetName("TriangleId")
    bary = vtkDoubleArray()
    bary.SetName("Barycentric")
    bary.SetNumberOfComponents(2)
    for s in range(rng.choice((2, 3))):
        ids = []
        for _ in range(rng.randrange(3, 7)):
            t = rng.randrange(surface.GetNumberOfCells())
            u = 0.05 + 0.9 * rng.random()
            v = (1 - u) * (0.05 + 0.9 * rng.random())
            cell = surface.GetCell(t)
            x = [surface.GetPoint(cell.GetPointId(k)) for k in range(3)]
            ids.append(points.InsertNextPoint(
                [(1 - u - v) * x[0][k] + u * x[1][k] + v * x[2][k] for k in range(3)]))
            tri.InsertNextValue(t)
            bary.InsertNextTuple2(u, v)
        polys.InsertNextCell(len(ids), ids)
        shape.InsertNextValue(s)
    pd.SetPoints(points)
    pd.SetPolys(polys)
    pd.GetCellData().AddArray(shape)
    pd.GetPointData().AddArray(tri)
    pd.GetPointData().AddArray(bary)
    return pd


def producer(pd):
    source = PVTrivialProducer()
    source.GetClientSideObject().SetOutput(pd)
    return source


def same_data(a, b, what):
    assert a.GetNumberOfPoints() == b.GetNumberOfPoints(), what
    assert a.GetNumberOfCells() == b.GetNumberOfCells(), what
    for p in range(a.GetNumberOfPoints()):
        assert a.GetPoint(p) == b.GetPoint(p), (what, p)
    for attributes in ("GetPointData", "GetCellData"):
        x, y = getattr(a, attributes)(), getattr(b, attributes)()
        assert x.GetNumberOfArrays() == y.GetNumberOfArrays(), (what, attributes)
        for i in range(x.GetNumberOfArrays()):
            ax = x.GetArray(i)
            ay = y.GetArray(ax.GetName())
            assert ay is not None, (what, ax.GetName())
            assert ax.GetNumberOfValues() == ay.GetNumberOfValues(), (what, ax.GetName())
            for k in range(ax.GetNumberOfValues()):
                assert ax.GetVariantValue(k) == ay.GetVariantValue(k), (what, ax.GetName(), k)
    for c in range(a.GetNumberOfCells()):
        ia, ib = a.GetCell(c).GetPointIds(), b.GetCell(c).GetPointIds()
        assert [ia.GetId(k) for k in range(ia.GetNumberOfIds())] == \
            [ib.GetId(k) for k in range(ib.GetNumberOfIds())], (what, c)


sphere = vtkSphereSource()
sphere.SetThetaResolution(24)
sphere.SetPhiResolution(16)
plane = vtkPlaneSource()
plane.SetResolution(10, 10)
folder = tempfile.mkdtemp()
checked = 0
for name, surface_pd in (("sphere", triangles(sphere)), ("plane", triangles(plane))):
    surface = producer(surface_pd)
    for trial in range(3):
        curves = producer(random_curves(surface_pd))
        traced = TraceSurfaceCurves(Surface=surface, Curves=curves)
        arrangement = SurfaceArrangement(Surface=surface, Curves=traced)
        labels = LabelArrangementCells(Input=arrangement)
        boolean = SurfaceBoolean(Input=labels, Operation="Union", ShapeA=-1, ShapeB=-1)
        boolean.UpdatePipeline()
        if sm.Fetch(boolean).GetFieldData().GetAbstractArray("Expression") is None:
            continue  # refused (an inconsistent shape): the one-step test covers refusals
        for which, proxy in (("refined", arrangement), ("labeled", labels)):
            path = os.path.join(folder, "%s-%d-%s.vtp" % (name, trial, which))
            SaveData(path, proxy=OutputPort(proxy, 0))
            reader = XMLPolyDataReader(FileName=[path])
            read = LabelArrangementCells(Input=reader) if which == "refined" else reader
            again = SurfaceBoolean(Input=read, Operation="Union", ShapeA=-1, ShapeB=-1)
            again.UpdatePipeline()
            for port in range(4):
                same_data(sm.Fetch(boolean, idx=port), sm.Fetch(again, idx=port),
                          "%s, trial %d, %s file, port %d" % (name, trial, which, port))
            checked += 1
print("stages on %d files == the handed-over chain" % checked)
assert checked >= 4, checked

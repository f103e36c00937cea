"""Drawings and comparisons shared by the stage-chain tests (TestStageChainMatchesOneStep,
TestStageChainFromFiles): random overlapping control polygons on a surface, a producer for
them, and an exact comparison of two outputs (points, arrays value by value, cells)."""
import math

from paraview.simple import PVTrivialProducer
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkIdTypeArray, vtkIntArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkTriangleFilter


def triangles(algorithm):
    tri = vtkTriangleFilter()
    tri.SetInputConnection(algorithm.GetOutputPort())
    tri.Update()
    out = vtkPolyData()
    out.ShallowCopy(tri.GetOutput())
    return out



def random_curves(surface, rng, form="exact"):
    """2-3 closed polygons of 3-6 points near one place, so that they overlap, drawn with `rng`:
    given as exact surface points (form "exact"), as coordinates only, or exactly near an edge
    or a vertex ("near-edge", "near-vertex")."""
    n_cells = surface.GetNumberOfCells()
    center = [0.0] * 3
    surface.GetPoint(surface.GetCell(rng.randrange(n_cells)).GetPointId(0), center)
    bounds = surface.GetBounds()
    diagonal = math.sqrt(sum((bounds[2 * k + 1] - bounds[2 * k]) ** 2 for k in range(3)))
    near = []
    for t in range(n_cells):
        x = surface.GetPoint(surface.GetCell(t).GetPointId(0))
        if math.dist(x, center) < 0.25 * diagonal:
            near.append(t)
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
            t = rng.choice(near)
            u = 0.05 + 0.9 * rng.random()
            v = (1 - u) * (0.05 + 0.9 * rng.random())
            tiny = 10 ** -rng.uniform(12, 16)
            corner = rng.randrange(3)
            if form == "near-edge":
                off = tiny if rng.random() < 0.5 else -tiny
                along = 0.1 + 0.8 * rng.random()
                u, v = [(along, 1 - along - off), (off, along), (along, off)][corner]
            elif form == "near-vertex":
                a, b = tiny, 10 ** -rng.uniform(12, 16)
                u, v = [(a, b), (1 - a - b, b), (a, 1 - a - b)][corner]
            cell = surface.GetCell(t)
            x = [surface.GetPoint(cell.GetPointId(k)) for k in range(3)]
            p = [(1 - u - v) * x[0][k] + u * x[1][k] + v * x[2][k] for k in range(3)]
            ids.append(points.InsertNextPoint(p))
            tri.InsertNextValue(t)
            bary.InsertNextTuple2(u, v)
        polys.InsertNextCell(len(ids), ids)
        shape.InsertNextValue(s)
    pd.SetPoints(points)
    pd.SetPolys(polys)
    pd.GetCellData().AddArray(shape)
    if form != "coordinates":
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

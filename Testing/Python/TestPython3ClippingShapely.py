"""/usr/bin/python3: open curves clipped by a Boolean region (vtkBoolSurf port 3) on a flat mesh
have the length of shapely's intersection(line, region), to 1e-9, for random polygons and lines
and every operation; each piece starts and ends on the region's boundary or at an end of the
line. shapely (GEOS) is the exact planar oracle: on a flat mesh geodesics are straight."""
import random

import boolsurf
from shapely.geometry import LineString, Point, Polygon
from shapely.ops import polygonize, unary_union
from vtkmodules.vtkCommonCore import vtkIntArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkTriangleFilter
from vtkmodules.vtkFiltersSources import vtkPlaneSource

plane = vtkPlaneSource()
plane.SetOrigin(0, 0, 0)
plane.SetPoint1(1, 0, 0)
plane.SetPoint2(0, 1, 0)
plane.SetResolution(23, 19)
triangles = vtkTriangleFilter()
triangles.SetInputConnection(plane.GetOutputPort())
triangles.Update()
mesh = triangles.GetOutput()

rng = random.Random(4)


def random_points(n):
    # a dyadic grid keeps the inputs exact
    return [(rng.randint(205, 3891) / 4096.0, rng.randint(205, 3891) / 4096.0) for _ in range(n)]


def curves_polydata(closed_curves, open_curve):
    points, cells, shape = vtkPoints(), vtkCellArray(), vtkIntArray()
    points.SetDataTypeToDouble()
    shape.SetName("ShapeId")
    for s, curve in enumerate(closed_curves + [open_curve]):
        ids = [points.InsertNextPoint(x, y, 0.0) for x, y in curve]
        if s < len(closed_curves):
            ids.append(ids[0])  # closed: the first point repeated
        cells.InsertNextCell(len(ids), ids)
        shape.InsertNextValue(s)
    pd = vtkPolyData()
    pd.SetPoints(points)
    pd.SetLines(cells)
    pd.GetCellData().AddArray(shape)
    return pd


def nonzero_region(curve):
    """The non-zero filled region of a possibly self-intersecting polygon."""
    ring = LineString(curve + [curve[0]])
    pieces = unary_union(ring)  # the ring noded at its self-intersections
    faces = list(polygonize(pieces))
    inside = []
    for face in faces:
        p = face.representative_point()
        winding = 0
        for (x0, y0), (x1, y1) in zip(curve, curve[1:] + curve[:1]):
            if (y0 <= p.y) != (y1 <= p.y):
                t = (p.y - y0) / (y1 - y0)
                if x0 + t * (x1 - x0) > p.x:
                    winding += 1 if y1 > y0 else -1
        if winding != 0:
            inside.append(face)
    return unary_union(inside)


operations = ["union", "intersection", "difference", "symmetric_difference"]
checked = pieces_seen = 0
for trial in range(12):
    a, b = random_points(rng.randint(3, 6)), random_points(rng.randint(3, 6))
    line = random_points(rng.randint(2, 5))
    f = boolsurf.vtkBoolSurf()
    f.SetInputData(0, mesh)
    f.SetInputData(1, curves_polydata([a, b], line))
    op = trial % 4
    f.SetOperation(op)
    f.SetShapeA(0)
    f.SetShapeB(1)
    f.SetFillRule(0)  # non-zero
    f.Update()
    ra, rb = nonzero_region(a), nonzero_region(b)
    region = getattr(ra, operations[op])(rb)
    expected = LineString(line).intersection(region).length
    clipped = f.GetOutput(3)
    ours = 0.0
    boundary = region.boundary
    for c in range(clipped.GetNumberOfCells()):
        ids = clipped.GetCell(c).GetPointIds()
        pts = [clipped.GetPoint(ids.GetId(i))[:2] for i in range(ids.GetNumberOfIds())]
        ours += LineString(pts).length
        for end in (pts[0], pts[-1]):
            on_boundary = boundary.distance(Point(end)) < 1e-9
            at_line_end = min(Point(end).distance(Point(line[0])), Point(end).distance(Point(line[-1]))) < 1e-12
            assert on_boundary or at_line_end, (trial, end)
        pieces_seen += 1
    assert abs(ours - expected) <= 1e-9, (trial, ours, expected)
    assert abs(f.GetOutput(0).GetNumberOfCells()) > 0 or region.area < 1e-6
    checked += 1
assert checked == 12 and pieces_seen >= 5, (checked, pieces_seen)
print("CLIPPING_SHAPELY_OK", pieces_seen)

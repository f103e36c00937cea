"""A torus around the z axis as vtkPolyData, for the pvpython tests (not a test itself)."""
import math

from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData


def torus_polydata(R, r, nu, nv):
    """Major radius R, minor radius r, nu x nv quads split in two triangles, counter-clockwise
    seen from outside; vertex (i, j) is at angle 2 pi i / nu around z and 2 pi j / nv around
    the tube."""
    points, polys = vtkPoints(), vtkCellArray()
    for i in range(nu):
        for j in range(nv):
            a, b = 2 * math.pi * i / nu, 2 * math.pi * j / nv
            points.InsertNextPoint((R + r * math.cos(b)) * math.cos(a),
                                   (R + r * math.cos(b)) * math.sin(a), r * math.sin(b))

    def vid(i, j):
        return (i % nu) * nv + (j % nv)
    for i in range(nu):
        for j in range(nv):
            polys.InsertNextCell(3, [vid(i, j), vid(i + 1, j), vid(i + 1, j + 1)])
            polys.InsertNextCell(3, [vid(i, j), vid(i + 1, j + 1), vid(i, j + 1)])
    pd = vtkPolyData()
    pd.SetPoints(points)
    pd.SetPolys(polys)
    return pd

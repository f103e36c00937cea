"""What the pvbatch scripts on pieces (MpiPiecesChain.py, MpiOneStep.py, MpiPiecesCurves.py,
MpiPiecesEdits.py) read of an output: each rank's part fetched with the rank that holds each
cell, the refined triangles per source triangle, field arrays, polylines; and the split surface
they run on. Imported inside pvbatch (the Examples folder on the path).
"""
import argparse
import os
import sys

SOURCE_DIR = os.environ.get("BOOLSURF_SOURCE_DIR",
                            os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(SOURCE_DIR, "Examples"))
from boolsurf_example_utils import (SurfaceRays, curves_source, load_plugin,  # noqa: E402,F401
                                    ranks, sample_source, surface_circle)
from paraview.simple import (ExtractSurface, GenerateGlobalIds, PLYReader,  # noqa: E402
                             ProgrammableFilter, RedistributeDataSet)
from paraview import servermanager as sm  # noqa: E402
from vtkmodules.vtkCommonCore import vtkIdList  # noqa: E402
from vtkmodules.vtkFiltersVerdict import vtkCellSizeFilter  # noqa: E402

# The end of a programmable filter's script that writes its dict `values` as the arrays of one
# point (the script imports vtkDoubleArray and vtkPoints): one point per rank, so the fetched
# union lists what every rank said.
VALUES_AS_ONE_POINT = """
out = self.GetOutput()
points = vtkPoints()
points.InsertNextPoint(0, 0, 0)
out.SetPoints(points)
for name, value in values.items():
    array = vtkDoubleArray()
    array.SetName(name)
    array.InsertNextValue(value)
    out.GetPointData().AddArray(array)
"""


def start(doc, ns):
    """The script's arguments (--json, --partitions K), the plugin loaded into the script's
    namespace `ns`, and split_eight's surface: (args, (mesh, surface, rays, circles, control))."""
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument("--json", required=True)
    parser.add_argument("--partitions", type=int)
    args = parser.parse_args()
    load_plugin(ns)
    return args, split_eight(SOURCE_DIR, args.partitions)


def split_eight(source_dir, partitions=None):
    """Data/eight.ply with global ids in its serial order (Generate Global Ids), split across
    the ranks by RedistributeDataSet and Extract Surface (into `partitions` parts when given),
    and three circles on it, one crossing many pieces: (mesh, surface, rays, circles, control)."""
    mesh = PLYReader(FileNames=[os.path.join(source_dir, "Data", "eight.ply")])
    redistributed = RedistributeDataSet(Input=GenerateGlobalIds(Input=mesh))
    if partitions:
        redistributed.NumberOfPartitions = partitions
    surface = ExtractSurface(Input=redistributed)
    surface.UpdatePipeline()
    rays = SurfaceRays(mesh, axis=1)
    circles = [(surface_circle(rays, (0.0, -0.035), 0.06), 0),
               (surface_circle(rays, (0.0, 0.035), 0.06), 1),
               (surface_circle(rays, (0.0, 0.05), 0.08, n=40), 2)]
    control = curves_source(circles, surface)
    return mesh, surface, rays, circles, control


# Each rank's output with its rank as a cell array: the fetched union says who holds what.
RANK = """
from vtkmodules.vtkCommonCore import vtkIntArray
from vtkmodules.vtkParallelCore import vtkMultiProcessController
inp = self.GetInput()
out = self.GetOutput()
out.ShallowCopy(inp)
rank = vtkMultiProcessController.GetGlobalController().GetLocalProcessId()
held = vtkIntArray()
held.SetName("HeldBy")
held.SetNumberOfTuples(out.GetNumberOfCells())
held.Fill(rank)
out.GetCellData().AddArray(held)
"""


def fetched(proxy):
    return sm.Fetch(ProgrammableFilter(Input=proxy, Script=RANK))


def per_source(data, arrays):
    """Per SourceTriangle: the triangles' [area, *values of `arrays`], in output order."""
    sizes = vtkCellSizeFilter()
    sizes.SetInputData(data)
    sizes.Update()
    area = sizes.GetOutput().GetCellData().GetArray("Area")
    source = data.GetCellData().GetArray("SourceTriangle")
    values = [data.GetCellData().GetArray(a) for a in arrays]
    out = {}
    for c in range(data.GetNumberOfCells()):
        row = [area.GetValue(c)]
        for v in values:
            row += [v.GetComponent(c, k) for k in range(v.GetNumberOfComponents())]
        out.setdefault(str(int(source.GetTuple1(c))), []).append(row)
    return out


def holders(data):
    held = data.GetCellData().GetArray("HeldBy")
    counts = {}
    for c in range(data.GetNumberOfCells()):
        counts[held.GetValue(c)] = counts.get(held.GetValue(c), 0) + 1
    return {str(k): v for k, v in sorted(counts.items())}


def field(data, name):
    a = data.GetFieldData().GetAbstractArray(name)
    return [a.GetVariantValue(i).ToString() for i in range(a.GetNumberOfValues())] if a else None


def polylines(data, skip=("vtkOriginalIndices",)):
    """Every point's coordinates and arrays, every cell's points and arrays, exactly (the
    arrays named in `skip` left out)."""
    out = {"points": [list(data.GetPoint(i)) for i in range(data.GetNumberOfPoints())],
           "cells": []}
    for attributes, key in ((data.GetPointData(), "point"), (data.GetCellData(), "cell")):
        for k in range(attributes.GetNumberOfArrays()):
            a = attributes.GetArray(k)
            if a is not None and a.GetName() not in skip:
                out[key + ":" + a.GetName()] = [
                    a.GetComponent(i, c) for i in range(a.GetNumberOfTuples())
                    for c in range(a.GetNumberOfComponents())]
    ids = vtkIdList()
    for c in range(data.GetNumberOfCells()):
        data.GetCellPoints(c, ids)
        out["cells"].append([ids.GetId(i) for i in range(ids.GetNumberOfIds())])
    return out


def lines(data):
    """Each polyline as [closed, held by, [[x, y, z, TriangleId], ...]]."""
    closed = data.GetCellData().GetArray("Closed")
    held = data.GetCellData().GetArray("HeldBy")
    triangle = data.GetPointData().GetArray("TriangleId")
    out = []
    for c in range(data.GetNumberOfCells()):
        ids = data.GetCell(c).GetPointIds()
        n = ids.GetNumberOfIds() - (1 if closed.GetValue(c) else 0)
        points = [list(data.GetPoint(ids.GetId(k))) +
                  [int(triangle.GetTuple1(ids.GetId(k))) if triangle else -1] for k in range(n)]
        out.append([int(closed.GetValue(c)), held.GetValue(c), points])
    return out


def control_curves(data):
    """Each sub-curve of a control-curves output (a Boolean's port 2 or 3) as
    [{cell array: value}, [[x, y, z, TriangleId, u, v], ...]], a whole closed curve's repeated
    first point left out."""
    cells = data.GetCellData()
    names = [cells.GetArrayName(k) for k in range(cells.GetNumberOfArrays())
             if cells.GetArrayName(k) not in ("HeldBy", "vtkOriginalIndices")]
    triangle = data.GetPointData().GetArray("TriangleId")
    uv = data.GetPointData().GetArray("Barycentric")
    ids = vtkIdList()
    out = []
    for c in range(data.GetNumberOfCells()):
        data.GetCellPoints(c, ids)
        values = {name: [cells.GetArray(name).GetComponent(c, k)
                         for k in range(cells.GetArray(name).GetNumberOfComponents())]
                  for name in names}
        n = ids.GetNumberOfIds()
        if n > 1 and ids.GetId(0) == ids.GetId(n - 1):
            n -= 1
        points = [list(data.GetPoint(ids.GetId(k))) +
                  [int(triangle.GetTuple1(ids.GetId(k))), uv.GetComponent(ids.GetId(k), 0),
                   uv.GetComponent(ids.GetId(k), 1)] for k in range(n)]
        out.append([values, points])
    return out

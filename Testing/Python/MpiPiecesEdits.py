"""Edits on the pieces of a surface split across MPI ranks: Trace Surface Curves, Surface
Arrangement, Label Arrangement Cells and Surface Boolean updated after each of several edits,
their outputs written as JSON per source triangle after each, with what each rank's Surface
Arrangement kept (its field array PieceArrangementReuse): run by TestPython3MpiPiecesEdits.py
with pvbatch on 1, 2 and 3 ranks, whose unions over ranks must agree with one rank's outputs
after every edit.

    mpiexec -np N pvbatch Testing/Python/MpiPiecesEdits.py --json out.json

The surface (Data/eight.ply, through a Transform that the last edits change) gets global ids,
then RedistributeDataSet and Extract Surface split it across the ranks. The edits: a circle
moved a little, a small circle moved from one side of the surface to the other (across rank
boundaries), a circle moved back, the surface scaled (every piece changes: built again), then
a circle moved on the scaled surface.
"""
import argparse
import builtins
import json
import os
import sys

source_dir = os.environ.get("BOOLSURF_SOURCE_DIR",
                            os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(source_dir, "Examples"))
from boolsurf_example_utils import (SurfaceRays, curves_source, load_plugin,  # noqa: E402
                                    ranks, surface_circle)
from paraview.simple import *  # noqa: E402,F401,F403
from paraview import servermanager as sm  # noqa: E402
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mpi_pieces_fetch import VALUES_AS_ONE_POINT, per_source  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--json", required=True)
args = parser.parse_args()
load_plugin(globals())

mesh = PLYReader(FileNames=[os.path.join(source_dir, "Data", "eight.ply")])
scaled = Transform(Input=mesh)
scaled.Transform = "Transform"
surface = ExtractSurface(Input=RedistributeDataSet(Input=GenerateGlobalIds(Input=scaled)))
surface.UpdatePipeline()
rays = SurfaceRays(mesh, axis=1)
# In the rays' coordinates (z, x): the pieces split the eight along x (and y on 3 ranks).
circles = [(surface_circle(rays, (0.0, -0.035), 0.06), 0),
           (surface_circle(rays, (0.0, 0.035), 0.06), 1),
           (surface_circle(rays, (-0.3, 0.19), 0.03, n=12), 2)]
control = curves_source(circles, surface)
traced = TraceSurfaceCurves(Surface=surface, Curves=control)
arrangement = SurfaceArrangement(Surface=surface, Curves=traced)
labels = LabelArrangementCells(Input=arrangement, PerTriangleLabels=1)
boolean = SurfaceBoolean(Input=labels, Operation="Union", ShapeA=0, ShapeB=2)

# Each rank's output with its rank as a cell array, and one point per rank with its
# PieceArrangementReuse (and the PieceTracingTraffic of Surface Curves' port 1 and of Trace Surface
# Curves): the fetched unions say who holds what and what each rank kept.
RANK = """
from vtkmodules.vtkCommonCore import vtkIntArray
from vtkmodules.vtkParallelCore import vtkMultiProcessController
out = self.GetOutput()
out.ShallowCopy(self.GetInput())
held = vtkIntArray()
held.SetName("HeldBy")
held.SetNumberOfTuples(out.GetNumberOfCells())
held.Fill(vtkMultiProcessController.GetGlobalController().GetLocalProcessId())
out.GetCellData().AddArray(held)
"""
ROW = """
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
from vtkmodules.vtkParallelCore import vtkMultiProcessController
reuse = self.GetInput().GetFieldData().GetArray("%s")
values = {"Rank": vtkMultiProcessController.GetGlobalController().GetLocalProcessId()}
for k in range(reuse.GetNumberOfComponents() if reuse else 0):
    values[reuse.GetComponentName(k)] = reuse.GetComponent(0, k)
""" + VALUES_AS_ONE_POINT


def fetched(proxy, script=RANK, **kw):
    """The proxy's output with `script` run on each rank, fetched; the filter is deleted, so it
    holds no output of the stages (an edit reuses what no output holds any more)."""
    filter = ProgrammableFilter(Input=proxy, Script=script, **kw)
    data = sm.Fetch(filter)
    Delete(filter)
    return data


def field(data, name):
    a = data.GetFieldData().GetAbstractArray(name)
    return [a.GetVariantValue(i).ToString() for i in range(a.GetNumberOfValues())] if a else None


def rows(proxy, name):
    """Each rank's field array `name` of `proxy`, by rank: {component name: value}."""
    data = fetched(proxy, ROW % name, OutputDataSetType="vtkPolyData")
    pd = data.GetPointData()
    return {str(int(pd.GetArray("Rank").GetValue(i))): {
        pd.GetArrayName(k): pd.GetArray(k).GetValue(i) for k in range(pd.GetNumberOfArrays())}
        for i in range(data.GetNumberOfPoints())}


def shape_triangles(shape):
    """The surface triangles the traced points of shape `shape` lie on."""
    data = sm.Fetch(traced)
    shapes = data.GetCellData().GetArray("ShapeId")
    triangle = data.GetPointData().GetArray("TriangleId")
    out = set()
    for c in range(data.GetNumberOfCells()):
        if int(shapes.GetTuple1(c)) == shape:
            ids = data.GetCell(c).GetPointIds()
            out |= {int(triangle.GetTuple1(ids.GetId(k))) for k in range(ids.GetNumberOfIds())}
    return out


def step(name):
    boolean.UpdatePipeline()
    out = {"name": name, "reuse": rows(arrangement, "PieceArrangementReuse"),
           "display": rows(OutputPort(control, 1), "PieceTracingTraffic"),
           "tracing": rows(traced, "PieceTracingTraffic")}
    for stage, proxy, arrays in (("arrangement", arrangement, ["ArrangementCell"]),
                                 ("labels", labels, ["ArrangementCell", "Labels"]),
                                 ("boolean", boolean, ["ArrangementCell", "Region"])):
        data = fetched(proxy)
        out[stage] = {"triangles": data.GetNumberOfCells(),
                      "by_source": per_source(data, arrays),
                      "NumberOfCells": field(data, "NumberOfCells"),
                      "CellLabels": field(data, "CellLabels"),
                      "pieces": field(data, "ArrangementOnPieces") is not None}
        if stage == "arrangement":
            # The ranks holding the small circle's triangles (rank 0 on one rank).
            held = data.GetCellData().GetArray("HeldBy")
            source = data.GetCellData().GetArray("SourceTriangle")
            small = shape_triangles(2)
            out["small_circle_ranks"] = sorted({
                held.GetValue(c) for c in range(data.GetNumberOfCells())
                if int(source.GetTuple1(c)) in small})
    return out


def move(index, center, radius, n):
    points = list(control.Points)
    sizes = [int(n) for n in control.CurveSizes]
    first = 3 * builtins.sum(sizes[:index])
    circle = [x for p in surface_circle(rays, center, radius, n=n) for x in p]
    assert len(circle) == 3 * sizes[index]
    points[first:first + len(circle)] = circle
    control.Points = points


steps = [step("first")]
move(0, (0.0, -0.03), 0.06, 24)
steps.append(step("a circle moved a little"))
move(2, (0.3, -0.19), 0.03, 12)
steps.append(step("the small circle moved to the other side"))
move(0, (0.0, -0.035), 0.06, 24)
steps.append(step("a circle moved back"))
scaled.Transform.Scale = [1.0, 1.0, 1.01]
steps.append(step("the surface scaled"))
move(1, (0.0, 0.04), 0.06, 24)
steps.append(step("a circle moved on the scaled surface"))
with open(args.json, "w") as f:
    json.dump({"ranks": ranks(), "steps": steps}, f, indent=1, sort_keys=True)
print("done", ranks())

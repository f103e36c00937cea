"""The Surface Curves source on the pieces of a surface split across MPI ranks, its outputs
written as JSON: run by TestPython3MpiPiecesCurves.py with pvbatch on 1, 2 and 3 ranks, whose
rank 0 outputs must equal one rank's.

    mpiexec -np N pvbatch Testing/Python/MpiPiecesCurves.py --json out.json
        [--appended out.vtp | --whole in.vtp]

The surface (Data/eight.ply) gets global ids in its serial order, then RedistributeDataSet and
Extract Surface split it across the ranks. Surface Curves holds three circles given by position
(snapped), then the same points given by TriangleId and Barycentric; its port 0 (control curves)
and port 1 (their trace) are written with every rank's PieceSnapping and PieceTracingTraffic.
An edit moves one point. A point naming a triangle no rank has must fail on every rank.

Pieces without GlobalIds: the same mesh redistributed without them; the filters generate them.
--appended writes the surface those pieces form (rank 0's piece first, as the gathered surface)
for the one-rank run of the same chain (--whole), whose results must equal the pieces'.
"""
import argparse
import json
import os
import sys

source_dir = os.environ.get("BOOLSURF_SOURCE_DIR",
                            os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(source_dir, "Examples"))
from boolsurf_example_utils import (SurfaceRays, load_plugin, ranks,  # noqa: E402
                                    surface_circle)
from paraview.simple import *  # noqa: E402,F401,F403
from paraview import servermanager as sm  # noqa: E402
from paraview import simple  # noqa: E402
from vtkmodules.vtkFiltersCore import vtkCleanPolyData  # noqa: E402
from vtkmodules.vtkFiltersVerdict import vtkCellSizeFilter  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter  # noqa: E402
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mpi_pieces_fetch import VALUES_AS_ONE_POINT, polylines  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--json", required=True)
parser.add_argument("--appended")
parser.add_argument("--whole")
args = parser.parse_args()
load_plugin(globals())
SurfaceCurvesSource = simple._create_func("SurfaceCurves", sm.filters)

mesh = PLYReader(FileNames=[os.path.join(source_dir, "Data", "eight.ply")])
surface = ExtractSurface(Input=RedistributeDataSet(Input=GenerateGlobalIds(Input=mesh)))
surface.UpdatePipeline()
rays = SurfaceRays(mesh, axis=1)
circles = [(surface_circle(rays, (0.0, -0.035), 0.06), 0),
           (surface_circle(rays, (0.0, 0.035), 0.06), 1),
           (surface_circle(rays, (0.0, 0.05), 0.08, n=40), 2)]
points = [x for pts, _ in circles for p in pts for x in p]
sizes = [len(pts) for pts, _ in circles]
shapes = [shape for _, shape in circles]

# Per rank, one point carrying what the rank's outputs say of the run (field arrays' components).
PER_RANK = """
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
from vtkmodules.vtkParallelCore import vtkMultiProcessController
rank = vtkMultiProcessController.GetGlobalController().GetLocalProcessId()
values = {"Rank": rank}
for port in range(self.GetNumberOfInputConnections(0)):
    data = self.GetInputDataObject(0, port)
    values["Lines%d" % port] = data.GetNumberOfLines()
    for name in ("PieceSnapping", "PieceTracingTraffic"):
        a = data.GetFieldData().GetArray(name)
        for k in range(a.GetNumberOfComponents() if a else 0):
            values[name + ":" + a.GetComponentName(k)] = a.GetComponent(0, k)
""" + VALUES_AS_ONE_POINT


def per_rank(source):
    data = sm.Fetch(ProgrammableFilter(Input=[OutputPort(source, 0), OutputPort(source, 1)],
                                       Script=PER_RANK, OutputDataSetType="vtkPolyData"))
    pd = data.GetPointData()
    return {str(int(pd.GetArray("Rank").GetValue(i))): {
        pd.GetArrayName(k): pd.GetArray(k).GetValue(i) for k in range(pd.GetNumberOfArrays())}
        for i in range(data.GetNumberOfPoints())}


def ports(source):
    source.UpdatePipeline()
    return {"curves": polylines(sm.Fetch(source, idx=0)),
            "traced": polylines(sm.Fetch(source, idx=1))}


results = {"ranks": ranks(), "surface_triangles": sm.Fetch(mesh).GetNumberOfCells()}

# Points given by position: snapped to the closest surface point.
snapped = SurfaceCurvesSource(Surface=surface, Points=points, CurveSizes=sizes, ShapeIds=shapes)
results["snapped"] = ports(snapped)
results["snapped_ranks"] = per_rank(snapped)

# The same points given exactly (rank 0's port 0 names them by global cell id).
exact_data = sm.Fetch(snapped, idx=0)
triangle_ids = exact_data.GetPointData().GetArray("TriangleId")
uv = exact_data.GetPointData().GetArray("Barycentric")
written = [i for c, cell in enumerate(polylines(exact_data)["cells"]) for i in cell[:sizes[c]]]
exact = SurfaceCurvesSource(Surface=surface, Points=points, CurveSizes=sizes, ShapeIds=shapes,
                            TriangleIds=[int(triangle_ids.GetTuple1(i)) for i in written],
                            Barycentrics=[x for i in written for x in uv.GetTuple2(i)])
results["exact"] = ports(exact)
results["exact_ranks"] = per_rank(exact)

# An edit: one point moved; the piece and the tracer are kept.
moved = list(points)
moved[0:3] = [x + 0.002 for x in moved[0:3]]
snapped.Points = moved
results["edited"] = ports(snapped)
results["edited_ranks"] = per_rank(snapped)

# The LocallyShortest method: port 1 is not traced on pieces; the update gathers (warning).
shortest = SurfaceCurvesSource(Surface=surface, Points=points, CurveSizes=sizes,
                               ShapeIds=shapes, GeodesicMethod="Locally shortest")
results["shortest"] = ports(shortest)

# A point naming a triangle no rank has: an error naming the curve and point on every rank.
bad = SurfaceCurvesSource(Surface=surface, Points=points[:9] + points[:9], CurveSizes=[3, 3],
                          TriangleIds=[3, 40, 5, 6, 7, 1000000],
                          Barycentrics=[0.25] * 12)
bad.UpdatePipeline()
results["bad"] = {"lines": sm.Fetch(bad, idx=0).GetNumberOfCells()}

# Pieces without GlobalIds (or, with --whole, the surface they form, on one rank).
if args.whole:
    plain = XMLPolyDataReader(FileName=[args.whole])
else:
    redistributed = RedistributeDataSet(Input=mesh)
    redistributed.GenerateGlobalCellIds = 0
    plain = ExtractSurface(Input=redistributed)
plain.UpdatePipeline()
if args.appended:
    clean = vtkCleanPolyData()  # the pieces' common points merged, the cells in rank order
    clean.SetInputData(sm.Fetch(plain))
    clean.PointMergingOn()
    clean.SetTolerance(0.0)
    clean.Update()
    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(clean.GetOutput())
    writer.SetFileName(args.appended)
    writer.Write()
plain_curves = SurfaceCurvesSource(Surface=plain, Points=points, CurveSizes=sizes,
                                   ShapeIds=shapes)
traced = TraceSurfaceCurves(Surface=plain, Curves=plain_curves)
boolean = SurfaceBoolean(Input=LabelArrangementCells(
    Input=SurfaceArrangement(Surface=plain, Curves=traced), PerTriangleLabels=1),
    Operation="Union", ShapeA=0, ShapeB=2)
boolean.UpdatePipeline()
region = sm.Fetch(boolean)
sizes_filter = vtkCellSizeFilter()
sizes_filter.SetInputData(region)
sizes_filter.Update()
area = sizes_filter.GetOutput().GetCellData().GetArray("Area")
source = region.GetCellData().GetArray("SourceTriangle")
by_source = {}
for c in range(region.GetNumberOfCells()):
    by_source.setdefault(str(int(source.GetTuple1(c))), []).append(area.GetValue(c))
results["plain"] = {"curves": ports(plain_curves),
                    "traced": polylines(sm.Fetch(traced),
                                        skip=("vtkOriginalIndices", "PieceCurvesMessage")),
                    "ranks": per_rank(plain_curves),
                    "region": {k: sorted(v) for k, v in by_source.items()}}
with open(args.json, "w") as f:
    json.dump(results, f, indent=1, sort_keys=True)
print("done", ranks())

"""Surface Arrangement, Label Arrangement Cells and Surface Boolean on the pieces of a surface
split across MPI ranks, their outputs written as JSON per source triangle: run by
TestPython3MpiPiecesChain.py with pvbatch on 1, 2 and 3 ranks, whose unions over ranks must
agree with one rank's outputs.

    mpiexec -np N pvbatch Testing/Python/MpiPiecesChain.py --json out.json [--partitions K]

The surface (Data/eight.ply) gets global ids in its serial order (Generate Global Ids), then
RedistributeDataSet and Extract Surface split it across the ranks; on one rank it stays whole
and every filter computes as ever. Three circles, one crossing many pieces; the Boolean's boundary loops (port 1). Each output is
fetched with the rank that holds each triangle, so the test sees that every rank holds only
its part (--partitions 2 on 3 ranks: a rank with no triangles); a filter that gathers its input (Boundary Sampled Curves) fed the labeled pieces
must refuse them.
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mpi_pieces_fetch import (VALUES_AS_ONE_POINT, fetched, field, holders, lines,  # noqa: E402
                              per_source, polylines, ranks, sample_source, start)
from paraview.simple import *  # noqa: E402,F401,F403
from paraview import servermanager as sm  # noqa: E402

args, (mesh, surface, rays, circles, control) = start(__doc__, globals())

traced = TraceSurfaceCurves(Surface=surface, Curves=control)
# The gathered path's message 0 (the same curves on the surface held by rank 0 alone), which
# the pieces' must equal byte for byte.
whole = ExtractSurface(Input=GenerateGlobalIds(Input=mesh))
reference = TraceSurfaceCurves(Surface=whole, Curves=control)

# Per rank, one point: what Trace Surface Curves' output on that rank carries (its message 0's
# digest, the reference's on the rank holding it, its traffic), so the fetched union says it.
PER_RANK = """
import zlib
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkParallelCore import vtkMultiProcessController
from vtkmodules.util.numpy_support import vtk_to_numpy
rank = vtkMultiProcessController.GetGlobalController().GetLocalProcessId()
def digest(data):
    a = data.GetFieldData().GetAbstractArray("PieceCurvesMessage") if data else None
    return float(zlib.crc32(vtk_to_numpy(a).tobytes())) if a else -1.0
pieces = self.GetInputDataObject(0, 0)
gathered = self.GetInputDataObject(0, 1)
traffic = pieces.GetFieldData().GetArray("PieceTracingTraffic")
values = {"Rank": rank, "Message": digest(pieces), "Reference": digest(gathered),
          "Lines": pieces.GetNumberOfLines()}
for k in range(traffic.GetNumberOfComponents() if traffic else 0):
    values[traffic.GetComponentName(k)] = traffic.GetComponent(0, k)
""" + VALUES_AS_ONE_POINT


def per_rank(pieces, gathered):
    data = sm.Fetch(ProgrammableFilter(Input=[pieces, gathered], Script=PER_RANK,
                                       OutputDataSetType="vtkPolyData"))
    pd = data.GetPointData()
    rows = {}
    for i in range(data.GetNumberOfPoints()):
        rows[str(int(pd.GetArray("Rank").GetValue(i)))] = {
            pd.GetArrayName(k): pd.GetArray(k).GetValue(i) for k in range(pd.GetNumberOfArrays())}
    return rows


arrangement = SurfaceArrangement(Surface=surface, Curves=traced)
labels = LabelArrangementCells(Input=arrangement, PerTriangleLabels=1)
boolean = SurfaceBoolean(Input=labels, Operation="Union", ShapeA=0, ShapeB=2)
results = {"ranks": ranks(), "surface_triangles": sm.Fetch(mesh).GetNumberOfCells(),
           "traced": polylines(sm.Fetch(traced)), "tracing": per_rank(traced, reference)}
for name, proxy, arrays in (("arrangement", arrangement, ["ArrangementCell"]),
                            ("labels", labels, ["ArrangementCell", "Labels"]),
                            ("boolean", boolean, ["ArrangementCell", "Region"])):
    data = fetched(proxy)
    results[name] = {"triangles": data.GetNumberOfCells(), "by_source": per_source(data, arrays),
                     "held": holders(data), "NumberOfCells": field(data, "NumberOfCells"),
                     "CellLabels": field(data, "CellLabels"),
                     "ShapeConsistent": field(data, "ShapeConsistent"),
                     "plugs": [field(data, a) for a in ("CellComponent", "ZeroCellCandidates",
                                                        "NumberOfBoundaryPlugs",
                                                        "BoundaryPlugLinks")],
                     "pieces": field(data, "ArrangementOnPieces") is not None}

# The zero cell given by a point (inside the first circle only): found on the rank owning the
# point's triangle, shared with every rank; the same labels as one rank.
pointed = LabelArrangementCells(Input=arrangement, ZeroCellMode="Point",
                                ZeroCellPoint=list(rays.hit(0.0, -0.035)))
data = sm.Fetch(pointed)
results["pointed"] = {"CellLabels": field(data, "CellLabels"),
                      "ShapeConsistent": field(data, "ShapeConsistent")}


# Port 1: the region's boundary loops (whole on rank 0 when on pieces).
boundary = fetched(OutputPort(boolean, 1))
results["boundary"] = {"lines": lines(boundary),
                       "pieces": field(boundary, "ArrangementOnPieces") is not None,
                       "Expression": field(boundary, "Expression")}
# A filter that gathers its input cannot use the pieces: it refuses (empty output), never a
# wrong answer.
middle = rays.hit(0.0, 0.0)
samples = sample_source([(circles[0][0][18], tuple(m - x for m, x in zip(middle,
                                                                            circles[0][0][18])))])
bsc = BoundarySampledCurves(Input=labels, Samples=samples)
results["bsc"] = {"triangles": sm.Fetch(bsc).GetNumberOfCells()}

# The LocallyShortest method does not trace on pieces: gathered (a warning says why), with the
# one-rank polylines and a message 0 on rank 0 for Surface Arrangement on pieces.
shortest = TraceSurfaceCurves(Surface=surface, Curves=control, GeodesicMethod="Locally shortest")
shortest_reference = TraceSurfaceCurves(Surface=whole, Curves=control,
                                        GeodesicMethod="Locally shortest")
results["shortest"] = {"traced": polylines(sm.Fetch(shortest)),
                       "tracing": per_rank(shortest, shortest_reference)}

# An edit of the curves only (the first circle moved): the ringed piece and the directory are
# kept, and the message still equals the gathered path's.
moved = list(control.Points)
moved[0:3] = [x + 0.002 for x in moved[0:3]]
control.Points = moved
boolean.UpdatePipeline()
results["edited"] = {"tracing": per_rank(traced, reference),
                     "boolean": per_source(fetched(boolean), ["ArrangementCell", "Region"])}

# A curve naming a triangle no rank holds: an error naming the curve on every rank, no rank
# left waiting.
BAD = """
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkIdTypeArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray
from vtkmodules.vtkParallelCore import vtkMultiProcessController
out = self.GetOutput()
if vtkMultiProcessController.GetGlobalController().GetLocalProcessId() == 0:
    points = vtkPoints()
    triangles = vtkIdTypeArray()
    triangles.SetName("TriangleId")
    uv = vtkDoubleArray()
    uv.SetName("Barycentric")
    uv.SetNumberOfComponents(2)
    lines = vtkCellArray()
    lines.InsertNextCell(3)
    for i, t in enumerate((3, 40, 1000000)):
        points.InsertNextPoint(0, 0, 0)
        triangles.InsertNextValue(t)
        uv.InsertNextTuple2(0.25, 0.25)
        lines.InsertCellPoint(i)
    out.SetPoints(points)
    out.SetLines(lines)
    out.GetPointData().AddArray(triangles)
    out.GetPointData().AddArray(uv)
"""
bad_curves = ProgrammableSource(Script=BAD, OutputDataSetType="vtkPolyData")
bad = TraceSurfaceCurves(Surface=surface, Curves=bad_curves)
bad.UpdatePipeline()
errors = sm.Fetch(bad).GetFieldData().GetAbstractArray("TraceErrors")
results["bad"] = [errors.GetValue(i) for i in range(errors.GetNumberOfValues())] if errors else []
with open(args.json, "w") as f:
    json.dump(results, f, indent=1, sort_keys=True)
print("done", ranks())

"""The one-step BoolSurf filter on the pieces of a surface split across MPI ranks, its outputs
written as JSON per source triangle: run by TestPython3MpiOneStep.py with pvbatch on 1, 2 and
3 ranks, whose unions over ranks must agree with one rank's outputs.

    mpiexec -np N pvbatch Testing/Python/MpiOneStep.py --json out.json [--partitions K]

The surface and the three circles are MpiPiecesChain.py's (mpi_pieces_fetch.split_eight). The
filter answers several Booleans (the labeled arrangement reused between them), a zero cell given
by a point, an edit of the curves and an open polyline clipped by the region (port 3, also by
a region bounded by one whole circle, inside and outside); the
stage chain on the same pieces gives the boundary loops and control curves the filter's ports 1
and 2 must equal; Selection BSC runs on the gathered surface (a warning says why), and switching
back to a Boolean runs on the pieces again.
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mpi_pieces_fetch import (control_curves, fetched, field, holders, lines,  # noqa: E402
                              per_source, ranks, sample_source, start)
from paraview.simple import *  # noqa: E402,F401,F403
from paraview import servermanager as sm  # noqa: E402

args, (mesh, surface, rays, circles, control) = start(__doc__, globals())
one = BoolSurf(Surface=surface, Curves=control, Operation="Union", ShapeA=0, ShapeB=2)
# The stage chain on the same pieces: the filter's port 1 must be its port 1.
traced = TraceSurfaceCurves(Surface=surface, Curves=control)
labels = LabelArrangementCells(Input=SurfaceArrangement(Surface=surface, Curves=traced))
chain = SurfaceBoolean(Input=labels, Operation="Union", ShapeA=0, ShapeB=2)


def stage_names(data):
    """The steps StageTimes names (on pieces: the steps this update ran)."""
    times = data.GetFieldData().GetArray("StageTimes")
    return [times.GetComponentName(k) for k in range(times.GetNumberOfComponents())] if times \
        else None


def outputs(proxy):
    """The region per source triangle, who holds it, its field data, the boundary loops and
    the sizes of ports 2 and 3."""
    data = fetched(proxy)
    boundary = fetched(OutputPort(proxy, 1))
    return {"triangles": data.GetNumberOfCells(),
            "by_source": per_source(data, ["ArrangementCell"]), "held": holders(data),
            "fields": {name: field(data, name) for name in ("CellLabels", "ShapeConsistent",
                                                            "ShapeIds", "Expression")},
            "StageTimes": stage_names(data),
            "pieces": field(data, "ArrangementOnPieces") is not None,
            "lines": lines(boundary), "expression": field(boundary, "Expression"),
            "ports23": [control_curves(fetched(OutputPort(proxy, k))) for k in (2, 3)],
            "held23": sorted({int(held) for k in (2, 3) for held in holders(
                fetched(OutputPort(proxy, k)))})}


results = {"ranks": ranks(), "surface_triangles": sm.Fetch(mesh).GetNumberOfCells(),
           "chain": {"lines": lines(fetched(OutputPort(chain, 1))),
                     "ports23": [control_curves(fetched(OutputPort(chain, k))) for k in (2, 3)]}}
for name, settings in (("union", dict(Operation="Union", ShapeA=0, ShapeB=2)),
                       ("intersection", dict(Operation="Intersection", ShapeA=0, ShapeB=1)),
                       ("difference", dict(Operation="Difference", ShapeA=2, ShapeB=0)),
                       ("expression", dict(Operation="Expression", Expression="(S0 | S1) & ~S2"))):
    for key, value in settings.items():
        setattr(one, key, value)
    results[name] = outputs(one)

# The zero cell given by a point (inside the first circle only): other labels.
one.Operation = "Union"
one.ShapeA, one.ShapeB = 0, 2
one.ZeroCellMode = "Point"
one.ZeroCellPoint = list(rays.hit(0.0, -0.035))
results["pointed"] = outputs(one)
one.ZeroCellMode = "Automatic"

# An edit of the curves only (the first circle's first point moved).
moved = list(control.Points)
moved[0:3] = [x + 0.002 for x in moved[0:3]]
control.Points = moved
results["edited"] = outputs(one)

# Selection BSC does not run on pieces: gathered, the one-rank answer. Then a Boolean again, on
# the pieces.
middle = rays.hit(0.0, 0.0)
samples = sample_source([(circles[0][0][18], tuple(m - x for m, x in zip(middle,
                                                                            circles[0][0][18])))])
one.Samples = samples
one.Selection = "BSC"
results["bsc"] = outputs(one)
one.Selection = "Boolean"
results["back"] = outputs(one)

# An open polyline across the first circle (shape 3, crossing no other curve): port 3 clips it
# to the union's region.
line = [rays.hit(x, -0.035) for x in (-0.09, -0.045, 0.0, 0.045, 0.09)]
with_line = SurfaceCurves(Surface=surface,
                          Points=[x for pts, _ in circles for p in pts for x in p] +
                          [x for p in line for x in p],
                          CurveSizes=[len(pts) for pts, _ in circles] + [len(line)],
                          ShapeIds=[shape for _, shape in circles] + [3],
                          ClosedCurves=[1, 1, 1, 0])
clipping = BoolSurf(Surface=surface, Curves=with_line, Operation="Union", ShapeA=0, ShapeB=2)
results["open"] = outputs(clipping)
# The first circle alone and its outside: loops that are one closed curve all around, which
# the second circle and the polyline meet (walked along the circle, then against it), and the
# polyline clipped in one piece, then in two.
clipping.Operation = "Expression"
clipping.Expression = "S0"
results["whole"] = outputs(clipping)
clipping.Expression = "~S0"
results["whole_reversed"] = outputs(clipping)
with open(args.json, "w") as f:
    json.dump(results, f, indent=1, sort_keys=True)
print("done", ranks())

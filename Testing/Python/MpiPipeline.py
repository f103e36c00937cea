"""Every BoolSurf filter on one scene, its results written as JSON: run by
TestPython3MpiRanks.py with pvbatch on 1, 2 and 3 MPI ranks, whose answers must agree.

    mpiexec -np N pvbatch Testing/Python/MpiPipeline.py --json out.json [--distribute]

--distribute splits the surface across the ranks first (RedistributeDataSet, then Extract
Surface: every rank holds a piece with global cell ids), as a parallel reader would; the
filters gather the pieces to the first rank. Curves come from a Surface Curves source (its
points are properties, so every rank has the same proxy; the curves exist once, on rank 0).
"""
import argparse
import json
import os
import sys

source_dir = os.environ.get("BOOLSURF_SOURCE_DIR",
                            os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(source_dir, "Examples"))
from boolsurf_example_utils import (SurfaceRays, area, curves_source, load_plugin,  # noqa: E402
                                    ranks, sample_source, surface_circle)
from paraview.simple import *  # noqa: E402,F401,F403
from paraview import servermanager as sm  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--json", required=True)
parser.add_argument("--distribute", action="store_true")
args = parser.parse_args()
load_plugin(globals())

mesh = PLYReader(FileNames=[os.path.join(source_dir, "Data", "eight.ply")])
surface = mesh
if args.distribute:
    surface = ExtractSurface(Input=RedistributeDataSet(Input=mesh))
surface.UpdatePipeline()
rays = SurfaceRays(mesh, axis=1)
discs = [surface_circle(rays, (0.0, -0.035), 0.06), surface_circle(rays, (0.0, 0.035), 0.06)]
control = curves_source([(discs[0], 0), (discs[1], 1)], surface)


def cells(proxy, port=0):
    return sm.Fetch(proxy, idx=port).GetNumberOfCells()


def distinct(proxy, array, port=0):
    data = sm.Fetch(proxy, idx=port).GetCellData().GetArray(array)
    return len({data.GetValue(i) for i in range(data.GetNumberOfTuples())}) if data else 0


results = {"ranks": ranks()}
if args.distribute:
    # How many ranks hold a piece of the surface (the point of --distribute).
    ids = sm.Fetch(ProcessIdScalars(Input=surface)).GetPointData().GetArray("ProcessId")
    results["surface_pieces"] = len({ids.GetValue(i) for i in range(ids.GetNumberOfTuples())})
check = CheckSurface(Input=surface)
genus = sm.Fetch(check).GetFieldData().GetArray("Genus")
results["check"] = {"triangles": cells(check), "genus": genus.GetValue(0) if genus else None}
results["curves"] = {"points": sm.Fetch(control).GetNumberOfPoints(), "cells": cells(control)}
traced = TraceSurfaceCurves(Surface=surface, Curves=control)
results["trace"] = {"points": sm.Fetch(traced).GetNumberOfPoints(), "cells": cells(traced)}
arrangement = SurfaceArrangement(Surface=surface, Curves=traced)
results["arrangement"] = {"triangles": cells(arrangement),
                          "cells": distinct(arrangement, "ArrangementCell")}
labels = LabelArrangementCells(Input=arrangement)
results["labels"] = {"triangles": cells(labels)}
boolean = SurfaceBoolean(Input=labels, Operation="Intersection")
results["boolean"] = {"triangles": cells(boolean), "area": area(boolean)}
one = BoolSurf(Surface=surface, Curves=control, Operation="SymmetricDifference")
results["one_step"] = {"triangles": cells(one), "area": area(one),
                       "boundary_points": sm.Fetch(one, idx=1).GetNumberOfPoints(),
                       "control_curves": cells(one, 2)}
# Boundary-Sampled Curves: a sample on each disc's boundary, pointing to the middle of the
# two discs (into both); the samples come from a BSC Samples source (properties: they exist
# once under MPI, as the curves do).
middle = rays.hit(0.0, 0.0)
samples = sample_source([(p, tuple(m - x for m, x in zip(middle, p)))
                         for p in (discs[0][18], discs[1][6])])
results["samples"] = {"points": sm.Fetch(samples).GetNumberOfPoints()}
bsc = BoolSurf(Surface=surface, Curves=control, Samples=samples, Selection="BSC")
results["bsc"] = {"triangles": cells(bsc), "area": area(bsc)}
resolved = ResolveInconsistentShapes(Surface=surface, Curves=control)
results["resolve"] = {"curves": cells(resolved)}
drawing = MapSVGOntoSurface(Input=surface, FileName=os.path.join(source_dir, "Data", "star.svg"),
                            Center=rays.hit(0.0, 0.0), Radius=0.05)
star = BoolSurf(Surface=surface, Curves=drawing, ShapeA=-1, ShapeB=-1, FillRule="EvenOdd")
results["svg"] = {"curves": cells(drawing), "area": area(star)}
finer = SubdivideSurfaceWithCurves(Surface=surface, Curves=control)
results["subdivide"] = {"triangles": cells(finer), "curve_points": sm.Fetch(finer, idx=1)
                        .GetNumberOfPoints()}
# A scene file (read on every rank that executes the reader: the curves must come out once).
scene_path = args.json + ".scene.json"
with open(scene_path, "w") as f:
    json.dump({"model": "eight.ply",
               "points": [{"face": 10, "uv": uv} for uv in
                          ([0.1, 0.1], [0.8, 0.1], [0.1, 0.8], [0.3, 0.3], [0.7, 0.2],
                           [0.6, 0.3])],
               "polygons": [[0, 1, 2], [3, 4, 5]], "shapes": [[0], [1]],
               "operations": [{"a": 0, "b": 1, "type": 0}]}, f)
reader = BoolSurfSceneReader(FileName=scene_path, MeshSearchPath=os.path.join(source_dir, "Data"))
scene = BoolSurf(Surface=OutputPort(reader, 0), Curves=OutputPort(reader, 1), Operation="Union")
results["scene"] = {"curves": cells(reader, 1), "triangles": cells(scene), "area": area(scene)}
with open(args.json, "w") as f:
    json.dump(results, f, indent=1, sort_keys=True)
print(json.dumps(results, sort_keys=True))

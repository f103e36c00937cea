"""The one-step BoolSurf filter on Data/eight.ply, from pvpython connected to a pvserver (or in
a builtin session without --server), its region written as JSON: run by
TestPython3ClientServer.py.

    pvpython Testing/Python/ClientServerPipeline.py --json out.json [--server localhost:11111]
"""
import argparse
import json
import os
import sys

source_dir = os.environ.get("BOOLSURF_SOURCE_DIR",
                            os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(source_dir, "Examples"))
from paraview.simple import *  # noqa: E402,F401,F403
from paraview import servermanager as sm  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--json", required=True)
parser.add_argument("--server")
args = parser.parse_args()
plugin = os.environ["BOOLSURF_PLUGIN"]
if args.server:
    host, port = args.server.split(":")
    Connect(host, int(port))
    # The filters run on the server; the client needs the proxy definitions too.
    LoadPlugin(plugin, remote=True, ns=globals())
    LoadPlugin(plugin, remote=False, ns=globals())
else:
    LoadPlugin(plugin, remote=False, ns=globals())
from boolsurf_example_utils import SurfaceRays, area, curves_source, surface_circle  # noqa: E402

mesh = PLYReader(FileNames=[os.path.join(source_dir, "Data", "eight.ply")])
rays = SurfaceRays(mesh, axis=1)
control = curves_source([(surface_circle(rays, (0.0, -0.035), 0.06), 0),
                         (surface_circle(rays, (0.0, 0.035), 0.06), 1)], mesh)
one = BoolSurf(Surface=mesh, Curves=control, Operation="SymmetricDifference")
one.UpdatePipeline()
region = sm.Fetch(one)
cells = region.GetCellData().GetArray("ArrangementCell")
result = {"triangles": region.GetNumberOfCells(), "area": area(one),
          "cells": len({cells.GetValue(i) for i in range(cells.GetNumberOfTuples())}),
          "boundary_points": sm.Fetch(one, idx=1).GetNumberOfPoints(),
          "ranks": sm.ActiveConnection.GetNumberOfDataPartitions()}
with open(args.json, "w") as f:
    json.dump(result, f)
print(result)

"""The inputs of mpi_scale.py, made once per mesh: the surface with point and cell GlobalIds as
one file (the one-rank run reads it) and as a partitioned file of P pieces (P ranks each read
their own piece, so no rank ever reads the whole surface), and the scenes' curves.

    pvpython mpi_scale_prepare.py --mesh M.ply [--subdivide 1] --out DIR/NAME --whole
        writes DIR/NAME.vtp (global ids in the mesh's order) and, for each --scene, the
        placed curves DIR/NAME-<scene>.json (paper_scale_scene.py; placed on the whole mesh)
    mpiexec -np P pvbatch mpi_scale_prepare.py --out DIR/NAME --pieces
        reads DIR/NAME.vtp on rank 0, splits it with RedistributeDataSet (P pieces) and writes
        DIR/NAME-P.pvtp (its pieces DIR/NAME-P/NAME-P_<rank>.vtp)

Subdivision is VTK's vtkLinearSubdivisionFilter (1-to-4 midpoint), as the 4.3M benchmark of
Benchmarks/VTK/BenchmarkFilterEdits.cxx makes igea_1m subdivided once. On a subdivided mesh the
scenes are placed on the mesh before subdivision (the same surface: placing the 112 shapes on
the 4.3M triangles in Python took over 20 minutes, on igea_1m tens of seconds; that placement is
cached too, DIR/NAME-<scene>-coarse.json) and each control point is carried to the
subdivided triangle holding it, its position unchanged.
"""
import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

from vtkmodules.vtkFiltersParallelDIY2 import vtkGenerateGlobalIds  # noqa: E402
from vtkmodules.vtkFiltersModeling import vtkLinearSubdivisionFilter  # noqa: E402
from vtkmodules.vtkIOPLY import vtkPLYReader  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter  # noqa: E402


def barycentric_in(mesh, t, x):
    """(u, v) of x in triangle t of `mesh` by least squares in its plane, and how far outside
    the triangle that is (0 inside)."""
    ids = mesh.GetCell(t).GetPointIds()
    a, b, c = (mesh.GetPoint(ids.GetId(k)) for k in range(3))
    e1 = [b[i] - a[i] for i in range(3)]
    e2 = [c[i] - a[i] for i in range(3)]
    d = [x[i] - a[i] for i in range(3)]
    dot = lambda p, q: sum(p[i] * q[i] for i in range(3))  # noqa: E731
    a11, a12, a22 = dot(e1, e1), dot(e1, e2), dot(e2, e2)
    b1, b2 = dot(d, e1), dot(d, e2)
    det = a11 * a22 - a12 * a12
    u = (a22 * b1 - a12 * b2) / det
    v = (a11 * b2 - a12 * b1) / det
    return u, v, max(0.0, -u, -v, u + v - 1)


def subdivided_versions(coarse, fine, versions):
    """The scene placed on `coarse`, on `fine` (vtkLinearSubdivisionFilter once: the children of
    coarse triangle t are fine triangles 4t .. 4t + 3): each control point in the child holding
    it, its barycentric (u, v) there clamped into the child (the subdivided mesh's midpoints are
    rounded to floats, so a point near a child's edge may lie off it by about 1e-6)."""
    out = []
    for points, triangles, weights, sizes in versions:
        mapped_triangles, mapped_weights = [], []
        for i, t in enumerate(triangles):
            # The point as its triangle and weights name it (its listed position may be that of
            # a neighbouring triangle's form, off this triangle's plane by rounding).
            ids = coarse.GetCell(t).GetPointIds()
            a, b, c = (coarse.GetPoint(ids.GetId(k)) for k in range(3))
            u, v = weights[2 * i], weights[2 * i + 1]
            x = [(1 - u - v) * a[k] + u * b[k] + v * c[k] for k in range(3)]
            best = min((barycentric_in(fine, 4 * t + k, x) + (4 * t + k,) for k in range(4)),
                       key=lambda r: r[2])
            u, v, outside, child = best
            if outside > 1e-4:  # the midpoints are stored as floats
                raise RuntimeError("control point %d: no child of triangle %d holds it (%g)" % (
                    i, t, outside))
            u, v = min(max(u, 0.0), 1.0), min(max(v, 0.0), 1.0)
            if u + v > 1:
                u, v = u / (u + v), v / (u + v)
            mapped_triangles.append(child)
            mapped_weights += [u, v]
        out.append((points, mapped_triangles, mapped_weights, sizes))
    return out


def whole(args):
    import json
    from paper_scale_scene import scene_versions
    reader = vtkPLYReader()
    reader.SetFileName(args.mesh)
    reader.Update()
    mesh = coarse = reader.GetOutput()
    if args.subdivide:
        subdivide = vtkLinearSubdivisionFilter()
        subdivide.SetInputData(mesh)
        subdivide.SetNumberOfSubdivisions(args.subdivide)
        subdivide.Update()
        mesh = subdivide.GetOutput()
    ids = vtkGenerateGlobalIds()
    ids.SetInputData(mesh)
    ids.Update()
    mesh = ids.GetOutput()
    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(mesh)
    writer.SetFileName(args.out + ".vtp")
    writer.SetDataModeToAppended()
    writer.EncodeAppendedDataOff()
    writer.Write()
    print("%s.vtp: %d triangles, %d points" % (args.out, mesh.GetNumberOfCells(),
                                                mesh.GetNumberOfPoints()))
    for scene in args.scene:
        cache = "%s-%s.json" % (args.out, scene)
        if args.subdivide == 1 and not os.path.exists(cache):
            placed = scene_versions(coarse, scene, "%s-%s-coarse.json" % (args.out, scene))
            versions = subdivided_versions(coarse, mesh, placed)
            with open(cache, "w") as f:
                json.dump({"scene": scene, "cells": mesh.GetNumberOfCells(),
                           "versions": versions}, f)
        versions = scene_versions(mesh, scene, cache)
        print("%s-%s.json: %d curves" % (args.out, scene, len(versions[0][3])))


def pieces(args):
    from paraview.simple import ExtractSurface, RedistributeDataSet, SaveData, XMLPolyDataReader
    from vtkmodules.vtkParallelCore import vtkMultiProcessController
    ranks = vtkMultiProcessController.GetGlobalController().GetNumberOfProcesses()
    surface = XMLPolyDataReader(FileName=[args.out + ".vtp"])
    split = ExtractSurface(Input=RedistributeDataSet(Input=surface))
    split.UpdatePipeline()
    path = "%s-%d.pvtp" % (args.out, ranks)
    SaveData(path, proxy=split, DataMode="Appended", EncodeAppendedData=0,
             CompressorType="None")
    print("%s: %d pieces, %d triangles" % (path, ranks,
                                           split.GetDataInformation().GetNumberOfCells()))


parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--mesh")
parser.add_argument("--subdivide", type=int, default=0)
parser.add_argument("--out", required=True, help="DIR/NAME of the files written")
parser.add_argument("--scene", action="append", default=[], choices=("ten", "paper"))
parser.add_argument("--whole", action="store_true")
parser.add_argument("--pieces", action="store_true")
args = parser.parse_args()
if args.whole:
    whole(args)
if args.pieces:
    pieces(args)

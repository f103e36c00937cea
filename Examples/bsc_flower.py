"""Boundary-Sampled Curves (BSC): a flower of bands and petals on a torus, which no Boolean can
express (in the spirit of BoolSurf Figs. 6 and 19).

Six meridians cut the torus into six bands; each meridian is a shape of its own, and a lone
meridian bounds nothing (it is not null-homologous): every one of these shapes is
inconsistent, so Surface Boolean refuses them all. Three petals (small loops on the top of the
tube) sit in every other band. BSC needs no labels: one sample per meridian points into
the band it should bound, one sample per petal points to its center, and the result is three
bands plus three petals, the least-boundary region whose boundary holds every sample.

    xvfb-run -a pvbatch Examples/bsc_flower.py --output out
writes out/bsc_flower.vtp (the region, inline binary) and out/bsc_flower.png.
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from boolsurf_example_utils import (ROOT, area, curves_source, load_plugin,  # noqa: E402
                                    render_result, sample_source, save_result)
from paraview.simple import *  # noqa: E402,F401,F403
from paraview import servermanager as sm  # noqa: E402
from vtkmodules.vtkCommonCore import vtkPoints  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--output", default=os.path.join(ROOT, "out"))
parser.add_argument("--bands", type=int, default=6, help="meridians (even)")
args = parser.parse_args()
load_plugin(globals())
os.makedirs(args.output, exist_ok=True)

R, r = 1.0, 0.4


def torus_point(u, v):
    return ((R + r * math.cos(v)) * math.cos(u), (R + r * math.cos(v)) * math.sin(u),
            r * math.sin(v))


def trivial_source(polydata):
    source = PVTrivialProducer()
    source.GetClientSideObject().SetOutput(polydata)
    source.UpdatePipeline()
    return source


# The surface: a torus of nu x nv quads split in two, (du, dv) counter-clockwise seen from
# outside (normals outward).
nu, nv = 120, 48
surface = vtkPolyData()
positions = vtkPoints()
positions.SetDataTypeToDouble()
for i in range(nu):
    for j in range(nv):
        positions.InsertNextPoint(torus_point(2 * math.pi * i / nu, 2 * math.pi * j / nv))
polys = vtkCellArray()
for i in range(nu):
    for j in range(nv):
        a, b = i * nv + j, ((i + 1) % nu) * nv + j
        c, d = ((i + 1) % nu) * nv + (j + 1) % nv, i * nv + (j + 1) % nv
        polys.InsertNextCell(3, (a, b, c))
        polys.InsertNextCell(3, (a, c, d))
surface.SetPoints(positions)
surface.SetPolys(polys)
mesh = trivial_source(surface)

# Curves: meridians (one shape each) and petals (one shape each).
n = args.bands
curves, samples = [], []  # samples: (point, direction)
for k in range(n):
    u = 2 * math.pi * (k + 0.5) / n  # off the mesh's vertex columns
    curves.append(([torus_point(u, 2 * math.pi * j / 12) for j in range(12)], k))
    # On the outer equator, pointing along +u on even meridians and -u on odd ones: the bands
    # that start at an even meridian are inside.
    side = 1 if k % 2 == 0 else -1
    samples.append((torus_point(u, 0), (-side * math.sin(u), side * math.cos(u), 0)))
for k in range(1, n, 2):
    u0 = 2 * math.pi * (k + 1) / n  # the middle of a band that is outside
    petal = [torus_point(u0 + 0.3 * math.cos(t), 0.5 * math.pi + 0.9 * math.sin(t))
             for t in (2 * math.pi * j / 16 for j in range(16))]
    curves.append((petal, n + k))
    # A sample on the petal, pointing to its center.
    p = torus_point(u0 + 0.3, 0.5 * math.pi)
    c = torus_point(u0, 0.5 * math.pi)
    samples.append((p, tuple(c[i] - p[i] for i in range(3))))
control = curves_source(curves, mesh)

sample_points = sample_source(samples)

# The one-step filter with Selection = BSC: trace, arrange, then select by the samples.
flower = BoolSurf(Surface=mesh, Curves=control, Samples=sample_points, Selection="BSC")
flower.UpdatePipeline()
region = sm.Fetch(flower)
dropped = region.GetFieldData().GetArray("DroppedSamples")
print("BSC flower: %d triangles, area %.4f of %.4f; %d samples, %d dropped" % (
    region.GetNumberOfCells(), area(flower), area(mesh), len(samples),
    dropped.GetNumberOfTuples() if dropped else -1))

save_result(flower, os.path.join(args.output, "bsc_flower.vtp"))
render_result(os.path.join(args.output, "bsc_flower.png"), mesh, flower,
              boundary=OutputPort(flower, 1), curves=None, view_axis=2, view_up=(0, 1, 0))

"""pvpython: the stage filters give the one-step filter's answer, bit for bit.

Trace Surface Curves -> Surface Arrangement -> Label Arrangement Cells -> Surface Boolean, and
the one-step BoolSurf, on random closed curves over a sphere, a torus, a flat patch and (when
the shared mesh collection is present) a scanned surface. Control points are given as
coordinates (projected by the filters), as exact surface points, and as surface points pushed
1e-16 .. 1e-12 off mesh edges and vertices, in float32 and float64 meshes. Both pipelines must
refuse the same inputs and otherwise give the same region: the same points, cells and arrays.
"""
import math
import os
import random
import sys

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager as sm
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkIOPLY import vtkPLYReader

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from stage_chain_helpers import producer, random_curves, same_data, triangles  # noqa: E402

LoadPlugin(os.environ["BOOLSURF_PLUGIN"], remote=False, ns=globals())
rng = random.Random(26)


def torus(R=1.0, r=0.4, nu=28, nv=12):
    points = vtkPoints()
    points.SetDataTypeToDouble()
    polys = vtkCellArray()
    for i in range(nu):
        for j in range(nv):
            u, v = 2 * math.pi * i / nu, 2 * math.pi * j / nv
            points.InsertNextPoint((R + r * math.cos(v)) * math.cos(u),
                                   (R + r * math.cos(v)) * math.sin(u), r * math.sin(v))
    for i in range(nu):
        for j in range(nv):
            a, b = i * nv + j, ((i + 1) % nu) * nv + j
            c, d = ((i + 1) % nu) * nv + (j + 1) % nv, i * nv + (j + 1) % nv
            polys.InsertNextCell(3, [a, b, c])
            polys.InsertNextCell(3, [a, c, d])
    pd = vtkPolyData()
    pd.SetPoints(points)
    pd.SetPolys(polys)
    return pd


def with_point_type(pd, data_type):
    points = vtkPoints()
    points.SetDataType(data_type)
    points.DeepCopy(pd.GetPoints())
    out = vtkPolyData()
    out.SetPoints(points)
    out.SetPolys(pd.GetPolys())
    return out


def surfaces():
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(24)
    sphere.SetPhiResolution(16)
    plane = vtkPlaneSource()
    plane.SetResolution(12, 12)
    found = [("sphere", triangles(sphere)), ("torus", torus()), ("plane", triangles(plane))]
    shared = os.environ.get("BOOLSURF_SHARED_DATA", "")
    bunny = os.path.join(shared, "meshes", "bunny_npm.ply")
    if shared and os.path.exists(bunny):
        reader = vtkPLYReader()
        reader.SetFileName(bunny)
        found.append(("bunny_npm", triangles(reader)))
    else:
        print("shared mesh collection absent: scanned-surface case skipped")
    for name, pd in found:
        for data_type, label in ((11, "float64"), (10, "float32")):  # VTK_DOUBLE, VTK_FLOAT
            yield "%s %s" % (name, label), with_point_type(pd, data_type)


cases = refusals = 0
for name, surface_pd in surfaces():
    surface = producer(surface_pd)
    for form in ("coordinates", "exact", "near-edge", "near-vertex"):
        for trial in range(3):
            what = "%s, %s, trial %d" % (name, form, trial)
            curves = producer(random_curves(surface_pd, rng, form))
            operation = ["Union", "Intersection", "Difference", "SymmetricDifference"][trial % 4]
            a, b = (-1, -1) if operation == "Union" else (0, 1)
            one = BoolSurf(Surface=surface, Curves=curves, Operation=operation, ShapeA=a,
                           ShapeB=b)
            traced = TraceSurfaceCurves(Surface=surface, Curves=curves)
            arrangement = SurfaceArrangement(Surface=surface, Curves=traced)
            labels = LabelArrangementCells(Input=arrangement)
            boolean = SurfaceBoolean(Input=labels, Operation=operation, ShapeA=a, ShapeB=b)
            one.UpdatePipeline()
            boolean.UpdatePipeline()
            one_region, chain_region = sm.Fetch(one), sm.Fetch(boolean)
            # An empty region with no Expression field is a refusal (the filters' outputs are
            # emptied on error).
            one_ok = one_region.GetFieldData().GetAbstractArray("Expression") is not None
            chain_ok = chain_region.GetFieldData().GetAbstractArray("Expression") is not None
            assert one_ok == chain_ok, (what, one_ok, chain_ok)
            cases += 1
            if not one_ok:
                refusals += 1
                continue
            for port in range(4):
                same_data(sm.Fetch(one, idx=port), sm.Fetch(boolean, idx=port),
                          "%s, port %d" % (what, port))
            for proxy in (boolean, labels, arrangement, traced, one, curves):
                Delete(proxy)
    Delete(surface)
print("stage chain == one-step on %d drawings (%d refused by both)" % (cases, refusals))
assert cases - refusals >= cases // 2, (cases, refusals)

"""What a drag in the curve editor costs the pipeline: Surface Curves (10 circles of 12 exact
control points) -> BoolSurf (union of all shapes); each update moves one control point a little,
as the editor does during a drag (TriangleId -1: the source snaps it). Prints the median wall
time of 15 updates of Surface Curves alone (snap + traced display) and of the chain. (The
editor adds a picking render per mouse move, which depends on the GPU, not measured here.)

    pvpython Benchmarks/editor_drag.py <mesh.ply>
"""
import math
import os
import statistics
import sys
import time
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Examples"))
from paraview.simple import *  # noqa: E402,F401,F403
from paraview import servermanager as sm  # noqa: E402
from boolsurf_example_utils import SurfaceRays, load_plugin, surface_circle  # noqa: E402
load_plugin(globals())
mesh = PLYReader(FileNames=[sys.argv[1]])
mesh.UpdatePipeline()
b = mesh.GetDataInformation().GetBounds()
ext = [b[1]-b[0], b[3]-b[2], b[5]-b[4]]
axis = ext.index(min(ext)); u, v = (axis+1) % 3, (axis+2) % 3
rays = SurfaceRays(mesh, axis)
cu, cv = (b[2*u]+b[2*u+1])/2, (b[2*v]+b[2*v+1])/2
r = 0.06 * min(ext[u], ext[v])
pts, sizes = [], []
for k in range(10):
    a = 2*math.pi*k/10
    c = surface_circle(rays, (cu + 2.2*r*math.cos(a), cv + 2.2*r*math.sin(a)), r, n=12)
    pts += [x for p in c for x in p]; sizes.append(12)
n = len(pts)//3
curves = SurfaceCurves(Surface=mesh, Points=pts, CurveSizes=sizes, ShapeIds=list(range(10)))
curves.UpdatePipeline()
out = sm.Fetch(curves)
tri = out.GetPointData().GetArray("TriangleId"); bary = out.GetPointData().GetArray("Barycentric")
curves.TriangleIds = [tri.GetValue(i) for i in range(n)]
curves.Barycentrics = [x for i in range(n) for x in bary.GetTuple2(i)]
one = BoolSurf(Surface=mesh, Curves=curves, ShapeA=-1, ShapeB=-1, Operation="Union")
one.UpdatePipeline()
base = list(pts)
ids = list(curves.TriangleIds)
def move(step):
    p = list(base); p[0] += 0.002 * r * step; p[1] += 0.001 * r * step
    t = list(ids); t[0] = -1
    curves.Points = p; curves.TriangleIds = t
alone, chain = [], []
for step in range(1, 16):
    move(step); t0 = time.perf_counter(); curves.UpdatePipeline(); alone.append(1000*(time.perf_counter()-t0))
    one.UpdatePipeline(); chain.append(1000*(time.perf_counter()-t0))
print("mesh %s: %d triangles; drag one point: SurfaceCurves %.1f ms, SurfaceCurves+BoolSurf %.1f ms (medians of 15)" % (
    os.path.basename(sys.argv[1]), mesh.GetDataInformation().GetNumberOfCells(), statistics.median(alone), statistics.median(chain)))

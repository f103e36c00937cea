"""Renders the pictures of the filter pages (Docs/Filters/images/*.png).

    xvfb-run -a pvbatch Docs/make_pictures.py [--output Docs/Filters/images]

Uses the meshes in Data/ and, for the scene reader, ../shared/data/boolsurf-scenes when present
($BOOLSURF_SHARED_DATA overrides the location; the picture is skipped when it is absent).
"""
import argparse
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(here)
sys.path.insert(0, os.path.join(root, "Examples"))
from boolsurf_example_utils import (SurfaceRays, curves_source, first_hit,  # noqa: E402
                                    load_plugin, render_result, sample_source, surface_circle)
from paraview.simple import *  # noqa: E402,F401,F403

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--output", default=os.path.join(here, "Filters", "images"))
args = parser.parse_args()
load_plugin(globals())
os.makedirs(args.output, exist_ok=True)
size = (640, 480)


def out(name):
    return os.path.join(args.output, name + ".png")


# The genus-2 example's shapes: two discs and a band around a tube (see Examples/).
eight = PLYReader(FileNames=[os.path.join(root, "Data", "eight.ply")])
front = SurfaceRays(eight, axis=1)


def tube_loop(z, reverse):
    far = front.far
    points = [first_hit(front, (-0.175, far, z), (-0.175, -far, z)),
              first_hit(front, (-far, 0, z), (far, 0, z)),
              first_hit(front, (-0.175, -far, z), (-0.175, far, z)),
              first_hit(front, (0, 0, z), (-far, 0, z))]
    return points[::-1] if reverse else points


control = curves_source([(surface_circle(front, (0.0, -0.035), 0.06), 0),
                         (surface_circle(front, (0.0, 0.035), 0.06), 1),
                         (tube_loop(0.22, False), 2), (tube_loop(0.30, True), 2)], eight)
traced = TraceSurfaceCurves(Surface=eight, Curves=control)
arrangement = SurfaceArrangement(Surface=eight, Curves=traced)
labels = LabelArrangementCells(Input=arrangement, ColorShape=2)
boolean = SurfaceBoolean(Input=labels, Operation="Expression", Expression="(S0 ^ S1) | S2")
view = dict(view_axis=1, view_up=(0, 0, 1), size=size)

render_result(out("TraceSurfaceCurves"), eight, traced, curves=traced, **view)
render_result(out("SurfaceArrangement"), eight, arrangement, boundary=OutputPort(arrangement, 1),
              color_by="ArrangementCell", **view)
render_result(out("LabelArrangementCells"), eight, labels, boundary=OutputPort(arrangement, 1),
              color_by="ShapeLabel", **view)
render_result(out("SurfaceBoolean"), eight, boolean, boundary=OutputPort(boolean, 1),
              curves=traced, **view)

# Boundary Sampled Curves on the same arrangement: the two tube loops sampled towards the band
# between them, and disc S0 sampled towards its center (its first control point, outside S1).
samples = sample_source([(tube_loop(0.22, False)[0], (0, 0, 1)),
                         (tube_loop(0.30, True)[-1], (0, 0, -1)),
                         (surface_circle(front, (0.0, -0.035), 0.06)[0], (0, 0, -1))])
bsc = BoundarySampledCurves(Input=arrangement, Samples=samples)
render_result(out("BoundarySampledCurves"), eight, bsc, boundary=OutputPort(bsc, 1),
              curves=traced, **view)

nefertiti = PLYReader(FileNames=[os.path.join(root, "Data", "nefertiti_small.ply")])
check = CheckSurface(Input=nefertiti)
render_result(out("CheckSurface"), nefertiti, check, color_by="ComponentId", view_axis=2,
              view_up=(0, 1, 0), size=size)

bunny = PLYReader(FileNames=[os.path.join(root, "Data", "bunny_npm.ply")])
rays = SurfaceRays(bunny, axis=2)
discs = curves_source([(surface_circle(rays, (0.5 + dx, 3.4), 1.0, n=32), k)
                       for k, dx in enumerate((-0.6, 0.6))], bunny)
one = BoolSurf(Surface=bunny, Curves=discs, Operation="Difference", ShapeA=0, ShapeB=1)
render_result(out("BoolSurf"), bunny, one, boundary=OutputPort(one, 1), view_axis=2,
              view_up=(0, 1, 0), size=size)

# Offset Shapes: a disc (S0) grown by 0.3 along the surface and a band of half width 0.3 around
# an open stroke (S1) that passes near it: the fronts merge into one region (S2).
stroke = [rays.hit(x, y) for x, y in ((-1.9, 1.6), (-0.6, 2.2), (0.4, 1.6), (1.6, 2.0))]
disc = surface_circle(rays, (0.6, 2.9), 0.7, n=24)
drawing = SurfaceCurves(Surface=bunny, Points=[x for p in disc + stroke for x in p],
                        CurveSizes=[len(disc), len(stroke)], ShapeIds=[0, 1],
                        ClosedCurves=[1, 0])
grown = OffsetShapes(Surface=bunny, Curves=drawing, Distance=0.3, Shapes="0 1",
                     KeepInputCurves=0, OutputShapeId=2, OutputResolution=2)
margin = BoolSurf(Surface=bunny, Curves=grown, Operation="Union", ShapeA=2, ShapeB=2)
render_result(out("OffsetShapes"), bunny, margin, boundary=OutputPort(margin, 1),
              curves=OutputPort(drawing, 1), view_axis=2, view_up=(0, 1, 0), size=size)

shared = os.environ.get("BOOLSURF_SHARED_DATA") or os.path.join(root, "..", "shared", "data")
scene = os.path.join(shared, "boolsurf-scenes", "tests", "examples", "sphere0.json")
if os.path.exists(scene):
    reader = BoolSurfSceneReader(FileName=scene)
    scene_traced = TraceSurfaceCurves(Surface=reader, Curves=OutputPort(reader, 1))
    scene_labels = LabelArrangementCells(
        Input=SurfaceArrangement(Surface=reader, Curves=scene_traced))
    render_result(out("BoolSurfSceneReader"), reader, scene_labels, curves=scene_traced,
                  color_by="ArrangementCell", view_axis=2, view_up=(0, 1, 0), size=size)
else:
    print("skipped BoolSurfSceneReader.png: %s not found" % scene)

"""Renders the pictures of Docs/Homology.md (Docs/Filters/images/Homology-*.png).

    xvfb-run -a pvbatch Docs/make_homology_pictures.py [--output Docs/Filters/images]

On Data/eight.ply (genus 2): a shape made of a loop around one tube and a disc is
inconsistent; the picture shows its curves and the homology generators in excess, then the
region of the shape after each of the three fixes of Resolve Inconsistent Shapes (as in the
paper's Fig. 7).
"""
import argparse
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(here)
sys.path.insert(0, os.path.join(root, "Examples"))
from boolsurf_example_utils import (SurfaceRays, curves_source, first_hit,  # noqa: E402
                                    load_plugin, surface_circle)
from paraview.simple import *  # noqa: E402,F401,F403
from paraview import servermanager as sm  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--output", default=os.path.join(here, "Filters", "images"))
args = parser.parse_args()
load_plugin(globals())
os.makedirs(args.output, exist_ok=True)
size = [640, 480]

eight = PLYReader(FileNames=[os.path.join(root, "Data", "eight.ply")])
front = SurfaceRays(eight, axis=1)


def tube_loop(z):
    far = front.far
    return [first_hit(front, (-0.175, far, z), (-0.175, -far, z)),
            first_hit(front, (-far, 0, z), (far, 0, z)),
            first_hit(front, (-0.175, -far, z), (-0.175, far, z)),
            first_hit(front, (0, 0, z), (-far, 0, z))]


# Shape 0: a loop around the left tube (not null-homologous) and a disc.
control = curves_source([(tube_loop(0.22), 0), (surface_circle(front, (0.0, -0.035), 0.06), 0)])


def show(png, parts):
    """parts: (proxy, color, line width or None for surfaces, lift) drawn in one view."""
    view = CreateView("RenderView")
    view.ViewSize = size
    view.OrientationAxesVisibility = 0
    view.Background = [1, 1, 1]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    for proxy, color, width, lift in parts:
        if lift:
            # Regions lie on the surface: lift them along their normals to be seen.
            proxy = WarpByVector(Input=GenerateSurfaceNormals(Input=proxy, Splitting=0),
                                 Vectors=["POINTS", "Normals"], ScaleFactor=0.004)
        d = Show(proxy, view)
        d.ColorArrayName = ["POINTS", ""]
        d.AmbientColor = d.DiffuseColor = color
        if width:
            d.LineWidth = width
    camera = view.GetActiveCamera()
    camera.SetFocalPoint(0, 0, 0)
    camera.SetPosition(0, 1, 0)
    camera.SetViewUp(0, 0, 1)
    view.ResetCamera(False)
    Render(view)
    SaveScreenshot(png, view, ImageResolution=size)
    print("wrote %s" % png)
    Delete(view)


gray, black, red, orange = [0.8, 0.8, 0.8], [0, 0, 0], [0.85, 0.1, 0.1], [0.95, 0.45, 0.1]
traced = TraceSurfaceCurves(Surface=eight, Curves=control)
labels = LabelArrangementCells(Input=SurfaceArrangement(Surface=eight, Curves=traced))
labels.UpdatePipeline()
excess = sm.Fetch(labels).GetFieldData().GetArray("HomologyExcess")
in_excess = [g for g in range(excess.GetNumberOfComponents()) if excess.GetComponent(0, g) != 0]
print("generators in excess:", in_excess)
generators = []
for g in in_excess:
    t = Threshold(Input=OutputPort(labels, 1), Scalars=["CELLS", "GeneratorId"])
    try:
        t.LowerThreshold, t.UpperThreshold = g, g
    except AttributeError:
        t.ThresholdRange = [g, g]
    generators.append((t, red, 3, False))  # the tree-cotree loop and its shortened loop
show(os.path.join(args.output, "Homology-inconsistent.png"),
     [(eight, gray, None, False), (traced, black, 2, False)] + generators)

for strategy in ("AddGenerators", "DuplicateReversed", "RemoveCurves"):
    resolved = ResolveInconsistentShapes(Surface=eight, Curves=control, Strategy=strategy)
    region = BoolSurf(Surface=eight, Curves=resolved, Operation="Union", ShapeA=0, ShapeB=0)
    curves = TraceSurfaceCurves(Surface=eight, Curves=resolved)
    show(os.path.join(args.output, "Homology-%s.png" % strategy),
         [(eight, gray, None, False), (region, orange, None, True), (curves, black, 2, False)])

"""Renders the pictures of Docs/WindingNumbers.md (Docs/images/winding_*.png).

    xvfb-run -a -s "-screen 0 1280x1024x24" pvbatch Docs/make_winding_pictures.py \
        [--output Docs/images]

(or `pvpython --force-offscreen-rendering` in place of pvbatch: the same pictures, though not
byte for byte). The plugin is found as the other scripts find it: $BOOLSURF_PLUGIN, else
build/lib/paraview-5.11/plugins/BoolSurf/BoolSurf.so beside Examples/. Needs only Data/ (the
torus is generated here), and gives the same files on every run: the curves are fixed lists of
points, no random numbers. Prints w's range, the residuals and BoundsRegion of each scene.

Two scenes, each through the Winding Numbers filter (`WindingNumbers`):

1. A circle on the bunny (Data/bunny_npm.ply) drawn as three open strokes with gaps between them
   (shape 0): the strokes (winding_bunny_curves.png), the field w, point data `WindingNumber` of
   the Refined Surface (winding_bunny_field.png), and the Region w >= 1/2 with the Completed
   Curves, its boundary (winding_bunny_completed.png).
2. A torus with, in one shape, a meridian (a loop around the tube: it bounds nothing) and a small
   circle on the top: w with `RemoveNonBounding = 0`, a ramp around the handle
   (winding_torus_ramp.png), and with the default correction, only the circle's disc, the
   meridian drawn in red where `BoundsRegion` (port 3) is 0 (winding_torus_corrected.png).
"""
import argparse
import math
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(here)
sys.path.insert(0, os.path.join(root, "Examples"))
from boolsurf_example_utils import SurfaceRays, load_plugin  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403
from paraview import servermanager as sm  # noqa: E402
from vtkmodules.vtkCommonCore import vtkPoints  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--output", default=os.path.join(here, "images"))
args = parser.parse_args()
load_plugin(globals())
os.makedirs(args.output, exist_ok=True)
SIZE = [800, 600]
GRAY, BLACK, BLUE, ORANGE, RED = ([0.82, 0.82, 0.82], [0, 0, 0], [0.15, 0.3, 0.9],
                                  [0.95, 0.45, 0.1], [0.85, 0.05, 0.05])
# Color scales of w: diverging, white at the default Threshold 1/2.
BUNNY_RANGE, TORUS_RANGE = (-0.25, 1.25), (-0.5, 1.5)


def out(name):
    return os.path.join(args.output, "winding_%s.png" % name)


def new_view():
    view = CreateView("RenderView")
    view.ViewSize = SIZE
    view.OrientationAxesVisibility = 0
    view.Background = [1, 1, 1]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    return view


def plain(proxy, view, color, width=None, port=0):
    d = Show(OutputPort(proxy, port), view)
    d.ColorArrayName = ["POINTS", ""]
    d.AmbientColor = d.DiffuseColor = color
    if width:
        d.LineWidth = width
    return d


def field(proxy, view, value_range, title="w"):
    """Port 0 of Winding Numbers colored by w (point data WindingNumber), a diverging map
    centered on the middle of value_range, with its legend."""
    # Normals for smooth shading (the refined surface has none); point data is kept.
    d = Show(GenerateSurfaceNormals(Input=OutputPort(proxy, 0), Splitting=0), view)
    ColorBy(d, ("POINTS", "WindingNumber"))
    lut = GetColorTransferFunction("WindingNumber")
    lut.ApplyPreset("Cool to Warm", True)
    lut.AutomaticRescaleRangeMode = "Never"
    lut.RescaleTransferFunction(value_range[0], value_range[1])
    GetOpacityTransferFunction("WindingNumber").RescaleTransferFunction(*value_range)
    d.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(lut, view)
    bar.Title = title
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    bar.TitleFontSize = 20
    bar.LabelFontSize = 16
    bar.ScalarBarLength = 0.4
    bar.WindowLocation = "Lower Right Corner"
    bar.RangeLabelFormat = "%.2f"
    bar.AddRangeLabels = 1
    return d


def save(view, png, position, up, zoom=1.0, focus=None):
    """Looks along -position at the scene (at `focus` when given), then zooms."""
    Render(view)  # updates the pipelines first: the camera reset below needs their bounds
    camera = view.GetActiveCamera()
    camera.SetFocalPoint(0, 0, 0)
    camera.SetPosition(*position)
    camera.SetViewUp(*up)
    view.ResetCamera(False)
    if focus is not None:
        distance = camera.GetDistance()
        norm = math.sqrt(sum(x * x for x in position))
        camera.SetFocalPoint(*focus)
        camera.SetPosition(*[f + distance * x / norm for f, x in zip(focus, position)])
    camera.Zoom(zoom)
    Render(view)
    SaveScreenshot(png, view, ImageResolution=SIZE)
    print("wrote %s" % png)
    Delete(view)


def report(winding):
    """Prints what the pictures show: w's range, the curves' residuals and BoundsRegion."""
    winding.UpdatePipeline()
    w = sm.Fetch(winding, idx=0).GetPointData().GetArray("WindingNumber")
    curves = sm.Fetch(winding, idx=3).GetCellData()
    residual, bounds = curves.GetArray("WindingResidual"), curves.GetArray("BoundsRegion")
    print("  w in [%.3f, %.3f]; residuals %s; BoundsRegion %s" % (
        w.GetRange(0)[0], w.GetRange(0)[1],
        ["%.3f" % residual.GetValue(i) for i in range(residual.GetNumberOfTuples())],
        [bounds.GetValue(i) for i in range(bounds.GetNumberOfTuples())]))


# --- 1. A broken circle on the bunny ------------------------------------------------------
bunny = PLYReader(FileNames=[os.path.join(root, "Data", "bunny_npm.ply")])
bunny_shaded = GenerateSurfaceNormals(Input=bunny, Splitting=0)  # smooth shading
rays = SurfaceRays(bunny, axis=2)  # seen from +z, y up (as the filter pages' bunny)
CENTER, RADIUS, N = (1.2, 3.0), 1.7, 40


def arc(first, last):
    """Control points k = first..last of a counter-clockwise circle of N points."""
    return [rays.hit(CENTER[0] + RADIUS * math.cos(2 * math.pi * k / N),
                     CENTER[1] + RADIUS * math.sin(2 * math.pi * k / N))
            for k in range(first, last + 1)]


# Three strokes, counter-clockwise (the disc on their left), with gaps of 3 legs.
strokes = [arc(0, 10), arc(13, 24), arc(27, 37)]
drawing = SurfaceCurves(Surface=bunny, Points=[x for s in strokes for p in s for x in p],
                        CurveSizes=[len(s) for s in strokes], ShapeIds=[0] * len(strokes),
                        ClosedCurves=[0] * len(strokes))
bunny_winding = WindingNumbers(Surface=bunny, Curves=drawing)
print("bunny:")
report(bunny_winding)
bunny_camera = dict(position=(0, 0, 1), up=(0, 1, 0), zoom=1.4, focus=(0.3, 4.1, 0))

view = new_view()
plain(bunny_shaded, view, GRAY)
plain(bunny_winding, view, BLACK, 4, port=3)
save(view, out("bunny_curves"), **bunny_camera)

view = new_view()
field(bunny_winding, view, BUNNY_RANGE)
plain(bunny_winding, view, BLACK, 3, port=3)
save(view, out("bunny_field"), **bunny_camera)

view = new_view()
plain(bunny_shaded, view, GRAY)
plain(bunny_winding, view, ORANGE, port=1)
plain(bunny_winding, view, BLUE, 7, port=2)
# The strokes lie on the completed curves: moved a little towards the camera to stay in sight.
lifted = Transform(Input=OutputPort(bunny_winding, 3))
lifted.Transform.Translate = [0, 0, 0.05]
plain(lifted, view, BLACK, 2)
save(view, out("bunny_completed"), **bunny_camera)


# --- 2. A torus: a meridian that bounds nothing and a small circle ------------------------
R, r, NU, NV = 1.0, 0.4, 120, 48


def torus_point(u, v):
    return [(R + r * math.cos(v)) * math.cos(u), (R + r * math.cos(v)) * math.sin(u),
            r * math.sin(v)]


def torus_polydata():
    """NU x NV quads split in two triangles, counter-clockwise seen from outside."""
    points, polys = vtkPoints(), vtkCellArray()
    for i in range(NU):
        for j in range(NV):
            points.InsertNextPoint(torus_point(2 * math.pi * i / NU, 2 * math.pi * j / NV))

    def vid(i, j):
        return (i % NU) * NV + (j % NV)
    for i in range(NU):
        for j in range(NV):
            polys.InsertNextCell(3, [vid(i, j), vid(i + 1, j), vid(i + 1, j + 1)])
            polys.InsertNextCell(3, [vid(i, j), vid(i + 1, j + 1), vid(i, j + 1)])
    pd = vtkPolyData()
    pd.SetPoints(points)
    pd.SetPolys(polys)
    return pd


torus = PVTrivialProducer()
torus.GetClientSideObject().SetOutput(torus_polydata())
# The meridian at u = -pi/4 (through mesh vertices' rings, 16 control points around the tube),
# and a small circle on the top of the tube at u = pi/2, counter-clockwise seen from above.
meridian = [torus_point(-math.pi / 4, 2 * math.pi * k / 16 + 0.05) for k in range(16)]
U0 = math.pi / 2
circle = []
for k in range(24):
    a = 2 * math.pi * k / 24
    # (u, v) around (U0, pi / 2), about 0.3 by 0.24 along the surface: counter-clockwise seen
    # from +z (the disc on its left).
    circle.append(torus_point(U0 + 0.3 * math.cos(a), math.pi / 2 + 0.6 * math.sin(a)))
loops = SurfaceCurves(Surface=torus, Points=[x for p in meridian + circle for x in p],
                      CurveSizes=[len(meridian), len(circle)], ShapeIds=[0, 0],
                      ClosedCurves=[1, 1])
ramp = WindingNumbers(Surface=torus, Curves=loops, RemoveNonBounding=0)
corrected = WindingNumbers(Surface=torus, Curves=loops)
print("torus, RemoveNonBounding 0:")
report(ramp)
print("torus, RemoveNonBounding 1:")
report(corrected)
torus_camera = dict(position=(0.9, -2.0, 2.2), up=(0, 0, 1), zoom=1.3)

view = new_view()
field(ramp, view, TORUS_RANGE)
plain(ramp, view, BLACK, 3, port=3)
save(view, out("torus_ramp"), **torus_camera)

view = new_view()
field(corrected, view, TORUS_RANGE)
bounding = Threshold(Input=OutputPort(corrected, 3), Scalars=["CELLS", "BoundsRegion"])
dropped = Threshold(Input=OutputPort(corrected, 3), Scalars=["CELLS", "BoundsRegion"])
try:
    bounding.LowerThreshold, bounding.UpperThreshold = 1, 1
    dropped.LowerThreshold, dropped.UpperThreshold = 0, 0
except AttributeError:
    bounding.ThresholdRange, dropped.ThresholdRange = [1, 1], [0, 0]
plain(bounding, view, BLACK, 3)
plain(dropped, view, RED, 5)
save(view, out("torus_corrected"), **torus_camera)

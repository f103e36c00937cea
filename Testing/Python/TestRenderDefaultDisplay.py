"""pvbatch under Xvfb: BoolSurf's outputs read at a glance with ParaView's defaults.

- The one-step filter's region (port 0) shows as the "BoolSurf Region" representation,
  colored by its active scalars Region (1 on every triangle) with the plugin's categorical
  map: a union of two overlapping discs is one color, distinct from the surface (pixel check:
  lit flat, every region pixel is that one color). Colored by ArrangementCell instead (one
  click), no cell comes out near-white (the surface) or near-black (a hole).
- No z-fighting: the region drawn in solid red over the coincident gray surface covers every
  pixel it covers when drawn alone (with the plain Surface representation, the surface shows
  through; that count is printed, not asserted: how many pixels lose depends on the driver).
- Curves on the surface (Trace Surface Curves) show as "BoolSurf Curves": every pixel of
  theirs drawn alone is still theirs over the coarse surface (plain Surface loses some).
- The Label filter's ShapeLabel (ColorShape set) is the active scalars, with a categorical
  color map (0 "outside" and the labels of the shape as annotated categories).
"""
import os
import sys

source_dir = os.environ["BOOLSURF_SOURCE_DIR"]
sys.path.insert(0, os.path.join(source_dir, "Examples"))
from boolsurf_example_utils import SurfaceRays, curves_source, surface_circle  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from render_pixels import chromaticity_spread, paint_unlit, view_pixels  # noqa: E402
import scratch  # noqa: E402

LoadPlugin(os.environ["BOOLSURF_PLUGIN"], remote=False, ns=globals())
mesh = PLYReader(FileNames=[os.path.join(source_dir, "Data", "eight.ply")])
rays = SurfaceRays(mesh, axis=1)
control = curves_source([(surface_circle(rays, (0.0, -0.035), 0.06), 0),
                         (surface_circle(rays, (0.0, 0.035), 0.06), 1)], mesh)
one = BoolSurf(Surface=mesh, Curves=control, Operation="Union")

view = CreateView("RenderView")
view.ViewSize = [400, 400]
view.OrientationAxesVisibility = 0
view.Background = [0, 0, 0]
try:
    view.UseColorPaletteForBackground = 0
except AttributeError:
    pass
surface = Show(mesh, view)
region = Show(one, view)
assert region.Representation == "BoolSurf Region", region.Representation
assert region.ColorArrayName[1] == "Region", region.ColorArrayName
region_lut = GetColorTransferFunction("Region")
assert region_lut.InterpretValuesAsCategories == 1
region_rgb = [0.0, 0.0, 0.0]
region_lut.GetClientSideObject().GetColor(1, region_rgb)
assert min(region_rgb) < 0.8 and max(region_rgb) > 0.5, region_rgb
cells = one.GetDataInformation().DataInformation.GetArrayInformation(
    "ArrangementCell", 1).GetComponentRange(0)
assert cells[1] > cells[0], cells  # a union of overlapping discs has several cells
# An oblique view, where coincident faces fight most.
camera = view.GetActiveCamera()
camera.SetFocalPoint(0, 0, 0)
camera.SetPosition(0.6, 1, 0.4)
camera.SetViewUp(0, 0, 1)
ResetCamera(view)


png = os.path.join(scratch.folder("boolsurf-display-"), "view.png")


def pixels():
    return view_pixels(view, png, (400, 400))


# The union with its default coloring, lit flat: one color over every region pixel.
region.Ambient, region.Diffuse = 1.0, 0.0
Hide(mesh, view)
default = pixels()
Show(mesh, view)
expected = tuple(float(round(255 * c)) for c in region_rgb)
region_pixels = [c for c in default if c != (0.0, 0.0, 0.0)]
colors = set(region_pixels)
print("default display: %d region pixels, colors %s" % (len(region_pixels), sorted(colors)[:5]))
assert len(region_pixels) > 500, len(region_pixels)
# Shading still scales the color (ParaView lights scalar colors): one color, one chromaticity.
worst = chromaticity_spread(colors, expected)
print("region colors: %d, brightest %s, chromaticity spread %.4f" % (len(colors), max(colors),
                                                                   worst))
assert expected in colors, (expected, sorted(colors)[-3:])
assert worst < 0.02, worst

# Per-cell coloring, one click away: no cell near-white (the surface) or near-black (a hole).
ColorBy(region, ("CELLS", "ArrangementCell"))
table = GetColorTransferFunction("ArrangementCell").GetClientSideObject()
for value in range(int(cells[0]), int(cells[1]) + 1):
    rgb = [0.0, 0.0, 0.0]
    table.GetColor(value, rgb)
    assert min(rgb) < 0.8, ("cell %d is drawn near-white" % value, rgb)
    assert max(rgb) > 0.5, ("cell %d is drawn near-black" % value, rgb)

ColorBy(region, None)
region.DiffuseColor = region.AmbientColor = [1, 0, 0]
region.Ambient, region.Diffuse = 1.0, 0.0  # flat red: every region pixel is exactly red
Hide(mesh, view)
alone = pixels()
footprint = [i for i, c in enumerate(alone) if c == (255.0, 0.0, 0.0)]
assert len(footprint) > 500, len(footprint)
Show(mesh, view)
surface.DiffuseColor = [0.5, 0.5, 0.5]


def lost(representation):
    region.Representation = representation
    together = pixels()
    return sum(1 for i in footprint if together[i] != (255.0, 0.0, 0.0))


plain = lost("Surface")
ours = lost("BoolSurf Region")
print("region pixels %d; hidden by the surface: %d with Surface, %d with BoolSurf Region"
      % (len(footprint), plain, ours))
assert ours == 0, ours

# Curves on the surface (Trace Surface Curves' output) show as "BoolSurf Curves": no pixel of
# theirs is lost to the coincident surface (with plain Surface, a coarse mesh's steep facets cut
# them into dashes: that count is printed).
Hide(one, view)
traced = TraceSurfaceCurves(Surface=mesh, Curves=control)
lines = Show(traced, view)
assert lines.Representation == "BoolSurf Curves", lines.Representation
paint_unlit(lines, [1, 0, 0])


def reddish(c):
    return c[0] > 150 and c[1] < 80 and c[2] < 80


Hide(mesh, view)
alone = pixels()
line_pixels = [i for i, c in enumerate(alone) if reddish(c)]
assert len(line_pixels) > 40, len(line_pixels)
Show(mesh, view)


def lost_lines(representation):
    lines.Representation = representation
    together = pixels()
    return sum(1 for i in line_pixels if not reddish(together[i]))


plain_lines = lost_lines("Surface")
our_lines = lost_lines("BoolSurf Curves")
print("curve pixels %d; hidden by the surface: %d with Surface, %d with BoolSurf Curves"
      % (len(line_pixels), plain_lines, our_lines))
assert our_lines == 0, our_lines
Hide(traced, view)

labels = LabelArrangementCells(Input=SurfaceArrangement(
    Surface=mesh, Curves=TraceSurfaceCurves(Surface=mesh, Curves=control)), ColorShape=0)
labeled = Show(labels, view)
assert labeled.ColorArrayName[1] == "ShapeLabel", labeled.ColorArrayName
shape_lut = GetColorTransferFunction("ShapeLabel")
assert shape_lut.InterpretValuesAsCategories == 1
annotations = list(shape_lut.Annotations)
assert "0" in annotations[0::2] and "1" in annotations[0::2], annotations
print("DEFAULT_DISPLAY_OK")

"""What a ParaView render view shows, read back for the tests that check pixels
(TestRenderDefaultDisplay.py, GuiTutorial.py)."""
from paraview.simple import Render, SaveScreenshot
from vtkmodules.vtkIOImage import vtkPNGReader


def view_pixels(view, png, size):
    """The RGB (0-255) of every pixel of `view` rendered at `size`, through the PNG `png`."""
    Render(view)
    SaveScreenshot(png, view, ImageResolution=list(size), TransparentBackground=0)
    reader = vtkPNGReader()
    reader.SetFileName(png)
    reader.Update()
    colors = reader.GetOutput().GetPointData().GetScalars()
    return [colors.GetTuple3(i) for i in range(colors.GetNumberOfTuples())]


def chromaticity_spread(colors, reference=None):
    """How far apart the chromaticities of `colors` are from that of `reference` (default: the
    first of them): shading scales a color, so one color lit has one chromaticity. Colors too
    dark for 8-bit rounding to keep it (no channel of 60 or more) are left out; 1 when none
    is left."""
    def chroma(c):
        total = sum(c)
        return tuple(x / total for x in c)
    bright = [c for c in colors if max(c) >= 60]
    if not bright:
        return 1.0
    ref = chroma(reference if reference is not None else bright[0])
    return max(max(abs(a - b) for a, b in zip(chroma(c), ref)) for c in bright)


def paint_unlit(display, rgb):
    """`display` in one flat color, unlit: each of its pixels is exactly `rgb` wherever nothing
    covers it, so the pixels it keeps over a coincident surface can be counted."""
    display.ColorArrayName = ["POINTS", ""]
    display.DiffuseColor = display.AmbientColor = rgb
    display.Ambient, display.Diffuse = 1.0, 0.0

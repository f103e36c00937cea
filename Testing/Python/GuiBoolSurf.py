"""ParaView GUI test (run by ctest as `xvfb-run -a paraview --script=GuiBoolSurf.py`).

Loads the BoolSurf plugin into the GUI client, checks that its filters are registered under
the "BoolSurf" menu category, applies the one-step filter (BoolSurf) to Data/eight.ply with two
discs drawn on it, and saves a screenshot of the render view; exits 0 when the PNG exists and
is a non-trivial image, 1 otherwise (the GUI is closed either way).
"""
import os
import sys
import traceback

# Run by the GUI as a string: no __file__.
sys.path.insert(0, os.path.join(os.environ["BOOLSURF_SOURCE_DIR"], "Testing", "Python"))
import scratch  # noqa: E402


def main():
    from paraview.simple import (GetActiveViewOrCreate, LoadPlugin, PLYReader,
                                 Render, ResetCamera, SaveScreenshot, Show)
    from paraview import servermanager as sm
    source_dir = os.environ["BOOLSURF_SOURCE_DIR"]
    LoadPlugin(os.environ["BOOLSURF_PLUGIN"], remote=False, ns=globals())
    # Every BoolSurf proxy is in the "BoolSurf" menu category.
    pxm = sm.ProxyManager()
    for group, name in (("filters", "BoolSurf"), ("filters", "TraceSurfaceCurves"),
                        ("filters", "SurfaceArrangement"), ("filters", "LabelArrangementCells"),
                        ("filters", "SurfaceBoolean"), ("filters", "CheckSurface"),
                        ("sources", "BoolSurfSceneReader")):
        proxy = pxm.GetPrototypeProxy(group, name)
        assert proxy is not None, (group, name)
        hints = proxy.GetHints()
        menu = hints.FindNestedElementByName("ShowInMenu") if hints else None
        assert menu is not None and menu.GetAttribute("category") == "BoolSurf", name
    sys.path.insert(0, os.path.join(source_dir, "Examples"))
    from boolsurf_example_utils import SurfaceRays, curves_source, surface_circle
    mesh = PLYReader(FileNames=[os.path.join(source_dir, "Data", "eight.ply")])
    rays = SurfaceRays(mesh, axis=1)
    control = curves_source([(surface_circle(rays, (0.0, -0.035), 0.06), 0),
                             (surface_circle(rays, (0.0, 0.035), 0.06), 1)], mesh)
    one = globals()["BoolSurf"](Surface=mesh, Curves=control, Operation="Union")
    one.UpdatePipeline()
    assert sm.Fetch(one).GetNumberOfCells() > 20
    view = GetActiveViewOrCreate("RenderView")
    Show(mesh, view)
    display = Show(one, view)
    display.DiffuseColor = [0.95, 0.45, 0.1]
    camera = view.GetActiveCamera()
    camera.SetFocalPoint(0, 0, 0)
    camera.SetPosition(0, 1, 0)
    camera.SetViewUp(0, 0, 1)
    ResetCamera(view)
    Render(view)
    png = os.environ.get("BOOLSURF_GUI_SCREENSHOT") or os.path.join(
        scratch.folder("boolsurf-gui-"), "gui_boolsurf.png")
    SaveScreenshot(png, view, ImageResolution=[800, 600])
    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    reader.SetFileName(png)
    reader.Update()
    dims = reader.GetOutput().GetDimensions()
    assert dims[:2] == (800, 600), dims
    scalars = reader.GetOutput().GetPointData().GetScalars()
    colors = set(scalars.GetTuple(i)[:3] for i in range(0, scalars.GetNumberOfTuples(), 53))
    assert len(colors) > 20, len(colors)
    sys.__stdout__.write("GUI_OK %s\n" % png)
    print("GUI_OK %s (%d bytes, %d sampled colors)" % (png, os.path.getsize(png), len(colors)))


try:
    main()
    code = 0
except Exception:
    # In the GUI, sys.stderr is the Output Messages window: also write to the terminal.
    traceback.print_exc(file=sys.__stderr__)
    code = 1
scratch.remove()
sys.stdout.flush()
sys.stderr.flush()
os._exit(code)  # close the GUI: ParaView would otherwise wait for the user

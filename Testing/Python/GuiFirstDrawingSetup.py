"""Set-up of the first-drawing GUI test (GuiFirstDrawing.py runs
`paraview --script=GuiFirstDrawingSetup.py --test-script=GuiFirstDrawing.xml ...`).

A new user's start: Data/eight.ply opened and shown, seen from its broad side (the bar between
its two holes in the middle of the view), active in the pipeline browser. Unlike the other GUI
tests, messages are left to ParaView's Output Messages window with its default settings: the
recorded events check that it never opens while the user draws.
"""
import os
import sys
import traceback


def main():
    from paraview.simple import (GetActiveViewOrCreate, LoadPlugin, PLYReader, Render,
                                 ResetCamera, SetActiveSource, Show)
    LoadPlugin(os.environ["BOOLSURF_PLUGIN"], remote=False, ns=globals())
    mesh = PLYReader(registrationName="eight.ply", FileNames=[
        os.path.join(os.environ["BOOLSURF_SOURCE_DIR"], "Data", "eight.ply")])
    view = GetActiveViewOrCreate("RenderView")
    view.OrientationAxesVisibility = 0
    Show(mesh, view)
    camera = view.GetActiveCamera()
    camera.SetFocalPoint(0, 0, 0)
    camera.SetPosition(0, 1, 0)
    camera.SetViewUp(1, 0, 0)
    ResetCamera(view)
    Render(view)
    SetActiveSource(mesh)
    record_frames(view)


def record_frames(view):
    """Saves every frame the view renders (a PNG and the camera's distance) into
    $BOOLSURF_GUI_RESULT-frames/, for the test to measure the markers at two zoom levels."""
    import json
    from vtkmodules.vtkIOImage import vtkPNGWriter
    from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
    folder = os.environ["BOOLSURF_GUI_RESULT"] + "-frames"
    os.makedirs(folder, exist_ok=True)
    window = view.GetRenderWindow()
    frames = []

    def saved(caller, event):
        grab = vtkWindowToImageFilter()
        grab.SetInput(window)
        grab.ShouldRerenderOff()
        grab.ReadFrontBufferOff()
        grab.Update()
        name = os.path.join(folder, "%04d.png" % len(frames))
        writer = vtkPNGWriter()
        writer.SetFileName(name)
        writer.SetInputConnection(grab.GetOutputPort())
        writer.Write()
        camera = view.GetRenderer().GetActiveCamera()
        frames.append({"png": name, "distance": camera.GetDistance(),
                       "angle": camera.GetViewAngle(), "size": list(window.GetSize())})
        with open(os.path.join(folder, "frames.json"), "w") as f:
            json.dump(frames, f)
    window.AddObserver("EndEvent", saved)


try:
    main()
except Exception:
    traceback.print_exc(file=sys.__stderr__)
    os._exit(1)

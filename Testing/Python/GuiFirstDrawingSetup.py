"""Set-up of the first-drawing GUI test (GuiFirstDrawing.py runs
`paraview --script=GuiFirstDrawingSetup.py --test-script=GuiFirstDrawing.xml ...`).

A new user's start: Data/eight.ply opened and shown, seen from its broad side (the bar between
its two holes in the middle of the view), active in the pipeline browser. Unlike the other GUI
tests, messages are left to ParaView's Output Messages window with its default settings: the
recorded events check that it never opens while the user draws.

With $BOOLSURF_GUI_STATE set, the state file it names is loaded instead (the second run of the
test: markers of a loaded drawing on the far side of the surface must hide).

For the checks afterwards, every frame the view renders is saved (a PNG, with the camera), and
after each frame the labels of the undo stack's sets (newest first), into
$BOOLSURF_GUI_RESULT-frames/ and $BOOLSURF_GUI_RESULT-undo.json.
"""
import json
import os
import sys
import traceback


def main():
    from paraview import simple
    from paraview.simple import GetActiveViewOrCreate, LoadPlugin, LoadState
    LoadPlugin(os.environ["BOOLSURF_PLUGIN"], remote=False, ns=globals())
    state = os.environ.get("BOOLSURF_GUI_STATE")
    if state:
        # The second run: the drawing as a state file gives it, without the points' normals.
        LoadState(state)
        record_frames(GetActiveViewOrCreate("RenderView"))
        return
    sys.path.insert(0, os.path.join(os.environ["BOOLSURF_SOURCE_DIR"], "Testing", "Python"))
    from gui_player import open_eight_broadside
    _, view = open_eight_broadside(simple)
    record_frames(view)


def undo_labels():
    """The labels of the undo stack's sets, newest first (read after a render, when no set is
    being pushed: reading them from the stack's own events crashed)."""
    from paraview import servermanager
    builder = servermanager.vtkSMProxyManager.GetProxyManager().GetUndoStackBuilder()
    stack = builder.GetUndoStack() if builder else None
    if not stack:
        return []
    return [stack.GetUndoSetLabel(i) for i in range(stack.GetNumberOfUndoSets())]


def record_frames(view):
    from vtkmodules.vtkIOImage import vtkPNGWriter
    from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
    result = os.environ["BOOLSURF_GUI_RESULT"]
    folder = result + "-frames"
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
                       "size": list(window.GetSize())})
        with open(os.path.join(folder, "frames.json"), "w") as f:
            json.dump(frames, f)
        with open(result + "-undo.json", "w") as f:
            json.dump(undo_labels(), f)
    window.AddObserver("EndEvent", saved)


try:
    main()
except Exception:
    traceback.print_exc(file=sys.__stderr__)
    os._exit(1)

"""Set-up of the GUI tutorial test (GuiTutorial.py runs
`paraview --script=GuiTutorialSetup.py --test-script=GuiTutorial.xml ...`).

Step 1 of the README tutorial as a user starts it: Data/eight.ply opened and shown, seen from
its broad side (the bar between its two holes in the middle of the view), active in the
pipeline browser. The recorded events do the rest from the menus and the panel.
"""
import os
import sys
import traceback


def main():
    from paraview.simple import (GetActiveViewOrCreate, LoadPlugin, PLYReader, Render,
                                 ResetCamera, SetActiveSource, Show)
    from vtkmodules.vtkCommonCore import vtkFileOutputWindow, vtkOutputWindow
    # Messages go to a log, not to the Output Messages dock (a curve of fewer than three
    # points cannot be traced yet while it is drawn).
    log = vtkFileOutputWindow()
    log.SetFileName(os.environ["BOOLSURF_GUI_RESULT"] + ".log")
    vtkOutputWindow.SetInstance(log)
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


try:
    main()
except Exception:
    traceback.print_exc(file=sys.__stderr__)
    os._exit(1)

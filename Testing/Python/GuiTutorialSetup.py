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
    from paraview import simple
    from paraview.simple import LoadPlugin
    from vtkmodules.vtkCommonCore import vtkFileOutputWindow, vtkOutputWindow
    # Messages go to a log, not to the Output Messages dock (GuiFirstDrawing.py checks that
    # dock while a user draws).
    log = vtkFileOutputWindow()
    log.SetFileName(os.environ["BOOLSURF_GUI_RESULT"] + ".log")
    vtkOutputWindow.SetInstance(log)
    LoadPlugin(os.environ["BOOLSURF_PLUGIN"], remote=False, ns=globals())
    sys.path.insert(0, os.path.join(os.environ["BOOLSURF_SOURCE_DIR"], "Testing", "Python"))
    from gui_player import open_eight_broadside
    open_eight_broadside(simple)


try:
    main()
except Exception:
    traceback.print_exc(file=sys.__stderr__)
    os._exit(1)

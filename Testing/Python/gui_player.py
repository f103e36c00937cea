"""ParaView's GUI driven by its test player, for the GUI tests (GuiTutorial.py,
GuiFirstDrawing.py): the set-up script, the recorded events and a scratch folder."""
import os
import subprocess


def play(paraview, setup, events, out, env):
    """Runs `paraview --script=<setup> --test-script=<events>` (both beside this file) with
    `out` as the test directory and `env` as environment; the finished process, its output in
    .stdout."""
    here = os.path.dirname(os.path.abspath(__file__))
    return subprocess.run([paraview, "--dr", "--script=" + os.path.join(here, setup),
                           "--test-script=" + os.path.join(here, events),
                           "--test-directory=" + out, "--exit"], env=env,
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=600,
                          universal_newlines=True)


def open_eight_broadside(simple):
    """Data/eight.ply opened and shown in the render view, seen from its broad side (the bar
    between its two holes in the middle of the view), active in the pipeline browser: a new
    user's start. `simple` is paraview.simple."""
    mesh = simple.PLYReader(registrationName="eight.ply", FileNames=[
        os.path.join(os.environ["BOOLSURF_SOURCE_DIR"], "Data", "eight.ply")])
    view = simple.GetActiveViewOrCreate("RenderView")
    view.OrientationAxesVisibility = 0
    simple.Show(mesh, view)
    camera = view.GetActiveCamera()
    camera.SetFocalPoint(0, 0, 0)
    camera.SetPosition(0, 1, 0)
    camera.SetViewUp(1, 0, 0)
    simple.ResetCamera(view)
    simple.Render(view)
    simple.SetActiveSource(mesh)
    return mesh, view

"""pvbatch under Xvfb: a view keeps following the drawing after BoolSurf failed.

A curve drawn point by point (as the curve editor does) gives no region while it is open, and
no message either (a curve being drawn is no error: messages opened ParaView's Output Messages
window over the view). An expression that fails makes BoolSurf report the error and leave the
region empty (never the previous region); once the expression is fixed and the curve closed,
the displayed region must be the new one. (Filters returned failure before: ParaView's display
of the region then never updated again, whatever changed upstream.)
"""
import os

from paraview.simple import *  # noqa: F401,F403
from vtkmodules.vtkCommonCore import vtkCommand

LoadPlugin(os.environ["BOOLSURF_PLUGIN"], remote=False, ns=globals())
square = Triangulate(Input=Plane(XResolution=24, YResolution=24))
curves = SurfaceCurves(Surface=square)
region = BoolSurf(Surface=square, Curves=curves, Operation="Expression", Expression="S0")
errors = []
region.GetClientSideObject().AddObserver(vtkCommand.ErrorEvent,
                                         lambda obj, event: errors.append(event))
view = CreateView("RenderView")
display = Show(region, view)
corners = [-0.3, -0.3, 0, 0.3, -0.3, 0, 0.3, 0.3, 0, -0.3, 0.3, 0]
for n in range(1, 5):  # open curves of 1..4 points: no shape yet
    curves.Points = corners[:3 * n]
    curves.CurveSizes = [n]
    curves.ClosedCurves = [0]
    Render(view)
    shown = display.GetRepresentedDataInformation().GetNumberOfCells()
    assert shown == 0, (n, shown)
assert not errors, "an open drawing is no error: %s" % errors
region.Expression = "S0 &"
Render(view)
assert errors, "a bad expression is reported"
assert display.GetRepresentedDataInformation().GetNumberOfCells() == 0
region.Expression = "S0"
curves.ClosedCurves = [1]
Render(view)
shown = display.GetRepresentedDataInformation().GetNumberOfCells()
computed = region.GetDataInformation().GetNumberOfCells()
assert shown > 0 and shown == computed, (shown, computed)
bounds = display.GetRepresentedDataInformation().GetBounds()
assert abs(bounds[0] + 0.3) < 1e-9 and abs(bounds[1] - 0.3) < 1e-9, bounds
# And again: an error, then a fix.
region.Expression = "S0 &"
Render(view)
assert display.GetRepresentedDataInformation().GetNumberOfCells() == 0
region.Expression = "S0"
Render(view)
assert display.GetRepresentedDataInformation().GetNumberOfCells() == computed
print("FOLLOWS_EDITS_OK")

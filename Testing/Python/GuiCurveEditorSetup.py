"""Set-up of the GUI curve-editor test (TestGuiCurveEditor.py runs
`paraview --script=GuiCurveEditorSetup.py --test-script=GuiCurveEditor.xml ...`).

Builds the pipeline a user would: a flat triangulated square, an empty Surface Curves source
on it (its panel, the curve editor, active) and the one-step BoolSurf of shape 0 below it.
The recorded events (GuiCurveEditor.xml) then click four points on the square, close the curve
by clicking its first point, drag a point, undo and redo. Every time BoolSurf executes, its
result and the drawing's properties are appended to the list in $BOOLSURF_GUI_RESULT (JSON),
which the test checks.
"""
import json
import os
import sys
import traceback


def triangle_area(points, ids):
    a, b, c = (points.GetPoint(ids.GetId(k)) for k in range(3))
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    return 0.5 * sum(x * x for x in n) ** 0.5


def main():
    from paraview.simple import (GetActiveViewOrCreate, LoadPlugin, Plane, Render, ResetCamera,
                                 SetActiveSource, Show, Triangulate)
    from vtkmodules.vtkCommonCore import vtkFileOutputWindow, vtkOutputWindow
    from vtkmodules.vtkCommonCore import vtkCommand, vtkIdList
    # Messages go to a log, not to the Output Messages dock: a drawing of fewer than three
    # points makes BoolSurf report "no closed curve" until the curve is closed.
    log = vtkFileOutputWindow()
    log.SetFileName(os.environ["BOOLSURF_GUI_RESULT"] + ".log")
    vtkOutputWindow.SetInstance(log)

    from paraview import servermanager
    LoadPlugin(os.environ["BOOLSURF_PLUGIN"], remote=False, ns=globals())
    if servermanager.ActiveConnection.IsRemote():
        LoadPlugin(os.environ["BOOLSURF_PLUGIN"], remote=True, ns=globals())
    BoolSurf, SurfaceCurves = globals()["BoolSurf"], globals()["SurfaceCurves"]
    square = Triangulate(Input=Plane(XResolution=24, YResolution=24))
    curves = SurfaceCurves(Surface=square)
    region = BoolSurf(Surface=square, Curves=curves, Operation="Expression", Expression="S0")

    view = GetActiveViewOrCreate("RenderView")
    view.OrientationAxesVisibility = 0
    surface_display = Show(square, view)
    surface_display.DiffuseColor = [0.8, 0.8, 0.8]
    Show(curves, view)
    Show(region, view)
    camera = view.GetActiveCamera()
    camera.SetFocalPoint(0, 0, 0)
    camera.SetPosition(0, 0, 1)
    camera.SetViewUp(0, 1, 0)
    ResetCamera(view)
    Render(view)
    SetActiveSource(curves)
    # Python trace from here on: the editor's edits must appear in it.
    from paraview import smtrace
    smtrace.start_trace()

    result_path = os.environ["BOOLSURF_GUI_RESULT"]
    algorithm = region.GetClientSideObject()
    if algorithm is None:
        return  # connected to a pvserver: the test checks the saved state instead
    history = []  # every result, the last one the final state

    def record(caller, event):
        out = algorithm.GetOutputDataObject(0)
        ids = vtkIdList()
        area = 0.0
        for c in range(out.GetNumberOfCells()):
            out.GetCellPoints(c, ids)
            area += triangle_area(out.GetPoints(), ids)
        result = {"region_triangles": out.GetNumberOfCells(), "region_area": area}
        for name in ("Points", "TriangleIds", "Barycentrics", "CurveSizes", "ShapeIds",
                     "CurveTypes", "ClosedCurves"):
            result[name] = list(curves.GetPropertyValue(name))
        result["trace"] = smtrace.get_current_trace_output()
        history.append(result)
        with open(result_path, "w") as f:
            json.dump(history, f)

    algorithm.AddObserver(vtkCommand.EndEvent, record)


try:
    main()
except Exception:
    traceback.print_exc(file=sys.__stderr__)
    os._exit(1)

"""Helpers shared by the BoolSurf example scripts (pvpython / pvbatch).

- load_plugin(): loads the BoolSurf plugin ($BOOLSURF_PLUGIN, else build/ beside Examples/).
- surface_circle(): control points of a circle drawn on a surface, found by casting rays
  along one axis onto the mesh (the way a user would draw on a view of the surface).
- curves_source(): a Surface Curves source holding control polygons with a ShapeId per curve.
- sample_source(): a pipeline source holding BSC samples (points with a Direction vector).
- save_result() / render_result(): the .vtp (inline binary) and the .png with the region colored.
"""
import math
import os

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager as sm
from paraview import simple
from vtkmodules.vtkCommonCore import mutable
from vtkmodules.vtkCommonDataModel import vtkCellLocator

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def load_plugin(ns):
    plugin = os.environ.get("BOOLSURF_PLUGIN") or os.path.join(
        ROOT, "build", "lib", "paraview-5.11", "plugins", "BoolSurf", "BoolSurf.so")
    LoadPlugin(plugin, remote=False, ns=ns)


class SurfaceRays:
    """Casts rays along an axis (0 x, 1 y, 2 z) from its positive side onto a mesh."""

    def __init__(self, mesh_proxy, axis):
        self.mesh = sm.Fetch(mesh_proxy)
        self.locator = vtkCellLocator()
        self.locator.SetDataSet(self.mesh)
        self.locator.BuildLocator()
        self.axis = axis
        b = self.mesh.GetBounds()
        self.bounds = b
        self.far = 2 * max(b[1] - b[0], b[3] - b[2], b[5] - b[4]) + 1

    def hit(self, a, b):
        """The first surface point on the ray through in-plane coordinates (a, b): the
        coordinates along axes (axis+1)%3 and (axis+2)%3 (for axis y: (z, x))."""
        start, end = [0.0] * 3, [0.0] * 3
        start[(self.axis + 1) % 3] = end[(self.axis + 1) % 3] = a
        start[(self.axis + 2) % 3] = end[(self.axis + 2) % 3] = b
        start[self.axis] = self.far
        end[self.axis] = -self.far
        t, x, pc, sub = mutable(0.0), [0.0] * 3, [0.0] * 3, mutable(0)
        if not self.locator.IntersectWithLine(start, end, 1e-9, t, x, pc, sub):
            raise RuntimeError("no surface under (%g, %g) along axis %d" % (a, b, self.axis))
        return x


def first_hit(rays, start, end):
    """The first surface point on the segment start -> end."""
    t, x, pc, sub = mutable(0.0), [0.0] * 3, [0.0] * 3, mutable(0)
    if not rays.locator.IntersectWithLine(list(start), list(end), 1e-9, t, x, pc, sub):
        raise RuntimeError("no surface between %s and %s" % (start, end))
    return x


def surface_circle(rays, center, radius, n=24, clockwise=False):
    """Control points of a circle on the surface (center in the rays' in-plane coordinates),
    counter-clockwise as seen from the rays' side, so that on a surface whose normals face
    the rays it encloses its disc (the left side of a curve is its inside); clockwise=True
    reverses it."""
    points = []
    for k in range(n):
        angle = 2 * math.pi * k / n
        points.append(rays.hit(center[0] + radius * math.cos(angle),
                               center[1] + radius * math.sin(angle)))
    if clockwise:
        points.reverse()
    return points


def curves_source(curves, surface):
    """curves: list of (points, shape_id), each a closed geodesic polygon drawn on the surface
    proxy `surface`. A Surface Curves source: the points are properties (saved in state files,
    sent to a pvserver, produced once under MPI), snapped to the surface as exact surface
    points."""
    points = [x for pts, _ in curves for p in pts for x in p]
    # load_plugin() adds the plugin's constructors to the script's namespace, not to this
    # module's: build the same constructor paraview.simple gives the script.
    surface_curves = simple._create_func("SurfaceCurves", sm.filters)
    source = surface_curves(Surface=surface, Points=points,
                            CurveSizes=[len(pts) for pts, _ in curves],
                            ShapeIds=[shape for _, shape in curves])
    source.UpdatePipeline()
    return source


def sample_source(samples):
    """samples: list of (point, direction): BSC samples, each on or near a curve, its
    Direction pointing to the side that must be inside. A BSC Samples source: the samples are
    properties (saved in state files, sent to a pvserver, produced once under MPI)."""
    bsc_samples = simple._create_func("BSCSamples", sm.sources)
    source = bsc_samples(Points=[x for p, _ in samples for x in p],
                         Directions=[x for _, d in samples for x in d])
    source.UpdatePipeline()
    return source


def area(proxy, port=0):
    from vtkmodules.vtkFiltersVerdict import vtkCellSizeFilter
    sizes = vtkCellSizeFilter()
    sizes.SetInputData(sm.Fetch(proxy, idx=port))
    sizes.Update()
    a = sizes.GetOutput().GetCellData().GetArray("Area")
    return sum(a.GetValue(i) for i in range(a.GetNumberOfTuples())) if a else 0.0


def ranks():
    """The number of MPI ranks running the pipeline (1 unless under mpiexec)."""
    return sm.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()


def save_result(proxy, path):
    if ranks() > 1:
        # Under MPI ParaView offers only the partitioned .pvtp writer for .vtp; BoolSurf's
        # results live on the first rank, so fetch them and write one plain .vtp file.
        from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
        writer = vtkXMLPolyDataWriter()
        writer.SetInputData(sm.Fetch(proxy))
        writer.SetDataModeToBinary()
        writer.SetFileName(path)
        writer.Write()
    else:
        # Inline binary: VTK 9.2 on Debian 12 cannot read back appended-mode XML files.
        SaveData(path, proxy=proxy, DataMode="Binary")
    print("wrote %s" % path)


def render_result(png, surface, region, boundary=None, curves=None, view_axis=1,
                  view_up=(0, 0, 1), size=(1024, 768), color_by=None):
    """Gray surface, the region in orange (or colored by color_by cell array), boundary
    curves in dark blue, input curves (if given) in black."""
    view = CreateView("RenderView")
    view.ViewSize = list(size)
    view.OrientationAxesVisibility = 0
    view.Background = [1, 1, 1]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    d = Show(surface, view)
    d.ColorArrayName = ["POINTS", ""]
    d.DiffuseColor = [0.8, 0.8, 0.8]
    d.Opacity = 1.0
    # The region lies on the surface: its default representation ("BoolSurf Region") draws it
    # over the coincident gray surface without z-fighting.
    r = Show(region, view)
    if color_by:
        ColorBy(r, ("CELLS", color_by))
        r.RescaleTransferFunctionToDataRange(True, False)
    else:
        r.ColorArrayName = ["POINTS", ""]
        r.DiffuseColor = [0.95, 0.45, 0.1]
    if boundary is not None:
        b = Show(boundary, view)
        b.ColorArrayName = ["POINTS", ""]
        b.AmbientColor = b.DiffuseColor = [0.1, 0.1, 0.5]
        b.LineWidth = 3
    if curves is not None:
        c = Show(curves, view)
        c.ColorArrayName = ["POINTS", ""]
        c.AmbientColor = c.DiffuseColor = [0, 0, 0]
        c.LineWidth = 1.5
    position = [0.0, 0.0, 0.0]
    position[view_axis] = 1.0
    camera = view.GetActiveCamera()
    camera.SetFocalPoint(0, 0, 0)
    camera.SetPosition(*position)
    camera.SetViewUp(*view_up)
    view.ResetCamera(False)
    Render(view)
    SaveScreenshot(png, view, ImageResolution=list(size))
    print("wrote %s" % png)
    return view

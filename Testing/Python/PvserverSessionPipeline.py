"""The pvserver session of Docs/Parallel.md ("A pvserver session on pieces"), built through
ParaView's proxies as a user would: run by pvpython (connected to a pvserver, or in a builtin
session for the one-rank answer) and, through build_session(), by the GUI client's script.

    pvpython PvserverSessionPipeline.py --json out.json --folder DIR [--server host:port]
    pvpython PvserverSessionPipeline.py --json out.json --read region.pvtp

Data/eight.ply gets Generate Global Ids, is split by RedistributeDataSet and Extract Surface,
and three circles are drawn on it with a Surface Curves source, set as the curve editor sets
it (Points, then the exact TriangleIds and Barycentrics read back from the source's output).
Trace Surface Curves, Surface Arrangement, Label Arrangement Cells and Surface Boolean (shape 0
union shape 2) follow; the region is rendered in a render view (on the server: remote rendering
forced) to a PNG, measured per SourceTriangle with the rank holding each triangle (Process Id
Scalars), written with Save Data as a .pvtp (a piece per rank) and read back in the same
session. The one-step BoolSurf filter then gives the same Boolean from the same drawing, and its
region is measured and rendered in the same view in place of the chain's, in another color. --read measures a .pvtp in a fresh one-process session instead. The JSON is what
pvserver_session.py compares.
"""
import argparse
import json
import os
import sys

source_dir = os.environ.get("BOOLSURF_SOURCE_DIR",
                            os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(source_dir, "Examples"))
sys.path.insert(0, os.path.join(source_dir, "Testing", "Python"))
from paraview import servermanager as sm  # noqa: E402
from paraview import simple  # noqa: E402

# The region's color: unlit, so that its pixels can be counted exactly in the screenshot. The
# one-step filter's region has another, so that the chain's region hidden before it is seen gone.
REGION_RGB = (255, 115, 25)
ONE_STEP_RGB = (25, 115, 255)


def load_plugin_everywhere():
    """The filters run on the server (every rank loads the plugin), the client needs the proxy
    definitions too."""
    plugin = os.environ.get("BOOLSURF_PLUGIN") or os.path.join(
        source_dir, "build", "lib", "paraview-5.11", "plugins", "BoolSurf", "BoolSurf.so")
    if sm.ActiveConnection.IsRemote():
        simple.LoadPlugin(plugin, remote=True)
    simple.LoadPlugin(plugin, remote=False)


def plugin_proxy(name, group, **properties):
    return simple._create_func(name, getattr(sm, group))(**properties)


def draw_as_the_editor(surface, curves):
    """A Surface Curves source holding `curves` (list of (points, shape)) as the curve editor
    leaves it: it first writes the picked positions, then reads back the exact surface points
    (TriangleId, Barycentric) from the Control Curves output and stores them."""
    points = [x for pts, _ in curves for p in pts for x in p]
    source = plugin_proxy("SurfaceCurves", "filters", Surface=surface, Points=points,
                          CurveSizes=[len(pts) for pts, _ in curves],
                          ShapeIds=[shape for _, shape in curves])
    source.UpdatePipeline()
    control = sm.Fetch(source, idx=0)
    triangles = control.GetPointData().GetArray("TriangleId")
    weights = control.GetPointData().GetArray("Barycentric")
    n = control.GetNumberOfPoints()
    if triangles is None or weights is None or n != len(points) // 3:
        raise RuntimeError("Surface Curves gave no exact surface point per control point")
    source.TriangleIds = [int(triangles.GetComponent(i, 0)) for i in range(n)]
    source.Barycentrics = [weights.GetComponent(i, k) for i in range(n) for k in range(2)]
    source.Points = [x for i in range(n) for x in control.GetPoint(i)]
    source.UpdatePipeline()
    return source


def build_session():
    """The pipeline on the active connection: returns the proxies by name."""
    from boolsurf_example_utils import SurfaceRays, surface_circle
    mesh = simple.PLYReader(FileNames=[os.path.join(source_dir, "Data", "eight.ply")])
    redistributed = simple.RedistributeDataSet(Input=simple.GenerateGlobalIds(Input=mesh))
    surface = simple.ExtractSurface(Input=redistributed)
    surface.UpdatePipeline()
    # Where a user clicks: points cast along y onto the mesh (fetched to the client, as the
    # GUI's picking would find them).
    rays = SurfaceRays(mesh, axis=1)
    curves = draw_as_the_editor(surface, [
        (surface_circle(rays, (0.0, -0.035), 0.06), 0),
        (surface_circle(rays, (0.0, 0.035), 0.06), 1),
        (surface_circle(rays, (0.0, 0.05), 0.08, n=40), 2)])
    traced = plugin_proxy("TraceSurfaceCurves", "filters", Surface=surface, Curves=curves)
    arrangement = plugin_proxy("SurfaceArrangement", "filters", Surface=surface, Curves=traced)
    labels = plugin_proxy("LabelArrangementCells", "filters", Input=arrangement)
    region = plugin_proxy("SurfaceBoolean", "filters", Input=labels, Operation="Union",
                          ShapeA=0, ShapeB=2)
    region.UpdatePipeline()
    return {"mesh": mesh, "surface": surface, "curves": curves, "region": region}


def measure(proxy):
    """The data of `proxy` on every rank: triangles, per SourceTriangle [triangles, area], the
    rank holding each triangle (Process Id Scalars' point ids, the first point of each triangle:
    a rank's piece has points of its own) and the field arrays."""
    from vtkmodules.vtkFiltersVerdict import vtkCellSizeFilter
    data = sm.Fetch(simple.ProcessIdScalars(Input=proxy))
    sizes = vtkCellSizeFilter()
    sizes.SetInputData(data)
    sizes.Update()
    areas = sizes.GetOutput().GetCellData().GetArray("Area")
    source = data.GetCellData().GetArray("SourceTriangle")
    rank = data.GetPointData().GetArray("ProcessId")
    by_source, held = {}, {}
    for c in range(data.GetNumberOfCells()):
        entry = by_source.setdefault(str(int(source.GetTuple1(c))), [0, 0.0])
        entry[0] += 1
        entry[1] += areas.GetValue(c)
        holder = str(int(rank.GetTuple1(data.GetCell(c).GetPointId(0))))
        held[holder] = held.get(holder, 0) + 1
    field = data.GetFieldData()
    return {"triangles": data.GetNumberOfCells(), "by_source": by_source, "held": held,
            "fields": sorted(field.GetArrayName(i) for i in range(field.GetNumberOfArrays()))}


def render_region(session, png, size=(800, 600), hide=None, rgb=REGION_RGB):
    """The surface in gray and the region in flat orange, seen along y, rendered on the server
    when connected to one; returns the number of the region's pixels in the PNG and whether
    the server rendered it: (exact color, at least half the color (covered_pixels), on the
    server). `hide`: a region shown before, hidden first."""
    from render_pixels import paint_unlit, view_pixels
    simple.GetSettingsProxy("RenderViewSettings").RemoteRenderThreshold = 0.0
    view = simple.GetActiveViewOrCreate("RenderView")
    view.OrientationAxesVisibility = 0
    if hide is not None:
        simple.Hide(hide, view)
    surface = simple.Show(session["surface"], view)
    surface.ColorArrayName = ["POINTS", ""]
    surface.DiffuseColor = [0.8, 0.8, 0.8]
    region = simple.Show(session["region"], view)
    paint_unlit(region, [c / 255.0 for c in rgb])
    camera = view.GetActiveCamera()
    camera.SetFocalPoint(0, 0, 0)
    camera.SetPosition(0, 1, 0)
    camera.SetViewUp(0, 0, 1)
    view.ResetCamera(False)
    pixels = view_pixels(view, png, size)
    # Whether the last render ran on the server's ranks (composited there), not on the client.
    on_server = bool(view.GetClientSideObject().GetUseDistributedRenderingForRender())
    exact = sum(1 for p in pixels if tuple(int(round(x)) for x in p) == rgb)
    return exact, covered_pixels(pixels, rgb), on_server


def covered_pixels(pixels, rgb):
    """The pixels at least half the region's color: their red minus blue (the region's colors
    differ from the gray surface and the background there) past half the color's own. Counted
    so, two colors cover the same pixels; counted exactly they do not, because the edges'
    anti-aliasing blends each color by its own contrast."""
    way = rgb[0] - rgb[2]
    return sum(1 for p in pixels if (p[0] - p[2]) * way > way * way / 2)


def save_pieces(region, path):
    """Save Data as a user does: under MPI the .pvtp writer writes a piece per rank (inline
    binary: VTK 9.2 here cannot read back appended XML files)."""
    simple.SaveData(path, proxy=region, DataMode="Binary")
    piece_dir = os.path.splitext(path)[0]
    return sorted(os.listdir(piece_dir)) if os.path.isdir(piece_dir) else []


def run_session(folder):
    """The whole session on the active connection; the measurements as a dict."""
    load_plugin_everywhere()
    session = build_session()
    region = session["region"]
    result = {"ranks": sm.ActiveConnection.GetNumberOfDataPartitions(),
              "drawing": {name: list(session["curves"].GetPropertyValue(name))
                          for name in ("TriangleIds", "Barycentrics", "CurveSizes", "ShapeIds")},
              "surface": measure_surface(session["surface"]),
              "region": measure(region)}
    result["png"] = os.path.join(folder, "region.png")
    (result["region_pixels"], result["region_covered"],
     result["rendered_on_server"]) = render_region(session, result["png"])
    pvtp = os.path.join(folder, "region.pvtp")
    result["pvtp"] = pvtp
    result["pvtp_pieces"] = save_pieces(region, pvtp)
    result["read_back"] = measure(simple.OpenDataFile(pvtp))
    # The one-step filter on the same drawing and Boolean: on the pieces too, the same region.
    one_step = plugin_proxy("BoolSurf", "filters", Surface=session["surface"],
                            Curves=session["curves"], Operation="Union", ShapeA=0, ShapeB=2)
    one_step.UpdatePipeline()
    result["one_step"] = measure(one_step)
    result["one_step_png"] = os.path.join(folder, "one_step.png")
    _, result["one_step_pixels"], result["one_step_rendered_on_server"] = render_region(
        dict(session, region=one_step), result["one_step_png"], hide=region, rgb=ONE_STEP_RGB)
    return result


def measure_surface(surface):
    """How the redistributed surface lies on the ranks: triangles per rank."""
    data = sm.Fetch(simple.ProcessIdScalars(Input=surface))
    rank = data.GetPointData().GetArray("ProcessId")
    held = {}
    for c in range(data.GetNumberOfCells()):
        holder = str(int(rank.GetTuple1(data.GetCell(c).GetPointId(0))))
        held[holder] = held.get(holder, 0) + 1
    return {"triangles": data.GetNumberOfCells(), "held": held}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--json", required=True)
    parser.add_argument("--folder")
    parser.add_argument("--server")
    parser.add_argument("--read")
    args = parser.parse_args()
    if args.read:
        result = {"ranks": sm.ActiveConnection.GetNumberOfDataPartitions(),
                  "read_back": measure(simple.OpenDataFile(args.read))}
    else:
        if args.server:
            host, port = args.server.rsplit(":", 1)
            simple.Connect(host, int(port))
        result = run_session(args.folder)
    with open(args.json, "w") as f:
        json.dump(result, f, indent=1, sort_keys=True)
    print("session done on %d rank(s)" % result["ranks"])


if __name__ == "__main__":
    main()

"""What a pvpython user waits for after an edit at paper scale: the one-step BoolSurf filter with
its default outputs (four ports) on igea_1m, 112 circles x 32 exact control points in clusters
of four (the scene of BM_OneStepPaperScaleXor, paper_scale_scene.py), symmetric difference of
all shapes, every circle moved per edit (the two prepared versions in turn, every control point
also moved by ~1e-12 so nothing is recalled from the tracer's memory), through a Surface Curves
source as a user would feed it.

Each edit sets the source's properties, then times, apart:
  curves   the Surface Curves source's update (its port 0; it also traces port 1 for display);
  update   BoolSurf's UpdatePipeline() (every output port, as paraview.simple does);
  info     the data information of BoolSurf's four ports (bounds, every array's range: what the
           GUI's panels and a representation read after an update);
and splits `update` with the filter's own StageTimes field array (Total, per port) from the
rest (ParaView's pipeline passes and proxies). Prints medians and ranges, the machine's cores
and load, and the process's resident memory (current and peak) after each phase.

    pvpython Benchmarks/ParaView/paper_scale_update.py [--mesh PATH] [--edits N]
        [--scene paper|ten] [--scene-cache FILE.json] [--threads N] [--no-control-curves]
        [--show] [--stage-chain]

--show also shows the four ports in a render view and renders once per edit (needs a display:
Testing/run-with-xvfb.sh). --stage-chain runs the same edits through the stage filters (Trace
Surface Curves -> Surface Arrangement -> Label Arrangement Cells -> Surface Boolean, the last
one updated and its ports read; StageTimes are then absent and "the rest" is the whole chain).
The plugin: $BOOLSURF_PLUGIN, else build/ beside Benchmarks/.
"""
import argparse
import os
import statistics
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(ROOT, "Examples"))

from paraview.simple import *  # noqa: E402,F401,F403
from paraview import servermanager as sm  # noqa: E402
from boolsurf_example_utils import load_plugin  # noqa: E402
from paper_scale_scene import scene_versions  # noqa: E402

STAGES = ("Trace", "Hash", "Intersections", "Refinement", "FloodFill", "CellGraph", "Labeling",
          "Selection", "Output", "ControlCurves", "Total", "Port0Region", "Port1Boundary",
          "Port2BoundaryControlCurves", "Port3ClippedCurves")


def memory_mb():
    """(resident, peak resident) of this process in MB."""
    values = {}
    with open("/proc/self/status") as status:
        for line in status:
            key, _, rest = line.partition(":")
            if key in ("VmRSS", "VmHWM"):
                values[key] = int(rest.split()[0]) / 1024.0
    return values.get("VmRSS", 0.0), values.get("VmHWM", 0.0)


def load_average():
    with open("/proc/loadavg") as f:
        return " ".join(f.read().split()[:3])


def moved(weights, step):
    """Every control point moved by about 1e-12 of its triangle (as the C++ benchmark's Moved)."""
    shift = 1e-12 * (1 + step % 4096)
    out = list(weights)
    for i in range(0, len(out), 2):
        out[i] += shift if out[i] + out[i + 1] + shift < 1 else -shift
    return out


def stage_times(proxy):
    """The filter's StageTimes of its last update, read from the output object itself (pvpython
    runs the pipeline in this process): {component name: milliseconds}."""
    region = proxy.GetClientSideObject().GetOutputDataObject(0)
    times = region.GetFieldData().GetArray("StageTimes") if region else None
    if not times or times.GetNumberOfTuples() < 1:
        return {}
    return {times.GetComponentName(k) or str(k): times.GetComponent(0, k)
            for k in range(times.GetNumberOfComponents())}


def read_information(proxy):
    """What ParaView gathers of every port after an update: its data information (bounds, the
    ranges of every point and cell array)."""
    for port in range(proxy.SMProxy.GetNumberOfOutputPorts()):
        proxy.GetDataInformation(port).GetNumberOfCells()


def summary(values):
    return "%.1f (%.1f-%.1f)" % (statistics.median(values), min(values), max(values))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--mesh", default=os.path.join(ROOT, "..", "shared", "data", "meshes",
                                                       "igea_1m.ply"))
    parser.add_argument("--scene", default="paper", choices=("paper", "ten"))
    parser.add_argument("--edits", type=int, default=10)
    parser.add_argument("--scene-cache", help="JSON file of the placed scene (written if absent)")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--no-control-curves", action="store_true")
    parser.add_argument("--show", action="store_true")
    parser.add_argument("--stage-chain", action="store_true",
                        help="the same edits through Trace Surface Curves, Surface Arrangement, "
                        "Label Arrangement Cells and Surface Boolean instead of BoolSurf")
    args = parser.parse_args()

    print("cores %d, load %s" % (os.cpu_count(), load_average()))
    memory = [("start", memory_mb())]
    load_plugin(globals())
    mesh = PLYReader(FileNames=[args.mesh])
    mesh.UpdatePipeline()
    memory.append(("mesh read", memory_mb()))
    t0 = time.perf_counter()
    # The reader's own output (pvpython runs the pipeline in this process): no copy of the mesh.
    versions = scene_versions(mesh.GetClientSideObject().GetOutputDataObject(0), args.scene,
                              args.scene_cache)
    print("scene %s: %d curves placed in %.1f s" % (args.scene, len(versions[0][3]),
                                                    time.perf_counter() - t0))
    memory.append(("scene placed", memory_mb()))
    points, triangles, weights, sizes = versions[0]
    curves = SurfaceCurves(Surface=mesh, Points=points, TriangleIds=triangles,
                           Barycentrics=weights, CurveSizes=sizes,
                           ShapeIds=list(range(len(sizes))))
    curves.UpdatePipeline()
    memory.append(("curves source updated", memory_mb()))
    if args.stage_chain:
        traced = TraceSurfaceCurves(Surface=mesh, Curves=curves)
        arranged = SurfaceArrangement(Surface=mesh, Curves=traced, NumberOfThreads=args.threads)
        labeled = LabelArrangementCells(Input=arranged)
        one = SurfaceBoolean(Input=labeled, Operation="SymmetricDifference", ShapeA=-1, ShapeB=-1)
    else:
        one = BoolSurf(Surface=mesh, Curves=curves, Operation="SymmetricDifference", ShapeA=-1,
                       ShapeB=-1, NumberOfThreads=args.threads,
                       ComputeControlCurves=0 if args.no_control_curves else 1)
    t0 = time.perf_counter()
    one.UpdatePipeline()
    first = 1000 * (time.perf_counter() - t0)
    read_information(one)
    memory.append(("first BoolSurf update", memory_mb()))
    view = None
    if args.show:
        view = CreateView("RenderView")
        for port in range(one.SMProxy.GetNumberOfOutputPorts()):
            Show(OutputPort(one, port), view)
        Render(view)
        memory.append(("shown and rendered", memory_mb()))

    rows = {"curves": [], "update": [], "info": [], "render": [], "rest": []}
    stages = {}
    for step in range(1, args.edits + 1):
        points, triangles, weights, sizes = versions[step % len(versions)]
        curves.Points = points
        curves.TriangleIds = triangles
        curves.Barycentrics = moved(weights, step)
        t0 = time.perf_counter()
        curves.UpdatePipeline()
        t1 = time.perf_counter()
        one.UpdatePipeline()
        t2 = time.perf_counter()
        read_information(one)
        t3 = time.perf_counter()
        if view is not None:
            Render(view)
        t4 = time.perf_counter()
        times = {} if args.stage_chain else stage_times(one)
        rows["curves"].append(1000 * (t1 - t0))
        rows["update"].append(1000 * (t2 - t1))
        rows["info"].append(1000 * (t3 - t2))
        rows["render"].append(1000 * (t4 - t3))
        rows["rest"].append(1000 * (t2 - t1) - times.get("Total", 0.0))
        for name, value in times.items():
            stages.setdefault(name, []).append(value)
    memory.append(("after %d edits" % args.edits, memory_mb()))

    region = one.GetDataInformation(0)
    print("region %d triangles, %d points; boundary %d points; first update %.0f ms" % (
        region.GetNumberOfCells(), region.GetNumberOfPoints(),
        one.GetDataInformation(1).GetNumberOfPoints(), first))
    print("edit (ms), median (range) of %d, load %s:" % (args.edits, load_average()))
    print("  Surface Curves source update     %s" % summary(rows["curves"]))
    print("  BoolSurf UpdatePipeline          %s" % summary(rows["update"]))
    print("    the filter's Total (StageTimes) %s" % summary(stages.get("Total", [0])))
    print("    the rest (ParaView)             %s" % summary(rows["rest"]))
    print("  data information of the 4 ports  %s" % summary(rows["info"]))
    print("  update + information             %s" % summary(
        [u + i for u, i in zip(rows["update"], rows["info"])]))
    if view is not None:
        print("  render                           %s" % summary(rows["render"]))
    print("  stages: " + ", ".join("%s %.1f" % (name, statistics.median(stages[name]))
                                  for name in STAGES if name in stages))
    print("memory (MB, resident / peak):")
    for name, (rss, peak) in memory:
        print("  %-28s %7.0f / %7.0f" % (name, rss, peak))


main()

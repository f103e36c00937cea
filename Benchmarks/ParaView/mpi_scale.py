"""What each MPI rank holds, sends and spends when the stage filters run on a split surface:
Trace Surface Curves -> Surface Arrangement -> Label Arrangement Cells -> Surface Boolean (the
symmetric difference of every shape), first update then edits that move every curve, on P
ranks of pvbatch (Docs/Parallel.md; issue 56's benchmark). Run by mpi_scale.sh:

    mpiexec -np P pvbatch --symmetric mpi_scale.py --surface S --scene-cache C.json
        --json OUT.json [--edits N] [--threads T]
    pvpython mpi_scale.py --summarize OUT1.json OUT2.json ...   (the tables and the targets)

S is the surface with point and cell GlobalIds (mpi_scale_prepare.py): a .vtp on one rank, a
.pvtp of P pieces on P ranks, so each rank reads only its piece. Every rank runs this script
(--symmetric) and measures itself: its peak resident memory (VmHWM of /proc/self/status) after
loading the plugin (the idle pvbatch, the reference) and after each stage, each stage's wall
time (UpdatePipeline on this rank, so it includes waiting for the others), the stage filters'
own per-rank arrays (StageTimes; PieceBytes, the bytes sent and received per message, and any
other field array whose name ends in Bytes, such as a tracer's traffic), and the size of its
piece. Rank 0 gathers the records (files beside OUT) and writes OUT with the machine's load.
The summary also gives each rank's peak after each stage's first update, which says what holds
a rank's memory.

No stage gathers the surface: Surface Curves places and traces on the pieces, Trace Surface
Curves traces there (sharing Surface Curves' ringed piece and tracer), and the curves, which
live on rank 0, travel nowhere else before Surface Arrangement broadcasts them. The bytes of
the ghost exchange (vtkGhostCellsGenerator) are not counted; Surface Arrangement estimates its
ring (RingEstimate).
"""
import argparse
import json
import os
import statistics
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "Examples"))

STAGES = ("curves", "trace", "arrangement", "labels", "boolean")


def memory_kb():
    values = {}
    with open("/proc/self/status") as status:
        for line in status:
            key, _, rest = line.partition(":")
            if key in ("VmRSS", "VmHWM"):
                values[key] = int(rest.split()[0])
    return {"rss": values.get("VmRSS", 0), "hwm": values.get("VmHWM", 0)}


def load_average():
    with open("/proc/loadavg") as f:
        return [float(x) for x in f.read().split()[:3]]


def moved(weights, step):
    """Every control point moved by about 1e-12 of its triangle, so nothing is recalled from a
    tracer's memory (as paper_scale_update.py)."""
    shift = 1e-12 * (1 + step % 4096)
    out = list(weights)
    for i in range(0, len(out), 2):
        out[i] += shift if out[i] + out[i + 1] + shift < 1 else -shift
    return out


def field_arrays(data):
    """The field arrays a stage writes per rank: StageTimes, every *Bytes array and Surface
    Arrangement's PieceArrangementReuse (what an edit kept), as {array: {component: value}}."""
    out = {}
    if data is None:
        return out
    fd = data.GetFieldData()
    for i in range(fd.GetNumberOfArrays()):
        array = fd.GetArray(i)
        if not array or not array.GetName() or array.GetNumberOfTuples() < 1:
            continue
        name = array.GetName()
        if name not in ("StageTimes", "PieceArrangementReuse") and not name.endswith("Bytes"):
            continue
        out[name] = {array.GetComponentName(k) or str(k): array.GetComponent(0, k)
                     for k in range(array.GetNumberOfComponents())}
    return out


def run(args):
    from vtkmodules.vtkParallelCore import vtkMultiProcessController
    import paraview.simple as simple
    from boolsurf_example_utils import load_plugin

    controller = vtkMultiProcessController.GetGlobalController()
    rank, ranks = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()
    record = {"rank": rank, "memory": {"start": memory_kb()}}
    load_plugin(vars(simple))
    record["memory"]["idle"] = memory_kb()  # pvbatch with the plugin, no data: the reference

    surface = simple.OpenDataFile(args.surface)
    surface.UpdatePipeline()
    piece = surface.GetClientSideObject().GetOutputDataObject(0)
    record["piece"] = {"triangles": piece.GetNumberOfCells(), "points": piece.GetNumberOfPoints(),
                       "bytes": piece.GetActualMemorySize() * 1024}
    record["memory"]["read"] = memory_kb()

    with open(args.scene_cache) as f:
        versions = json.load(f)["versions"]
    points, triangles, weights, sizes = versions[0]
    curves = simple.SurfaceCurves(Surface=surface, Points=points, TriangleIds=triangles,
                                  Barycentrics=weights, CurveSizes=sizes,
                                  ShapeIds=list(range(len(sizes))))
    traced = simple.TraceSurfaceCurves(Surface=surface, Curves=curves)
    arranged = simple.SurfaceArrangement(Surface=surface, Curves=traced,
                                         NumberOfThreads=args.threads)
    labeled = simple.LabelArrangementCells(Input=arranged)
    boolean = simple.SurfaceBoolean(Input=labeled, Operation="SymmetricDifference", ShapeA=-1,
                                    ShapeB=-1)
    proxies = dict(zip(STAGES, (curves, traced, arranged, labeled, boolean)))

    def update(kind):
        stages = {}
        for name in STAGES:
            proxy = proxies[name]
            t0 = time.perf_counter()
            proxy.UpdatePipeline()
            wall = 1000 * (time.perf_counter() - t0)
            data = proxy.GetClientSideObject().GetOutputDataObject(0)
            stages[name] = {"wall_ms": wall, "cells": data.GetNumberOfCells() if data else 0,
                            "arrays": field_arrays(data), "memory": memory_kb()}
        return {"kind": kind, "stages": stages}

    record["updates"] = [update("first")]
    for step in range(1, args.edits + 1):
        points, triangles, weights, sizes = versions[step % len(versions)]
        curves.Points = points
        curves.TriangleIds = triangles
        curves.Barycentrics = moved(weights, step)
        record["updates"].append(update("edit"))
    record["memory"]["end"] = memory_kb()

    # Every rank's record to rank 0, through files beside the output (small; no pipeline).
    mine = "%s.rank%d" % (args.json, rank)
    with open(mine, "w") as f:
        json.dump(record, f)
    controller.Barrier()
    if rank != 0:
        return
    records = []
    for r in range(ranks):
        path = "%s.rank%d" % (args.json, r)
        with open(path) as f:
            records.append(json.load(f))
        os.remove(path)
    result = {"ranks": ranks, "surface": args.surface, "scene": args.scene_cache,
              "threads": args.threads, "edits": args.edits, "cores": os.cpu_count(),
              "load": load_average(), "records": records}
    with open(args.json, "w") as f:
        json.dump(result, f)
    print_run(result)


# --- reading the records ------------------------------------------------------------------


def bytes_of(stage):
    """(sent, received) of a stage's update on a rank: every *Bytes array's components."""
    sent = received = 0.0
    for name, components in stage["arrays"].items():
        if not name.endswith("Bytes"):
            continue
        for component, value in components.items():
            if component.endswith("Sent"):
                sent += value
            elif component.endswith("Received"):
                received += value
    return sent, received


def times(stage):
    return stage["arrays"].get("StageTimes", {})


def distributed_part(update, ranks):
    """Refinement + flood fill + output of one update on one rank (ms): the arrangement's
    Refinement and FloodFill (its StageTimes), its writing of the refined surface (on pieces its
    Output step; on one rank its wall time past its StageTimes Total), and Surface Boolean's
    wall time."""
    arrangement = update["stages"]["arrangement"]
    t = times(arrangement)
    if ranks > 1:
        written = t.get("Output", 0.0)
    else:
        written = arrangement["wall_ms"] - t.get("Total", 0.0)
    return (t.get("Refinement", 0.0) + t.get("FloodFill", 0.0) + written +
            update["stages"]["boolean"]["wall_ms"])


def surface_bytes(result):
    """The surface's own size: its positions as 3 floats and its triangles as 3 32-bit ids (what
    a PLY file holds), the smallest it can travel in; the pieces in memory (with GlobalIds,
    double positions) are 2 to 3 times that."""
    return sum(12 * (r["piece"]["points"] + r["piece"]["triangles"]) for r in result["records"])


def memory_bytes(result):
    return sum(r["piece"]["bytes"] for r in result["records"])


def surface_triangles(result):
    return sum(r["piece"]["triangles"] for r in result["records"])


def summarize_run(result):
    """Per rank: memory, first update and median edit (wall per stage, bytes)."""
    rows = []
    for r in result["records"]:
        first, edits = r["updates"][0], r["updates"][1:]
        row = {"rank": r["rank"], "triangles": r["piece"]["triangles"],
               "idle_mb": r["memory"]["idle"]["hwm"] / 1024.0,
               "peak_mb": r["memory"]["end"]["hwm"] / 1024.0}
        row["above_idle_mb"] = row["peak_mb"] - row["idle_mb"]
        # What each stage's first update added to the rank's peak (the piece as read first).
        row["stage_peaks_mb"] = [("read", (r["memory"]["read"]["hwm"] - r["memory"]["idle"]["hwm"])
                                  / 1024.0)] + [
            (s, (first["stages"][s]["memory"]["hwm"] - r["memory"]["idle"]["hwm"]) / 1024.0)
            for s in STAGES]
        for label, updates in (("first", [first]), ("edit", edits or [first])):
            walls = {s: statistics.median(u["stages"][s]["wall_ms"] for u in updates)
                     for s in STAGES}
            traffic = {s: [statistics.median(bytes_of(u["stages"][s])[k] for u in updates)
                           for k in (0, 1)] for s in STAGES}
            row[label] = {"wall_ms": walls, "bytes": traffic,
                          "distributed_ms": statistics.median(
                              distributed_part(u, result["ranks"]) for u in updates),
                          "stage_times": {s: {k: statistics.median(
                              times(u["stages"][s]).get(k, 0.0) for u in updates)
                              for k in times(updates[0]["stages"][s])} for s in STAGES}}
        rows.append(row)
    return rows


def print_run(result):
    rows = summarize_run(result)
    print("%d rank(s), %s, %s; %d triangles (%.1f MB as floats and ids, %.1f MB in memory); "
          "%d cores, load %s" % (
              result["ranks"], os.path.basename(result["surface"]),
              os.path.basename(result["scene"]), surface_triangles(result),
              surface_bytes(result) / 1e6, memory_bytes(result) / 1e6, result["cores"],
              " ".join("%.2f" % x for x in result["load"])))
    print("rank triangles | idle MB  peak MB  above idle | first update wall ms: curves trace "
          "arrangement labels boolean | R+F+output ms first/edit | bytes sent/received: first "
          "update / per edit")
    for row in rows:
        f, e = row["first"], row["edit"]
        sent_first = sum(v[0] for v in f["bytes"].values())
        received_first = sum(v[1] for v in f["bytes"].values())
        sent_edit = sum(v[0] for v in e["bytes"].values())
        received_edit = sum(v[1] for v in e["bytes"].values())
        print("%4d %9d | %7.0f %8.0f %10.0f | %s | %7.0f / %7.0f | %s / %s / %s / %s" % (
                  row["rank"], row["triangles"], row["idle_mb"], row["peak_mb"],
                  row["above_idle_mb"],
                  " ".join("%7.0f" % f["wall_ms"][s] for s in STAGES),
                  f["distributed_ms"], e["distributed_ms"],
                  human(sent_first), human(received_first), human(sent_edit),
                  human(received_edit)))
    print("peak above idle after each stage's first update (MB; the last edit's peak above):")
    for row in rows:
        print("  rank %d: %s" % (row["rank"], ", ".join("%s %.0f" % (s, mb)
                                                        for s, mb in row["stage_peaks_mb"])))
    print("per message (rank: first update sent/received; per edit sent/received):")
    for r, row in zip(result["records"], rows):
        for s in ("arrangement", "labels", "boolean", "trace"):
            arrays = r["updates"][-1]["stages"][s]["arrays"]
            parts = []
            for name, components in sorted(arrays.items()):
                if not name.endswith("Bytes"):
                    continue
                first = r["updates"][0]["stages"][s]["arrays"].get(name, {})
                for c in components:
                    if c.endswith("Sent"):
                        m = c[:-4]
                        parts.append("%s %s/%s; %s/%s" % (
                            m, human(first.get(m + "Sent", 0)),
                            human(first.get(m + "Received", 0)),
                            human(components.get(m + "Sent", 0)),
                            human(components.get(m + "Received", 0))))
            if parts:
                print("  rank %d %s: %s" % (row["rank"], s, ", ".join(parts)))
    print("arrangement steps per rank, median edit (ms):")
    for row in rows:
        steps = row["edit"]["stage_times"]["arrangement"]
        print("  rank %d: %s" % (row["rank"], ", ".join("%s %.0f" % (k, v)
                                                        for k, v in steps.items())))
    if result["ranks"] > 1:
        print("what each edit kept (PieceArrangementReuse: piece, arrangement computed in place):")
        for r in result["records"]:
            kept = [u["stages"]["arrangement"]["arrays"].get("PieceArrangementReuse", {})
                    for u in r["updates"][1:]]
            print("  rank %d: %s" % (r["rank"], " ".join(
                "%d/%d" % (k.get("KeptPiece", -1), k.get("KeptArrangement", -1))
                for k in kept)))


def human(n):
    n = float(n)
    for unit in ("B", "kB", "MB", "GB"):
        if abs(n) < 1000 or unit == "GB":
            return ("%.0f %s" if unit == "B" else "%.1f %s") % (n, unit)
        n /= 1000.0


def summarize(paths):
    """Each run's table, then the issue's targets against the one-rank run of the same surface
    and scene."""
    results = []
    for path in paths:
        with open(path) as f:
            results.append(json.load(f))
    for result in results:
        print_run(result)
        print()
    for result in results:
        if result["ranks"] == 1:
            continue
        base = [b for b in results if b["ranks"] == 1 and b["scene"] == result["scene"] and
                os.path.splitext(os.path.basename(b["surface"]))[0] ==
                os.path.splitext(os.path.basename(result["surface"]))[0].rsplit("-", 1)[0]]
        rows = summarize_run(result)
        size = surface_bytes(result)
        worst_edit = max(sum(v[0] + v[1] for v in row["edit"]["bytes"].values())
                         for row in rows)
        total_edit = sum(sum(v[0] for v in row["edit"]["bytes"].values()) for row in rows)
        print("%d ranks, %s: bytes per edit, the most a rank sent+received %s (%.3f %% of the "
              "surface's %s), all ranks' sent %s" % (
                  result["ranks"], os.path.basename(result["scene"]), human(worst_edit),
                  100.0 * worst_edit / size, human(size), human(total_edit)))
        if not base:
            continue
        one = summarize_run(base[0])[0]
        largest = max(rows, key=lambda row: row["above_idle_mb"])
        largest_piece = max(row["above_idle_mb"] for row in rows if row["rank"] != 0) \
            if len(rows) > 1 else 0
        print("  memory above idle: largest rank (rank %d) %.0f MB = %.2f x one rank's %.0f MB;"
              " the largest rank other than 0 %.0f MB = %.2f x" % (
                  largest["rank"], largest["above_idle_mb"],
                  largest["above_idle_mb"] / one["above_idle_mb"], one["above_idle_mb"],
                  largest_piece, largest_piece / one["above_idle_mb"]))
        for label in ("first", "edit"):
            slowest = max(row[label]["distributed_ms"] for row in rows)
            print("  refinement + flood fill + output, %s: slowest rank %.0f ms = %.2f x one "
                  "rank's %.0f ms" % (label, slowest, slowest / one[label]["distributed_ms"],
                                      one[label]["distributed_ms"]))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--surface")
    parser.add_argument("--scene-cache")
    parser.add_argument("--json")
    parser.add_argument("--edits", type=int, default=3)
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument("--summarize", nargs="+", metavar="JSON")
    args = parser.parse_args()
    if args.summarize:
        summarize(args.summarize)
    else:
        run(args)


main()

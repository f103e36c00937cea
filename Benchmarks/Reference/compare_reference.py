#!/usr/bin/env python3
"""Arrange + label on the authors' scenes: their command-line tool beside our filters.

    python3 Benchmarks/Reference/compare_reference.py --reference <boolsurf_ref_test> \
        [--benchmarks build/bin/BoolSurfVTKBenchmarks] [--data ../shared/data] [--runs 10] \
        [--rounds 3] [--scenes REGEX] [--json out.json]

The reference binary is built by ../shared/tools/build_reference.sh (it prints the path). For
each scene that has its mesh in the shared collection, in turn and `--rounds` times (so both
programs see the same state of a shared machine): the reference tool with `--num-tests RUNS`
(its own timers: slice_mesh, make_cell_graph, compute_cell_labels per run, from the
"cumulative ms" lines its patched build prints), then our BM_StageChainScene (Surface
Arrangement + Label Arrangement Cells, counter ArrangeLabel_ms) and BM_OneStepScene (the
one-step filter's hash ... labeling stages, the same counter) on 1 and 2 threads. Per scene the
median over rounds; the table gives each and the ratios of the sums over the scenes that both
answer (our chain skips scenes whose shapes are all inconsistent: the Boolean refuses them).
"""
import argparse
import json
import os
import re
import statistics
import subprocess
import sys

ROW = re.compile(r"^\| `([^`]+\.json)` \|[^|]*\| `\.\./meshes/([^`]+)` \|.*mesh available")


def scenes(data, pattern):
    with open(os.path.join(data, "boolsurf-scenes", "README.md")) as readme:
        for line in readme:
            m = ROW.search(line)
            if m and re.search(pattern, m.group(1)):
                yield m.group(1), m.group(2)


def reference_ms(binary, data, scene, mesh, runs):
    """Median over runs of slice + cell graph + labels (ms), from the cumulative sums."""
    out = subprocess.run(
        [binary, "--model", os.path.join(data, "meshes", mesh), "--num-tests", str(runs),
         os.path.join(data, "boolsurf-scenes", scene)],
        capture_output=True, text=True, cwd=os.environ.get("TMPDIR", "/tmp"))
    sums = [[float(x) for x in line.split()[2:5]] for line in out.stdout.splitlines()
            if line.startswith("cumulative ms:")]
    if out.returncode != 0 or not sums:
        return None
    per_run, previous = [], 0.0
    for s in sums:
        total = sum(s)
        per_run.append(total - previous)
        previous = total
    return statistics.median(per_run)


def ours_ms(binary, scene, runs):
    """ArrangeLabel_ms of the chain and the one-step filter, 1 and 2 threads."""
    name = re.escape(scene)
    out = subprocess.run(
        [binary, "--benchmark_filter=BM_(StageChainScene|OneStepScene)/%s/[12](/|$)" % name,
         "--benchmark_format=json"],
        capture_output=True, text=True,
        env=dict(os.environ, BOOLSURF_BENCHMARK_ITERATIONS=str(runs)))
    result = {}
    try:
        report = json.loads(out.stdout)
    except ValueError:
        return result
    for b in report.get("benchmarks", []):
        if b.get("error_occurred") or "ArrangeLabel_ms" not in b:
            continue
        kind = "chain" if b["name"].startswith("BM_StageChainScene") else "onestep"
        threads = b["name"].split(".json/")[1][0]  # .../<scene>.json/<threads>[/iterations:N]
        result["%s_%st" % (kind, threads)] = b["ArrangeLabel_ms"]
    return result


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--reference", required=True)
    parser.add_argument("--benchmarks", default="build/bin/BoolSurfVTKBenchmarks")
    parser.add_argument("--data", default=os.path.join("..", "shared", "data"))
    parser.add_argument("--runs", type=int, default=10)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--scenes", default=".")
    parser.add_argument("--json")
    args = parser.parse_args()
    args.data = os.path.abspath(args.data)
    args.reference = os.path.abspath(args.reference)
    if not os.path.isdir(os.path.join(args.data, "boolsurf-scenes")):
        sys.exit("no boolsurf-scenes in %s (the shared data folder)" % args.data)

    keys = ["ref", "chain_1t", "chain_2t", "onestep_1t", "onestep_2t"]
    rows = {}
    for scene, mesh in scenes(args.data, args.scenes):
        samples = {k: [] for k in keys}
        for _ in range(args.rounds):
            ref = reference_ms(args.reference, args.data, scene, mesh, args.runs)
            if ref is not None:
                samples["ref"].append(ref)
            for k, v in ours_ms(args.benchmarks, scene, args.runs).items():
                samples[k].append(v)
        rows[scene] = {k: statistics.median(v) if v else None for k, v in samples.items()}
        print(scene, " ".join("%s=%s" % (k, "-" if rows[scene][k] is None else
                                         "%.2f" % rows[scene][k]) for k in keys), flush=True)

    both = [s for s, r in rows.items() if all(r[k] is not None for k in keys)]
    sums = {k: sum(rows[s][k] for s in both) for k in keys}
    print("\n| scene | reference | chain 1t | chain 2t | one-step 1t | one-step 2t |")
    print("|---|---:|---:|---:|---:|---:|")
    for s in both:
        print("| %s | %s |" % (s, " | ".join("%.2f" % rows[s][k] for k in keys)))
    print("| **sum, %d scenes** | %s |" % (len(both), " | ".join("%.1f" % sums[k] for k in keys)))
    if sums["ref"] > 0:
        print("| ratio to the reference | 1 | %s |" %
              " | ".join("%.2f" % (sums[k] / sums["ref"]) for k in keys[1:]))
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"scenes": rows, "sums": sums, "load": os.getloadavg()}, f, indent=1)


if __name__ == "__main__":
    main()

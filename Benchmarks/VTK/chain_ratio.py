#!/usr/bin/env python3
"""Stage chain against one-step filter on the reference scenes, from a Google Benchmark JSON.

Reads BM_PairedSceneEdit results (the two pipelines timed in turn within each iteration) and
prints, per thread count, the sums over the scenes of the median one-step and chain edits and
their ratio, plus the median of the per-scene ratios. With --scenes, one line per scene.
Scenes the benchmark skipped (an error) are left out of both sums.

  BoolSurfVTKBenchmarks --benchmark_filter=PairedSceneEdit --benchmark_out=paired.json
  python3 Benchmarks/VTK/chain_ratio.py paired.json [--scenes]
"""
import collections
import json
import statistics
import sys


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    runs = json.load(open(sys.argv[1]))["benchmarks"]
    # Repetitions give one median row each; without repetitions the single run is used.
    rows = collections.defaultdict(list)
    for b in runs:
        if not b["name"].startswith("BM_PairedSceneEdit/") or b.get("error_occurred"):
            continue
        if b.get("run_type") == "aggregate" and b.get("aggregate_name") != "median":
            continue
        if any(r.get("run_type") == "aggregate" for r in runs) and b.get("run_type") != "aggregate":
            continue
        scene, threads = b["run_name"].split("/", 1)[1].rsplit("/", 1)
        rows[threads.split(":")[0]].append((scene, b["OneStep_ms"], b["Chain_ms"], b["Ratio"]))
    for threads, scenes in sorted(rows.items()):
        one = sum(r[1] for r in scenes)
        chain = sum(r[2] for r in scenes)
        print(f"threads {threads}: {len(scenes)} scenes, one-step {one:.1f} ms, chain {chain:.1f} ms,"
              f" chain / one-step {chain / one:.3f} (median per-scene ratio"
              f" {statistics.median(r[3] for r in scenes):.3f})")
        if "--scenes" in sys.argv:
            for scene, o, c, r in sorted(scenes, key=lambda r: -r[1]):
                print(f"  {scene:40s} {o:8.2f} {c:8.2f}  {r:.2f}")


if __name__ == "__main__":
    main()

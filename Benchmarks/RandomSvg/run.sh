#!/usr/bin/env bash
# The paper's randomized benchmark (Fig. 22) end to end: runs BoolSurfRandomSvgBenchmark on
# every shared mesh of >= 100k triangles and draws the histogram of full-update times.
#   bash Benchmarks/RandomSvg/run.sh [trials-per-mesh] [output-folder] [benchmark options...]
# Needs the build (Scripts/setup.sh) and the shared data beside the project (../shared/data)
# or in BOOLSURF_SHARED_DATA. Writes random_svg_booleans.csv, .txt (the summary) and .png.
set -euo pipefail
cd "$(dirname "$0")/../.."
trials=${1:-40}
out=${2:-out}
shift $(( $# < 2 ? $# : 2 ))
mkdir -p "$out"
export BOOLSURF_SHARED_DATA=${BOOLSURF_SHARED_DATA:-$(pwd)/../shared/data}
build/bin/BoolSurfRandomSvgBenchmark --trials "$trials" --csv "$out/random_svg_booleans.csv" "$@" |
  tee "$out/random_svg_booleans.txt"
if [ -s "$out/random_svg_booleans.csv" ]; then
  Testing/run-with-xvfb.sh /usr/bin/pvpython Benchmarks/RandomSvg/plot_histogram.py \
    "$out/random_svg_booleans.csv" "$out/random_svg_booleans.png" --cores "$(nproc)"
fi

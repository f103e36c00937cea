#!/usr/bin/env bash
# Sets up (packages + build, see setup.sh) and runs Examples/demo.py with pvbatch under Xvfb,
# writing a .vtp result and a .png screenshot into out/ (or the folder given as $1).
set -euo pipefail
cd "$(dirname "$0")/.."
bash Scripts/setup.sh
out="${1:-out}"
mkdir -p "$out"
export BOOLSURF_PLUGIN="$PWD/build/lib/paraview-5.11/plugins/BoolSurf/BoolSurf.so"
xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" pvbatch Examples/demo.py --output "$out"

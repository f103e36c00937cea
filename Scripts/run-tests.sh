#!/usr/bin/env bash
# Sets up (packages + build, see setup.sh) and runs every test with ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash Scripts/setup.sh
cd build
ctest -j"$(nproc)" --output-on-failure --timeout 900

#!/usr/bin/env bash
# Sets up (packages + build, see setup.sh) and runs every test with ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash Scripts/setup.sh
(cd build && ctest -j"$(nproc)" --output-on-failure --timeout 900)

# The C++ tests again under AddressSanitizer and UndefinedBehaviorSanitizer (a second build in
# build-sanitize/: Core, the filters module and the two test executables).
echo "== sanitizer pass: Core and filter tests with -fsanitize=address,undefined"
# Leak checks off (VTK keeps singletons alive until exit); test discovery runs the executables
# at build time, so this holds for the build too.
export ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1
cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DBOOLSURF_SANITIZE=ON \
  -DBOOLSURF_BUILD_BENCHMARKS=OFF -DPython3_EXECUTABLE=/usr/bin/python3 \
  > build-sanitize.log 2>&1 || { cat build-sanitize.log; exit 1; }
cmake --build build-sanitize --target BoolSurfCoreTests BoolSurfFilterTests -- -j"$(nproc)" \
  >> build-sanitize.log 2>&1 || { tail -50 build-sanitize.log; exit 1; }
# BOOLSURF_SANITIZER_PASS: tests at scale (ten thousand segments in one triangle) run a
# smaller drawing here; they ran at full size above.
(cd build-sanitize && BOOLSURF_SANITIZER_PASS=1 ctest -j"$(nproc)" --output-on-failure --timeout 1800)

# Fuzzing (a third build in build-fuzz/, clang with libFuzzer, ASan and UBSan: Core, the scene
# reader and the four targets of Testing/Fuzz/): each target runs from its checked-in seeds for
# a bounded number of inputs (BOOLSURF_FUZZ_RUNS, at most BOOLSURF_FUZZ_SECONDS each).
echo "== fuzz pass: libFuzzer targets from their seed corpora"
cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang \
  -DCMAKE_CXX_COMPILER=clang++ -DBOOLSURF_FUZZ=ON -DBOOLSURF_BUILD_BENCHMARKS=OFF \
  -DPython3_EXECUTABLE=/usr/bin/python3 > build-fuzz.log 2>&1 || { cat build-fuzz.log; exit 1; }
cmake --build build-fuzz --target BoolSurfFuzzTargets -- -j"$(nproc)" >> build-fuzz.log 2>&1 ||
  { tail -50 build-fuzz.log; exit 1; }
(cd build-fuzz && ctest -L fuzz -j"$(nproc)" --output-on-failure)

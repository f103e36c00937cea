#!/usr/bin/env bash
# Sets up (packages + build, see setup.sh) and runs every test with ctest, then the C++ suites
# under the sanitizers and the fuzz targets. Six phases, each announced and timed on a line
# "== phase N/6: ..." (the three builds take most of the time: README, "The two commands").
set -euo pipefail
cd "$(dirname "$0")/.."

phases=6 phase=0 phase_name="" phase_started=0
elapsed() { printf '%dm%02ds' $(($1 / 60)) $(($1 % 60)); }
begin_phase() {
  phase=$1 phase_name=$2 phase_started=$SECONDS
  echo "== phase $phase/$phases: $phase_name (start; $(elapsed $SECONDS) elapsed)"
}
end_phase() {
  echo "== phase $phase/$phases: $phase_name done in $(elapsed $((SECONDS - phase_started)))" \
    "($(elapsed $SECONDS) elapsed)"
}
# A failing phase says so, with the times, before the script exits with its status.
trap 'status=$?; if ((status != 0)); then echo "== phase $phase/$phases: $phase_name FAILED" \
  "after $(elapsed $((SECONDS - phase_started))) ($(elapsed $SECONDS) elapsed)"; fi' EXIT

begin_phase 1 "setup and build (Debian packages, Release build in build/)"
bash Scripts/setup.sh
end_phase

begin_phase 2 "ctest in build/ (every test)"
(cd build && ctest -j"$(nproc)" --output-on-failure --timeout 900)
end_phase

# The C++ tests again under AddressSanitizer and UndefinedBehaviorSanitizer (a second build in
# build-sanitize/: Core, the filters module and the C++ test programs, MPI's included).
begin_phase 3 "sanitizer build in build-sanitize/ (-fsanitize=address,undefined)"
# Leak checks off (VTK keeps singletons alive until exit); test discovery runs the executables
# at build time, so this holds for the build too.
export ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1
cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DBOOLSURF_SANITIZE=ON \
  -DBOOLSURF_BUILD_BENCHMARKS=OFF -DPython3_EXECUTABLE=/usr/bin/python3 \
  > build-sanitize.log 2>&1 || { cat build-sanitize.log; exit 1; }
cmake --build build-sanitize --target BoolSurfCxxTests -- -j"$(nproc)" \
  >> build-sanitize.log 2>&1 || { tail -50 build-sanitize.log; exit 1; }
end_phase

begin_phase 4 "sanitizer ctest in build-sanitize/ (Core, filter and MPI tests)"
# BOOLSURF_SANITIZER_PASS: tests at scale (ten thousand segments in one triangle) run a
# smaller drawing here; they ran at full size above.
(cd build-sanitize && BOOLSURF_SANITIZER_PASS=1 ctest -j"$(nproc)" --output-on-failure --timeout 1800)
end_phase

# Fuzzing (a third build in build-fuzz/, clang with libFuzzer, ASan and UBSan: Core, the scene
# reader and the five targets of Testing/Fuzz/): each target runs from its checked-in seeds for
# a bounded number of inputs (BOOLSURF_FUZZ_RUNS, at most BOOLSURF_FUZZ_SECONDS each).
begin_phase 5 "fuzz build in build-fuzz/ (clang, libFuzzer)"
cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang \
  -DCMAKE_CXX_COMPILER=clang++ -DBOOLSURF_FUZZ=ON -DBOOLSURF_BUILD_BENCHMARKS=OFF \
  -DPython3_EXECUTABLE=/usr/bin/python3 > build-fuzz.log 2>&1 || { cat build-fuzz.log; exit 1; }
cmake --build build-fuzz --target BoolSurfFuzzTargets -- -j"$(nproc)" >> build-fuzz.log 2>&1 ||
  { tail -50 build-fuzz.log; exit 1; }
end_phase

begin_phase 6 "fuzz run: libFuzzer targets from their seed corpora (ctest -L fuzz)"
(cd build-fuzz && ctest -L fuzz -j"$(nproc)" --output-on-failure)
end_phase
echo "== all $phases phases passed in $(elapsed $SECONDS)"

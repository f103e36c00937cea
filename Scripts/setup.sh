#!/usr/bin/env bash
# Installs the Debian packages BoolSurf needs (only the missing ones) and builds it (Release)
# in ./build. Idempotent: quick when everything is already there.
set -euo pipefail
cd "$(dirname "$0")/.."

# Why each package is here (README, "Dependencies", says more):
packages=(
  # ParaView 5.11 with its bundled VTK 9.2, pvpython/pvbatch, and CMake packages for plugins
  paraview paraview-dev python3-paraview
  # everything ParaView's CMake config find_package()s when a plugin is configured
  qtbase5-dev qttools5-dev libqt5svg5-dev libqt5opengl5-dev qtxmlpatterns5-dev-tools
  mpi-default-bin mpi-default-dev libutfcpp-dev libavformat-dev libavcodec-dev libavutil-dev
  libswscale-dev libgdal-dev libhdf5-mpi-dev libnetcdf-dev libboost-dev libexpat1-dev
  libfreetype-dev libgl2ps-dev libglew-dev libjpeg-dev liblz4-dev liblzma-dev libxml2-dev
  libpng-dev libsqlite3-dev libtheora-dev libtiff-dev zlib1g-dev libdouble-conversion-dev
  libx11-dev libgl1-mesa-dev libxt-dev python3-dev python3-mpi4py libeigen3-dev
  # build tools and test/benchmark frameworks
  cmake ninja-build g++ googletest libgtest-dev libbenchmark-dev clang-format
  # clang (with libFuzzer) for the fuzz targets, built in build-fuzz/ by run-tests.sh
  clang
  # libraries used by BoolSurf: parallel loops, max-flow (BSC), Clipper (2D test oracle),
  # JSON (scene files, test manifests)
  libtbb-dev libboost-graph-dev libpolyclipping-dev nlohmann-json3-dev
  # GMP: exact rationals behind the arrangement's crossing predicates (when their filter
  # cannot decide)
  libgmp-dev
  # winding numbers: Eigen with CHOLMOD (SuiteSparse) for the mesh Laplacian's Cholesky
  # factorization, OpenBLAS for its dense kernels
  libsuitesparse-dev libopenblas0-pthread
  # SVG drawings (Map SVG onto Surface): svgpp, header-only on Boost, with libxml2 as parser
  libsvgpp-dev libxml2-dev
  # CGAL (header-only) and its number types: the exact polyhedral shortest-path oracle
  # (Surface_mesh_shortest_path) of the geodesic tests and benchmark; never in the product
  libcgal-dev libmpfr-dev
  # shapely (GEOS): the exact oracle of the clipping test (length of line ∩ polygon)
  python3-shapely
  # headless rendering: Debian's ParaView renders only through X
  xvfb xauth
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if ((${#missing[@]})); then
  echo "== installing ${#missing[@]} Debian package(s): ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  SUDO=""
  if [ "$(id -u)" != 0 ]; then SUDO=sudo; fi
  $SUDO apt-get update -q
  $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
else
  echo "== all ${#packages[@]} Debian packages present"
fi

echo "== configuring and building (Release) in build/"
# /usr/bin/python3 explicitly: a python3 earlier on PATH (pyenv, venv) cannot see Debian's
# ParaView modules.
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3 \
  > build.log 2>&1 || { cat build.log; exit 1; }
cmake --build build -- -j"$(nproc)" >> build.log 2>&1 || { tail -50 build.log; exit 1; }
echo "== build done: plugin at build/lib/paraview-5.11/plugins/BoolSurf/BoolSurf.so"

#!/bin/sh
# The MPI scale benchmark (mpi_scale.py): prepares the surfaces once, runs pvbatch on each
# rank count and prints the tables and the issue's targets. Not a timed test: times on a
# shared machine are only indicative (the load is printed with them); memory and bytes are not
# affected by load.
#
#   Benchmarks/ParaView/mpi_scale.sh [WORK_DIR]
#
# Environment: MESHES (the shared meshes, default ../shared/data/meshes beside the repository),
# BOOLSURF_PLUGIN (default build/), EDITS (3), THREADS (1 per rank), and what to run:
#   LARGE_RANKS  ("1 2 4")  on igea_1m subdivided once (4.3M triangles), LARGE_SCENES ("ten")
#                            ("ten paper" adds the 112 shapes)
#   SMALL_RANKS  ("1 2 4 16 32") on eight_200k (199k triangles), SMALL_SCENES ("ten")
# Rank counts above the cores are oversubscribed (mpiexec --oversubscribe).
set -e
HERE=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$HERE/../.." && pwd)
WORK=${1:-/tmp/boolsurf-mpi-scale}
MESHES=${MESHES:-$ROOT/../shared/data/meshes}
EDITS=${EDITS:-3}
THREADS=${THREADS:-1}
LARGE_RANKS=${LARGE_RANKS-"1 2 4"}
LARGE_SCENES=${LARGE_SCENES-"ten"}
SMALL_RANKS=${SMALL_RANKS-"1 2 4 16 32"}
SMALL_SCENES=${SMALL_SCENES-"ten"}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p "$WORK"

# prepare NAME MESH SUBDIVISIONS "SCENES" RANKS...: the whole surface with its scenes (placing
# the 112 shapes on 4.3M triangles takes tens of minutes in Python), then its pieces.
prepare() {
  name=$1 mesh=$2 subdivide=$3 scenes=$4
  shift 4
  missing=""
  [ -f "$WORK/$name.vtp" ] || missing=yes
  for scene in $scenes; do [ -f "$WORK/$name-$scene.json" ] || missing=yes; done
  if [ -n "$missing" ]; then
    args=""
    for scene in $scenes; do args="$args --scene $scene"; done
    pvpython "$HERE/mpi_scale_prepare.py" --mesh "$MESHES/$mesh" --subdivide "$subdivide" \
      --out "$WORK/$name" --whole $args
  fi
  for ranks in "$@"; do
    if [ "$ranks" -gt 1 ] && [ ! -f "$WORK/$name-$ranks.pvtp" ]; then
      mpiexec --oversubscribe -np "$ranks" pvbatch "$HERE/mpi_scale_prepare.py" \
        --out "$WORK/$name" --pieces
    fi
  done
}

# measure NAME SCENE RANKS: one run, its JSON in WORK.
measure() {
  name=$1 scene=$2 ranks=$3
  surface="$WORK/$name.vtp"
  [ "$ranks" -gt 1 ] && surface="$WORK/$name-$ranks.pvtp"
  out="$WORK/run-$name-$scene-$ranks.json"
  mpiexec --oversubscribe -np "$ranks" pvbatch --symmetric "$HERE/mpi_scale.py" \
    --surface "$surface" --scene-cache "$WORK/$name-$scene.json" --json "$out" \
    --edits "$EDITS" --threads "$THREADS"
  RUNS="$RUNS $out"
}

RUNS=""
if [ -n "$LARGE_RANKS" ]; then
  prepare igea_4m igea_1m.ply 1 "$LARGE_SCENES" $LARGE_RANKS
  for scene in $LARGE_SCENES; do
    for ranks in $LARGE_RANKS; do measure igea_4m "$scene" "$ranks"; done
  done
fi
if [ -n "$SMALL_RANKS" ]; then
  prepare eight_200k eight_200k.ply 0 "$SMALL_SCENES" $SMALL_RANKS
  for scene in $SMALL_SCENES; do
    for ranks in $SMALL_RANKS; do measure eight_200k "$scene" "$ranks"; done
  done
fi
pvpython "$HERE/mpi_scale.py" --summarize $RUNS | tee "$WORK/summary.txt"

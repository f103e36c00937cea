#!/bin/sh
# Runs a libFuzzer target for the CTest test fuzz.<Target>:
#   run-fuzz-target.sh <target> <scratch corpus> <artifact folder> <seed corpus> <libFuzzer options>
# The scratch corpus (where libFuzzer writes the new inputs it keeps) is emptied first, so every
# run starts from the checked-in seeds alone; inputs that crash go to the artifact folder.
set -eu
target=$1 work=$2 artifacts=$3 seeds=$4
shift 4
rm -rf "$work"
mkdir -p "$work" "$artifacts"
exec "$target" -artifact_prefix="$artifacts$(basename "$target")-" "$@" "$work" "$seeds"

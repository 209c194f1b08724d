#!/usr/bin/env bash
# A real cluster in the tests: on a single-node Slurm on localhost (local_slurm.sh), `lamina
# farm plan --submit` runs a 4-task job array rendering the Cornell box in four sample ranges
# and the merge job after it. The merged image must equal a single-process render of all the
# samples (R, G, B relative 1e-6) and its Variance.Y the single render's. Every wait is
# bounded; the daemons are stopped and the scratch directory removed on every way out.
# Usage: slurm_array_test.sh LAMINA EXR_AGREEMENT SCENE
set -euo pipefail

lamina=$1 agreement=$2 scene=$3
deadline=$((SECONDS + 240))  # CTest's timeout is 300 s: leave time to clean up

source "$(dirname "$0")/local_slurm.sh"
local_slurm_require
local_slurm_start

# The plan, submitted: four shards of 2 samples, then the merge.
timeout 30 "$lamina" farm plan "$scene" --shards 4 --spp 8 --resolution 64x64 --max-depth 4 \
  --threads 1 -o "$work/plan" --submit || fail "farm plan --submit"
wait_for "the array and the merge job" queue_empty
[ -f "$work/plan/image.exr" ] || fail "the merge job wrote no image"

# The same render in one process; with --aovs for its Variance.Y.
timeout 60 "$lamina" render "$scene" --spp 8 --resolution 64x64 --max-depth 4 -q \
  -o "$work/single.exr"
timeout 60 "$lamina" render "$scene" --spp 8 --resolution 64x64 --max-depth 4 -q --aovs \
  -o "$work/single-aovs.exr"
"$agreement" "$work/plan/image.exr" "$work/single.exr" R G B || fail "the merged image differs"
"$agreement" "$work/plan/image.exr" "$work/single-aovs.exr" Variance.Y ||
  fail "the merged variance differs"
echo "cluster test: 4 array tasks and the merge job on a local Slurm agree with one render"

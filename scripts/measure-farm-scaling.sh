#!/usr/bin/env bash
# Measures how wall time to a given error falls with the number of shards, on a single-node
# Slurm on localhost (tests/cluster/local_slurm.sh): for each shard count N, `lamina farm plan
# --shards N --submit` renders the same samples per pixel (one thread per task), and the wall
# time from submission to the merged image is taken, with the merge job's own time and one
# shard's scene loading (a 1-sample render) measured apart. Then `lamina convergence --merged`
# measures every merged image against a reference rendered with another seed.
# Usage: scripts/measure-farm-scaling.sh BUILD_DIR SCENE OUT_DIR [SPP] [RESOLUTION] [N...]
# docs/distributed.md quotes its output (OUT_DIR/scaling.csv, OUT_DIR/convergence/summary.md).
set -euo pipefail

build=$(realpath "$1") scene=$(realpath "$2") out=$3
spp=${4:-64} resolution=${5:-256x256}
shift $(( $# < 5 ? $# : 5 ))
counts=("$@")
[ ${#counts[@]} -gt 0 ] || counts=(1 2 4)
lamina=$build/app/lamina
deadline=$((SECONDS + 3600))
mkdir -p "$out"
out=$(realpath "$out")

source "$(dirname "$0")/../tests/cluster/local_slurm.sh"
local_slurm_require
local_slurm_start

now() { date +%s.%N; }
since() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.2f", b - a }'; }
load_start=$(now)
"$lamina" render "$scene" --spp 1 --resolution "$resolution" --threads 1 -q -o "$out/load.exr"
load=$(since "$load_start")
echo "shards,spp,wall_seconds,merge_seconds,one_sample_render_seconds" > "$out/scaling.csv"
merged=()
for n in "${counts[@]}"; do
  plan=$work/plan-$n
  start=$(now)
  "$lamina" farm plan "$scene" --shards "$n" --spp "$spp" --resolution "$resolution" \
    --threads 1 -o "$plan" --submit >/dev/null
  wait_for "the $n-shard render" queue_empty
  wall=$(since "$start")
  [ -f "$plan/image.exr" ] || fail "$n shards: no merged image"
  merge_start=$(now)
  bash "$plan/merge.sh" 2>/dev/null
  merge=$(since "$merge_start")
  cp "$plan/image.exr" "$out/merged-$n.exr"
  merged+=("$out/merged-$n.exr")
  echo "$n,$spp,$wall,$merge,$load" | tee -a "$out/scaling.csv"
done
"$lamina" render "$scene" --spp $((spp * 16)) --resolution "$resolution" --seed 1234567 -q \
  -o "$out/reference.exr"
list=$(IFS=,; echo "${merged[*]}")
"$lamina" convergence "$scene" --merged "$list" --reference "$out/reference.exr" \
  -o "$out/convergence" >/dev/null
cat "$out/convergence/summary.md"
